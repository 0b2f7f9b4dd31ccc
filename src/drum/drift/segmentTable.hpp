// The drum-segment table (file format "dryerSegmentTable 1"): the gas
// velocity inside each flight's curtain when every flight's curtain falls at
// once in the drum's own cross-section (drumSegmentCase), per
// release angle. Its one writer is writeSegmentTable; this is its
// one reader.
//
// The format, line by line:
//   # dryerSegmentTable 1                      magic and version
//   # generator: <tool ; solver>               "# key: value" lines; required:
//   # fixed: gas=air(rho=R,nu=N,T=..C) flights=N_F ...     generator, fixed
//   # <any other key>: <text>                  (notes, kept in header())
//   repose_angle_deg,gas_velocity_m_s,release_angle_deg,spill_rate_kg_m_s,
//        fall_height_m,vc_over_vg,drift_m,landed_fraction,case
//   <one row per releasing flight of each segment run>
//
// release_angle_deg is the flight's root angle from the drum bottom in the
// direction of rotation, the angle of Lee's (2008) unloading model (Ch. 4;
// drum::LeeFlight). Each segment run (one dynamic angle of repose phi and
// one gas velocity V_g) gives one curve vc_over_vg(psi) through its
// releasing flights.
//
// Lookup at (phi, V_g, psi): linear in psi along each run's curve; within
// one flight pitch (360/N_F) beyond the run's first or last releasing flight,
// that flight's value (a release angle there is a flight starting or ending
// its discharge, between a releasing one and one that is not); then linear
// in phi and in V_g between the runs. Out of range (a phi or V_g outside the
// runs', a psi more than a pitch beyond a run's curtains): the
// OutOfRangePolicy of the drift table (refuse: InputError naming the
// quantity, the value and the range; clamp: the nearest value, counted and
// reported once per quantity).
#ifndef DRUM_DRIFT_SEGMENTTABLE_HPP
#define DRUM_DRIFT_SEGMENTTABLE_HPP

#include "drum/drift/driftTable.hpp"

#include <array>
#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drum
{

//- The data columns, in order
const std::vector<std::string>& segmentTableColumns();

struct SegmentTableOptions
{
    OutOfRangePolicy outside = OutOfRangePolicy::refuse;
    std::function<void(const std::string&)> warn;   //!< clamp warnings; null: std::cerr
};

class SegmentTable
{
public:

    //- One releasing flight of one run
    struct Curtain
    {
        double releaseAngleDeg = 0, spillRate = 0, fallHeight = 0;
        double vcOverVg = 0, drift = 0, landedFraction = 0;
        std::string caseName;
    };

    //- Read and check; InputError naming the file, the line and the field
    static SegmentTable read(const std::filesystem::path& file, SegmentTableOptions options = {});

    //- V_c/V_g in the curtain released at psi (deg) at repose angle phi
    //  (deg) and gas velocity V_g (m/s)
    double vcOverVg(double reposeDeg, double gasVelocity, double releaseAngleDeg) const;

    //- The runs' repose angles and gas velocities (ascending)
    const std::vector<double>& reposeNodes() const { return phi_; }
    const std::vector<double>& gasVelocityNodes() const { return vg_; }
    //- The curtains of the run at node (i, j), ascending in release angle
    const std::vector<Curtain>& curtains(std::size_t iPhi, std::size_t jVg) const
    {
        return runs_.at(iPhi*vg_.size() + jVg);
    }
    //- The flight pitch 360/N_F, deg
    double pitchDeg() const { return pitch_; }

    const std::map<std::string, std::string>& header() const { return header_; }
    //- Item `key=value` of the `fixed:` line; empty when absent
    std::optional<std::string> fixedSetting(const std::string& key) const;
    const std::filesystem::path& file() const { return file_; }
    //- Out-of-range events so far: 0 repose angle, 1 gas velocity, 2 release angle
    long clampCount(int quantity) const { return counters_->count.at(quantity).load(); }

private:
    struct Counters
    {
        std::array<std::atomic<long>, 3> count{};
        std::array<std::atomic<bool>, 3> warned{};
    };

    // lower node and weight of x on nodes; policy outside
    void locate(int quantity, const std::vector<double>& nodes, double x, std::size_t& i, double& w) const;
    double alongRun(const std::vector<Curtain>& run, double psi) const;
    void outside(int quantity, const std::string& what) const;

    std::filesystem::path file_;
    SegmentTableOptions options_;
    std::map<std::string, std::string> header_;
    std::vector<double> phi_, vg_;
    std::vector<std::vector<Curtain>> runs_;   // phi-major
    double pitch_ = 0;
    std::shared_ptr<Counters> counters_ = std::make_shared<Counters>();
};

} // namespace drum

#endif
