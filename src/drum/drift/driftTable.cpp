#include "drum/drift/driftTable.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

namespace drum
{

namespace
{

const std::array<std::string, driftAxisCount> axisNames{{
    "gas_velocity_m_s", "spill_rate_kg_m_s", "fall_height_m",
    "flight_length_m", "particle_density_kg_m3", "particle_diameter_m"}};

const std::vector<std::string> columns{
    "case", "gas_velocity_m_s", "spill_rate_kg_m_s", "fall_height_m", "flight_length_m",
    "particle_density_kg_m3", "particle_diameter_m", "vc_over_vg", "drift_m", "captured_fraction"};

constexpr double nodeTol = 1e-9;   // relative: two printed values are one node

bool sameNode(double a, double b)
{
    return std::abs(a - b) <= nodeTol*std::max({1e-300, std::abs(a), std::abs(b)});
}

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

std::string fmt(double v)
{
    std::ostringstream os;
    os.precision(6);
    os << v;
    return os.str();
}

} // namespace


OutOfRangePolicy parseOutOfRangePolicy(const std::string& word, const std::string& entry, const std::string& file)
{
    if (word == "refuse") return OutOfRangePolicy::refuse;
    if (word == "clamp") return OutOfRangePolicy::clamp;
    throw InputError(file, entry, "unknown out-of-range policy '" + word + "': valid names are refuse, clamp");
}


std::string policyName(OutOfRangePolicy p)
{
    return p == OutOfRangePolicy::refuse ? "refuse" : "clamp";
}


const std::string& driftAxisName(int axis)
{
    return axisNames.at(axis);
}


DriftTable DriftTable::read(const std::filesystem::path& path, DriftTableOptions options)
{
    const std::string file = path.string();
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

    DriftTable t;
    t.file_ = path;
    t.options_ = std::move(options);

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
    std::vector<std::string> keyOrder;
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
        if (t.header_.count(key))
        {
            // one '# missing:' line per missing case; other keys only once
            if (key != "missing")
            {
                throw InputError(file, line(int(k) + 1), "header key '" + key + "' given twice");
            }
            t.header_[key] += "\n" + trim(body.substr(colon + 1));
            continue;
        }
        t.header_[key] = trim(body.substr(colon + 1));
        keyOrder.push_back(key);
    }

    // Required keys, in the contract's order
    if (!t.header_.count("axes"))
    {
        throw InputError(file, "header", "missing header key 'axes' (truncated or not a version 1 table)");
    }
    std::array<bool, driftAxisCount> listed{};
    {
        int last = -1;
        for (const auto& w : words(t.header_.at("axes")))
        {
            const auto it = std::find(axisNames.begin(), axisNames.end(), w);
            if (it == axisNames.end())
            {
                throw InputError(file, "header axes", "unknown axis '" + w + "'; the axes are gas_velocity_m_s "
                    "spill_rate_kg_m_s fall_height_m flight_length_m particle_density_kg_m3 particle_diameter_m");
            }
            const int a = int(it - axisNames.begin());
            if (a <= last)
            {
                throw InputError(file, "header axes", "axes must be listed once each, in the contract's order");
            }
            last = a;
            listed[a] = true;
        }
    }
    std::vector<std::string> required{"generator", "dictionary", "axes"};
    for (int a = 0; a < driftAxisCount; ++a)
    {
        if (listed[a]) required.push_back("range " + axisNames[a]);
    }
    // elapsed_s (the sweep's wall time) is optional: tables written since the sweeps are
    // reproducible leave it out, so the same inputs give the same file
    for (const char* key : {"fixed", "mesh", "cases"}) required.push_back(key);
    {
        std::size_t pos = 0;
        for (const auto& key : required)
        {
            const auto it = std::find(keyOrder.begin(), keyOrder.end(), key);
            if (it == keyOrder.end())
            {
                throw InputError(file, "header", "missing header key '" + key + "'");
            }
            const std::size_t at = std::size_t(it - keyOrder.begin());
            if (at < pos)
            {
                throw InputError(file, "header " + key, "header keys out of the contract's order "
                    "(generator, dictionary, axes, range lines, fixed, mesh, [elapsed_s,] cases)");
            }
            pos = at;
        }
    }
    std::array<std::pair<double, double>, driftAxisCount> declared{};
    for (int a = 0; a < driftAxisCount; ++a)
    {
        if (!listed[a]) continue;
        const std::string key = "range " + axisNames[a];
        const auto w = words(t.header_.at(key));
        if (w.size() != 2)
        {
            throw InputError(file, "header " + key, "needs '<min> <max>'");
        }
        declared[a] = {number(w[0], file, "header " + key), number(w[1], file, "header " + key)};
    }
    const bool missingAllowed = t.header_.count("missing") > 0;

