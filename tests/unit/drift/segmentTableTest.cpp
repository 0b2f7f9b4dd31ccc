// The drum-segment table (segmentTable.hpp): its reader's errors, the
// lookup along each run's release angles and between runs, the out-of-range
// policy, the segmentVc drift model against the lone particle at V_c, and
// the flight-model partition passing its release and repose angles.
#include "drum/drift/driftDictionary.hpp"
#include "drum/drift/segmentDrift.hpp"
#include "drum/drift/segmentTable.hpp"
#include "drum/io/inputError.hpp"
#include "drum/transport/compartment/compartmentFlightModel.hpp"
#include "testTempDir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <unistd.h>

using namespace drum;
namespace fs = std::filesystem;

namespace
{

fs::path tmpDir()
{
    return testTempDir("segmentTableTest");
}

const std::string header =
    "# dryerSegmentTable 1\n"
    "# generator: segmentTableTest\n"
    "# fixed: gas=air(rho=1.20412,nu=1.51e-05) flights=28 particle_diameter_m=0.00085\n"
    "repose_angle_deg,gas_velocity_m_s,release_angle_deg,spill_rate_kg_m_s,fall_height_m,vc_over_vg,drift_m,landed_fraction,case\n";

//- A row per (phi, V_g, psi) with V_c/V_g = f(phi, V_g, psi)
std::string rows(const std::vector<double>& phis, const std::vector<double>& vgs, const std::vector<double>& psis,
                 const std::function<double(double, double, double)>& f)
{
    std::ostringstream os;
    os.precision(17);
    for (double phi : phis)
        for (double vg : vgs)
            for (double psi : psis)
                os << phi << ',' << vg << ',' << psi << ",10,3," << f(phi, vg, psi) << ",0.05,0.97,run" << phi << '\n';
    return os.str();
}

fs::path write(const std::string& name, const std::string& text)
{
    const fs::path f = tmpDir()/name;
    std::ofstream(f) << text;
    return f;
}

const std::vector<double> psis{94.2857, 107.1429, 120, 132.857, 145.714};
double linear(double phi, double vg, double psi) { return 0.3 + 0.002*psi + 0.004*(phi - 40) + 0.05*(vg - 1); }

void expectInputError(const fs::path& f, const std::string& part)
{
    try
    {
        SegmentTable::read(f);
        ADD_FAILURE() << f << ": no error";
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(e.file(), f.string());
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

} // namespace


TEST(SegmentTable, LinearAlongTheRunsAndBetweenThem)
{
    const auto f = write("linear.csv", header + rows({37, 48, 59}, {0.5, 1.5}, psis, linear));
    const SegmentTable t = SegmentTable::read(f);
    EXPECT_EQ(t.reposeNodes().size(), 3u);
    EXPECT_EQ(t.gasVelocityNodes().size(), 2u);
    EXPECT_NEAR(t.pitchDeg(), 360.0/28, 1e-12);
    // a linear function is reproduced anywhere inside
    for (double phi : {37.0, 40.0, 48.0, 55.5, 59.0})
        for (double vg : {0.5, 0.8, 1.5})
            for (double psi : {94.2857, 100.0, 120.0, 139.0, 145.714})
                EXPECT_NEAR(t.vcOverVg(phi, vg, psi), linear(phi, vg, psi), 1e-12) << phi << ' ' << vg << ' ' << psi;
    // within one pitch beyond the first and last releasing flights: their value
    EXPECT_NEAR(t.vcOverVg(48, 1.5, 94.2857 - 12.0), linear(48, 1.5, 94.2857), 1e-12);
    EXPECT_NEAR(t.vcOverVg(48, 1.5, 145.714 + 12.0), linear(48, 1.5, 145.714), 1e-12);
}

TEST(SegmentTable, OutsideRefusedOrClampedAndCounted)
{
    const auto f = write("refuse.csv", header + rows({37, 59}, {1}, psis, linear));
    const SegmentTable t = SegmentTable::read(f);
    EXPECT_THROW(t.vcOverVg(36, 1, 120), InputError);             // phi below the runs
    EXPECT_THROW(t.vcOverVg(48, 1.1, 120), InputError);           // V_g: one run
    EXPECT_THROW(t.vcOverVg(48, 1, 145.714 + 13.0), InputError);  // more than a pitch past the last flight
    EXPECT_THROW(t.vcOverVg(48, 1, std::nan("")), InputError);    // no release angle
    try { t.vcOverVg(48, 1, 200); }
    catch (const InputError& e)
    {
        EXPECT_EQ(e.entry(), "release_angle_deg");
        EXPECT_NE(std::string(e.what()).find("94.2857-145.714"), std::string::npos) << e.what();
    }

    std::vector<std::string> warnings;
    SegmentTableOptions o;
    o.outside = OutOfRangePolicy::clamp;
    o.warn = [&](const std::string& w) { warnings.push_back(w); };
    const SegmentTable c = SegmentTable::read(f, o);
    EXPECT_NEAR(c.vcOverVg(30, 1, 120), linear(37, 1, 120), 1e-12);
    EXPECT_NEAR(c.vcOverVg(30, 1, 130), linear(37, 1, 130), 1e-12);
    EXPECT_NEAR(c.vcOverVg(48, 2, 300), 0.5*(linear(37, 1, 145.714) + linear(59, 1, 145.714)), 1e-12);
    EXPECT_EQ(c.clampCount(0), 2);
    EXPECT_EQ(c.clampCount(1), 1);
    EXPECT_EQ(c.clampCount(2), 2);   // 300 deg: once per run blended
    EXPECT_EQ(warnings.size(), 3u);  // once per quantity
}

TEST(SegmentTable, BadFilesNameTheFileAndTheLine)
{
    const std::string body = rows({40}, {1}, psis, linear);
    expectInputError(write("magic.csv", "# dryerDriftTable 1\n" + header.substr(header.find('\n') + 1) + body),
                     "dryerSegmentTable 1");
    std::string noFlights = header;
    noFlights.replace(noFlights.find(" flights=28"), 11, "");
    expectInputError(write("flights.csv", noFlights + body), "N_F");
    std::string cols = header;
    cols.replace(cols.find("vc_over_vg"), 10, "vc");
    expectInputError(write("columns.csv", cols + body), "column row");
    expectInputError(write("number.csv", header + "40,1,120,10,3,abc,0.05,0.97,r\n"), "line 5");
    expectInputError(write("range.csv", header + "40,1,120,10,3,2.5,0.05,0.97,r\n"), "vc_over_vg");
    expectInputError(write("fields.csv", header + "40,1,120,10,3,0.5,0.05,0.97\n"), "9 comma-separated");
    expectInputError(write("twice.csv", header + body + "40,1,120,10,3,0.5,0.05,0.97,r\n"), "given twice");
    expectInputError(write("grid.csv", header + rows({40}, {1}, psis, linear) + rows({50}, {2}, psis, linear)),
                     "every repose angle needs a run at every gas velocity");
    expectInputError(write("empty.csv", header), "no curtains");
    expectInputError(tmpDir()/"absent.csv", "file not found");
}

TEST(SegmentVcDrift, IsTheLoneParticleAtTheSegmentsVc)
{
    const auto f = write("drift.csv", header + rows({37, 59}, {0.5, 1.5}, psis, linear));
    const particleDrag::Gas air = particleDrag::Gas::air(20);
    const SegmentVcDrift m(std::make_shared<const SegmentTable>(SegmentTable::read(f)), air);
    const IsolatedParticleDrift lone(air);
    DriftQuery q;
    q.particleDiameter = 850e-6;
    q.particleDensity = 1590;
    q.gasVelocity = 1.2;
    q.fallHeight = 3.5;
    q.spillRate = 10;
    q.flightLength = 1.133;
    q.incline = -0.05;
    q.releaseAngleDeg = 128;
    q.reposeAngleDeg = 44;
    DriftQuery atVc = q;
    atVc.gasVelocity = linear(44, 1.2, 128)*1.2;
    EXPECT_NEAR(m.displacement(q), lone.displacement(atVc), 1e-12);
    EXPECT_LT(m.displacement(q), lone.displacement(q));
    DriftQuery noAngle = q;
    noAngle.releaseAngleDeg = std::nan("");
    EXPECT_THROW(m.displacement(noAngle), InputError);
    // no gas: the lone particle's slide, no table query
    DriftQuery still = noAngle;
    still.gasVelocity = 0;
    EXPECT_DOUBLE_EQ(m.displacement(still), lone.displacement(still));
}

TEST(SegmentVcDrift, FactoryNeedsTheTableAndItsGas)
{
    DriftSettings s;
    s.model = "segmentVc";
    EXPECT_THROW(makeDriftModel(s, particleDrag::Gas::air(20)), InputError);
    s.segmentTable = write("gas.csv", header + rows({40}, {1}, psis, linear));
    EXPECT_NO_THROW(makeDriftModel(s, particleDrag::Gas::air(20)));
    EXPECT_THROW(makeDriftModel(s, particleDrag::Gas::air(80)), InputError);   // swept at 20 degC
}

TEST(SegmentVcDrift, FlightModelPartitionPassesItsAngles)
{
    // V_c/V_g = 1 on every angle the flights can release at: the partition
    // must equal the lone particle's; 0.5: the lone particle at half V_g
    const std::vector<double> all{0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330, 360};
    const particleDrag::Gas air = particleDrag::Gas::air(20);
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    FlightModelPartition p;
    p.gasVelocity = 2.0;
    p.sizes = {850e-6};
    p.fractions = {1.0};
    p.particleDensity = 1590;
    p.flightAxialLength = 1.133;
    p.drift = std::make_shared<IsolatedParticleDrift>(air);
    const auto lone = flightModelSliceData(d, 10, p);
    p.drift = std::make_shared<SegmentVcDrift>(std::make_shared<const SegmentTable>(SegmentTable::read(
        write("one.csv", header + rows({30, 50}, {1, 3}, all, [](double, double, double) { return 1.0; })))), air);
    const auto one = flightModelSliceData(d, 10, p);
    p.gasVelocity = 1.0;
    p.drift = std::make_shared<IsolatedParticleDrift>(air);
    const auto loneHalf = flightModelSliceData(d, 10, p);
    p.gasVelocity = 2.0;
    p.drift = std::make_shared<SegmentVcDrift>(std::make_shared<const SegmentTable>(SegmentTable::read(
        write("half.csv", header + rows({30, 50}, {1, 3}, all, [](double, double, double) { return 0.5; })))), air);
    const auto half = flightModelSliceData(d, 10, p);
    for (std::size_t i = 0; i < lone.size(); ++i)
    {
        EXPECT_NEAR(one[i].slice.backFraction, lone[i].slice.backFraction, 1e-12);
        EXPECT_NEAR(one[i].slice.forwardFraction, lone[i].slice.forwardFraction, 1e-12);
        EXPECT_NEAR(half[i].slice.backFraction, loneHalf[i].slice.backFraction, 1e-12);
        EXPECT_NEAR(half[i].slice.forwardFraction, loneHalf[i].slice.forwardFraction, 1e-12);
    }
    // a repose angle outside the runs is refused (the slices are at 40 deg; runs at 45-50)
    p.drift = std::make_shared<SegmentVcDrift>(std::make_shared<const SegmentTable>(SegmentTable::read(
        write("far.csv", header + rows({45, 50}, {1, 3}, all, [](double, double, double) { return 0.5; })))), air);
    EXPECT_THROW(flightModelSliceData(d, 10, p), InputError);
}
