// writeDriftTable -in SWEEP.json -out TABLE.csv: the drift table of a sweep,
// written by the one drift-table writer (drum/drift/driftTableFile.hpp).
// buildDriftTable collects its cases into SWEEP.json and calls this:
//   {"header": [["generator", "..."], ["dictionary", "..."], ...],
//    "rows": [["<case>", V_g, spill, fall height, flight length, density,
//              diameter, vc_over_vg, drift_m, captured_fraction
//              [, tunnel_drift_m]], ...]}   (the last value in every row or in none)
// (JSON, read with yaml-cpp). The table is checked as the reader checks it
// (header order, ranges, complete grid) before anything is written; the
// output is replaced atomically. Exit 1 with the file and the defect.
#include "drum/drift/driftTableFile.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/yamlInput.hpp"

#include <yaml-cpp/yaml.h>

#include <cstring>
#include <iostream>

namespace
{

const char* const usage = "Usage: writeDriftTable -in SWEEP.json -out TABLE.csv\n";

drum::DriftTableFile readSweep(const std::string& file)
{
    const YAML::Node root = drum::loadYamlFile(file);
    drum::onlyKeys(root, "", {"header", "rows"}, file);
    const YAML::Node h = root["header"], rows = root["rows"];
    if (!h || !h.IsSequence())
    {
        throw drum::InputError(file, "header", "missing: a list of [key, value] pairs");
    }
    if (!rows || !rows.IsSequence() || rows.size() == 0)
    {
        throw drum::InputError(file, "rows", "missing: a list of rows [case, 6 axis values, 3 values]");
    }
    drum::DriftTableFile t;
    for (std::size_t i = 0; i < h.size(); ++i)
    {
        const std::string at = "header[" + std::to_string(i) + "]";
        if (!h[i].IsSequence() || h[i].size() != 2 || !h[i][0].IsScalar() || !h[i][1].IsScalar())
        {
            throw drum::InputError(drum::fileLine(file, h[i]), at, "must be [key, value]");
        }
        t.header.emplace_back(h[i][0].Scalar(), h[i][1].Scalar());
    }
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const std::string at = "rows[" + std::to_string(i) + "]";
        const YAML::Node r = rows[i];
        if (!r.IsSequence() || (r.size() != 10 && r.size() != 11) || !r[0].IsScalar())
        {
            throw drum::InputError(drum::fileLine(file, r), at, "must be [case, 6 axis values, 3 values"
                                   " [, tunnel_drift_m]]");
        }
        drum::DriftTableRecord rec;
        rec.caseName = r[0].Scalar();
        for (int a = 0; a < 6; ++a)
        {
            rec.x[a] = drum::yamlNumber(r[1 + a], at + "." + drum::driftTableColumns()[1 + a], file);
        }
        for (int v = 0; v < 3; ++v)
        {
            rec.v[v] = drum::yamlNumber(r[7 + v], at + "." + drum::driftTableColumns()[7 + v], file);
        }
        if (r.size() == 11) rec.tunnelDrift = drum::yamlNumber(r[10], at + "." + drum::tunnelDriftColumn(), file);
        t.rows.push_back(rec);
    }
    return t;
}

} // namespace


int main(int argc, char* argv[])
{
    std::string in, out;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "-in") == 0 && i + 1 < argc) in = argv[++i];
        else if (std::strcmp(argv[i], "-out") == 0 && i + 1 < argc) out = argv[++i];
        else if (std::strcmp(argv[i], "-help") == 0 || std::strcmp(argv[i], "--help") == 0)
        {
            std::cout << usage;
            return 0;
        }
        else
        {
            std::cerr << "writeDriftTable: unknown argument '" << argv[i] << "'\n" << usage;
            return 2;
        }
    }
    if (in.empty() || out.empty())
    {
        std::cerr << "writeDriftTable: -in and -out are required\n" << usage;
        return 2;
    }
    try
    {
        const drum::DriftTableFile t = readSweep(in);
        drum::writeDriftTableFile(t, out);
        std::cout << "writeDriftTable: wrote " << out << " (" << t.rows.size() << " rows)" << std::endl;
    }
    catch (const std::exception& e)
    {
        std::cerr << "writeDriftTable: error: " << e.what() << " (" << out << " left as it was)" << std::endl;
        return 1;
    }
    return 0;
}
