// Strict reading of the drum side's YAML dictionaries (drumDict, flight
// files, drift-model constants): yaml-cpp accepts a duplicated key and keeps
// the first, and a misspelt key is simply never read. These helpers refuse
// both, and name the file, the line and the entry in every error.
#ifndef DRUM_IO_YAMLINPUT_HPP
#define DRUM_IO_YAMLINPUT_HPP

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace drum
{

//- Parse a YAML file / text; syntax errors and duplicated keys (at any depth)
//  are InputErrors naming file:line
YAML::Node loadYamlFile(const std::string& file);
YAML::Node loadYamlText(const std::string& text, const std::string& file);

//- "file:line" of a node (1-based line; just file when the node has no mark)
std::string fileLine(const std::string& file, const YAML::Node& node);

//- Refuse every key of the mapping `map` (entry path `where`, "" at the top)
//  that is not in `allowed`, naming the nearest allowed key
void onlyKeys
(
    const YAML::Node& map,
    const std::string& where,
    const std::vector<std::string>& allowed,
    const std::string& file
);

//- The allowed key nearest to `key` (edit distance at most a third of its
//  length, at least 2), "" if none is that close
std::string nearestKey(const std::string& key, const std::vector<std::string>& allowed);

//- A scalar entry as a number / a whole number; InputError naming file:line
//  and `entry` if it is not one
double yamlNumber(const YAML::Node& node, const std::string& entry, const std::string& file);
long yamlWholeNumber(const YAML::Node& node, const std::string& entry, const std::string& file);

} // namespace drum

#endif
