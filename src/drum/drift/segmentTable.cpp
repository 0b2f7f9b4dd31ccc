#include "drum/drift/segmentTable.hpp"

#include "drum/drift/driftTableFile.hpp"
#include "drum/io/inputError.hpp"
#include "particleDrag/releaseLayer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

namespace drum
{

namespace
{

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

const std::array<std::string, 3> quantityNames{{"repose_angle_deg", "gas_velocity_m_s", "release_angle_deg"}};

std::vector<std::string> split(const std::string& s)
{
    std::vector<std::string> out;
    std::string field;
    std::istringstream is(s);
    while (std::getline(is, field, ',')) out.push_back(field);
    if (!s.empty() && s.back() == ',') out.emplace_back();
    return out;
}

void addNode(std::vector<double>& nodes, double x)
{
    for (double n : nodes) if (sameNode(n, x)) return;
    nodes.insert(std::upper_bound(nodes.begin(), nodes.end(), x), x);
}

std::size_t nodeIndex(const std::vector<double>& nodes, double x)
{
    for (std::size_t i = 0; i < nodes.size(); ++i) if (sameNode(nodes[i], x)) return i;
    return nodes.size();
}

} // namespace


const std::vector<std::string>& segmentTableColumns()
{
    static const std::vector<std::string> c{"repose_angle_deg", "gas_velocity_m_s", "release_angle_deg",
        "spill_rate_kg_m_s", "fall_height_m", "vc_over_vg", "drift_m", "landed_fraction", "case"};
    return c;
}


SegmentTable SegmentTable::read(const std::filesystem::path& path, SegmentTableOptions options)
{
    const std::string file = path.string();
    requireReadableFile(file);
    std::ifstream in(path);
    if (!in)
    {
        throw InputError(file, "", "cannot open the drum-segment table");
    }
    SegmentTable t;
    t.file_ = path;
    t.options_ = std::move(options);

    std::string text;
    int n = 0;
    if (!std::getline(in, text) || text != "# dryerSegmentTable 1")
    {
        throw InputError(file, driftTableParse::line(1),
            "not a drum-segment table: the first line must be '# dryerSegmentTable 1'");
    }
    ++n;
    // header lines, then the column row
    bool columns = false;
    while (std::getline(in, text))
    {
        ++n;
        if (text.rfind("#", 0) != 0)
        {
            std::ostringstream expected;
            for (std::size_t k = 0; k < segmentTableColumns().size(); ++k)
            {
                expected << (k ? "," : "") << segmentTableColumns()[k];
            }
            if (text != expected.str())
            {
                throw InputError(file, driftTableParse::line(n), "the column row must be '" + expected.str() + "'");
            }
            columns = true;
            break;
        }
        const auto colon = text.find(':');
        if (colon == std::string::npos || colon < 3)
        {
            throw InputError(file, driftTableParse::line(n), "header lines are '# key: value'");
        }
        const std::string key = text.substr(2, colon - 2);
        std::string value = text.substr(colon + 1);
        value.erase(0, value.find_first_not_of(' '));
        if (t.header_.count(key))
        {
            throw InputError(file, driftTableParse::line(n), "header key '" + key + "' given twice");
        }
        t.header_[key] = value;
    }
    for (const char* key : {"generator", "fixed"})
    {
        if (!t.header_.count(key))
        {
            throw InputError(file, std::string("# ") + key, "missing header line");
        }
    }
    if (!columns)
    {
        throw InputError(file, driftTableParse::line(n + 1), "no column row and no data");
    }
    const auto flights = t.fixedSetting("flights");
    const double nf = flights ? driftTableParse::number(*flights, file, "# fixed: flights") : 0;
    if (!(nf >= 2 && nf <= 200 && nf == std::floor(nf)))
    {
        throw InputError(file, "# fixed: flights", "the number of flights N_F must be an integer in [2, 200]");
    }
    t.pitch_ = 360.0/nf;

    struct Row { double phi, vg; Curtain c; int line; };
    std::vector<Row> rows;
    while (std::getline(in, text))
    {
        ++n;
        const std::string where = driftTableParse::line(n);
        const auto f = split(text);
        if (f.size() != segmentTableColumns().size())
        {
            throw InputError(file, where, "expected " + std::to_string(segmentTableColumns().size())
                             + " comma-separated fields, found " + std::to_string(f.size()));
        }
        const auto num = [&](std::size_t k, double lo, double hi, bool openLo)
        {
            const std::string entry = where + ", " + segmentTableColumns()[k];
            const double v = driftTableParse::number(f[k], file, entry);
            if ((openLo ? !(v > lo) : !(v >= lo)) || !(v <= hi))
            {
                throw InputError(file, entry, fmt(v) + " outside the allowed range " + (openLo ? "(" : "[")
                                 + fmt(lo) + ", " + fmt(hi) + "]");
            }
            return v;
        };
        Row r;
        r.phi = num(0, 0, 90, true);
        r.vg = num(1, 0, 50, true);
        r.c.releaseAngleDeg = num(2, 0, 360, false);
        r.c.spillRate = num(3, 0, particleDrag::maxSpillRate, true);
        r.c.fallHeight = num(4, 0, 50, true);
        r.c.vcOverVg = num(5, -2, 2, false);
        r.c.drift = num(6, -100, 100, false);
        r.c.landedFraction = num(7, 0, 1.05, false);
        r.c.caseName = f[8];
        r.line = n;
        rows.push_back(r);
        addNode(t.phi_, r.phi);
        addNode(t.vg_, r.vg);
    }
    if (rows.empty())
    {
        throw InputError(file, driftTableParse::line(n + 1), "the table has no curtains");
    }
    t.runs_.assign(t.phi_.size()*t.vg_.size(), {});
    for (const Row& r : rows)
    {
        auto& run = t.runs_[nodeIndex(t.phi_, r.phi)*t.vg_.size() + nodeIndex(t.vg_, r.vg)];
        for (const Curtain& c : run)
        {
            if (sameNode(c.releaseAngleDeg, r.c.releaseAngleDeg))
            {
                throw InputError(file, driftTableParse::line(r.line), "release angle " + fmt(r.c.releaseAngleDeg)
                                 + " deg given twice for repose angle " + fmt(r.phi) + " deg and V_g " + fmt(r.vg) + " m/s");
            }
        }
        run.push_back(r.c);
    }
    for (std::size_t i = 0; i < t.phi_.size(); ++i)
    {
        for (std::size_t j = 0; j < t.vg_.size(); ++j)
        {
            auto& run = t.runs_[i*t.vg_.size() + j];
            if (run.empty())
            {
                throw InputError(file, "grid", "no segment run at repose angle " + fmt(t.phi_[i]) + " deg and V_g "
                                 + fmt(t.vg_[j]) + " m/s: every repose angle needs a run at every gas velocity");
            }
            std::sort(run.begin(), run.end(),
                      [](const Curtain& a, const Curtain& b) { return a.releaseAngleDeg < b.releaseAngleDeg; });
        }
    }
    return t;
}


std::optional<std::string> SegmentTable::fixedSetting(const std::string& key) const
{
    return driftTableParse::fixedSetting(header_, key);
}


void SegmentTable::outside(int q, const std::string& what) const
{
    if (options_.outside == OutOfRangePolicy::refuse)
    {
        throw InputError(file_.string(), quantityNames[q], what + " (policy refuse; use clamp to take the nearest "
                         "value, or add segment runs that cover it)");
    }
    counters_->count[q].fetch_add(1);
    if (!counters_->warned[q].exchange(true))
    {
        const std::string msg = "warning: drum-segment table " + file_.string() + ": " + what
                              + "; clamped (reported once per quantity; further clamps are counted)";
        if (options_.warn) options_.warn(msg);
        else std::cerr << msg << std::endl;
    }
}


void SegmentTable::locate(int q, const std::vector<double>& nodes, double x, std::size_t& i, double& w) const
{
    if (!std::isfinite(x))
    {
        throw InputError(file_.string(), quantityNames[q], "query value is not finite");
    }
    const double tol = nodeTol*std::max({1e-300, std::abs(nodes.front()), std::abs(nodes.back())});
    if (x < nodes.front() - tol || x > nodes.back() + tol)
    {
        outside(q, quantityNames[q] + " = " + fmt(x) + " is outside the segment runs' range ["
                + fmt(nodes.front()) + ", " + fmt(nodes.back()) + "]");
    }
    i = 0;
    w = 0;
    if (nodes.size() == 1 || x <= nodes.front()) return;
    if (x >= nodes.back())
    {
        i = nodes.size() - 2;
        w = 1;
        return;
    }
    i = std::size_t(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin()) - 1;
    w = (x - nodes[i])/(nodes[i + 1] - nodes[i]);
}


double SegmentTable::alongRun(const std::vector<Curtain>& run, double psi) const
{
    const double lo = run.front().releaseAngleDeg, hi = run.back().releaseAngleDeg;
    if (psi < lo - pitch_ || psi > hi + pitch_)
    {
        outside(2, "release angle " + fmt(psi) + " deg is more than one flight pitch (" + fmt(pitch_)
                + " deg) beyond the releasing flights of a segment run, " + fmt(lo) + "-" + fmt(hi) + " deg");
    }
    if (psi <= lo) return run.front().vcOverVg;
    if (psi >= hi) return run.back().vcOverVg;
    const auto k = std::size_t(std::upper_bound(run.begin(), run.end(), psi,
        [](double x, const Curtain& c) { return x < c.releaseAngleDeg; }) - run.begin());
    const Curtain& a = run[k - 1];
    const Curtain& b = run[k];
    const double w = (psi - a.releaseAngleDeg)/(b.releaseAngleDeg - a.releaseAngleDeg);
    return (1 - w)*a.vcOverVg + w*b.vcOverVg;
}


double SegmentTable::vcOverVg(double reposeDeg, double gasVelocity, double releaseAngleDeg) const
{
    if (!std::isfinite(releaseAngleDeg))
    {
        throw InputError(file_.string(), quantityNames[2], "the drift query carries no release angle: the "
                         "drum-segment table serves models that pass Lee's release angle (compartment, flightModel)");
    }
    std::size_t i, j;
    double wi, wj;
    locate(0, phi_, reposeDeg, i, wi);
    locate(1, vg_, gasVelocity, j, wj);
    const std::size_t i1 = std::min(i + 1, phi_.size() - 1), j1 = std::min(j + 1, vg_.size() - 1);
    // only the runs with a weight are asked (a run not used raises no event)
    const auto at = [&](std::size_t a, std::size_t b) { return alongRun(runs_[a*vg_.size() + b], releaseAngleDeg); };
    const auto inPhi = [&](std::size_t b)
    {
        if (wi <= 0) return at(i, b);
        if (wi >= 1) return at(i1, b);
        return (1 - wi)*at(i, b) + wi*at(i1, b);
    };
    if (wj <= 0) return inPhi(j);
    if (wj >= 1) return inPhi(j1);
    return (1 - wj)*inPhi(j) + wj*inPhi(j1);
}

} // namespace drum
