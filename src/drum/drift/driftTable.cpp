#include "drum/drift/driftTable.hpp"

#include "drum/drift/driftTableFile.hpp"
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

// the axes' names are the file format's columns after `case` (driftTableFile: their one home)
const std::array<std::string, driftAxisCount> axisNames = []
{
    std::array<std::string, driftAxisCount> names;
    for (int a = 0; a < driftAxisCount; ++a)
    {
        names[a] = driftTableColumns().at(1 + a);
    }
    return names;
}();

using namespace driftTableParse;

constexpr double nodeTol = 1e-9;   // relative: two printed values are one node

bool sameNode(double a, double b)
{
    return std::abs(a - b) <= nodeTol*std::max({1e-300, std::abs(a), std::abs(b)});
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
    return fromFile(readDriftTableFile(path), path, std::move(options));
}


DriftTable DriftTable::fromFile(const DriftTableFile& f, const std::filesystem::path& path, DriftTableOptions options)
{
    const std::string file = path.string();
    DriftTable t;
    t.file_ = path;
    t.options_ = std::move(options);
    std::vector<std::string> keyOrder;
    for (const auto& kv : f.header)
    {
        if (t.header_.count(kv.first))
        {
            if (kv.first != "missing")
            {
                throw InputError(file, "header " + kv.first, "header key '" + kv.first + "' given twice");
            }
            t.header_[kv.first] += "\n" + kv.second;
            continue;
        }
        t.header_[kv.first] = kv.second;
        keyOrder.push_back(kv.first);
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
                std::string all;
                for (const auto& n : axisNames)
                {
                    all += " " + n;
                }
                throw InputError(file, "header axes", "unknown axis '" + w + "'; the axes are" + all);
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

    if (f.rows.empty())
    {
        throw InputError(file, "", "no data rows (truncated drift table?)");
    }
    const auto& raw = f.rows;
    // rows not read from a file are named by their position
    const auto where = [](const DriftTableRecord& r, std::size_t i)
    {
        return r.line > 0 ? line(r.line) : "row " + std::to_string(i + 1);
    };

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
            // the rows span the declared range; with missing cases ('# missing:')
            // an edge node may be absent, and the table covers what is there
            const auto& d = declared[a];
            const bool spans = sameNode(d.first, nodes.front()) && sameNode(d.second, nodes.back());
            const bool within = (sameNode(d.first, nodes.front()) || d.first < nodes.front())
                             && (sameNode(d.second, nodes.back()) || d.second > nodes.back());
            if (!(spans || (missingAllowed && within)))
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
    t.values_.assign(valueCount*n, nan);
    t.hasTunnelDrift_ = raw.front().tunnelDrift.has_value();
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
            throw InputError(file, where(r, std::size_t(&r - raw.data())), "grid point duplicated (first at "
                + where(raw[seenAt[idx] - 1], seenAt[idx] - 1) + "): each combination of the axes must appear once");
        }
        seenAt[idx] = int(&r - raw.data()) + 1;
        if (r.tunnelDrift.has_value() != t.hasTunnelDrift_)
        {
            throw InputError(file, where(r, std::size_t(&r - raw.data())), "a value of " + tunnelDriftColumn()
                + " in some rows only: every row has one or none has");
        }
        for (int v = 0; v < 3; ++v) t.values_[valueCount*idx + v] = r.v[v];
        if (r.tunnelDrift) t.values_[valueCount*idx + 3] = *r.tunnelDrift;
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


std::optional<std::string> DriftTable::fixedSetting(const std::string& key) const
{
    return driftTableParse::fixedSetting(header_, key);
}


bool DriftTable::inRange(int a, double x) const
{
    const auto& nodes = axes_.at(a);
    const double tol = nodeTol*std::max({1e-300, std::abs(nodes.front()), std::abs(nodes.back())});
    return x >= nodes.front() - tol && x <= nodes.back() + tol;
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


void DriftTable::requireTunnelDrift() const
{
    if (!hasTunnelDrift_)
    {
        throw InputError(file_.string(), tunnelDriftColumn(), "the tunnel's reading needs this column, which "
            "the table has not (a sweep outside the wind tunnel's domain, or written before the column "
            "existed: buildDriftTable writes it again from its finished cases)");
    }
}


double DriftTable::tunnelDrift(const DriftQuery& q) const
{
    requireTunnelDrift();
    return evaluate(q, true).tunnelDrift;
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
        const double* val = &values_[valueCount*idx];
        if (std::isnan(val[0])) missingPoint(idx);
        v.vcOverVg += w*val[0];
        v.drift += w*val[1];
        v.capturedFraction += w*val[2];
        v.tunnelDrift += w*val[3];
    }
    if (anchored)
    {
        v.drift *= q.fallHeight/y0;   // exact anchor: no drift without a fall
        v.tunnelDrift *= q.fallHeight/y0;
    }
    return v;
}


std::vector<DriftTable::Row> DriftTable::rows() const
{
    std::vector<Row> out;
    for (std::size_t idx = 0; idx < size(); ++idx)
    {
        if (std::isnan(values_[valueCount*idx])) continue;
        Row r;
        for (int a = 0; a < driftAxisCount; ++a)
        {
            r.x[a] = axes_[a][(idx/stride_[a]) % axes_[a].size()];
        }
        const double* val = &values_[valueCount*idx];
        r.v = {val[0], val[1], val[2], val[3]};
        out.push_back(r);
    }
    return out;
}

} // namespace drum
