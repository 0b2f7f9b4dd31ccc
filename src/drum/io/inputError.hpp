// The error every drum-side reader and model throws for bad input: it names
// the file, the entry and the allowed range, so a user can fix the input.
#ifndef DRUM_IO_INPUTERROR_HPP
#define DRUM_IO_INPUTERROR_HPP

#include <stdexcept>
#include <string>

namespace drum
{

class InputError : public std::runtime_error
{
public:
    //- file: the file read (may be empty); entry: the dictionary entry,
    //  CSV row/column or parameter; message: what is wrong and what is allowed
    InputError(std::string file, std::string entry, const std::string& message);

    const std::string& file() const { return file_; }
    const std::string& entry() const { return entry_; }

private:
    std::string file_;
    std::string entry_;
};

//- Throw InputError unless lo <= value <= hi (inclusive bounds)
void requireInRange
(
    double value, double lo, double hi,
    const std::string& entry, const std::string& file = ""
);

//- Throw InputError unless value > 0 and finite
void requirePositive(double value, const std::string& entry, const std::string& file = "");

//- Throw InputError naming the file (and the entry that named it, if any)
//  unless `file` is an existing regular file that can be opened for reading:
//  "not found", "is a folder, not a file" or "cannot be read"
void requireReadableFile(const std::string& file, const std::string& entry = "");

} // namespace drum

#endif
