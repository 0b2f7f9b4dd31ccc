// DriftTable: exact on nodes and on functions multilinear in the
// interpolation coordinates, the ln-axis choice, out-of-range policies, the
// fall-height anchor and every malformed-file error
#include "drum/drift/driftTable.hpp"
#include "drum/drift/driftTableFile.hpp"
#include "drum/drift/segmentTable.hpp"
#include "drum/io/projectPaths.hpp"
#include "drum/io/inputError.hpp"
#include "syntheticTable.hpp"
#include "testTempDir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace drum;
namespace fs = std::filesystem;

namespace
{

fs::path tmpDir()
{
    return testTempDir("driftTableTest");
}

DriftQuery query(const synthetic::Point& p)
{
    DriftQuery q;
    q.gasVelocity = p[0];
    q.spillRate = p[1];
    q.fallHeight = p[2];
    q.flightLength = p[3];
    q.particleDensity = p[4];
    q.particleDiameter = p[5];
    return q;
}

// Multilinear in (V, ln S, y, ln L, rho, ln d): what the default scales reproduce exactly
synthetic::Values multilinear(const synthetic::Point& p)
{
    const double u[6] = {p[0], std::log(p[1]), p[2], std::log(p[3]), p[4]/1000, std::log(p[5])};
    double vc = 0.3 + 0.05*u[0] - 0.1*u[1] + 0.02*u[2] - 0.03*u[3] + 0.01*u[4]*u[1] + 0.02*u[0]*u[2]*u[5];
    double drift = 1 + 0.2*u[0]*u[2] + 0.1*u[5] - 0.05*u[1]*u[3]*u[4];
    double cap = 0.9 + 0.001*u[0]*u[1]*u[2]*u[3]*u[4]*u[5];
    return {vc, drift, cap};
}

std::string expectError(const fs::path& file, const std::string& needle)
{
    try
    {
        DriftTable::read(file);
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        EXPECT_EQ(e.file(), file.string());
        return e.what();
    }
    ADD_FAILURE() << "no InputError for " << needle;
    return "";
}

} // namespace


TEST(DriftTable, ExactOnNodesAndMultilinearFunctions)
{
    const fs::path f = tmpDir()/"multilinear.csv";
    const auto grid = synthetic::defaultGrid();
    synthetic::write(f, synthetic::table(grid, multilinear));
    const DriftTable t = DriftTable::read(f);
    EXPECT_EQ(t.size(), 3u*3*3*2*2*3);
    EXPECT_EQ(t.header().at("mesh"), "coarse (1000 cells)");
    // every node
    for (const auto& r : t.rows())
    {
        const auto v = t.lookup(query(r.x));
        const auto e = multilinear(r.x);
        EXPECT_NEAR(v.vcOverVg, e.vc, 1e-12);
        EXPECT_NEAR(v.drift, e.drift, 1e-12);
        EXPECT_NEAR(v.capturedFraction, e.captured, 1e-12);
    }
    // random interior points: exact for a function multilinear in the coordinates
    std::mt19937 rng(7);
    for (int k = 0; k < 200; ++k)
    {
        synthetic::Point p;
        for (int a = 0; a < 6; ++a)
        {
            std::uniform_real_distribution<double> u(0, 1);
            const double lo = grid[a].front(), hi = grid[a].back(), s = u(rng);
            p[a] = (a == 1 || a == 3 || a == 5) ? lo*std::pow(hi/lo, s) : lo + s*(hi - lo);
        }
        const auto v = t.lookup(query(p));
        const auto e = multilinear(p);
        EXPECT_NEAR(v.vcOverVg, e.vc, 1e-10);
        EXPECT_NEAR(v.drift, e.drift, 1e-10);
        EXPECT_NEAR(v.capturedFraction, e.captured, 1e-10);
    }
}


