// windTunnelDrift: drift models on wind-tunnel style test rows.
//
//   windTunnelDrift -tests FILE.csv -out PRED.csv -model NAME [-materials FILE]
//                [-table FILE[,FILE...]] [-outside refuse|clamp] [-constants FILE]
//                [-level coarse|medium|fine] [-np N] [-drag NAME] [-work DIR] [-keep]
//                [-turbulence kEpsilon|realizableKE|kOmegaSST]
//                [-particleTurbulence none|Simonin|SimoninCrowe] [-wakeShare CP]
//                [-turbulentDispersion none|gradientDiffusion] [-particleParticleDrag none|Syamlal]
//                [-releaseVelocity V]
//                                     (cfd: curtainCase's options)
//                [-collection sherritt|landed]  (cfd, table: the tunnel's reading, default,
//                                 or the mean drift of what crossed the fall height)
//                [-sieveBottom UM]    (lower bound of the open bottom sieve bin, default 37)
//                [-sheetConstants k,a,b,c]  (sherritt: Eq 142 refitted, for out-of-sample scores)
//                [-quantity advance|apparentVc|advance,apparentVc]  (the bulk mean
//                                 advance, default, and/or Sherritt's apparent in-sheet gas
//                                 velocity: Eq 141 on the model's class advances, in the air
//                                 of his analysis, 20 degC and 1 atm, whatever -gasPressure)
//                [-skipFailed]   (a row the model cannot answer - a failed CFD run, a
//                                 table query needing a missing grid point or outside
//                                 the range under refuse - is reported and left out)
//       writes test,mean_advance_m (and/or vc_m_s) for every row of FILE.csv
//       (columns of data/windtunnel_tests.csv; the measured values are never read)
//   windTunnelDrift -tunnelReading LANDING.csv -out READING.csv
//       the tunnel's reading of each class of one curtainCase run, at every
//       fall height (buildDriftTable's tunnel_drift_m)
//   windTunnelDrift -fit porousSheet -table FILE[,FILE...] -out CONSTANTS.yaml
//       least-squares constants of the reduced model on the CFD table(s)
//   windTunnelDrift -score -tests FILE.csv -predictions NAME=PRED.csv,... -out SCORES.csv [-png FILE]
//                [-pngModels NAME,...] [-byMaterial FILE.csv] [-quantity advance|apparentVc]
//                [-allowMissing]
//       RMS ln(pred/measured), bias and share within 25 % per model and fall height
//       (and per material); the picture draws the -pngModels (default every model);
//       a measured test without a prediction is refused unless -allowMissing
//
// Models: isolated, sherritt, table, tableVc, porousSheet, cfd (README.md).
#include "cfdPrediction.hpp"
#include "driftScores.hpp"

