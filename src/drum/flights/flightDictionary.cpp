#include "drum/flights/flightDictionary.hpp"

#include "drum/flights/angleOfRepose.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/yamlInput.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

namespace drum
{

namespace
{

void onlyKnown(const YAML::Node& node, const std::string& where,
               const std::set<std::string>& known, const std::string& file)
{
    onlyKeys(node, where == "(top level)" ? "" : where,
             std::vector<std::string>(known.begin(), known.end()), file);
}

double number(const YAML::Node& parent, const std::string& where, const std::string& key,
              const std::string& file)
{
    const YAML::Node n = parent[key];
    if (!n)
    {
        throw InputError(file, where + "." + key, "missing entry");
    }
    return yamlNumber(n, where + "." + key, file);
}

double numberOr(const YAML::Node& parent, const std::string& where, const std::string& key,
                double fallback, const std::string& file)
{
    return parent[key] ? number(parent, where, key, file) : fallback;
}

} // namespace


FlightCase parseFlightDictionary(const std::string& text, const std::string& file)
{
    const YAML::Node root = loadYamlText(text, file);
    onlyKnown(root, "(top level)", {"drum", "flight", "material", "output"}, file);
    for (const char* section : {"drum", "flight", "material"})
    {
        if (!root[section]) throw InputError(file, section, "missing section");
    }
    const YAML::Node drum = root["drum"];
    const YAML::Node flight = root["flight"];
    const YAML::Node material = root["material"];
    onlyKnown(drum, "drum", {"radius", "nFlights", "speed", "slope", "bedDepth"}, file);
    onlyKnown(flight, "flight",
              {"baseLength", "tipLength", "baseAngle", "tipAngle", "length", "serration"}, file);
    onlyKnown(material, "material", {"bulkDensity", "dynamicAngleOfRepose", "moisture",
                                     "layerVelocity", "layerBulkDensity"}, file);

    FlightCase c;
    c.geometry.drumRadius = number(drum, "drum", "radius", file);
    const double nf = number(drum, "drum", "nFlights", file);
    if (nf != std::floor(nf) || nf < 3 || nf > 1000)
    {
        throw InputError(file, "drum.nFlights", "must be an integer in the allowed range [3, 1000]");
    }
    c.geometry.nFlights = int(nf);
    c.settings.speedRpm = number(drum, "drum", "speed", file);
    c.settings.drumSlopeDeg = numberOr(drum, "drum", "slope", 0.0, file);
    c.settings.bedDepth = numberOr(drum, "drum", "bedDepth", 0.0, file);

    c.geometry.baseLength = number(flight, "flight", "baseLength", file);
    c.geometry.tipLength = number(flight, "flight", "tipLength", file);
    c.geometry.baseAngleDeg = numberOr(flight, "flight", "baseAngle", 90.0, file);
    c.geometry.tipAngleDeg = number(flight, "flight", "tipAngle", file);
    c.settings.flightLength = numberOr(flight, "flight", "length", 1.0, file);
    if (const YAML::Node s = flight["serration"])
    {
        onlyKnown(s, "flight.serration", {"width", "depth", "perMetre"}, file);
        c.geometry.tipLength = serratedTipLength(c.geometry.tipLength,
            number(s, "flight.serration", "width", file),
            number(s, "flight.serration", "depth", file),
            number(s, "flight.serration", "perMetre", file), file);
    }

    c.settings.bulkDensity = number(material, "material", "bulkDensity", file);
    const bool hasPhi = bool(material["dynamicAngleOfRepose"]);
    const bool hasW = bool(material["moisture"]);
    if (hasPhi == hasW)
    {
        throw InputError(file, "material.dynamicAngleOfRepose",
            "give exactly one of dynamicAngleOfRepose [deg, allowed range (0, 90)] or "
            "moisture [kg/kg, Lee 2008 Eq 7.2 for raw sugar]");
    }
    if (hasPhi)
    {
        c.phiDeg = number(material, "material", "dynamicAngleOfRepose", file);
        c.phiSource = "dynamicAngleOfRepose";
    }
    else
    {
        try
        {
            c.phiDeg = brittonMoistureAngleDeg(number(material, "material", "moisture", file));
        }
        catch (const InputError& e)
        {
            throw InputError(file, "material.moisture", e.what());
        }
        c.phiSource = "moisture (Lee 2008 Eq 7.2)";
    }
    c.settings.layerVelocity = numberOr(material, "material", "layerVelocity", 1.0, file);
    c.settings.layerBulkDensity = numberOr(material, "material", "layerBulkDensity", 0.0, file);

    if (const YAML::Node out = root["output"])
    {
        onlyKnown(out, "output",
                  {"angleStart", "angleEnd", "angleStep", "snapshotAngle", "plots"}, file);
        c.angleStartDeg = numberOr(out, "output", "angleStart", 0.0, file);
        c.angleEndDeg = numberOr(out, "output", "angleEnd", -1.0, file);
        c.angleStepDeg = numberOr(out, "output", "angleStep", 0.5, file);
        c.snapshotAngleDeg = numberOr(out, "output", "snapshotAngle", 120.0, file);
        if (out["plots"])
        {
            try { c.plots = out["plots"].as<bool>(); }
            catch (const YAML::Exception&)
            {
                throw InputError(file, "output.plots", "must be true or false");
            }
        }
    }
    requireInRange(c.angleStepDeg, 1e-3, 30.0, "output.angleStep", file);
    requireInRange(c.angleStartDeg, -90.0, 360.0, "output.angleStart", file);
    if (c.angleEndDeg >= 0.0)
    {
        requireInRange(c.angleEndDeg, c.angleStartDeg + c.angleStepDeg, 720.0, "output.angleEnd", file);
    }
    requireInRange(c.snapshotAngleDeg, 0.0, 360.0, "output.snapshotAngle", file);
    return c;
}


FlightCase readFlightDictionary(const std::filesystem::path& path)
{
    requireReadableFile(path.string());
    std::ifstream in(path);
    if (!in)
    {
        throw InputError(path.string(), "", "cannot open the dictionary");
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return parseFlightDictionary(ss.str(), path.string());
}

} // namespace drum