    // Column header row
    if (k >= lines.size())
    {
        throw InputError(file, line(int(k) + 1), "truncated: no column header row after the comment header");
    }
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
        if (cols.size() != columns.size())
        {
            throw InputError(file, line(int(k) + 1), "extra column '" + cols[columns.size()] + "'");
        }
    }
    ++k;

    // Data rows
    struct Raw { std::array<double, driftAxisCount> x; double v[3]; int line; };
    std::vector<Raw> raw;
    for (; k < lines.size(); ++k)
    {
        const int ln = int(k) + 1;
        const std::string l = trim(lines[k]);
        if (l.empty())
        {
            throw InputError(file, line(ln), "empty line inside the data rows");
        }
        const auto f = split(l, ',');
        if (f.size() != columns.size())
        {
            throw InputError(file, line(ln), std::to_string(f.size()) + " fields, expected "
                + std::to_string(columns.size()) + (f.size() < columns.size() ? " (truncated file?)" : ""));
        }
        if (f[0].empty())
        {
            throw InputError(file, line(ln) + ", column case", "empty case name");
        }
        Raw r;
        r.line = ln;
        for (int a = 0; a < driftAxisCount; ++a)
        {
            r.x[a] = number(f[1 + a], file, line(ln) + ", column " + axisNames[a]);
        }
        for (int v = 0; v < 3; ++v)
        {
            r.v[v] = number(f[7 + v], file, line(ln) + ", column " + columns[7 + v]);
        }
        raw.push_back(r);
    }
    if (!endsWithNewline)
    {
        throw InputError(file, line(int(lines.size())), "the last line has no line end: truncated file");
    }
    if (raw.empty())
    {
        throw InputError(file, "", "no data rows (truncated drift table?)");
    }

    // Grid nodes
    for (int a = 0; a < driftAxisCount; ++a)
    {
        std::vector<double> v;
        for (const auto& r : raw) v.push_back(r.x[a]);
        std::sort(v.begin(), v.end());
        std::vector<double> nodes;
        for (double x : v)
        {
            if (nodes.empty() || !sameNode(nodes.back(), x)) nodes.push_back(x);
        }
        if (!listed[a] && nodes.size() > 1)
        {
            throw InputError(file, "column " + axisNames[a], "varies (" + fmt(nodes.front()) + " to "
                + fmt(nodes.back()) + ") but is not listed on the axes line");
        }
        if (listed[a])
        {
            const auto& d = declared[a];
            if (!sameNode(d.first, nodes.front()) || !sameNode(d.second, nodes.back()))
            {
                throw InputError(file, "header range " + axisNames[a], "declares [" + fmt(d.first) + ", "
                    + fmt(d.second) + "] but the rows span [" + fmt(nodes.front()) + ", " + fmt(nodes.back()) + "]");
            }
        }
        if (t.options_.scale[a] == AxisScale::log && !(nodes.front() > 0))
        {
            t.options_.scale[a] = AxisScale::linear;   // ln needs positive nodes
        }
        t.axes_[a] = nodes;
        for (double x : nodes)
        {
            t.coord_[a].push_back(t.options_.scale[a] == AxisScale::log ? std::log(x) : x);
        }
    }
    std::size_t n = 1;
    for (int a = driftAxisCount - 1; a >= 0; --a)
    {
        t.stride_[a] = n;
        n *= t.axes_[a].size();
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    t.values_.assign(3*n, nan);
    std::vector<int> seenAt(n, 0);
    for (const auto& r : raw)
    {
        std::size_t idx = 0;
        for (int a = 0; a < driftAxisCount; ++a)
        {
            const auto& nodes = t.axes_[a];
            auto it = std::lower_bound(nodes.begin(), nodes.end(), r.x[a]);
            if (it == nodes.end() || (it != nodes.begin() && !sameNode(*it, r.x[a]))) --it;
            idx += std::size_t(it - nodes.begin())*t.stride_[a];
        }
        if (seenAt[idx])
        {
            throw InputError(file, line(r.line), "grid point duplicated (first at line "
                + std::to_string(seenAt[idx]) + "): each combination of the axes must appear once");
        }
        seenAt[idx] = r.line;
        for (int v = 0; v < 3; ++v) t.values_[3*idx + v] = r.v[v];
    }
    if (raw.size() != n)
    {
        // Name the first missing point
        std::size_t idx = 0;
        while (seenAt[idx]) ++idx;
        std::ostringstream os;
        os << raw.size() << " rows for a " << n << "-point grid (" << (n - raw.size())
           << " missing; first missing:";
        for (int a = 0; a < driftAxisCount; ++a)
        {
            if (listed[a]) os << ' ' << axisNames[a] << '=' << fmt(t.axes_[a][(idx/t.stride_[a]) % t.axes_[a].size()]);
        }
        os << ")";
        if (!missingAllowed)
        {
            throw InputError(file, "data rows", "grid incomplete: " + os.str()
                + "; a table with missing points must say so in a '# missing:' header line");
        }
    }
    return t;
}


