// The CFD drift table (file format "dryerDriftTable 1", driftTableFile.hpp,
// written from curtainFoam sweeps by buildDriftTable through writeDriftTable)
// read back with strict errors and interpolated multilinearly on its
// rectilinear grid.
//
// Axes, in contract order: gas velocity, spill rate, fall height, flight
// length, particle density, particle diameter. Axes not listed on the
// `# axes:` line are single-valued (the fixed value the sweep held).
//
// Interpolation coordinate per axis (AxisScale): spill rate, flight length
// and particle diameter are interpolated in ln(x) - they span decades and
// the curtain's shielding follows power laws in them (Eq 142: S^-0.857,
// L^-0.437; drag K ~ 1/d), which are linear in ln-ln and closer to linear in
// ln-lin than in lin-lin; gas velocity, fall height and density in x (the
// drift grows about linearly in V_g and in y over a fall). Values
// (vc_over_vg, drift_m, captured_fraction and, when the table has it,
// tunnel_drift_m) are interpolated linearly.
//
// Exact anchor: drift_m -> 0 as the fall height -> 0, so below the smallest
// tabulated fall height y0 drift_m = drift(y0) y/y0 (no out-of-range event;
// tunnel_drift_m alike);
// vc_over_vg and captured_fraction follow the out-of-range policy there.
//
// Out of range (OutOfRangePolicy): refuse throws drum::InputError naming the
// axis, the value and the table's range; clamp evaluates at the nearest
// point of the range, counts the event per axis and reports it once per axis
// through the warning sink (std::cerr by default).
#ifndef DRUM_DRIFT_DRIFTTABLE_HPP
#define DRUM_DRIFT_DRIFTTABLE_HPP

#include "drum/drift/driftModel.hpp"
#include "drum/drift/driftTableFile.hpp"

#include <array>
#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace drum
{

enum class OutOfRangePolicy { refuse, clamp };

//- "refuse" | "clamp"; InputError naming `entry` otherwise
OutOfRangePolicy parseOutOfRangePolicy(const std::string& word, const std::string& entry, const std::string& file = "");
std::string policyName(OutOfRangePolicy p);

enum class AxisScale { linear, log };

//- The six axes of the contract, in its order
enum DriftAxis
{
    gasVelocityAxis, spillRateAxis, fallHeightAxis, flightLengthAxis, densityAxis, diameterAxis
};
constexpr int driftAxisCount = 6;

//- Column name of an axis ("gas_velocity_m_s", ...)
const std::string& driftAxisName(int axis);

//- What a lookup returns
struct DriftTableValue
{
    double vcOverVg = 0;        //!< V_c/V_g in the curtain
    double drift = 0;           //!< mean axial displacement of the class, m
    double capturedFraction = 0;
    double tunnelDrift = 0;     //!< the tunnel's reading of the class, m (NaN: the table has none)
};

struct DriftTableOptions
{
    OutOfRangePolicy outside = OutOfRangePolicy::refuse;
    //- Per-axis interpolation coordinate (defaults as documented above)
    std::array<AxisScale, driftAxisCount> scale{{AxisScale::linear, AxisScale::log, AxisScale::linear,
                                                 AxisScale::log, AxisScale::linear, AxisScale::log}};
    //- Where clamp warnings go (once per axis); default std::cerr
    std::function<void(const std::string&)> warn;
};

class DriftTable
{
public:
    //- Read and check a table file; throws InputError naming the file, the
    //  line and the field for every defect (see driftTable.cpp)
    static DriftTable read(const std::filesystem::path& file, DriftTableOptions options = {});

    //- The table of a file's contents (driftTableFile.hpp); `file` names it
    //  in errors. Checks the header order, the ranges and the grid.
    static DriftTable fromFile(const DriftTableFile& contents, const std::filesystem::path& file,
                               DriftTableOptions options = {});

    //- Interpolated values at the query (incline is not a table axis); the
    //  out-of-range policy applies on every axis
    DriftTableValue lookup(const DriftQuery& q) const;

    //- drift_m at the query, with the exact anchor below the smallest fall
    //  height (drift(y0) y/y0); the policy applies elsewhere
    double drift(const DriftQuery& q) const;

    //- vc_over_vg at the query (no anchor)
    double vcOverVg(const DriftQuery& q) const;

    //- Whether the table has the tunnel_drift_m column
    bool hasTunnelDrift() const { return hasTunnelDrift_; }
    //- InputError naming the file and the column when the table has none
    void requireTunnelDrift() const;
    //- tunnel_drift_m at the query, with drift_m's anchor below the smallest
    //  fall height; InputError naming the file when the table has no such column
    double tunnelDrift(const DriftQuery& q) const;

    //- Grid nodes of an axis (one node for an axis the sweep held fixed)
    const std::vector<double>& nodes(int axis) const { return axes_[axis]; }
    //- Whether x lies in [nodes.front(), nodes.back()] of `axis` within the
    //  table's node tolerance (relative 1e-9: the queries' own rounding)
    bool inRange(int axis, double x) const;

    //- Header entries (key -> text after "key:"), e.g. "generator", "mesh"
    const std::map<std::string, std::string>& header() const { return header_; }
    //- The value of item `key=value` of the header's `fixed:` line (the sweep's
    //  settings, space-separated), e.g. "gas" -> "air(rho=1.2086,nu=1.5054e-05)";
    //  empty when the table has no such item
    std::optional<std::string> fixedSetting(const std::string& key) const;

    const std::filesystem::path& file() const { return file_; }
    OutOfRangePolicy policy() const { return options_.outside; }

    //- Clamp events so far on an axis
    long clampCount(int axis) const { return counters_->count[axis].load(); }

    //- Number of data rows (grid points)
    std::size_t size() const { return values_.size()/valueCount; }

    //- Every grid point: axis values and the tabulated values (for
    //  fitting reduced models to the table)
    struct Row { std::array<double, driftAxisCount> x; DriftTableValue v; };
    std::vector<Row> rows() const;

private:
    struct Counters
    {
        std::array<std::atomic<long>, driftAxisCount> count{};
        std::array<std::atomic<bool>, driftAxisCount> warned{};
    };

    DriftTableValue evaluate(const DriftQuery& q, bool anchorFallHeight) const;
    [[noreturn]] void missingPoint(std::size_t idx) const;

    // Cell of axis a holding x: lower index and weight; handles policy
    void locate(int axis, double x, int& i, double& w, bool anchorBelow) const;

    std::filesystem::path file_;
    DriftTableOptions options_;
    std::map<std::string, std::string> header_;
    std::array<std::vector<double>, driftAxisCount> axes_;
    std::array<std::vector<double>, driftAxisCount> coord_;  // scaled nodes
    std::array<std::size_t, driftAxisCount> stride_{};
    static constexpr std::size_t valueCount = 4;
    // (vc, drift, captured, tunnel drift) per grid point; NaN: missing (the
    // tunnel drift NaN throughout when the table has no such column)
    std::vector<double> values_;
    bool hasTunnelDrift_ = false;
    std::shared_ptr<Counters> counters_ = std::make_shared<Counters>();
};

} // namespace drum

#endif
