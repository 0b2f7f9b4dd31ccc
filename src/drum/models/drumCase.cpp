#include "drum/models/drumCase.hpp"
#include "drum/io/unitSlips.hpp"
#include "particleDrag/gasProperties.hpp"

#include "drum/drift/porousSheetDrift.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/projectPaths.hpp"
#include "drum/io/yamlInput.hpp"
#include "drum/numerics/constants.hpp"

#include <algorithm>

namespace drum
{

namespace
{

SherrittFlightSpec readSherrittFlight
(
    const DictReader& r,
    const YAML::Node& n,
    const std::string& sec,
    double D,
    double Di,
    double phiDefaultDeg,
    bool interior
)
{
    SherrittFlightSpec s;
    s.type = parseSherrittFlightType(
        r.word(n, sec, "type", {"twoSided", "EAD", "CBD", "table"}), sec + ".type", r.file());
    s.count = r.integer(n, sec, "count", interior ? 1 : 2, 200);
    // keys each type reads (anything else is a typo)
    std::vector<std::string> keys = {"type", "count"};
    switch (s.type)
    {
        case SherrittFlightType::twoSided:
            s.baseLength = r.number(n, sec, "baseLength", 0, D/2, {}, true);
            s.tipLength = r.number(n, sec, "tipLength", 0, D/2, 0.0);
            s.tipAngle = r.number(n, sec, "tipAngle_deg", 60, 180, 90.0)*deg;
            s.baseAngle = r.number(n, sec, "baseAngle_deg", 30, 150, 90.0)*deg;
            keys.insert(keys.end(), {"baseLength", "tipLength", "tipAngle_deg", "baseAngle_deg"});
            break;
        case SherrittFlightType::ead:
        case SherrittFlightType::cbd:
        {
            const bool cbd = s.type == SherrittFlightType::cbd;
            s.radius = r.number(n, sec, "radius", 0, D/4, {}, true);
            s.designRepose = r.number(n, sec, "designRepose_deg", 0, 90, phiDefaultDeg, true)*deg;
            s.tipDiameter = cbd ? r.number(n, sec, "tipDiameter", 0, D, {}, true)
                                : r.number(n, sec, "tipDiameter", 0, D, 0.0);
            if (cbd)
            {
                s.bias = r.number(n, sec, "bias", 0, 0.99);
            }
            keys.insert(keys.end(), {"radius", "designRepose_deg", "tipDiameter", "bias"});
            break;
        }
        case SherrittFlightType::table:
        {
            s.tipDiameter = r.number(n, sec, "tipDiameter", interior ? Di : 0, D, {}, true);
            const YAML::Node a = n["angles_deg"], l = n["lengths"];
            if (!a || !a.IsSequence() || a.size() < 2)
            {
                throw InputError(r.file(), sec + ".angles_deg", "a list of at least 2 ascending rotation angles in deg");
            }
            if (!l || !l.IsSequence() || l.size() != a.size())
            {
                throw InputError(r.file(), sec + ".lengths", "one horizontal length (m, >= 0) per angle in angles_deg");
            }
            for (std::size_t i = 0; i < a.size(); ++i)
            {
                const std::string at = "[" + std::to_string(i) + "]";
                s.angles.push_back(yamlNumber(a[i], sec + ".angles_deg" + at, r.file())*deg);
                s.lengths.push_back(yamlNumber(l[i], sec + ".lengths" + at, r.file()));
            }
            keys.insert(keys.end(), {"tipDiameter", "angles_deg", "lengths"});
            break;
        }
    }
    for (const auto& kv : n)
    {
        const std::string k = kv.first.as<std::string>();
        if (std::find(keys.begin(), keys.end(), k) == keys.end())
        {
            std::string list;
            for (const auto& a : keys) list += (list.empty() ? "" : ", ") + a;
            const std::string near = nearestKey(k, keys);
            throw InputError(fileLine(r.file(), kv.first), sec + "." + k, "unknown entry for type "
                + toString(s.type) + (near.empty() ? "" : " (did you mean '" + sec + "." + near + "'?)")
                + "; allowed: " + list);
        }
    }
    return s;
}

} // namespace


DrumCase readDrumCase(const std::filesystem::path& caseDir, const std::vector<std::string>& sections)
{
    DrumCase c;
    c.caseDir = caseDir;
    c.path = caseDir/"drumDict";
    const DictReader r = c.reader();
    const std::string& file = r.file();
    if (!std::filesystem::exists(c.path))
    {
        throw InputError(file, "", "case dictionary not found");
    }
    c.root = loadYamlFile(file);
    const YAML::Node& root = c.root;
    // every key of every section is one a model reads: a misspelt one is refused
    std::vector<std::string> top = {"drum", "flights", "material", "gas", "model", "rtd"};
    for (const std::string& s : sections)
    {
        if (std::find(top.begin(), top.end(), s) == top.end()) top.push_back(s);
    }
    r.only(root, "", top);

    const YAML::Node dr = r.section(root, "drum");
    r.only(dr, "drum", {"length", "diameter", "slope_deg", "speed_rpm", "centrefillDiameter"});
    CaseDrum& d = c.drum;
    d.length = r.number(dr, "drum", "length", 0, 500, {}, true);
    d.diameter = r.number(dr, "drum", "diameter", 0, 20, {}, true);
    d.slopeDeg = r.number(dr, "drum", "slope_deg", 0, 20);
    d.speedRpm = r.number(dr, "drum", "speed_rpm", 0, 60, {}, true);
    d.centrefillDiameter = r.number(dr, "drum", "centrefillDiameter", 0, 0.95*d.diameter, 0.0);

    // flights: Lee's two-section flight (flat entries) or Sherritt's
    // description (exterior/interior subsections, read after the material)
    const YAML::Node fl = r.section(root, "flights");
    r.only(fl, "flights", {"axialLength", "tableStep_deg", "count", "baseLength", "tipLength",
                           "baseAngle_deg", "tipAngle_deg", "exterior", "interior"});
    const bool sherrittFlights = bool(fl["exterior"]);
    c.flights.axialLength = r.number(fl, "flights", "axialLength", 0, d.length, d.length, true);
    c.flights.tableStepDeg = r.number(fl, "flights", "tableStep_deg", 0.1, 5, 1.0);
    if (!sherrittFlights)
    {
        if (fl["interior"])
        {
            throw InputError(file, "flights.interior", "needs flights.exterior (Sherritt's flight description)");
        }
        TwoSectionFlight f;
        f.count = r.integer(fl, "flights", "count", 2, 200);
        f.baseLength = r.number(fl, "flights", "baseLength", 0, d.diameter/2, {}, true);
        f.tipLength = r.number(fl, "flights", "tipLength", 0, d.diameter/2, 0.0);
        f.baseAngleDeg = r.number(fl, "flights", "baseAngle_deg", 30, 150, 90.0);
        f.tipAngleDeg = r.number(fl, "flights", "tipAngle_deg", 60, 180, 90.0);
        c.flights.twoSection = f;
    }
    else
    {
        for (const char* k : {"count", "baseLength", "tipLength", "baseAngle_deg", "tipAngle_deg"})
        {
            if (fl[k])
            {
                throw InputError(file, std::string("flights.") + k,
                    "give either the two-section flight entries or flights.exterior, not both");
            }
        }
    }

    const YAML::Node m = r.section(root, "material");
    r.only(m, "material", {"feedRate", "bulkDensity", "particleDensity", "sphericity", "repose_deg",
                           "moisture", "sizes_um", "fractions_pct"});
    CaseMaterial& mat = c.material;
    mat.feedRate = r.number(m, "material", "feedRate", 0, 1e4, {}, true);
    mat.bulkDensity = r.number(m, "material", "bulkDensity", 0, 2e4, {}, true);
    mat.particleDensity = r.number(m, "material", "particleDensity", mat.bulkDensity, 2e4);
    mat.sphericity = r.number(m, "material", "sphericity", 0, 1, 1.0, true);
    if (m["repose_deg"])
    {
        mat.reposeDeg = r.number(m, "material", "repose_deg", 0, 90, {}, true);
    }
    if (m["moisture"])
    {
        const YAML::Node w = m["moisture"];
        r.only(w, "material.moisture", {"inlet", "outlet"});
        mat.moisture = std::make_pair(r.number(w, "material.moisture", "inlet", 0, 1, {}, true),
                                      r.number(w, "material.moisture", "outlet", 0, 1, {}, true));
    }
    if (!mat.reposeDeg && !mat.moisture)
    {
        throw InputError(file, "material.repose_deg", "give repose_deg (deg, (0, 90]) or material.moisture {inlet, outlet}");
    }
    const YAML::Node sz = m["sizes_um"], fr = m["fractions_pct"];
    if (!sz || !sz.IsSequence() || sz.size() == 0)
    {
        throw InputError(file, "material.sizes_um", "missing: a list of sieve sizes in um, each in (0, 1e5]");
    }
    if (!fr || !fr.IsSequence() || fr.size() != sz.size())
    {
        throw InputError(file, "material.fractions_pct", "needs one mass percentage (>= 0) per size in sizes_um");
    }
    double sum = 0;
    for (std::size_t i = 0; i < sz.size(); ++i)
    {
        const std::string at = "[" + std::to_string(i) + "]";
        const double s = yamlNumber(sz[i], "material.sizes_um" + at, file);
        const double f = yamlNumber(fr[i], "material.fractions_pct" + at, file);
        if (!(s > 0 && s <= 1e5)) throw InputError(file, "material.sizes_um" + at, "outside (0, 1e5] um");
        if (!(f >= 0)) throw InputError(file, "material.fractions_pct" + at, "must be >= 0");
        mat.sizes.push_back(s*1e-6);
        mat.fractions.push_back(f);
        sum += f;
    }
    if (!(sum > 0)) throw InputError(file, "material.fractions_pct", "must not all be zero");
    for (double& f : mat.fractions) f /= sum;

    if (sherrittFlights)
    {
        const double phiDefault = mat.reposeDeg.value_or(45.0);
        c.flights.exterior = readSherrittFlight(r, r.section(fl, "exterior"), "flights.exterior",
            d.diameter, 0.0, phiDefault, false);
        if (fl["interior"])
        {
            if (!(d.centrefillDiameter > 0))
            {
                throw InputError(file, "flights.interior", "interior flights need drum.centrefillDiameter > 0");
            }
            c.flights.interior = readSherrittFlight(r, r.section(fl, "interior"), "flights.interior",
                d.diameter, d.centrefillDiameter, phiDefault, true);
        }
    }
    else if (d.centrefillDiameter > 0)
    {
        throw InputError(file, "drum.centrefillDiameter", "a centrefill needs Sherritt's flight description (flights.exterior, flights.interior)");
    }

    const YAML::Node gas = r.section(root, "gas", false);
    const YAML::Node g = gas ? gas : YAML::Node(YAML::NodeType::Map);
    r.only(g, "gas", {"flow", "massRate", "temperature_C", "pressure_kPa"});
    c.gas.counterCurrent = r.word(g, "gas", "flow", {"coCurrent", "counterCurrent"}, std::string("counterCurrent")) == "counterCurrent";
    c.gas.massRate = r.number(g, "gas", "massRate", 0, 1e4, 0.0);
    c.gas.temperatureC = r.number(g, "gas", "temperature_C", particleDrag::minTemperatureC,
                                  particleDrag::maxTemperatureC, 20.0);
    c.gas.pressureKPa = r.number(g, "gas", "pressure_kPa", particleDrag::minPressureKPa,
                                 particleDrag::maxPressureKPa, particleDrag::standardPressureKPa);

    r.section(root, "model");

    const YAML::Node rt = r.section(root, "rtd", false);
    const YAML::Node rr = rt ? rt : YAML::Node(YAML::NodeType::Map);
    r.only(rr, "rtd", {"integrator", "timeStep", "recovery", "pulseDuration", "onUnstable", "tracer"});
    c.rtd.integrator = parseRtdIntegrator(
        r.word(rr, "rtd", "integrator", {"exact", "trbdf2", "backwardEuler", "forwardEuler"}, std::string("exact")),
        "rtd.integrator", file);
    c.rtd.timeStep = r.number(rr, "rtd", "timeStep", 0, 1e5, 5.0, true);
    c.rtd.recovery = r.number(rr, "rtd", "recovery", 0.5, 0.999999, 0.999);
    c.rtd.pulseDuration = r.number(rr, "rtd", "pulseDuration", 0, 1e5, 0.0);
    c.rtd.onUnstable = r.word(rr, "rtd", "onUnstable", {"error", "fallback"}, std::string("error")) == "fallback"
        ? UnstableStepPolicy::fallback : UnstableStepPolicy::error;
    if (rr["tracer"])
    {
        const YAML::Node t = rr["tracer"];
        r.only(t, "rtd.tracer", {"file", "timeColumn", "timeUnit", "EColumn", "EUnit", "bodyEnd"});
        if (!t["file"])
        {
            throw InputError(file, "rtd.tracer.file", "missing: path of the measured tracer CSV");
        }
        TracerFile tf;
        tf.dict = file;
        tf.file = expandPath(t["file"].as<std::string>(), caseDir, file, "rtd.tracer.file");
        if (!std::filesystem::exists(tf.file))
        {
            throw InputError(file, "rtd.tracer.file", "tracer file not found: " + tf.file.string());
        }
        tf.timeColumn = t["timeColumn"] ? t["timeColumn"].as<std::string>() : "time_s";
        const std::string tu = r.word(t, "rtd.tracer", "timeUnit", {"s", "min", "h"}, std::string("s"));
        tf.timeScale = tu == "s" ? 1.0 : tu == "min" ? 60.0 : 3600.0;
        tf.eColumn = t["EColumn"] ? t["EColumn"].as<std::string>() : "E_per_s";
        const std::string eu = r.word(t, "rtd.tracer", "EUnit", {"per_s", "per_min", "per_h"}, std::string("per_s"));
        tf.eScale = eu == "per_s" ? 1.0 : eu == "per_min" ? 1.0/60.0 : 1.0/3600.0;
        tf.bodyEnd = r.number(t, "rtd.tracer", "bodyEnd", 0, 1e6, 0.0, true);
        c.tracer = tf;
    }
    // legal values that look like another unit: warned, used as given
    const auto suspect = [&](const std::string& entry, double v)
    {
        if (const auto w = unitSlipWarning(entry, v)) c.warnings.push_back(file + ": " + *w);
    };
    suspect("drum.speed_rpm", c.drum.speedRpm);
    suspect("material.bulkDensity", c.material.bulkDensity);
    if (m["particleDensity"]) suspect("material.particleDensity", c.material.particleDensity);
    for (const double d : c.material.sizes) suspect("material.sizes_um", d*1e6);
    if (g["temperature_C"]) suspect("gas.temperature_C", c.gas.temperatureC);
    return c;
}


DenseDispersionEntry readDenseDispersion(const DictReader& r, const YAML::Node& model)
{
    DenseDispersionEntry d;
    if (model["denseDispersion"])
    {
        const std::string w = r.numberOrWord(model, "model", "denseDispersion", 0, 1, {"none", "sherritt2001"},
            "none, sherritt2001 or a value in [0, 1] m2/s", d.value);
        d.kind = w.empty() ? "value" : w;
    }
    return d;
}


DriftSettings readCaseDriftSettings(const DrumCase& c)
{
    DriftSettings s = readDriftSettings(c.root, c.path.string(), c.caseDir);
    std::vector<double> dp;
    for (double x : c.material.sizes) dp.push_back(x*c.material.sphericity);
    s.curtainDiameter = sauterDiameter(dp, c.material.fractions);
    return s;
}

} // namespace drum