void DriftTable::locate(int a, double x, int& i, double& w, bool anchorBelow) const
{
    const auto& nodes = axes_[a];
    const double tol = nodeTol*std::max({1e-300, std::abs(nodes.front()), std::abs(nodes.back())});
    const bool below = x < nodes.front() - tol;
    const bool above = x > nodes.back() + tol;
    if (!std::isfinite(x))
    {
        throw InputError(file_.string(), driftAxisName(a), "query value is not finite");
    }
    if ((below && !anchorBelow) || above)
    {
        if (options_.outside == OutOfRangePolicy::refuse)
        {
            std::ostringstream os;
            os << "query " << driftAxisName(a) << " = " << fmt(x) << " is outside the table's range ["
               << fmt(nodes.front()) << ", " << fmt(nodes.back()) << "] (policy refuse; use clamp to "
               << "evaluate at the nearest point of the range, or extend the sweep)";
            throw InputError(file_.string(), driftAxisName(a), os.str());
        }
        counters_->count[a].fetch_add(1);
        if (!counters_->warned[a].exchange(true))
        {
            std::ostringstream os;
            os << "warning: drift table " << file_.string() << ": " << driftAxisName(a) << " = " << fmt(x)
               << " outside the table's range [" << fmt(nodes.front()) << ", " << fmt(nodes.back())
               << "]; clamped (reported once per axis; further clamps are counted)";
            if (options_.warn) options_.warn(os.str());
            else std::cerr << os.str() << std::endl;
        }
    }
    if (nodes.size() == 1 || x <= nodes.front())
    {
        i = 0;
        w = 0;
        return;
    }
    const int last = int(nodes.size()) - 1;
    if (x >= nodes.back())
    {
        i = last - 1;
        w = 1;
        return;
    }
    i = int(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin()) - 1;
    i = std::min(std::max(i, 0), last - 1);
    const auto& c = coord_[a];
    const double xc = options_.scale[a] == AxisScale::log ? std::log(x) : x;
    w = (xc - c[i])/(c[i + 1] - c[i]);
}


namespace
{
// Corners of the cell over the axes with a neighbour: the tensor-product
// weights and offsets are built by doubling (2 + 4 + ... + 2^n products)
struct Corners
{
    std::array<double, 1u << driftAxisCount> w;
    std::array<std::size_t, 1u << driftAxisCount> off;
    unsigned n = 1;

    void add(double t, std::size_t step)
    {
        for (unsigned k = 0; k < n; ++k)
        {
            w[n + k] = w[k]*t;
            off[n + k] = off[k] + step;
            w[k] *= 1 - t;
        }
        n *= 2;
    }
};
} // namespace


DriftTableValue DriftTable::lookup(const DriftQuery& q) const
{
    return evaluate(q, false);
}


double DriftTable::drift(const DriftQuery& q) const
{
    return evaluate(q, true).drift;
}


double DriftTable::vcOverVg(const DriftQuery& q) const
{
    return evaluate(q, false).vcOverVg;
}


void DriftTable::missingPoint(std::size_t idx) const
{
    std::ostringstream os;
    os << "the query needs grid point";
    for (int a = 0; a < driftAxisCount; ++a)
    {
        os << ' ' << driftAxisName(a) << '=' << fmt(axes_[a][(idx/stride_[a]) % axes_[a].size()]);
    }
    os << ", which the table lists as missing (failed case)";
    throw InputError(file_.string(), "missing", os.str());
}


DriftTableValue DriftTable::evaluate(const DriftQuery& q, bool anchor) const
{
    const std::array<double, driftAxisCount> x{{q.gasVelocity, q.spillRate, q.fallHeight,
                                                q.flightLength, q.particleDensity, q.particleDiameter}};
    const double y0 = axes_[fallHeightAxis].front();
    const bool anchored = anchor && q.fallHeight < y0 && y0 > 0;
    if (anchored && !(q.fallHeight >= 0))
    {
        throw InputError(file_.string(), driftAxisName(fallHeightAxis), "query fall height must be >= 0");
    }
    Corners c;
    c.w[0] = 1;
    c.off[0] = 0;
    std::size_t base = 0;
    for (int a = 0; a < driftAxisCount; ++a)
    {
        int i;
        double w;
        locate(a, anchored && a == fallHeightAxis ? y0 : x[a], i, w, anchor && a == fallHeightAxis);
        base += std::size_t(i)*stride_[a];
        if (axes_[a].size() > 1) c.add(w, stride_[a]);
    }
    DriftTableValue v;
    for (unsigned k = 0; k < c.n; ++k)
    {
        const double w = c.w[k];
        if (w == 0) continue;
        const std::size_t idx = base + c.off[k];
        const double* val = &values_[3*idx];
        if (std::isnan(val[0])) missingPoint(idx);
        v.vcOverVg += w*val[0];
        v.drift += w*val[1];
        v.capturedFraction += w*val[2];
    }
    if (anchored)
    {
        v.drift *= q.fallHeight/y0;   // exact anchor: no drift without a fall
    }
    return v;
}


std::vector<DriftTable::Row> DriftTable::rows() const
{
    std::vector<Row> out;
    for (std::size_t idx = 0; idx < size(); ++idx)
    {
        if (std::isnan(values_[3*idx])) continue;
        Row r;
        for (int a = 0; a < driftAxisCount; ++a)
        {
            r.x[a] = axes_[a][(idx/stride_[a]) % axes_[a].size()];
        }
        r.v = {values_[3*idx], values_[3*idx + 1], values_[3*idx + 2]};
        out.push_back(r);
    }
    return out;
}

} // namespace drum
