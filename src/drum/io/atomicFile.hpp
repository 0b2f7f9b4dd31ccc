// Write a file so that it is either complete or absent: the text goes to a
// temporary beside the target and is renamed over it only once written.
// Nothing the user already had is lost when a run fails half-way.
#ifndef DRUM_IO_ATOMICFILE_HPP
#define DRUM_IO_ATOMICFILE_HPP

#include <filesystem>
#include <fstream>
#include <string>

namespace drum
{

class AtomicFile
{
public:
    explicit AtomicFile(std::filesystem::path target);

    //- Removes the temporary unless commit() was called
    ~AtomicFile();

    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::ofstream& stream() { return out_; }

    //- Flush, check, and rename the temporary over the target
    void commit();

    const std::filesystem::path& target() const { return target_; }

private:
    std::filesystem::path target_;
    std::filesystem::path temp_;
    std::ofstream out_;
    bool committed_ = false;
};

//- Write text to path atomically
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

} // namespace drum

#endif
