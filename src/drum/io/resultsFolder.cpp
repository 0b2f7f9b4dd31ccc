#include "drum/io/resultsFolder.hpp"

#include "drum/io/atomicFile.hpp"
#include "drum/io/inputError.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <cerrno>
#include <csignal>
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

//- Remove the files a run wrote (its manifest `mine`) from a folder, then the
//  folders left empty: never a file the tool did not write
void removeWritten(const fs::path& folder, const std::set<fs::path>& mine)
{
    std::error_code ec;
    for (const auto& f : mine) fs::remove(folder/f, ec);
    std::vector<fs::path> dirs;
    for (const auto& e : fs::recursive_directory_iterator(folder, ec))
    {
        if (e.is_directory()) dirs.push_back(e.path());
    }
    std::sort(dirs.begin(), dirs.end(), [](const fs::path& a, const fs::path& b)
              { return a.string().size() > b.string().size(); });
    for (const auto& d : dirs) fs::remove(d, ec);
    fs::remove(folder, ec);
}

std::set<fs::path> manifestOf(const fs::path& folder)
{
    return writtenBefore(folder, {});
}

//- The pid a hidden folder ".<name><kind><pid>" of `target` belongs to, or -1
long hiddenPid(const fs::path& entry, const fs::path& target, const std::string& kind)
{
    const std::string head = "." + target.filename().string() + kind;
    const std::string name = entry.filename().string();
    if (name.size() <= head.size() || name.compare(0, head.size(), head) != 0) return -1;
    const std::string digits = name.substr(head.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return -1;
    return std::stol(digits);
}

bool processGone(long pid)
{
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
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
    // what killed runs left beside the target: a partial folder is removed; a swap
    // that had begun (the old folder renamed away, the new one not yet in place) is
    // finished, then the old folder's own files are removed
    std::error_code ec;
    const fs::path parent = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
    std::vector<fs::path> partials, olds;
    for (const auto& e : fs::directory_iterator(parent, ec))
    {
        const long pp = hiddenPid(e.path(), target_, ".partial"), po = hiddenPid(e.path(), target_, ".old");
        if (pp > 0 && pp != ::getpid() && processGone(pp)) partials.push_back(e.path());
        if (po > 0 && po != ::getpid() && processGone(po)) olds.push_back(e.path());
    }
    for (const auto& p : partials)
    {
        const long pid = hiddenPid(p, target_, ".partial");
        const fs::path old = parent/("." + target_.filename().string() + ".old" + std::to_string(pid));
        if (!fs::exists(target_) && fs::exists(old) && fs::exists(p/manifestName()))
        {
            fs::rename(p, target_, ec);   // the killed run's complete results
        }
        else
        {
            fs::remove_all(p, ec);
        }
        cleaned_.push_back(p);
    }
    for (const auto& o : olds)
    {
        if (fs::exists(target_))
        {
            removeWritten(o, manifestOf(o));
            cleaned_.push_back(o);
        }
    }
    fs::remove_all(partial_, ec);
    fs::create_directories(partial_, ec);
    if (ec)
    {
        throw std::runtime_error("cannot write the results folder " + target_.string() + ": " + ec.message());
    }
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
        removeWritten(trash, mine);
    }
    else
    {
        fs::rename(partial_, target_);
        committed_ = true;
    }
    return kept;
}

} // namespace drum