TEST(DriftTable, LnAxesBeatLinearAxesOnPowerLaws)
{
    // Eq 142-like shielding: vc ~ S^-0.857 L^-0.437, drift ~ 1/d (y, V on nodes or
    // linear: the same in both settings)
    const auto f = [](const synthetic::Point& p) -> synthetic::Values
    {
        return {0.6*std::pow(p[1], -0.857)*std::pow(p[3], -0.437), 1e-3/p[5], 1.0};
    };
    auto grid = synthetic::defaultGrid();
    const fs::path file = tmpDir()/"powerLaw.csv";
    synthetic::write(file, synthetic::table(grid, f));
    DriftTableOptions lin;
    lin.scale.fill(AxisScale::linear);
    const DriftTable tLog = DriftTable::read(file), tLin = DriftTable::read(file, lin);
    double eLog = 0, eLin = 0;
    for (double S : {3.0, 5.0, 12.0, 20.0})
    {
        for (double d : {2e-4, 3e-4, 1e-3, 1.5e-3})
        {
            const synthetic::Point p{2.2, S, 4.0, 1.5, 2000, d};
            const auto e = f(p);
            const auto a = tLog.lookup(query(p)), b = tLin.lookup(query(p));
            eLog += std::pow(std::log(a.vcOverVg/e.vc), 2) + std::pow(std::log(a.drift/e.drift), 2);
            eLin += std::pow(std::log(b.vcOverVg/e.vc), 2) + std::pow(std::log(b.drift/e.drift), 2);
        }
    }
    EXPECT_LT(eLog, 0.5*eLin) << "ln " << eLog << " lin " << eLin;
}


TEST(DriftTable, RefuseNamesAxisValueAndRange)
{
    const fs::path f = tmpDir()/"refuse.csv";
    synthetic::write(f, synthetic::table(synthetic::defaultGrid(), multilinear));
    const DriftTable t = DriftTable::read(f);
    EXPECT_EQ(t.policy(), OutOfRangePolicy::refuse);
    DriftQuery q = query({2, 5, 3, 1.5, 2000, 3e-4});
    q.gasVelocity = 12;
    try
    {
        t.lookup(q);
        FAIL() << "no error";
    }
    catch (const InputError& e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("gas_velocity_m_s"), std::string::npos) << m;
        EXPECT_NE(m.find("12"), std::string::npos) << m;
        EXPECT_NE(m.find("[1.5, 6]"), std::string::npos) << m;
    }
    q = query({2, 5, 3, 1.5, 2000, 3e-4});
    q.particleDiameter = 5e-5;
    EXPECT_THROW(t.lookup(q), InputError);
    q = query({2, 5, 3, 1.5, 2000, 3e-4});
    q.spillRate = -1;
    EXPECT_THROW(t.lookup(q), InputError);
    q.spillRate = std::nan("");
    EXPECT_THROW(t.lookup(q), InputError);
}


TEST(DriftTable, ClampEvaluatesAtTheEdgeWarnsOncePerAxisAndCounts)
{
    const fs::path f = tmpDir()/"clamp.csv";
    synthetic::write(f, synthetic::table(synthetic::defaultGrid(), multilinear));
    std::vector<std::string> warnings;
    DriftTableOptions o;
    o.outside = OutOfRangePolicy::clamp;
    o.warn = [&](const std::string& w) { warnings.push_back(w); };
    const DriftTable t = DriftTable::read(f, o);
    const synthetic::Point inside{6.0, 5, 3, 1.5, 2000, 3e-4};
    for (double v : {7.0, 9.0, 20.0})
    {
        synthetic::Point p = inside;
        p[0] = v;
        const auto got = t.lookup(query(p));
        const auto edge = t.lookup(query(inside));
        EXPECT_DOUBLE_EQ(got.vcOverVg, edge.vcOverVg);
        EXPECT_DOUBLE_EQ(got.drift, edge.drift);
    }
    synthetic::Point p = inside;
    p[5] = 1e-2;
    const auto big = t.lookup(query(p));
    p[5] = 2e-3;
    EXPECT_DOUBLE_EQ(big.drift, t.lookup(query(p)).drift);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find("gas_velocity_m_s"), std::string::npos);
    EXPECT_NE(warnings[1].find("particle_diameter_m"), std::string::npos);
    EXPECT_EQ(t.clampCount(gasVelocityAxis), 3);
    EXPECT_EQ(t.clampCount(diameterAxis), 1);
    EXPECT_EQ(t.clampCount(spillRateAxis), 0);
}


