// A results folder that is replaced whole, never mixed: a run writes into a
// fresh hidden folder beside the target; commit() keeps the user's own files
// of the old folder (those the tool did not write, per the old folder's
// manifest), swaps the folders with two renames and removes what the
// previous run wrote. Until commit() the old folder is untouched; a run that
// fails (or throws) leaves it as it was and removes its partial folder; the
// partial folder of a run that was killed (its process gone) is removed by the
// next run (a swap it had begun is finished first), so none is left behind.
#ifndef DRUM_IO_RESULTSFOLDER_HPP
#define DRUM_IO_RESULTSFOLDER_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace drum
{

//- The absolute path of a tool's output folder `out` (given by `option`);
//  InputError when it is the current folder or holds it (replacing it whole
//  would replace the folder the user stands in)
std::filesystem::path ownOutputFolder(const std::filesystem::path& out, const std::string& option);

class ResultsFolder
{
public:
    explicit ResultsFolder(std::filesystem::path target);

    //- Removes the partial folder unless commit() was called
    ~ResultsFolder();

    ResultsFolder(const ResultsFolder&) = delete;
    ResultsFolder& operator=(const ResultsFolder&) = delete;

    //- Where this run writes its outputs
    const std::filesystem::path& path() const { return partial_; }

    //- The hidden folders of killed runs that this one removed (or finished)
    const std::vector<std::filesystem::path>& cleaned() const { return cleaned_; }

    const std::filesystem::path& target() const { return target_; }

    //- Install the outputs as the target folder; returns the user's files
    //  kept from the previous folder (relative paths)
    std::vector<std::filesystem::path> commit();

    //- Name of the manifest (list of the files the run wrote) in the folder
    static const char* manifestName() { return ".written"; }

private:
    std::filesystem::path target_;
    std::filesystem::path partial_;
    bool committed_ = false;
    std::vector<std::filesystem::path> cleaned_;
};

} // namespace drum

#endif
