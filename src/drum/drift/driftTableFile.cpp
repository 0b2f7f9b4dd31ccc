#include "drum/drift/driftTableFile.hpp"

#include "drum/drift/driftTable.hpp"
#include "drum/io/atomicFile.hpp"
#include "drum/io/inputError.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace drum
{

namespace
{

using namespace driftTableParse;

// the format's columns, their one home (a function-local static: safe to read
// from another file's static initialisation, driftTable.cpp's axis names)
const std::vector<std::string>& columnNames()
{
    static const std::vector<std::string> names{
        "case", "gas_velocity_m_s", "spill_rate_kg_m_s", "fall_height_m", "flight_length_m",
        "particle_density_kg_m3", "particle_diameter_m", "vc_over_vg", "drift_m", "captured_fraction"};
    return names;
}

const std::string tunnelColumn = "tunnel_drift_m";

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep)
{
    std::vector<std::string> out;
    std::string cur;
    std::istringstream is(s);
    while (std::getline(is, cur, sep)) out.push_back(trim(cur));
    if (!s.empty() && s.back() == sep) out.push_back("");
    return out;
}

std::string printed(const char* format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

} // namespace


namespace driftTableParse
{

std::vector<std::string> words(const std::string& s)
{
    std::istringstream is(s);
    std::vector<std::string> out;
    std::string w;
    while (is >> w) out.push_back(w);
    return out;
}

std::string line(int n)
{
    return "line " + std::to_string(n);
}

double number(const std::string& text, const std::string& file, const std::string& entry)
{
    try
    {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && std::isfinite(v)) return v;
    }
    catch (const std::exception&)
    {
    }
    throw InputError(file, entry, "'" + text + "' is not a finite number");
}

std::optional<std::string> fixedSetting(const std::map<std::string, std::string>& header,
                                        const std::string& key)
{
    const auto f = header.find("fixed");
    if (f == header.end()) return std::nullopt;
    std::istringstream is(f->second);
    std::string item;
    while (is >> item)
    {
        if (item.rfind(key + "=", 0) == 0) return item.substr(key.size() + 1);
    }
    return std::nullopt;
}

} // namespace driftTableParse


const std::vector<std::string>& driftTableColumns()
{
    return columnNames();
}


const std::string& tunnelDriftColumn()
{
    return tunnelColumn;
}


