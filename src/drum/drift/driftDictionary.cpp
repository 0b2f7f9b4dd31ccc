#include "drum/drift/driftDictionary.hpp"

#include "drum/drift/porousSheetDrift.hpp"
#include "drum/drift/segmentDrift.hpp"
#include "drum/drift/tableDrift.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/projectPaths.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>


namespace drum
{

const std::vector<std::string>& driftModelNames()
{
    static const std::vector<std::string> names{"isolated", "isolatedFullDrag", "sherritt", "table", "tableVc", "porousSheet", "auto", "segmentVc"};
    return names;
}


std::filesystem::path defaultDriftTableFile()
{
    return defaultsDir()/"driftTables"/"driftTable.csv";
}


namespace
{
std::string nameList()
{
    std::string s;
    for (const auto& n : driftModelNames()) s += (s.empty() ? "" : ", ") + n;
    return s;
}

std::string scalar(const YAML::Node& n, const std::string& file, const std::string& entry)
{
    if (!n.IsScalar()) throw InputError(file, entry, "must be a single word or path");
    return n.as<std::string>();
}
} // namespace


DriftSettings readDriftSettings
(
    const YAML::Node& root,
    const std::string& file,
    const std::filesystem::path& caseDir,
    const std::string& defaultModel
)
{
    DriftSettings s;
    s.model = defaultModel;
    const YAML::Node model = root["model"];
    if (model && model.IsMap() && model["drift"])
    {
        s.model = scalar(model["drift"], file, "model.drift");
    }
    const auto& names = driftModelNames();
    if (std::find(names.begin(), names.end(), s.model) == names.end())
    {
        throw InputError(file, "model.drift", "unknown drift model '" + s.model + "': valid names are " + nameList());
    }
    const YAML::Node d = root["drift"];
    if (!d) return s;
    if (!d.IsMap()) throw InputError(file, "drift", "must be a dictionary (table, segmentTable, outside, constants, auto, scale, recordQueries)");
    for (const auto& kv : d)
    {
        const std::string k = kv.first.as<std::string>();
        if (k != "table" && k != "segmentTable" && k != "outside" && k != "constants" && k != "auto"
            && k != "scale" && k != "recordQueries")
        {
            throw InputError(file, "drift." + k, "unknown entry; valid entries are table, segmentTable, outside, "
                             "constants, auto, scale, recordQueries");
        }
    }
    if (d["scale"])
    {
        try { s.scale = d["scale"].as<double>(); }
        catch (const std::exception&) { throw InputError(file, "drift.scale", "not a number"); }
        if (!(s.scale > 0 && s.scale <= 10))
        {
            throw InputError(file, "drift.scale", "value " + scalar(d["scale"], file, "drift.scale")
                             + " outside the allowed range (0, 10]");
        }
    }
    if (d["recordQueries"])
    {
        const std::string v = scalar(d["recordQueries"], file, "drift.recordQueries");
        if (v != "true" && v != "false")
        {
            throw InputError(file, "drift.recordQueries", "'" + v + "': true or false");
        }
        s.recordQueries = v == "true";
    }
    auto path = [&](const char* key)
    {
        const std::string entry = std::string("drift.") + key;
        const std::filesystem::path p = expandPath(scalar(d[key], file, entry), caseDir, file, entry);
        if (!std::filesystem::exists(p))
        {
            throw InputError(file, std::string("drift.") + key, "file not found: " + p.string());
        }
        return p;
    };
    if (d["table"]) s.table = path("table");
    if (d["segmentTable"]) s.segmentTable = path("segmentTable");
    if (d["constants"]) s.constants = path("constants");
    if (d["outside"])
    {
        s.outside = parseOutOfRangePolicy(scalar(d["outside"], file, "drift.outside"), "drift.outside", file);
    }
    if (const YAML::Node a = d["auto"])
    {
        if (!a.IsMap()) throw InputError(file, "drift.auto", "must be a dictionary (inside, outside, diluteRatio, fixedAxisTolerance)");
        for (const auto& kv : a)
        {
            const std::string k = kv.first.as<std::string>();
            if (k == "inside")
            {
                s.autoInside = scalar(kv.second, file, "drift.auto.inside");
                if (s.autoInside != "table" && s.autoInside != "tableVc")
                {
                    throw InputError(file, "drift.auto.inside", "'" + s.autoInside + "': valid names are table, tableVc");
                }
            }
            else if (k == "outside")
            {
                s.autoOutside = scalar(kv.second, file, "drift.auto.outside");
                if (s.autoOutside != "sherritt" && s.autoOutside != "porousSheet")
                {
                    throw InputError(file, "drift.auto.outside", "'" + s.autoOutside + "': valid names are sherritt, porousSheet");
                }
            }
            else if (k == "diluteRatio" || k == "fixedAxisTolerance")
            {
                const std::string entry = "drift.auto." + k;
                double v = 0;
                try { v = kv.second.as<double>(); }
                catch (const std::exception&) { throw InputError(file, entry, "not a number"); }
                if (k == "diluteRatio") { requireInRange(v, 0.5, 1.0, entry, file); s.autoOptions.diluteRatio = v; }
                else { requireInRange(v, 0.0, 1.0, entry, file); s.autoOptions.fixedAxisTolerance = v; }
            }
            else
            {
                throw InputError(file, "drift.auto." + k, "unknown entry; valid entries are inside, outside, diluteRatio, fixedAxisTolerance");
            }
        }
    }
    return s;
}


namespace
{
//- The value of KEY= in a sweep's gas setting, as the table writers record it:
//  gas=air(rho=R,nu=N[,T=..C][,p=..kPa]) (NaN when absent)
double sweepGasValue(const std::string& g, const std::string& key)
{
    const auto k = g.find(key + "=");
    return k == std::string::npos ? std::numeric_limits<double>::quiet_NaN()
                                  : std::strtod(g.c_str() + k + key.size() + 1, nullptr);
}
} // namespace


bool sweepGasMatches(const std::optional<std::string>& g, const particleDrag::Gas& gas)
{
    if (!g) return true;
    const double tol = 0.05;
    return !(std::abs(sweepGasValue(*g, "rho")/gas.density - 1) > tol
             || std::abs(sweepGasValue(*g, "nu")/(gas.viscosity/gas.density) - 1) > tol);
}


void requireSweepGas(const std::optional<std::string>& g, const std::string& file, const particleDrag::Gas& gas)
{
    if (!sweepGasMatches(g, gas))
    {
        const double rho = sweepGasValue(*g, "rho"), nu = sweepGasValue(*g, "nu");
        const double caseNu = gas.viscosity/gas.density;
        std::ostringstream os;
        os << "the table was swept in gas of density " << rho << " kg/m3 and kinematic viscosity " << nu
           << " m2/s; the case's gas is " << gas.density << " kg/m3, " << caseNu
           << " m2/s (allowed: within 5 % of the table's): sweep a table at the case's gas "
              "(buildDriftTable entries gasTemperature, gasPressure) or give the case the table's";
        throw InputError(file, "fixed gas", os.str());
    }
}


void requireTableGas(const DriftTable& table, const particleDrag::Gas& gas)
{
    requireSweepGas(table.fixedSetting("gas"), table.file().string(), gas);
}


namespace
{

std::shared_ptr<const DriftModel> makeBareDriftModel
(
    const DriftSettings& s,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law,
    const std::string& entry
)
{
    if (s.model == "isolated") return std::make_shared<IsolatedParticleDrift>(gas, law);
    if (s.model == "isolatedFullDrag") return std::make_shared<FullDragParticleDrift>(gas, law);
    if (s.model == "sherritt") return std::make_shared<SherrittSheetDrift>(gas, law);
    if (s.model == "table" || s.model == "tableVc")
    {
        DriftTableOptions o;
        o.outside = s.outside;
        o.warn = s.warn;
        const auto file = s.table.empty() ? defaultDriftTableFile() : s.table;
        auto table = std::make_shared<const DriftTable>(DriftTable::read(file, o));
        requireTableGas(*table, gas);
        if (s.model == "table")
        {
            return std::make_shared<TableDrift>(table, s.tunnelReading ? TableDrift::Reading::tunnel
                                                                       : TableDrift::Reading::crossed);
        }
        return std::make_shared<TableVcDrift>(table, gas, law);
    }
    if (s.model == "segmentVc")
    {
        if (s.segmentTable.empty())
        {
            throw InputError("", "drift.segmentTable", "the segmentVc drift model needs a drum-segment table "
                             "(writeSegmentTable writes one from drum-segment runs)");
        }
        SegmentTableOptions o;
        o.outside = s.outside;
        o.warn = s.warn;
        auto table = std::make_shared<const SegmentTable>(SegmentTable::read(s.segmentTable, o));
        requireSweepGas(table->fixedSetting("gas"), table->file().string(), gas);
        return std::make_shared<SegmentVcDrift>(table, gas, law);
    }
    if (s.model == "porousSheet")
    {
        const auto file = s.constants.empty() ? defaultPorousSheetConstantsFile() : s.constants;
        return std::make_shared<PorousSheetDrift>(readPorousSheetConstants(file), gas, law, s.curtainDiameter);
    }
    if (s.model == "auto")
    {
        // The table is optional here: without one, auto uses lone particles
        // and the reduced model, and says so
        std::shared_ptr<const DriftTable> table;
        std::shared_ptr<const DriftModel> inside;
        const auto file = s.table.empty() ? defaultDriftTableFile() : s.table;
        if (!s.table.empty() || std::filesystem::exists(file))
        {
            // inside the range by construction, except on fixed axes within
            // their tolerance: clamp there (with the table's warning)
            DriftTableOptions o;
            o.outside = OutOfRangePolicy::clamp;
            o.warn = s.warn;
            table = std::make_shared<const DriftTable>(DriftTable::read(file, o));
            requireTableGas(*table, gas);
            if (s.autoInside == "table") inside = std::make_shared<TableDrift>(table);
            else inside = std::make_shared<TableVcDrift>(table, gas, law);
        }
        const auto constants = s.constants.empty() ? defaultPorousSheetConstantsFile() : s.constants;
        auto reduced = std::make_shared<const PorousSheetDrift>(readPorousSheetConstants(constants), gas, law, s.curtainDiameter);
        auto isolated = std::make_shared<const IsolatedParticleDrift>(gas, law);
        std::shared_ptr<const DriftModel> outside;
        if (s.autoOutside == "sherritt") outside = std::make_shared<SherrittSheetDrift>(gas, law);
        return std::make_shared<AutoDrift>(table, inside, reduced, isolated, s.autoOptions, outside);
    }
    throw InputError("", entry, "unknown drift model '" + s.model + "': valid names are " + nameList());
}

} // namespace


std::shared_ptr<const DriftModel> makeDriftModel
(
    const DriftSettings& s,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law,
    const std::string& entry
)
{
    std::shared_ptr<const DriftModel> m = makeBareDriftModel(s, gas, law, entry);
    if (s.scale != 1.0)
    {
        m = std::make_shared<ScaledDrift>(m, s.scale);
    }
    if (s.recordQueries)
    {
        m = std::make_shared<RecordingDrift>(m);
    }
    return m;
}

} // namespace drum