TEST(DriftTable, DriftAnchoredToZeroBelowTheSmallestFallHeight)
{
    const fs::path f = tmpDir()/"anchor.csv";
    synthetic::write(f, synthetic::table(synthetic::defaultGrid(), multilinear));
    const DriftTable t = DriftTable::read(f);  // refuse
    synthetic::Point p{2, 5, 1.0, 1.5, 2000, 3e-4};
    const double d0 = t.drift(query(p));
    p[2] = 0.25;
    EXPECT_NEAR(t.drift(query(p)), 0.25*d0, 1e-12);
    p[2] = 0;
    EXPECT_EQ(t.drift(query(p)), 0.0);
    EXPECT_EQ(t.clampCount(fallHeightAxis), 0);
    p[2] = 0.25;
    EXPECT_THROW(t.vcOverVg(query(p)), InputError);   // V_c has no exact anchor
    p[2] = 11;
    EXPECT_THROW(t.drift(query(p)), InputError);
}


TEST(DriftTable, FixedAxesAreSingleNodes)
{
    auto grid = synthetic::defaultGrid();
    grid[4] = {2650};
    grid[3] = {2.0};
    const fs::path f = tmpDir()/"fixed.csv";
    const std::string text = synthetic::table(grid, multilinear);
    EXPECT_EQ(text.find("range particle_density"), std::string::npos);
    synthetic::write(f, text);
    const DriftTable t = DriftTable::read(f);
    EXPECT_EQ(t.nodes(densityAxis).size(), 1u);
    const synthetic::Point p{2, 5, 3, 2.0, 2650, 3e-4};
    EXPECT_NEAR(t.lookup(query(p)).drift, multilinear(p).drift, 1e-10);
    synthetic::Point q = p;
    q[4] = 1200;
    EXPECT_THROW(t.lookup(query(q)), InputError);
}