DriftTableFile readDriftTableFile(const std::filesystem::path& path)
{
    const auto& columns = columnNames();
    const std::string file = path.string();
    requireReadableFile(file);
    std::ifstream in(path, std::ios::binary);
    if (!std::filesystem::exists(path) || !in)
    {
        throw InputError(file, "", "drift table not found or not readable");
    }
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.empty())
    {
        throw InputError(file, "", "empty file (truncated drift table?)");
    }
    const bool endsWithNewline = text.back() == '\n';
    std::vector<std::string> lines;
    {
        std::istringstream is(text);
        std::string l;
        while (std::getline(is, l)) lines.push_back(l);
    }
    DriftTableFile t;

    // Magic line
    const std::string magic = trim(lines[0]);
    if (magic.rfind("# dryerDriftTable", 0) != 0)
    {
        throw InputError(file, line(1), "not a drift table: the first line must be '# dryerDriftTable 1', found '"
            + magic.substr(0, 60) + "'");
    }
    const auto mw = words(magic);
    if (mw.size() != 3 || mw[2] != "1")
    {
        throw InputError(file, line(1), "drift table version '" + (mw.size() > 2 ? mw[2] : std::string("?"))
            + "': this reader reads version 1 only (regenerate the table with buildDriftTable)");
    }

    // Header lines "# key: value"
    std::size_t k = 1;
    for (; k < lines.size() && trim(lines[k]).rfind('#', 0) == 0; ++k)
    {
        const std::string body = trim(trim(lines[k]).substr(1));
        const auto colon = body.find(':');
        if (colon == std::string::npos)
        {
            throw InputError(file, line(int(k) + 1), "header line is not '# key: value': '" + body + "'");
        }
        const std::string key = trim(body.substr(0, colon));
        for (const auto& kv : t.header)
        {
            // one '# missing:' line per missing case; other keys only once
            if (kv.first == key && key != "missing")
            {
                throw InputError(file, line(int(k) + 1), "header key '" + key + "' given twice");
            }
        }
        t.header.emplace_back(key, trim(body.substr(colon + 1)));
    }

    // Column header row
    if (k >= lines.size())
    {
        throw InputError(file, line(int(k) + 1), "truncated: no column header row after the comment header");
    }
    bool tunnel = false;
    {
        const auto cols = split(trim(lines[k]), ',');
        for (std::size_t c = 0; c < columns.size(); ++c)
        {
            if (c >= cols.size() || cols[c] != columns[c])
            {
                throw InputError(file, line(int(k) + 1), "column " + std::to_string(c + 1) + " must be '"
                    + columns[c] + "'" + (c < cols.size() ? ", found '" + cols[c] + "'" : ", missing"));
            }
        }
        tunnel = cols.size() == columns.size() + 1 && cols.back() == tunnelColumn;
        if (cols.size() != columns.size() && !tunnel)
        {
            const std::size_t extra = columns.size() + (cols[columns.size()] == tunnelColumn ? 1 : 0);
            throw InputError(file, line(int(k) + 1), "extra column '" + cols[extra] + "' (the one "
                "optional last column is '" + tunnelColumn + "')");
        }
    }
    ++k;
    const std::size_t width = columns.size() + (tunnel ? 1 : 0);

    // Data rows
    for (; k < lines.size(); ++k)
    {
        const int ln = int(k) + 1;
        const std::string l = trim(lines[k]);
        if (l.empty())
        {
            throw InputError(file, line(ln), "empty line inside the data rows");
        }
        const auto f = split(l, ',');
        if (f.size() != width)
        {
            throw InputError(file, line(ln), std::to_string(f.size()) + " fields, expected "
                + std::to_string(width) + (f.size() < width ? " (truncated file?)" : ""));
        }
        if (f[0].empty())
        {
            throw InputError(file, line(ln) + ", column case", "empty case name");
        }
        DriftTableRecord r;
        r.line = ln;
        r.caseName = f[0];
        for (int a = 0; a < 6; ++a)
        {
            r.x[a] = number(f[1 + a], file, line(ln) + ", column " + columns[1 + a]);
        }
        for (int v = 0; v < 3; ++v)
        {
            r.v[v] = number(f[7 + v], file, line(ln) + ", column " + columns[7 + v]);
        }
        if (tunnel) r.tunnelDrift = number(f[10], file, line(ln) + ", column " + tunnelColumn);
        t.rows.push_back(r);
    }
    if (!endsWithNewline)
    {
        throw InputError(file, line(int(lines.size())), "the last line has no line end: truncated file");
    }
    if (t.rows.empty())
    {
        throw InputError(file, "", "no data rows (truncated drift table?)");
    }

    return t;
}


std::string driftTableText(const DriftTableFile& table)
{
    const auto& columns = columnNames();
    std::string s = "# dryerDriftTable 1\n";
    for (const auto& kv : table.header)
    {
        s += "# " + kv.first + ": " + kv.second + "\n";
    }
    const bool tunnel = !table.rows.empty() && table.rows.front().tunnelDrift.has_value();
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
        s += (c ? "," : "") + columns[c];
    }
    s += (tunnel ? "," + tunnelColumn : std::string()) + "\n";
    for (const auto& r : table.rows)
    {
        s += r.caseName;
        for (int a = 0; a < 5; ++a) s += "," + printed("%.6g", r.x[a]);
        s += "," + printed("%.8g", r.x[5]);
        for (int v = 0; v < 3; ++v) s += "," + printed("%.8g", r.v[v]);
        if (tunnel) s += "," + printed("%.8g", *r.tunnelDrift);
        s += "\n";
    }
    return s;
}


void writeDriftTableFile(const DriftTableFile& table, const std::filesystem::path& file)
{
    for (const auto& r : table.rows)
    {
        if (r.caseName.empty() || r.caseName.find_first_of(",\n") != std::string::npos)
        {
            throw InputError(file.string(), "case '" + r.caseName + "'", "a case name must be one word without commas");
        }
    }
    for (const auto& kv : table.header)
    {
        if (kv.first.find_first_of(":\n") != std::string::npos || kv.second.find('\n') != std::string::npos)
        {
            throw InputError(file.string(), "header " + kv.first, "a header key has no ':' and neither has a line end");
        }
    }
    // what is written is what the reader accepts: check it as a table first
    DriftTable::fromFile(table, file);
    AtomicFile out(file);
    out.stream() << driftTableText(table);
    out.commit();
}

} // namespace drum
