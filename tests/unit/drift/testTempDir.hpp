// A scratch folder per test process, removed when the process ends
// (tests must not leave files behind in the system's temporary folder).
#ifndef DRUM_TESTS_TESTTEMPDIR_HPP
#define DRUM_TESTS_TESTTEMPDIR_HPP

#include <filesystem>
#include <map>
#include <string>
#include <system_error>

#include <unistd.h>

//- TMP/<stem>_<pid>, made on first use; the same folder for every call with
//  the same stem in this process, removed with its content at exit
inline std::filesystem::path testTempDir(const std::string& stem)
{
    struct Owned
    {
        std::filesystem::path path;
        ~Owned()
        {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static std::map<std::string, Owned> dirs;
    auto& dir = dirs[stem];
    if (dir.path.empty())
    {
        dir.path = std::filesystem::temp_directory_path()/(stem + "_" + std::to_string(::getpid()));
    }
    std::filesystem::create_directories(dir.path);
    return dir.path;
}

#endif
