#include "drum/io/dictReader.hpp"

#include "drum/io/inputError.hpp"
#include "drum/io/yamlInput.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

YAML::Node DictReader::section(const YAML::Node& root, const std::string& name, bool required) const
{
    const YAML::Node n = root[name];
    if (!n && required)
    {
        throw InputError(file_, name, "missing section");
    }
    if (n && !n.IsMap())
    {
        throw InputError(file_, name, "must be a dictionary of entries");
    }
    return n;
}


double DictReader::number(const YAML::Node& sec, const std::string& secName, const std::string& key,
                          double lo, double hi, std::optional<double> dflt, bool openLo) const
{
    const std::string entry = secName + "." + key;
    const YAML::Node n = sec[key];
    if (!n)
    {
        if (dflt) return *dflt;
        throw InputError(file_, entry, "missing; allowed range " + range(lo, hi, openLo));
    }
    double v;
    try
    {
        v = yamlNumber(n, entry, file_);
    }
    catch (const InputError& e)
    {
        throw InputError(e.file(), entry, "not a number; allowed range " + range(lo, hi, openLo));
    }
    if (!std::isfinite(v) || v < lo || v > hi || (openLo && v == lo))
    {
        std::ostringstream os;
        os << "value " << v << " outside the allowed range " << range(lo, hi, openLo);
        throw InputError(fileLine(file_, n), entry, os.str());
    }
    return v;
}


int DictReader::integer(const YAML::Node& sec, const std::string& secName, const std::string& key,
                        int lo, int hi, std::optional<int> dflt) const
{
    const std::string entry = secName + "." + key;
    const YAML::Node n = sec[key];
    if (!n && dflt) return *dflt;
    const double v = number(sec, secName, key, lo, hi);
    if (v != std::floor(v))
    {
        throw InputError(fileLine(file_, n), entry, "'" + n.Scalar()
            + "' is not a whole number; allowed range " + range(lo, hi, false) + " (integers)");
    }
    return int(v);
}


std::string DictReader::word(const YAML::Node& sec, const std::string& secName, const std::string& key,
                             const std::vector<std::string>& allowed, std::optional<std::string> dflt) const
{
    const std::string entry = secName + "." + key;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    const YAML::Node n = sec[key];
    if (!n)
    {
        if (dflt) return *dflt;
        throw InputError(file_, entry, "missing; allowed: " + list);
    }
    if (!n.IsScalar())
    {
        throw InputError(fileLine(file_, n), entry, "must be one word; allowed: " + list);
    }
    const std::string v = n.as<std::string>();
    for (const auto& a : allowed)
    {
        if (v == a) return v;
    }
    throw InputError(fileLine(file_, n), entry, "unknown value '" + v + "'; allowed: " + list);
}


std::string DictReader::numberOrWord(const YAML::Node& sec, const std::string& secName, const std::string& key,
                                     double lo, double hi, const std::vector<std::string>& words,
                                     const std::string& what, double& value, std::optional<double> dflt,
                                     bool openLo) const
{
    const YAML::Node n = sec[key];
    if (n && n.IsScalar())
    {
        for (const auto& w : words)
        {
            if (n.Scalar() == w) return w;
        }
    }
    if (n)
    {
        const std::string entry = secName + "." + key;
        try
        {
            yamlNumber(n, entry, file_);
        }
        catch (const InputError&)
        {
            throw InputError(fileLine(file_, n), entry, "'" + (n.IsScalar() ? n.Scalar() : std::string("?"))
                + "': " + what);
        }
    }
    value = number(sec, secName, key, lo, hi, dflt, openLo);
    return "";
}


void DictReader::only(const YAML::Node& sec, const std::string& secName, const std::vector<std::string>& keys) const
{
    if (sec) onlyKeys(sec, secName, keys, file_);
}


void DictReader::refuse(const YAML::Node& sec, const std::string& secName, const std::string& key,
                        const std::string& why) const
{
    if (sec && sec[key])
    {
        throw InputError(fileLine(file_, sec[key]), secName.empty() ? key : secName + "." + key,
            "not used " + why + "; remove it");
    }
}


std::string DictReader::range(double lo, double hi, bool openLo)
{
    std::ostringstream os;
    os << (openLo ? "(" : "[") << lo << ", " << hi << "]";
    return os.str();
}

} // namespace drum