#include "drum/io/projectPaths.hpp"
#include "drum/drift/driftDictionary.hpp"
#include "drum/drift/porousSheetDrift.hpp"
#include "drum/drift/porousSheetFit.hpp"
#include "drum/drift/tableDrift.hpp"
#include "drum/io/csvWriter.hpp"
#include "drum/io/inputError.hpp"
#include "scoring/apparentSheetVelocity.hpp"
#include "scoring/landingFile.hpp"
#include "scoring/windTunnelData.hpp"
#include "scoring/windTunnelPrediction.hpp"
#include "particleDrag/gasProperties.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace
{

const char* usage =
    "usage:\n"
    "  windTunnelDrift -tests FILE.csv -out PRED.csv -model NAME [-materials FILE] [-table FILE[,FILE...]]\n"
    "               [-outside refuse|clamp] [-constants FILE] [-level coarse|medium|fine] [-np N]\n"
    "               [-drag NAME [-sphericity PSI]] [-turbulence kEpsilon|realizableKE|kOmegaSST]\n"
    "               [-particleTurbulence none|Simonin|SimoninCrowe] [-wakeShare CP]\n"
    "               [-turbulentDispersion none|gradientDiffusion] [-particleParticleDrag none|Syamlal]\n"
    "               [-releaseVelocity V] [-sieveBottom UM]\n"
    "               [-layerThickness packed|B] [-gasPressure P]\n"
    "               [-sheetConstants k,a,b,c]\n"
    "               [-work DIR] [-keep] [-skipFailed] [-collection sherritt|landed] [-jobs N]\n"
    "               [-quantity advance|apparentVc|advance,apparentVc]\n"
    "  windTunnelDrift -fit porousSheet -table FILE[,FILE...] -out CONSTANTS.yaml\n"
    "  windTunnelDrift -score -tests FILE.csv -predictions NAME=PRED.csv,... -out SCORES.csv [-png FILE]\n"
    "               [-pngModels NAME,...] [-byMaterial FILE.csv] [-quantity advance|apparentVc] [-allowMissing]\n"
    "  windTunnelDrift -sizeClasses MATERIAL [-materials FILE] [-sieveBottom UM]\n"
    "  windTunnelDrift -tunnelReading LANDING.csv -out READING.csv\n"
    "models: isolated, isolatedFullDrag, sherritt, table, tableVc, porousSheet, cfd\n";

struct Args
{
    std::map<std::string, std::string> value;
    std::set<std::string> flag;

    bool has(const std::string& k) const { return value.count(k) || flag.count(k); }
    std::string get(const std::string& k, const std::string& dflt = "") const
    {
        const auto it = value.find(k);
        return it == value.end() ? dflt : it->second;
    }
    std::string need(const std::string& k) const
    {
        if (!value.count(k)) throw drum::InputError("", "-" + k, "missing option\n" + std::string(usage));
        return value.at(k);
    }
};

//- The number a whole option value (or list item) spells; empty if it is
//  not one finite number
std::optional<double> numberText(const std::string& text)
{
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
    return x;
}

//- -sheetConstants k,a,b,c: Eq 142 refitted (model sherritt only)
particleDrag::SheetVelocityConstants sheetConstants(const Args& a)
{
    const std::string text = a.get("sheetConstants");
    std::vector<double> v;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
    {
        const auto x = numberText(item);
        if (!x)
        {
            throw drum::InputError("", "-sheetConstants", "'" + text + "': four numbers k,a,b,c (Eq 142)");
        }
        v.push_back(*x);
    }
    if (v.size() != 4 || !(v[0] > 0))
    {
        throw drum::InputError("", "-sheetConstants", "'" + text + "': four numbers k,a,b,c with k > 0 (Eq 142)");
    }
    particleDrag::SheetVelocityConstants c;
    c.k = v[0];
    c.a = v[1];
    c.b = v[2];
    c.c = v[3];
    return c;
}

Args parse(int argc, char** argv)
{
    static const std::set<std::string> flags{"keep", "score", "help", "skipFailed", "allowMissing"};
    static const std::set<std::string> options{"tests", "out", "model", "materials", "table", "outside",
        "constants", "level", "np", "drag", "work", "fit", "predictions", "png", "pngModels", "particleTurbulence", "byMaterial", "turbulentDispersion", "particleParticleDrag", "collection", "jobs",
        "turbulence", "wakeShare", "releaseVelocity", "sphericity", "layerThickness", "sieveBottom", "sheetConstants", "sizeClasses",
        "gasPressure", "tunnelReading", "quantity"};
    Args a;
    for (int i = 1; i < argc; ++i)
    {
        std::string k = argv[i];
        if (k.size() < 2 || k[0] != '-') throw drum::InputError("", k, "unexpected argument\n" + std::string(usage));
        k = k.substr(1);
        if (flags.count(k) || options.count(k))
        {
            if (a.flag.count(k) || a.value.count(k)) throw drum::InputError("", "-" + k, "given twice: give it once");
        }
        if (flags.count(k)) { a.flag.insert(k); continue; }
        if (!options.count(k)) throw drum::InputError("", "-" + k, "unknown option\n" + std::string(usage));
        if (i + 1 >= argc) throw drum::InputError("", "-" + k, "needs a value");
        a.value[k] = argv[++i];
    }
    return a;
}

fs::path defaultMaterials()
{
    return drum::dataDir()/"windtunnel_materials.csv";
}

//- -sieveBottom UM: the lower bound given to the open bottom sieve bin (a
//  stated sensitivity; default 37 um)
drum::SieveClosure sieveClosure(const Args& a)
{
    drum::SieveClosure closure;
    if (a.has("sieveBottom"))
    {
        const std::string text = a.get("sieveBottom");
        const auto v = numberText(text);
        if (!v || !(*v >= 1 && *v <= 73))
        {
            throw drum::InputError("", "-sieveBottom", "'" + text + "' um outside the allowed range [1, 73] "
                                   "(the open bottom bin lies below the 74 um sieve)");
        }
        closure.bottomUm = *v;
    }
    return closure;
}

//- The tunnel's air: 20 degC (Sherritt's code and reference predictions) at
//  -gasPressure kPa (default 1 atm)
double gasPressure(const Args& a)
{
    if (!a.has("gasPressure")) return particleDrag::standardPressureKPa;
    const std::string text = a.get("gasPressure");
    const auto v = numberText(text);
    constexpr double lo = particleDrag::minPressureKPa, hi = particleDrag::maxPressureKPa;
    if (!v || !(*v >= lo && *v <= hi))
    {
        std::ostringstream os;
        os << "'" << text << "' kPa outside the allowed range [" << lo << ", " << hi << "]";
        throw drum::InputError("", "-gasPressure", os.str());
    }
    return *v;
}

//- -sizeClasses MATERIAL: the material's size classes as every tool of the
//  project represents them (Table A.1, open bins closed), and its particle and
//  bulk densities, for the sweep
//  dictionaries (buildDriftTable's `sizeClasses material;`), 6 digits
int sizeClasses(const Args& a)
{
    const std::string name = a.get("sizeClasses");
    const fs::path matFile = a.get("materials", defaultMaterials().string());
    const auto materials = drum::readWindTunnelMaterials(matFile, sieveClosure(a));
    const auto it = materials.find(name);
    if (it == materials.end())
    {
        std::string list;
        for (const auto& kv : materials) list += (list.empty() ? "" : ", ") + kv.first;
        throw drum::InputError(matFile.string(), "-sizeClasses", "unknown material '" + name + "'; the file has " + list);
    }
    std::vector<drum::SieveClass> classes = it->second.classes;   // ascending, as a sweep's axis
    std::sort(classes.begin(), classes.end(),
        [](const drum::SieveClass& x, const drum::SieveClass& y) { return x.diameter < y.diameter; });
    const auto line = [&](const char* key, auto value)
    {
        std::cout << key << ":";
        for (const auto& c : classes)
        {
            char buf[32];
            std::snprintf(buf, sizeof buf, " %.6g", value(c));
            std::cout << buf;
        }
        std::cout << "\n";
    };
    std::cout << "material: " << name << "\nparticleDensity: " << it->second.particleDensity
              << "\nbulkDensity: " << it->second.bulkDensity << "\n";
    line("diameter", [](const drum::SieveClass& c) { return c.diameter; });
    line("massFractions", [](const drum::SieveClass& c) { return c.massFraction; });
    return 0;
}


//- -tunnelReading LANDING.csv -out READING.csv: what Sherritt's tunnel would
//  record for each size class of a curtainCase run alone (the collection
//  rule, scoring/tunnelCollection.hpp, on its curtainLanding.csv) at every
//  fall height of the file; buildDriftTable tabulates it as tunnel_drift_m
int tunnelReading(const Args& a)
{
    const fs::path file = a.get("tunnelReading");
    const fs::path out = a.need("out");
    drum::CsvTable table({"fall_height_m", "class_index", "tunnel_drift_m", "suspended_fraction",
                          "fixed_fraction", "lost_fraction"});
    for (const auto& [y, classes] : drum::readLandingFile(file))
    {
        for (std::size_t i = 0; i < classes.size(); ++i)
        {
            const auto r = drum::classCollectedAdvance(classes[i], drum::TunnelFloor{}, file.string(), i);
            table.addRow({y, double(i), r.advance, r.suspended, r.fixed, r.lost});
        }
    }
    table.write(out);
    return 0;
}


//- The items of a comma-separated option value ("a,b,c"); an empty item
//  (",," or a trailing comma) is an InputError naming the option
std::vector<std::string> commaList(const std::string& list, const std::string& option)
{
    std::vector<std::string> items;
    if (list.empty()) return items;
    for (std::size_t pos = 0;;)
    {
        const auto comma = list.find(',', pos);
        items.push_back(list.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
        if (items.back().empty())
        {
            throw drum::InputError("", option, "empty item in '" + list + "' (a comma-separated list)");
        }
        if (comma == std::string::npos) return items;
        pos = comma + 1;
    }
}

//- The table file of each material from -table FILE[,FILE...] (models
//  table and tableVc): a table whose header names a material ('# material:',
//  buildDriftTable's `material` entry) serves that material; a table
//  without one serves every other material. Two tables for one material,
//  two generic tables, or a table naming a material the materials file
//  does not have: InputError. Without -table: the shipped tables swept in
//  the run's air (the generic table and the material tables of
//  etc/defaults/driftTables/materialTables and its subfolders, each kept
//  when its recorded gas is within 5 % of `air`), so each material is
//  served from its own table in that air. Other models ignore -table
//  (empty map), and so does auto without one (its table is then optional).
std::map<std::string, fs::path> tablesByMaterial
(
    const std::string& list,
    const std::map<std::string, drum::WindTunnelMaterial>& materials,
    const std::string& model,
    const particleDrag::Gas& air
)
{
    std::map<std::string, fs::path> out;
    // auto takes a table when given one (else the default, if present)
    if (model != "table" && model != "tableVc" && !(model == "auto" && !list.empty())) return out;
    // each table read once: its header says which material it serves (and, for the
    // shipped ones, in which air it was swept)
    std::vector<std::pair<fs::path, drum::DriftTable>> tables;
    for (const auto& f : commaList(list, "-table")) tables.emplace_back(f, drum::DriftTable::read(f));
    if (tables.empty())
    {
        std::vector<fs::path> shipped{drum::defaultDriftTableFile()}, own;
        const fs::path dir = drum::defaultDriftTableFile().parent_path()/"materialTables";
        if (fs::is_directory(dir))
        {
            for (const auto& e : fs::recursive_directory_iterator(dir))
            {
                const std::string n = e.path().filename().string();
                if (e.is_regular_file() && n.size() > 9 && n.compare(n.size() - 9, 9, "Table.csv") == 0)
                {
                    own.push_back(e.path());
                }
            }
        }
        std::sort(own.begin(), own.end());   // the same order, whatever the file system's
        shipped.insert(shipped.end(), own.begin(), own.end());
        for (const auto& f : shipped)
        {
            auto t = drum::DriftTable::read(f);
            if (drum::sweepGasMatches(t.fixedSetting("gas"), air)) tables.emplace_back(f, std::move(t));
        }
        if (tables.empty())
        {
            std::ostringstream os;
            os << "no shipped table was swept in this air (gas density " << air.density
               << " kg/m3; a table's within 5 %): give -table FILE[,FILE...] swept in it "
                  "(buildDriftTable entry gasPressure)";
            throw drum::InputError(dir.string(), "-table", os.str());
        }
    }
    fs::path generic;
    for (const auto& [f, table] : tables)
    {
        const auto& h = table.header();
        const auto it = h.find("material");
        if (it == h.end())
        {
            if (!generic.empty())
            {
                throw drum::InputError(f.string(), "-table", "two tables without a '# material:' header ("
                    + generic.string() + " and this one): which serves the other materials is ambiguous");
            }
            generic = f;
            continue;
        }
        if (!materials.count(it->second))
        {
            throw drum::InputError(f.string(), "header material", "'" + it->second
                + "' is not a material of the materials file");
        }
        if (out.count(it->second))
        {
            throw drum::InputError(f.string(), "header material", "a second table for '" + it->second
                + "' (the first: " + out.at(it->second).string() + ")");
        }
        out[it->second] = f;
    }
    for (const auto& kv : materials)
    {
        if (!out.count(kv.first) && !generic.empty()) out[kv.first] = generic;
    }
    return out;
}

//- -collection sherritt|landed (models cfd and table): how a row's advance
//  is measured. sherritt (default): as the tunnel measured it, its collection
//  rule on the landing distribution (cfd: each run's; table: the table's
//  tunnel_drift_m column, that rule on each swept case); landed: the mean
//  drift of what crossed the fall height
std::string collection(const Args& a, const std::string& model)
{
    if (!a.has("collection")) return "sherritt";
    const std::string c = a.get("collection");
    if (model != "cfd" && model != "table")
    {
        throw drum::InputError("", "-collection", "an option of the models cfd and table only (model " + model
                               + " gives each class one drift)");
    }
    if (c != "sherritt" && c != "landed")
    {
        throw drum::InputError("", "-collection", "'" + c + "': valid names are sherritt, landed");
    }
    return c;
}

int predict(const Args& a)
{
    const fs::path testsFile = a.need("tests"), out = a.need("out");
    const std::string model = a.need("model");
    const auto& names = drum::driftModelNames();
    if (model != "cfd" && std::find(names.begin(), names.end(), model) == names.end())
    {
        std::string list;
        for (const auto& n : names) list += n + ", ";
        throw drum::InputError("", "-model", "unknown model '" + model + "': valid names are " + list + "cfd");
    }
    if (model == "segmentVc")
    {
        throw drum::InputError("", "-model", "segmentVc reads a drum segment's curtains by release angle; a "
                               "wind-tunnel test has one slot and no flights: use table or tableVc");
    }
    // -quantity: the bulk advance and/or the apparent in-sheet velocity of Eq 141, a
    // column each (advance,apparentVc: both from one run of the model)
    std::vector<std::string> columns;
    for (const auto& name : commaList(a.get("quantity", "advance"), "-quantity"))
    {
        const std::string c = windTunnelDrift::scoredQuantity(name).column;
        if (std::find(columns.begin(), columns.end(), c) != columns.end())
        {
            throw drum::InputError("", "-quantity", "'" + name + "' given twice");
        }
        columns.push_back(c);
    }
    const fs::path matFile = a.get("materials", defaultMaterials().string());
    const auto materials = drum::readWindTunnelMaterials(matFile, sieveClosure(a));
    const auto tests = drum::readWindTunnelTests(testsFile, materials);
    // Sherritt's code and the reference predictions: air at 20 degC, Schiller-Naumann;
    // -gasPressure: the tunnel's site pressure (a table swept at another gas is refused)
    const double pressure = gasPressure(a);
    const particleDrag::Gas air = particleDrag::Gas::air(20, pressure);
    // Eq 141 as Sherritt evaluated it, in his code's air (20 degC, 1 atm), whatever air
    // the model breathed: the model's V_c is then measured as the tunnel's was
    const particleDrag::Gas sherrittAnalysisAir = particleDrag::Gas::air(20);

    // each answered row's values, in the order of `columns`
    std::map<int, std::vector<double>> pred;
    // the row's values from its bulk advance and its class advances (Eq 141 for V_c)
    const auto answer = [&](const drum::WindTunnelTest& t, double advance, const std::vector<double>& classes)
    {
        std::vector<double> v;
        for (const auto& c : columns)
        {
            v.push_back(c == "mean_advance_m" ? advance
                : drum::apparentSheetVelocity(t, materials.at(t.material), classes, sherrittAnalysisAir));
        }
        pred[t.test] = v;
    };
    // runs one row's answer: a row the model cannot answer (an InputError) is refused,
    // or reported and left out with -skipFailed
    const auto eachRow = [&](const drum::WindTunnelTest& t, const std::function<void()>& body)
    {
        try
        {
            body();
        }
        catch (const drum::InputError& e)
        {
            if (!a.has("skipFailed"))
            {
                throw drum::InputError(testsFile.string(), "test " + std::to_string(t.test), e.what());
            }
            std::cout << "windTunnelDrift: test " << t.test << " left out: " << e.what() << "\n";
        }
    };
    if (model == "cfd")
    {
        windTunnelDrift::CfdOptions o;
        o.level = a.get("level", "coarse");
        if (o.level != "coarse" && o.level != "medium" && o.level != "fine")
        {
            throw drum::InputError("", "-level", "'" + o.level + "': valid levels are coarse, medium, fine");
        }
        o.np = std::stoi(a.get("np", "1"));
        o.jobs = std::stoi(a.get("jobs", "1"));
        if (o.jobs < 1 || o.jobs > 64)
        {
            throw drum::InputError("", "-jobs", "'" + a.get("jobs") + "' outside the allowed range [1, 64]");
        }
        o.drag = a.get("drag");
        // curtainCase's names, checked here so that a typo stops before the first row runs
        const auto named = [&](const std::string& option, const std::vector<std::string>& valid)
        {
            const std::string v = a.get(option);
            if (!v.empty() && std::find(valid.begin(), valid.end(), v) == valid.end())
            {
                std::string list;
                for (const auto& n : valid) list += (list.empty() ? "" : ", ") + n;
                throw drum::InputError("", "-" + option, "'" + v + "': valid names are " + list);
            }
            return v;
        };
        o.collection = collection(a, model);
        o.turbulence = named("turbulence", {"kEpsilon", "realizableKE", "kOmegaSST"});
        o.particleTurbulence = named("particleTurbulence", {"none", "Simonin", "SimoninCrowe"});
        o.turbulentDispersion = named("turbulentDispersion", {"none", "gradientDiffusion"});
        o.particleParticleDrag = named("particleParticleDrag", {"none", "Syamlal"});
        o.wakeShare = a.get("wakeShare");
        o.releaseVelocity = a.get("releaseVelocity");
        o.layerThickness = a.get("layerThickness");
        if (!o.layerThickness.empty() && o.layerThickness != "packed" && !numberText(o.layerThickness))
        {
            throw drum::InputError("", "-layerThickness", "'" + o.layerThickness
                + "': packed, or a thickness in m (curtainCase checks its range)");
        }
        if (!o.releaseVelocity.empty() && !numberText(o.releaseVelocity))
        {
            throw drum::InputError("", "-releaseVelocity", "'" + o.releaseVelocity + "' is not a number (m/s)");
        }
        o.sphericity = a.get("sphericity");
        if (!o.sphericity.empty() && o.drag != "HaiderLevenspiel")
        {
            throw drum::InputError("", "-sphericity", "an entry of -drag HaiderLevenspiel only");
        }
        if (!o.sphericity.empty() && !numberText(o.sphericity))
        {
            throw drum::InputError("", "-sphericity", "'" + o.sphericity + "' is not a number "
                "(curtainCase checks its range)");
        }
        if (!o.wakeShare.empty() && o.particleTurbulence != "SimoninCrowe")
        {
            throw drum::InputError("", "-wakeShare", "an entry of -particleTurbulence SimoninCrowe only");
        }
        if (a.has("gasPressure")) o.gasPressure = pressure;
        o.keep = a.has("keep");
        o.skipFailed = a.has("skipFailed");
        o.work = a.get("work", (fs::temp_directory_path()/("windTunnelDrift_" + std::to_string(::getpid()))).string());
        const auto rows = windTunnelDrift::cfdPredictions(tests, materials, o);
        for (const auto& t : tests)
        {
            const auto it = rows.find(t.test);
            if (it != rows.end()) eachRow(t, [&] { answer(t, it->second.advance, it->second.classAdvance); });
        }
        if (pred.size() < tests.size())
        {
            std::cout << "windTunnelDrift: " << tests.size() - pred.size() << " of " << tests.size()
                      << " rows failed and are left out of " << out.string() << "; logs in " << o.work.string() << "\n";
        }
        else if (!o.keep)
        {
            fs::remove_all(o.work);
        }
        if (pred.empty()) throw drum::InputError(testsFile.string(), "", "every cfd row failed: nothing written");
    }
    else
    {
        drum::DriftSettings s;
        s.model = model;
        s.tunnelReading = collection(a, model) == "sherritt" && model == "table";
        if (a.has("constants")) s.constants = a.get("constants");
        s.outside = drum::parseOutOfRangePolicy(a.get("outside", "refuse"), "-outside");
        // -table FILE[,FILE...]: which table serves which material
        const auto tableFor = tablesByMaterial(a.get("table"), materials, model, air);
        // One model per material: the porousSheet curtain is the material's
        // PSD; a table model is built once per table file (one read, one
        // clamp count per table)
        std::map<std::string, std::shared_ptr<const drum::DriftModel>> models;
        std::map<std::string, std::shared_ptr<const drum::DriftModel>> byTable;
        for (const auto& [name, mat] : materials)
        {
            std::vector<double> d, x;
            for (const auto& c : mat.classes)
            {
                d.push_back(c.diameter);
                x.push_back(c.massFraction);
            }
            s.curtainDiameter = drum::sauterDiameter(d, x);
            const auto it = tableFor.find(name);
            s.table = it == tableFor.end() ? fs::path() : it->second;
            const bool usesTable = model == "table" || model == "tableVc";
            if (usesTable && it == tableFor.end()) continue;   // no table serves it: its rows are refused below
            // porousSheet and auto (its dilute test) use the material's curtain diameter
            const std::string key = model == "porousSheet" || model == "auto" ? name : s.table.string();
            if (!byTable.count(key))
            {
                byTable[key] = model == "sherritt" && a.has("sheetConstants")
                    ? std::make_shared<const drum::SherrittSheetDrift>(air, particleDrag::DragLaw{}, sheetConstants(a))
                    : drum::makeDriftModel(s, air, {}, "-model");
            }
            models[name] = byTable.at(key);
        }
        for (const auto& t : tests)
        {
            eachRow(t, [&]
            {
                if (!models.count(t.material))
                {
                    throw drum::InputError(a.get("table"), "material " + t.material,
                        "none of the -table files serves this material (a table with a '# material:' header "
                        "serves that material only; give a table without one, or one for " + t.material + ")");
                }
                const auto& mat = materials.at(t.material);
                const auto classes = drum::classAdvances(*models.at(t.material), t, mat);
                answer(t, drum::meanAdvance(mat, classes), classes);
            });
        }
        if (pred.empty()) throw drum::InputError(testsFile.string(), "", "the model answered no row: nothing written");
        if (pred.size() < tests.size())
        {
            std::cout << "windTunnelDrift: " << tests.size() - pred.size() << " of " << tests.size()
                      << " rows left out (-skipFailed)\n";
        }
        for (const auto& [key, m] : byTable)
        {
            const drum::DriftTable* table = nullptr;
            if (const auto* td = dynamic_cast<const drum::TableDrift*>(m.get())) table = &td->table();
            if (const auto* tv = dynamic_cast<const drum::TableVcDrift*>(m.get())) table = &tv->table();
            for (int ax = 0; table && ax < drum::driftAxisCount; ++ax)
            {
                if (table->clampCount(ax))
                {
                    std::cout << "windTunnelDrift: " << table->clampCount(ax) << " class queries clamped on "
                              << drum::driftAxisName(ax) << " (" << table->file().string() << ")\n";
                }
            }
        }
    }
    std::vector<std::string> header{"test"};
    header.insert(header.end(), columns.begin(), columns.end());
    drum::CsvTable table(header);
    for (const auto& t : tests)
    {
        if (!pred.count(t.test)) continue;
        std::vector<double> row{double(t.test)};
        row.insert(row.end(), pred.at(t.test).begin(), pred.at(t.test).end());
        table.addRow(row);
    }
    table.write(out);
    std::cout << "windTunnelDrift: " << table.rows().size() << " predictions (" << model << ") written to " << out.string() << "\n";
    return 0;
}

int fit(const Args& a)
{
    const std::string model = a.need("fit");
    if (model != "porousSheet")
    {
        throw drum::InputError("", "-fit", "'" + model + "': the reduced models with constants are: porousSheet");
    }
    // -table FILE[,FILE...]: one fit over the rows of all of them
    const std::string list = a.need("table");
    const fs::path out = a.need("out");
    std::vector<drum::DriftTable> tables;
    for (const auto& f : commaList(list, "-table")) tables.push_back(drum::DriftTable::read(f));
    std::vector<const drum::DriftTable*> ptrs;
    for (const auto& t : tables) ptrs.push_back(&t);
    const particleDrag::Gas air = particleDrag::Gas::air(20);
    drum::PorousSheetFit f = drum::fitPorousSheet(ptrs, air);
    f.constants.provenance["command"] = "windTunnelDrift -fit porousSheet -table " + list + " -out " + out.string();
    drum::writePorousSheetConstants(out, f.constants);
    std::cout << "windTunnelDrift: porousSheet a = " << f.constants.a << " 1/m, b = " << f.constants.b << " on "
              << f.rows << " table rows, RMS ln residual " << f.rmsLn << (f.converged ? "" : " (NOT converged)")
              << "; written to " << out.string() << "\n";
    return f.converged ? 0 : 2;
}

int score(const Args& a)
{
    std::vector<windTunnelDrift::NamedPredictions> preds;
    for (const auto& item : commaList(a.need("predictions"), "-predictions"))
    {
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
        {
            throw drum::InputError("", "-predictions", "'" + item + "' is not NAME=FILE");
        }
        preds.push_back({item.substr(0, eq), item.substr(eq + 1)});
    }
    std::vector<std::string> drawn;
    if (a.has("pngModels"))
    {
        if (!a.has("png")) throw drum::InputError("", "-pngModels", "belongs to -png (the picture it selects for)");
        drawn = commaList(a.get("pngModels"), "-pngModels");
    }
    windTunnelDrift::writeScores(a.need("tests"), preds, a.need("out"), a.get("png"), a.get("byMaterial"), drawn,
                                 windTunnelDrift::scoredQuantity(a.get("quantity", "advance")), a.has("allowMissing"));
    return 0;
}

} // namespace


int main(int argc, char** argv)
{
    try
    {
        const Args a = parse(argc, argv);
        if (a.has("help") || argc == 1)
        {
            std::cout << usage;
            return argc == 1 ? 1 : 0;
        }
        if (a.has("sizeClasses")) return sizeClasses(a);
        if (a.has("tunnelReading")) return tunnelReading(a);
        if (a.has("fit")) return fit(a);
        if (a.has("score")) return score(a);
        return predict(a);
    }
    catch (const std::exception& e)
    {
        std::cerr << "windTunnelDrift: error: " << e.what() << std::endl;
        return 1;
    }
}