TEST(DriftTable, MalformedFiles)
{
    const fs::path d = tmpDir();
    const auto grid = synthetic::defaultGrid();
    const std::string good = synthetic::table(grid, multilinear);
    const auto put = [&](const std::string& name, const std::string& text)
    {
        synthetic::write(d/name, text);
        return d/name;
    };
    auto replace = [](std::string s, const std::string& a, const std::string& b)
    {
        const auto i = s.find(a);
        EXPECT_NE(i, std::string::npos) << a;
        return s.replace(i, a.size(), b);
    };

    expectError(d/"absent.csv", "not found");
    expectError(put("empty.csv", ""), "empty");
    expectError(put("magic.csv", "test,material\n1,sand\n"), "not a drift table");
    expectError(put("version.csv", replace(good, "# dryerDriftTable 1", "# dryerDriftTable 2")), "version '2'");
    for (const char* key : {"generator", "dictionary", "fixed", "mesh", "cases"})
    {
        const auto at = good.find(std::string("# ") + key + ":");
        std::string s = good;
        s.erase(at, s.find('\n', at) - at + 1);
        expectError(put(std::string("no_") + key + ".csv", s), std::string("missing header key '") + key);
    }
    {
        // the sweep's wall time is optional (reproducible tables leave it out)
        const auto at = good.find("# elapsed_s:");
        std::string s = good;
        s.erase(at, s.find('\n', at) - at + 1);
        EXPECT_NO_THROW(DriftTable::read(put("no_elapsed.csv", s)));
    }
    expectError(put("noaxes.csv", replace(good, "# axes:", "# axis:")), "'axes'");
    expectError(put("twice.csv", replace(good, "# mesh:", "# mesh: fine\n# mesh:")), "'mesh' given twice");
    {
        const auto at = good.find("# range fall_height_m");
        std::string s = good;
        s.erase(at, s.find('\n', at) - at + 1);
        expectError(put("norange.csv", s), "range fall_height_m");
    }
    expectError(put("order.csv", replace(replace(good, "# mesh: coarse (1000 cells)\n", ""),
                                        "# cases: 1 (1 converged, 0 failed)\n",
                                        "# cases: 1 (1 converged, 0 failed)\n# mesh: coarse\n")), "order");
    expectError(put("order2.csv", replace(replace(good, "# generator:", "# generatorX:"),
                                         "# axes:", "# generator: x\n# axes:")), "order");
    expectError(put("badaxis.csv", replace(good, "fall_height_m flight", "height flight")), "unknown axis 'height'");
    expectError(put("range.csv", replace(good, "# range fall_height_m: 1 10", "# range fall_height_m: 1 12")),
                "declares [1, 12]");
    expectError(put("nocol.csv", replace(good, ",captured_fraction\n", "\n")), "captured_fraction");
    expectError(put("colname.csv", replace(good, ",drift_m,", ",drift,")), "column 9 must be 'drift_m'");
    expectError(put("extracol.csv", replace(good, "captured_fraction\n", "captured_fraction,x\n")), "extra column 'x'");
    const std::string row0 = synthetic::rows(grid, multilinear)[0];
    const auto firstRowLine = std::to_string(std::count(good.begin(), good.begin() + good.find(row0), '\n') + 1);
    {
        std::string bad = row0;
        bad.replace(bad.rfind(','), std::string::npos, ",abc\n");
        expectError(put("nonnumeric.csv", replace(good, row0, bad)), "line " + firstRowLine + ", column captured_fraction");
        bad = row0;
        bad.replace(bad.rfind(','), std::string::npos, ",nan\n");
        expectError(put("nan.csv", replace(good, row0, bad)), "'nan' is not a finite number");
        bad = row0;
        bad.replace(bad.rfind(','), std::string::npos, ",\n");
        expectError(put("emptyfield.csv", replace(good, row0, bad)), "captured_fraction");
    }
    expectError(put("short.csv", replace(good, row0, row0.substr(0, row0.size()/2) + "\n")), "truncated");
    expectError(put("cut.csv", good.substr(0, good.size() - 5)), "truncated");
    expectError(put("noRows.csv", synthetic::header(grid) + synthetic::columns()), "no data rows");
    expectError(put("noColumns.csv", synthetic::header(grid)), "no column header row");
    // a row cut out: grid incomplete; a row twice: duplicated
    {
        std::string s = good;
        const auto rows = synthetic::rows(grid, multilinear);
        s.erase(s.find(rows[5]), rows[5].size());
        expectError(put("incomplete.csv", s), "grid incomplete");
        s = good + rows[7];
        expectError(put("duplicate.csv", s), "duplicated");
    }
    {
        // unlisted axis that varies
        auto g2 = grid;
        const std::string t2 = replace(synthetic::table(g2, multilinear), " particle_density_kg_m3", "");
        expectError(put("unlisted.csv", t2), "not listed on the axes line");
    }
}


TEST(DriftTable, MissingPointsDeclaredInTheHeaderAreRefusedWhenNeeded)
{
    const auto grid = synthetic::defaultGrid();
    const auto rows = synthetic::rows(grid, multilinear);
    std::string s = synthetic::header(grid);
    s.insert(s.find("# cases:"), "# missing: c0 gas_velocity_m_s=1.5 (FAILED)\n# missing: 1 grid point in all\n");
    s += synthetic::columns();
    for (std::size_t i = 1; i < rows.size(); ++i) s += rows[i];
    const fs::path f = tmpDir()/"missing.csv";
    synthetic::write(f, s);
    const DriftTable t = DriftTable::read(f);
    EXPECT_EQ(t.rows().size(), rows.size() - 1);
    EXPECT_EQ(t.header().at("missing"), "c0 gas_velocity_m_s=1.5 (FAILED)\n1 grid point in all");
    // c0 is the first grid point (all axes at their minimum)
    EXPECT_THROW(t.lookup(query({1.5, 2, 1, 1, 1200, 1e-4})), InputError);
    EXPECT_THROW(t.lookup(query({1.6, 2, 1, 1, 1200, 1e-4})), InputError);
    const synthetic::Point far{5, 20, 8, 2, 2650, 1e-3};
    EXPECT_NEAR(t.lookup(query(far)).drift, multilinear(far).drift, 1e-10);
}


