#include "drum/io/resultsFolder.hpp"

#include "drum/io/atomicFile.hpp"
#include "drum/io/inputError.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace drum
{

std::filesystem::path ownOutputFolder(const std::filesystem::path& out, const std::string& option)
{
    const std::filesystem::path here = std::filesystem::current_path();
    const std::filesystem::path whole = std::filesystem::weakly_canonical(std::filesystem::absolute(out));
    if (whole == here || std::mismatch(whole.begin(), whole.end(), here.begin(), here.end()).first == whole.end())
    {
        throw InputError("", option, "'" + out.string() + "' is the current folder or holds it; "
                         "give a folder of its own for the results");
    }
    return whole;
}

namespace fs = std::filesystem;

namespace
{

std::set<fs::path> filesUnder(const fs::path& dir)
{
    std::set<fs::path> out;
    if (!fs::is_directory(dir)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
    {
        if (!e.is_directory()) out.insert(fs::relative(e.path(), dir));
    }
    return out;
}

//- The files the previous run wrote: its manifest; a folder without one
//  (written before manifests): the names this run writes too
std::set<fs::path> writtenBefore(const fs::path& old, const std::set<fs::path>& now)
{
    std::set<fs::path> mine;
    std::ifstream in(old/ResultsFolder::manifestName());
    if (in)
    {
        std::string line;
        while (std::getline(in, line))
        {
            if (!line.empty()) mine.insert(fs::path(line));
        }
        mine.insert(ResultsFolder::manifestName());
        return mine;
    }
    return now;
}

} // namespace


ResultsFolder::ResultsFolder(fs::path target)
:
    target_(std::move(target)),
    partial_(target_.parent_path()
        / ("." + target_.filename().string() + ".partial" + std::to_string(::getpid())))
{
    if (fs::exists(target_) && !fs::is_directory(target_))
    {
        throw std::runtime_error(target_.string() + " is a file, not a results folder");
    }
    std::error_code ec;
    fs::remove_all(partial_, ec);
    fs::create_directories(partial_);
}


ResultsFolder::~ResultsFolder()
{
    if (!committed_)
    {
        std::error_code ec;
        fs::remove_all(partial_, ec);
    }
}


std::vector<fs::path> ResultsFolder::commit()
{
    // the manifest of this run, written (and checked) like every output
    std::set<fs::path> now = filesUnder(partial_);
    now.insert(manifestName());
    std::ostringstream list;
    for (const auto& f : now) list << f.generic_string() << '\n';
    writeFileAtomically(partial_/manifestName(), list.str());

    std::vector<fs::path> kept;
    if (fs::is_directory(target_))
    {
        const std::set<fs::path> mine = writtenBefore(target_, now);
        for (const auto& f : filesUnder(target_))
        {
            if (mine.count(f)) continue;
            fs::path dst = partial_/f;
            if (fs::exists(dst)) dst = partial_/"kept"/f;   // the run wrote one of that name
            fs::create_directories(dst.parent_path());
            fs::rename(target_/f, dst);
            kept.push_back(fs::relative(dst, partial_));
        }
        const fs::path trash = target_.parent_path()
            / ("." + target_.filename().string() + ".old" + std::to_string(::getpid()));
        fs::rename(target_, trash);
        fs::rename(partial_, target_);
        committed_ = true;
        std::error_code ec;
        for (const auto& f : mine) fs::remove(trash/f, ec);
        // then the folders left empty (never a file this tool did not write)
        std::vector<fs::path> dirs;
        for (const auto& e : fs::recursive_directory_iterator(trash, ec))
        {
            if (e.is_directory()) dirs.push_back(e.path());
        }
        std::sort(dirs.begin(), dirs.end(), [](const fs::path& a, const fs::path& b)
                  { return a.string().size() > b.string().size(); });
        for (const auto& d : dirs) fs::remove(d, ec);
        fs::remove(trash, ec);
    }
    else
    {
        fs::rename(partial_, target_);
        committed_ = true;
    }
    return kept;
}

} // namespace drum
