#include "drum/io/yamlInput.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace drum
{

namespace
{

std::string join(const std::string& where, const std::string& key)
{
    return where.empty() ? key : where + "." + key;
}

void refuseDuplicates(const YAML::Node& node, const std::string& where, const std::string& file)
{
    if (node.IsMap())
    {
        std::map<std::string, YAML::Node> seen;
        for (const auto& kv : node)
        {
            const std::string key = kv.first.as<std::string>();
            const auto it = seen.find(key);
            if (it != seen.end())
            {
                throw InputError(fileLine(file, kv.first), join(where, key),
                    "given twice (first on line " + std::to_string(it->second.Mark().line + 1)
                    + "); give each entry once");
            }
            seen.emplace(key, kv.first);
            refuseDuplicates(kv.second, join(where, key), file);
        }
    }
    else if (node.IsSequence())
    {
        for (std::size_t i = 0; i < node.size(); ++i)
        {
            refuseDuplicates(node[i], where + "[" + std::to_string(i) + "]", file);
        }
    }
}

std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1,
                               prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

} // namespace


std::string fileLine(const std::string& file, const YAML::Node& node)
{
    const YAML::Mark m = node.Mark();
    return m.line >= 0 ? file + ":" + std::to_string(m.line + 1) : file;
}


YAML::Node loadYamlText(const std::string& text, const std::string& file)
{
    YAML::Node root;
    try
    {
        root = YAML::Load(text);
    }
    catch (const YAML::Exception& e)
    {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1), "",
                         "YAML syntax: " + e.msg);
    }
    refuseDuplicates(root, "", file);
    return root;
}


YAML::Node loadYamlFile(const std::string& file)
{
    requireReadableFile(file);
    YAML::Node root;
    try
    {
        root = YAML::LoadFile(file);
    }
    catch (const YAML::BadFile&)
    {
        throw InputError(file, "", "cannot read the file");
    }
    catch (const YAML::Exception& e)
    {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1), "",
                         "YAML syntax: " + e.msg);
    }
    refuseDuplicates(root, "", file);
    return root;
}


std::string nearestKey(const std::string& key, const std::vector<std::string>& allowed)
{
    std::string best;
    std::size_t bestD = std::max<std::size_t>(2, key.size()/3) + 1;
    for (const auto& a : allowed)
    {
        const std::size_t d = editDistance(key, a);
        if (d < bestD)
        {
            bestD = d;
            best = a;
        }
    }
    return best;
}


void onlyKeys
(
    const YAML::Node& map,
    const std::string& where,
    const std::vector<std::string>& allowed,
    const std::string& file
)
{
    if (!map.IsMap())
    {
        throw InputError(fileLine(file, map), where.empty() ? "(top level)" : where,
                         "must be a dictionary of entries");
    }
    for (const auto& kv : map)
    {
        const std::string key = kv.first.as<std::string>();
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        const std::string near = nearestKey(key, allowed);
        throw InputError(fileLine(file, kv.first), join(where, key),
            "unknown entry" + (near.empty() ? std::string() : " (did you mean '" + join(where, near) + "'?)")
            + "; allowed: " + list);
    }
}


double yamlNumber(const YAML::Node& node, const std::string& entry, const std::string& file)
{
    if (!node || !node.IsScalar())
    {
        throw InputError(fileLine(file, node), entry, "must be a number");
    }
    try
    {
        return node.as<double>();
    }
    catch (const YAML::Exception&)
    {
        throw InputError(fileLine(file, node), entry, "'" + node.Scalar() + "' is not a number");
    }
}


long yamlWholeNumber(const YAML::Node& node, const std::string& entry, const std::string& file)
{
    const double v = yamlNumber(node, entry, file);
    if (!std::isfinite(v) || v != std::floor(v) || std::abs(v) > 1e15)
    {
        throw InputError(fileLine(file, node), entry,
                         "'" + node.Scalar() + "' is not a whole number");
    }
    return long(v);
}

} // namespace drum