// The one writer reproduces every shipped table byte for byte from what the
// reader read: the format the sweeps wrote is the format of driftTableFile.hpp
TEST(DriftTableFile, ShippedTablesRoundTripByteForByte)
{
    // every shipped .csv is a drift table or the drum segment's table (a
    // format of its own, written by writeSegmentTable): the first round-trip,
    // the second is read by its reader
    std::vector<fs::path> files, segmentFiles;
    for (const fs::path& dir : {defaultsDir()/"driftTables", defaultsDir()/"driftTables"/"materialTables"})
    {
        for (const auto& e : fs::directory_iterator(dir))
        {
            if (e.path().extension() != ".csv") continue;
            std::ifstream in(e.path());
            std::string first;
            std::getline(in, first);
            (first == "# dryerSegmentTable 1" ? segmentFiles : files).push_back(e.path());
        }
    }
    ASSERT_GE(files.size(), 6u);   // generic, Invicta, lab drums, three materials
    ASSERT_GE(segmentFiles.size(), 1u);   // the Invicta segment
    for (const auto& f : segmentFiles)
    {
        EXPECT_NO_THROW(SegmentTable::read(f)) << f;
    }
    for (const auto& f : files)
    {
        std::ifstream in(f, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(driftTableText(readDriftTableFile(f)), text) << f;
    }
}


// write -> read gives the same header and values (to the half unit of the
// 6 or 8 significant digits written),
// and the writer refuses, leaving nothing behind, what the reader would refuse
TEST(DriftTableFile, WriteReadRoundTripAndRefusals)
{
    const fs::path src = tmpDir()/"roundTripSource.csv";
    synthetic::write(src, synthetic::table(synthetic::defaultGrid(), multilinear));
    const DriftTableFile in = readDriftTableFile(src);
    const fs::path out = tmpDir()/"roundTrip.csv";
    fs::remove(out);
    writeDriftTableFile(in, out);
    const DriftTableFile back = readDriftTableFile(out);
    EXPECT_EQ(back.header, in.header);
    ASSERT_EQ(back.rows.size(), in.rows.size());
    for (std::size_t i = 0; i < in.rows.size(); ++i)
    {
        EXPECT_EQ(back.rows[i].caseName, in.rows[i].caseName);
        for (int a = 0; a < 6; ++a)
        {
            EXPECT_NEAR(back.rows[i].x[a], in.rows[i].x[a], (a < 5 ? 5e-6 : 5e-8)*std::abs(in.rows[i].x[a]));
        }
        for (int v = 0; v < 3; ++v)
        {
            EXPECT_NEAR(back.rows[i].v[v], in.rows[i].v[v], 5e-8*std::abs(in.rows[i].v[v]));
        }
    }
    // written twice: the same bytes
    const fs::path again = tmpDir()/"roundTripAgain.csv";
    writeDriftTableFile(back, again);
    std::ifstream a(out, std::ios::binary), b(again, std::ios::binary);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>()),
              std::string((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>()));

    // a point missing without a '# missing:' line, a duplicated point, a bad case name
    const fs::path bad = tmpDir()/"refused.csv";
    fs::remove(bad);
    DriftTableFile holed = in;
    holed.rows.pop_back();
    EXPECT_THROW(writeDriftTableFile(holed, bad), InputError);
    DriftTableFile twice = in;
    for (auto& r : twice.rows) r.line = 0;   // rows made in memory are named by position
    twice.rows.back() = twice.rows.front();
    try
    {
        writeDriftTableFile(twice, bad);
        ADD_FAILURE() << "duplicated grid point written";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("duplicated (first at row 1)"), std::string::npos) << e.what();
    }
    DriftTableFile comma = in;
    comma.rows.front().caseName = "a,b";
    EXPECT_THROW(writeDriftTableFile(comma, bad), InputError);
    EXPECT_FALSE(fs::exists(bad));
}


