#include "drumDict.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/drift/porousSheetDrift.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/projectPaths.hpp"
#include "drum/io/yamlInput.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace drumSolver
{

namespace
{

using drum::InputError;

struct Reader
{
    std::string file;

    YAML::Node section(const YAML::Node& root, const std::string& name, bool required = true) const
    {
        const YAML::Node n = root[name];
        if (!n && required)
        {
            throw InputError(file, name, "missing section");
        }
        if (n && !n.IsMap())
        {
            throw InputError(file, name, "must be a dictionary of entries");
        }
        return n;
    }

    double number(const YAML::Node& sec, const std::string& secName, const std::string& key,
                  double lo, double hi, std::optional<double> dflt = {}, bool openLo = false) const
    {
        const std::string entry = secName + "." + key;
        const YAML::Node n = sec[key];
        if (!n)
        {
            if (dflt) return *dflt;
            throw InputError(file, entry, "missing; allowed range " + range(lo, hi, openLo));
        }
        double v;
        try
        {
            v = drum::yamlNumber(n, entry, file);
        }
        catch (const InputError& e)
        {
            throw InputError(e.file(), entry, "not a number; allowed range " + range(lo, hi, openLo));
        }
        if (!std::isfinite(v) || v < lo || v > hi || (openLo && v == lo))
        {
            std::ostringstream os;
            os << "value " << v << " outside the allowed range " << range(lo, hi, openLo);
            throw InputError(drum::fileLine(file, n), entry, os.str());
        }
        return v;
    }

    //- A whole-number entry: fractions are refused, not truncated
    int integer(const YAML::Node& sec, const std::string& secName, const std::string& key,
                int lo, int hi, std::optional<int> dflt = {}) const
    {
        const std::string entry = secName + "." + key;
        const YAML::Node n = sec[key];
        if (!n && dflt) return *dflt;
        const double v = number(sec, secName, key, lo, hi);
        if (v != std::floor(v))
        {
            throw InputError(drum::fileLine(file, n), entry, "'" + n.Scalar()
                + "' is not a whole number; allowed range " + range(lo, hi, false) + " (integers)");
        }
        return int(v);
    }

    //- Only these keys in a section
    void only(const YAML::Node& sec, const std::string& secName, const std::vector<std::string>& keys) const
    {
        if (sec) drum::onlyKeys(sec, secName, keys, file);
    }

    std::string word(const YAML::Node& sec, const std::string& secName, const std::string& key,
                     const std::vector<std::string>& allowed, std::optional<std::string> dflt = {}) const
    {
        const std::string entry = secName + "." + key;
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        const YAML::Node n = sec[key];
        if (!n)
        {
            if (dflt) return *dflt;
            throw InputError(file, entry, "missing; allowed: " + list);
        }
        if (!n.IsScalar())
        {
            throw InputError(drum::fileLine(file, n), entry, "must be one word; allowed: " + list);
        }
        const std::string v = n.as<std::string>();
        for (const auto& a : allowed)
        {
            if (v == a) return v;
        }
        throw InputError(drum::fileLine(file, n), entry, "unknown value '" + v + "'; allowed: " + list);
    }

    static std::string range(double lo, double hi, bool openLo)
    {
        std::ostringstream os;
        os << (openLo ? "(" : "[") << lo << ", " << hi << "]";
        return os.str();
    }
};

drum::SherrittFlightSpec readSherrittFlight
(
    const Reader& r,
    const YAML::Node& n,
    const std::string& sec,
    double D,
    double Di,
    double phiDefaultDeg,
    bool interior
)
{
    drum::SherrittFlightSpec s;
    s.type = drum::parseSherrittFlightType(
        r.word(n, sec, "type", {"twoSided", "EAD", "CBD", "table"}), sec + ".type", r.file);
    s.count = r.integer(n, sec, "count", interior ? 1 : 2, 200);
    // keys each type reads (anything else is a typo)
    std::vector<std::string> keys = {"type", "count"};
    switch (s.type)
    {
        case drum::SherrittFlightType::twoSided:
            s.baseLength = r.number(n, sec, "baseLength", 0, D/2, {}, true);
            s.tipLength = r.number(n, sec, "tipLength", 0, D/2, 0.0);
            s.tipAngle = r.number(n, sec, "tipAngle_deg", 60, 180, 90.0)*drum::deg;
            s.baseAngle = r.number(n, sec, "baseAngle_deg", 30, 150, 90.0)*drum::deg;
            keys.insert(keys.end(), {"baseLength", "tipLength", "tipAngle_deg", "baseAngle_deg"});
            break;
        case drum::SherrittFlightType::ead:
        case drum::SherrittFlightType::cbd:
        {
            const bool cbd = s.type == drum::SherrittFlightType::cbd;
            s.radius = r.number(n, sec, "radius", 0, D/4, {}, true);
            s.designRepose = r.number(n, sec, "designRepose_deg", 0, 90, phiDefaultDeg, true)*drum::deg;
            s.tipDiameter = cbd ? r.number(n, sec, "tipDiameter", 0, D, {}, true)
                                : r.number(n, sec, "tipDiameter", 0, D, 0.0);
            if (cbd)
            {
                s.bias = r.number(n, sec, "bias", 0, 0.99);
            }
            keys.insert(keys.end(), {"radius", "designRepose_deg", "tipDiameter", "bias"});
            break;
        }
        case drum::SherrittFlightType::table:
        {
            s.tipDiameter = r.number(n, sec, "tipDiameter", interior ? Di : 0, D, {}, true);
            const YAML::Node a = n["angles_deg"], l = n["lengths"];
            if (!a || !a.IsSequence() || a.size() < 2)
            {
                throw InputError(r.file, sec + ".angles_deg", "a list of at least 2 ascending rotation angles in deg");
            }
            if (!l || !l.IsSequence() || l.size() != a.size())
            {
                throw InputError(r.file, sec + ".lengths", "one horizontal length (m, >= 0) per angle in angles_deg");
            }
            for (std::size_t i = 0; i < a.size(); ++i)
            {
                const std::string at = "[" + std::to_string(i) + "]";
                s.angles.push_back(drum::yamlNumber(a[i], sec + ".angles_deg" + at, r.file)*drum::deg);
                s.lengths.push_back(drum::yamlNumber(l[i], sec + ".lengths" + at, r.file));
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
            const std::string near = drum::nearestKey(k, keys);
            throw InputError(drum::fileLine(r.file, kv.first), sec + "." + k, "unknown entry for type "
                + drum::toString(s.type) + (near.empty() ? "" : " (did you mean '" + sec + "." + near + "'?)")
                + "; allowed: " + list);
        }
    }
    return s;
}

} // namespace


DrumDict readDrumDict(const std::filesystem::path& caseDir)
{
    DrumDict d;
    d.path = caseDir/"drumDict";
    const Reader r{d.path.string()};
    if (!std::filesystem::exists(d.path))
    {
        throw InputError(r.file, "", "case dictionary not found");
    }
    const YAML::Node root = drum::loadYamlFile(d.path.string());
    const double big = 1e300;
    // every key of every section is one the solver reads: a misspelt one is refused
    r.only(root, "", {"drum", "flights", "material", "gas", "model", "drift", "rtd", "estimation"});

    const YAML::Node drum = r.section(root, "drum");
    r.only(drum, "drum", {"length", "diameter", "slope_deg", "speed_rpm", "centrefillDiameter"});
    d.length = r.number(drum, "drum", "length", 0, 500, {}, true);
    d.diameter = r.number(drum, "drum", "diameter", 0, 20, {}, true);
    d.slopeDeg = r.number(drum, "drum", "slope_deg", 0, 20);
    d.speedRpm = r.number(drum, "drum", "speed_rpm", 0, 60, {}, true);

    d.centrefillDiameter = r.number(drum, "drum", "centrefillDiameter", 0, 0.95*d.diameter, 0.0);

    // flights: Lee's two-section flight (flat entries) or Sherritt's
    // description (exterior/interior subsections, read after the material)
    const YAML::Node fl = r.section(root, "flights");
    r.only(fl, "flights", {"axialLength", "tableStep_deg", "count", "baseLength", "tipLength",
                           "baseAngle_deg", "tipAngle_deg", "exterior", "interior"});
    const bool sherrittFlights = bool(fl["exterior"]);
    d.flightAxialLength = r.number(fl, "flights", "axialLength", 0, d.length, d.length, true);
    d.flightTableStepDeg = r.number(fl, "flights", "tableStep_deg", 0.1, 5, 1.0);
    if (!sherrittFlights)
    {
        if (fl["interior"])
        {
            throw InputError(r.file, "flights.interior", "needs flights.exterior (Sherritt's flight description)");
        }
        d.flightCount = r.integer(fl, "flights", "count", 2, 200);
        d.baseLength = r.number(fl, "flights", "baseLength", 0, d.diameter/2, {}, true);
        d.tipLength = r.number(fl, "flights", "tipLength", 0, d.diameter/2, 0.0);
        d.baseAngleDeg = r.number(fl, "flights", "baseAngle_deg", 30, 150, 90.0);
        d.tipAngleDeg = r.number(fl, "flights", "tipAngle_deg", 60, 180, 90.0);
    }
    else
    {
        for (const char* k : {"count", "baseLength", "tipLength", "baseAngle_deg", "tipAngle_deg"})
        {
            if (fl[k])
            {
                throw InputError(r.file, std::string("flights.") + k,
                    "give either the two-section flight entries or flights.exterior, not both");
            }
        }
        d.flightCount = 0;
        d.baseLength = d.tipLength = d.baseAngleDeg = d.tipAngleDeg = 0;
    }

    const YAML::Node m = r.section(root, "material");
    r.only(m, "material", {"feedRate", "bulkDensity", "particleDensity", "sphericity", "repose_deg",
                           "moisture", "sizes_um", "fractions_pct"});
    d.feedRate = r.number(m, "material", "feedRate", 0, 1e4, {}, true);
    d.bulkDensity = r.number(m, "material", "bulkDensity", 0, 2e4, {}, true);
    d.particleDensity = r.number(m, "material", "particleDensity", d.bulkDensity, 2e4);
    d.sphericity = r.number(m, "material", "sphericity", 0, 1, 1.0, true);
    if (m["repose_deg"])
    {
        d.reposeDeg = r.number(m, "material", "repose_deg", 0, 90, {}, true);
    }
    if (m["moisture"])
    {
        const YAML::Node w = m["moisture"];
        r.only(w, "material.moisture", {"inlet", "outlet"});
        d.moisture = std::make_pair(r.number(w, "material.moisture", "inlet", 0, 1, {}, true),
                                    r.number(w, "material.moisture", "outlet", 0, 1, {}, true));
    }
    if (!d.reposeDeg && !d.moisture)
    {
        throw InputError(r.file, "material.repose_deg", "give repose_deg (deg, (0, 90]) or material.moisture {inlet, outlet}");
    }
    const YAML::Node sz = m["sizes_um"], fr = m["fractions_pct"];
    if (!sz || !sz.IsSequence() || sz.size() == 0)
    {
        throw InputError(r.file, "material.sizes_um", "missing: a list of sieve sizes in um, each in (0, 1e5]");
    }
    if (!fr || !fr.IsSequence() || fr.size() != sz.size())
    {
        throw InputError(r.file, "material.fractions_pct", "needs one mass percentage (>= 0) per size in sizes_um");
    }
    double sum = 0;
    for (std::size_t i = 0; i < sz.size(); ++i)
    {
        const std::string at = "[" + std::to_string(i) + "]";
        const double s = drum::yamlNumber(sz[i], "material.sizes_um" + at, r.file);
        const double f = drum::yamlNumber(fr[i], "material.fractions_pct" + at, r.file);
        if (!(s > 0 && s <= 1e5)) throw InputError(r.file, "material.sizes_um[" + std::to_string(i) + "]", "outside (0, 1e5] um");
        if (!(f >= 0)) throw InputError(r.file, "material.fractions_pct[" + std::to_string(i) + "]", "must be >= 0");
        d.sizes.push_back(s*1e-6);
        d.fractions.push_back(f);
        sum += f;
    }
    if (!(sum > 0)) throw InputError(r.file, "material.fractions_pct", "must not all be zero");
    for (double& f : d.fractions) f /= sum;

    if (sherrittFlights)
    {
        const double phiDefault = d.reposeDeg.value_or(45.0);
        d.exteriorFlight = readSherrittFlight(r, r.section(fl, "exterior"), "flights.exterior",
            d.diameter, 0.0, phiDefault, false);
        if (fl["interior"])
        {
            if (!(d.centrefillDiameter > 0))
            {
                throw InputError(r.file, "flights.interior", "interior flights need drum.centrefillDiameter > 0");
            }
            d.interiorFlight = readSherrittFlight(r, r.section(fl, "interior"), "flights.interior",
                d.diameter, d.centrefillDiameter, phiDefault, true);
        }
    }
    else if (d.centrefillDiameter > 0)
    {
        throw InputError(r.file, "drum.centrefillDiameter", "a centrefill needs Sherritt's flight description (flights.exterior, flights.interior)");
    }

    const YAML::Node gas = r.section(root, "gas", false);
    const YAML::Node g = gas ? gas : YAML::Node(YAML::NodeType::Map);
    r.only(g, "gas", {"flow", "massRate", "temperature_C"});
    d.counterCurrent = r.word(g, "gas", "flow", {"coCurrent", "counterCurrent"}, std::string("counterCurrent")) == "counterCurrent";
    d.gasMassRate = r.number(g, "gas", "massRate", 0, 1e4, 0.0);
    d.gasTemperatureC = r.number(g, "gas", "temperature_C", -50, 1500, 20.0);

    const YAML::Node mo = r.section(root, "model");
    r.only(mo, "model", {"type", "slices", "imposedDenseFlow", "dischargeEndAngle_deg", "axialSteps",
                         "denseDispersion", "dispersionBed", "subtractNumericalDispersion", "partition",
                         "kilnTime", "backFraction", "forwardDragFactor", "designLoadMultiplier",
                         "stagnantRatio", "exchangeTime", "drift"});
    d.model = r.word(mo, "model", "type", {"compartment", "twoPhase"});
    d.slicesGiven = bool(mo["slices"]);
    d.slices = r.integer(mo, "model", "slices", 1, 1000, 30);
    if (d.model == "compartment" && sherrittFlights)
    {
        throw InputError(r.file, "flights.exterior", "model compartment needs the two-section flight entries "
            "(flights.count, baseLength, tipLength, baseAngle_deg, tipAngle_deg)");
    }
    if (mo["imposedDenseFlow"])
    {
        d.imposedDenseFlow = r.number(mo, "model", "imposedDenseFlow", -1e4, 1e4);
    }
    if (mo["dischargeEndAngle_deg"])
    {
        d.dischargeEndAngleDeg = r.number(mo, "model", "dischargeEndAngle_deg", 40, 360);
    }
    d.axialSteps = r.integer(mo, "model", "axialSteps", 10, 100000, 200);
    d.denseDispersionValue = 0;
    d.denseDispersion = "none";
    if (const YAML::Node dd = mo["denseDispersion"])
    {
        if (!dd.IsScalar())
        {
            throw InputError(drum::fileLine(r.file, dd), "model.denseDispersion",
                             "none, sherritt2001 or a value in [0, 1] m2/s");
        }
        const std::string v = dd.as<std::string>();
        if (v == "none" || v == "sherritt2001")
        {
            d.denseDispersion = v;
        }
        else
        {
            d.denseDispersion = "value";
            d.denseDispersionValue = r.number(mo, "model", "denseDispersion", 0, 1);
        }
    }
    for (const char* k : {"imposedDenseFlow", "dischargeEndAngle_deg", "axialSteps"})
    {
        if (mo[k] && d.model != "twoPhase")
        {
            throw InputError(r.file, std::string("model.") + k, "only for model.type twoPhase");
        }
    }
    // compartment: which passive mass disperses, and the slicing's own part
    d.dispersionBed = r.word(mo, "model", "dispersionBed", {"kiln", "passive"}, std::string("kiln"));
    d.subtractNumericalDispersion =
        r.word(mo, "model", "subtractNumericalDispersion", {"true", "false"}, std::string("false")) == "true";
    for (const char* k : {"dispersionBed", "subtractNumericalDispersion"})
    {
        if (mo[k] && d.model != "compartment")
        {
            throw InputError(r.file, std::string("model.") + k, "only for model.type compartment");
        }
        if (mo[k] && d.denseDispersion == "none")
        {
            throw InputError(r.file, std::string("model.") + k, "needs model.denseDispersion (sherritt2001 or a value)");
        }
    }
    d.partition = r.word(mo, "model", "partition", {"leeCorrelations", "flightModel"}, std::string("leeCorrelations"));
    d.kilnTime = r.number(mo, "model", "kilnTime", 0, big, 9.28, true);
    d.backFraction = r.number(mo, "model", "backFraction", 0, 1, 0.0);
    d.dragFactor = r.number(mo, "model", "forwardDragFactor", 0, 100, 1.0);
    d.designLoadMultiplier = r.number(mo, "model", "designLoadMultiplier", 0, 100, 1.0, true);
    d.stagnantRatio = r.number(mo, "model", "stagnantRatio", 0, 10, 0.0);
    d.exchangeTime = r.number(mo, "model", "exchangeTime", 1, 1e6, 600.0);
    d.driftSettings = drum::readDriftSettings(root, r.file, caseDir);   // model.drift + drift section
    d.drift = d.driftSettings.model;
    {
        std::vector<double> dp;
        for (double s : d.sizes) dp.push_back(s*d.sphericity);
        d.driftSettings.curtainDiameter = drum::sauterDiameter(dp, d.fractions);
    }

    const YAML::Node rt = r.section(root, "rtd", false);
    const YAML::Node rr = rt ? rt : YAML::Node(YAML::NodeType::Map);
    r.only(rr, "rtd", {"integrator", "timeStep", "recovery", "pulseDuration", "onUnstable", "tracer"});
    d.rtd.integrator = drum::parseRtdIntegrator(
        r.word(rr, "rtd", "integrator", {"exact", "trbdf2", "backwardEuler", "forwardEuler"}, std::string("exact")),
        "rtd.integrator", r.file);
    d.rtd.timeStep = r.number(rr, "rtd", "timeStep", 0, 1e5, 5.0, true);
    d.rtd.recovery = r.number(rr, "rtd", "recovery", 0.5, 0.999999, 0.999);
    d.rtd.pulseDuration = r.number(rr, "rtd", "pulseDuration", 0, 1e5, 0.0);
    d.rtd.onUnstable = r.word(rr, "rtd", "onUnstable", {"error", "fallback"}, std::string("error")) == "fallback"
        ? drum::UnstableStepPolicy::fallback : drum::UnstableStepPolicy::error;
    if (rr["tracer"])
    {
        const YAML::Node t = rr["tracer"];
        r.only(t, "rtd.tracer", {"file", "timeColumn", "timeUnit", "EColumn", "EUnit"});
        if (!t["file"])
        {
            throw InputError(r.file, "rtd.tracer.file", "missing: path of the measured tracer CSV");
        }
        TracerFile tf;
        tf.file = drum::expandPath(t["file"].as<std::string>(), caseDir, r.file, "rtd.tracer.file");
        if (!std::filesystem::exists(tf.file))
        {
            throw InputError(r.file, "rtd.tracer.file", "tracer file not found: " + tf.file.string());
        }
        tf.timeColumn = t["timeColumn"] ? t["timeColumn"].as<std::string>() : "time_s";
        const std::string tu = r.word(t, "rtd.tracer", "timeUnit", {"s", "min", "h"}, std::string("s"));
        tf.timeScale = tu == "s" ? 1.0 : tu == "min" ? 60.0 : 3600.0;
        tf.eColumn = t["EColumn"] ? t["EColumn"].as<std::string>() : "E_per_s";
        const std::string eu = r.word(t, "rtd.tracer", "EUnit", {"per_s", "per_min", "per_h"}, std::string("per_s"));
        tf.eScale = eu == "per_s" ? 1.0 : eu == "per_min" ? 1.0/60.0 : 1.0/3600.0;
        d.tracer = tf;
    }

    d.starts = 1;
    d.logObjective = false;
    d.logOffset = 0.01;
    if (root["estimation"])
    {
        const YAML::Node e = root["estimation"];
        r.only(e, "estimation", {"parameters", "starts", "objective", "logOffset"});
        if (!d.tracer)
        {
            throw InputError(r.file, "estimation", "needs a measured curve: rtd.tracer");
        }
        if (d.model != "compartment" || d.partition != "leeCorrelations")
        {
            throw InputError(r.file, "estimation", "only for model.type compartment with partition leeCorrelations");
        }
        if (d.denseDispersion != "none")
        {
            throw InputError(r.file, "model.denseDispersion", "not with estimation (the fitted network has no "
                "passive dispersion); use none, or run the fitted parameters without an estimation section");
        }
        const YAML::Node ps = e["parameters"];
        if (!ps || !ps.IsSequence() || ps.size() == 0)
        {
            throw InputError(r.file, "estimation.parameters",
                "a list from: kilnTime, backFraction, forwardDragFactor, forwardShare, designLoadMultiplier");
        }
        for (const auto& p : ps)
        {
            std::string n = p.as<std::string>();
            if (n == "forwardDragFactor") n = "dragFactor";
            if (n != "kilnTime" && n != "backFraction" && n != "dragFactor" && n != "forwardShare"
             && n != "designLoadMultiplier" && n != "stagnantRatio" && n != "exchangeTime")
            {
                throw InputError(r.file, "estimation.parameters", "unknown parameter '" + n
                    + "'; allowed: kilnTime, backFraction, forwardDragFactor, forwardShare, designLoadMultiplier, "
                      "stagnantRatio, exchangeTime");
            }
            d.estimate.push_back(n);
        }
        d.starts = r.integer(e, "estimation", "starts", 1, 100, 4);
        d.logObjective = r.word(e, "estimation", "objective", {"linear", "log"}, std::string("linear")) == "log";
        d.logOffset = r.number(e, "estimation", "logOffset", 0, 100, 0.01, true);
    }
    return d;
}

} // namespace drumSolver
