// Where the project's own files are: the one lookup the drum library, its
// tools and tests use for the thesis tables (data/) and the shipped defaults
// (etc/defaults/). Each folder is found inside the checkout; an environment
// variable may point elsewhere. (The case templates, etc/templates/, are
// copied by the Python tools curtainCase and buildDriftTable.)
#ifndef DRUM_IO_PROJECTPATHS_HPP
#define DRUM_IO_PROJECTPATHS_HPP

#include <filesystem>
#include <string>

namespace drum
{

//- $DRYER_PROJECT if set (etc/bashrc sets it), else the checkout this
//  library was built from
std::filesystem::path projectDir();

//- $DRYER_DATA if set, else projectDir()/data (the theses' tables)
std::filesystem::path dataDir();

//- projectDir()/etc/defaults: shipped drift tables and model constants
std::filesystem::path defaultsDir();

//- A path from a dictionary: a leading $DRYER_DATA, $DRYER_PROJECT (also
//  written ${...}) resolves as above even when the variable is unset, any
//  other leading $VAR from the environment; relative paths are taken from
//  baseDir. Throws InputError(file, entry, ...) for an unset variable.
std::filesystem::path expandPath
(
    const std::string& raw,
    const std::filesystem::path& baseDir,
    const std::string& file,
    const std::string& entry
);

} // namespace drum

#endif