TEST(DriftTable, TheTunnelReadingColumnIsInterpolatedAnchoredAndOptional)
{
    // tunnel_drift_m: another multilinear function, exact on and between nodes,
    // anchored like drift_m below the smallest fall height
    const auto withTunnel = [](const synthetic::Point& p)
    {
        synthetic::Values v = multilinear(p);
        v.tunnel = 0.5 + 0.3*p[0]*p[2] - 0.02*std::log(p[5]);
        return v;
    };
    const fs::path f = tmpDir()/"tunnel.csv";
    synthetic::write(f, synthetic::table(synthetic::defaultGrid(), withTunnel));
    const DriftTable t = DriftTable::read(f);
    ASSERT_TRUE(t.hasTunnelDrift());
    for (const synthetic::Point& p : {synthetic::Point{1.5, 2, 1, 1, 1200, 1e-4}, synthetic::Point{2.2, 5, 3, 1.4, 2000, 3e-4},
                                      synthetic::Point{6, 30, 10, 2, 2650, 2e-3}})
    {
        EXPECT_NEAR(t.tunnelDrift(query(p)), *withTunnel(p).tunnel, 1e-12) << p[0] << " " << p[2];
        EXPECT_NEAR(t.drift(query(p)), withTunnel(p).drift, 1e-12);   // the other columns unchanged
    }
    synthetic::Point low{3, 8, 1, 1, 1200, 5e-4};
    const double atY0 = t.tunnelDrift(query(low));
    low[2] = 0.25;
    EXPECT_DOUBLE_EQ(t.tunnelDrift(query(low)), 0.25*atY0);

    // written back with the column, byte for byte
    const fs::path again = tmpDir()/"tunnelAgain.csv";
    fs::remove(again);
    writeDriftTableFile(readDriftTableFile(f), again);
    const DriftTableFile back = readDriftTableFile(again);
    ASSERT_TRUE(back.rows.front().tunnelDrift.has_value());
    std::ifstream a(again, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("captured_fraction,tunnel_drift_m\n"), std::string::npos);
    const fs::path third = tmpDir()/"tunnelThird.csv";
    writeDriftTableFile(back, third);
    std::ifstream b(third, std::ios::binary);
    EXPECT_EQ(text, std::string((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>()));

    // a value in some rows only: refused, nothing written
    DriftTableFile partial = back;
    partial.rows[3].tunnelDrift.reset();
    const fs::path bad = tmpDir()/"tunnelPartial.csv";
    fs::remove(bad);
    try
    {
        writeDriftTableFile(partial, bad);
        ADD_FAILURE() << "a tunnel column with a hole written";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("tunnel_drift_m in some rows only"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(bad));

    // a table without the column: no tunnel reading, named
    const fs::path plain = tmpDir()/"plain.csv";
    synthetic::write(plain, synthetic::table(synthetic::defaultGrid(), multilinear));
    const DriftTable p = DriftTable::read(plain);
    EXPECT_FALSE(p.hasTunnelDrift());
    try
    {
        p.tunnelDrift(query(synthetic::Point{3, 8, 4, 1, 1200, 5e-4}));
        ADD_FAILURE() << "tunnel reading of a table without the column";
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(e.file(), plain.string());
        EXPECT_NE(std::string(e.what()).find("tunnel_drift_m"), std::string::npos) << e.what();
    }

    // another last column, a row with a field too few: refused, naming the line
    std::string s = synthetic::table(synthetic::defaultGrid(), withTunnel);
    const fs::path renamed = tmpDir()/"renamed.csv";
    synthetic::write(renamed, std::string(s).replace(s.find("tunnel_drift_m"), 14, "hopper_drift_m"));
    expectError(renamed, "extra column 'hopper_drift_m'");
    const fs::path shortRow = tmpDir()/"shortRow.csv";
    const auto lastComma = s.rfind(',');
    synthetic::write(shortRow, s.substr(0, lastComma) + "\n");
    expectError(shortRow, "10 fields, expected 11");
}
