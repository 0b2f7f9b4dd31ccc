// windTunnelDrift end to end: every model on the shared wind-tunnel tests
// (isolated and Sherritt against the shared reference predictions, tableVc
// with a uniform V_c/V_g against them too, cfd through a stand-in
// curtainCase), the score mode against the data README's RMS values, and bad
// input: clear errors, no output file, an existing output left untouched.
#include "drum/io/projectPaths.hpp"
#include "drum/io/csv.hpp"
#include "scoring/apparentSheetVelocity.hpp"
#include "scoring/windTunnelData.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "particleDrag/sheetVelocity.hpp"
#include "syntheticTable.hpp"
#include "testTempDir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace
{

const fs::path data = drum::dataDir();

fs::path dir()
{
    return testTempDir("windTunnelDriftCli");
}

struct CliRun { int rc; std::string out; };

CliRun run(const std::string& args, const std::string& env = "")
{
    const fs::path log = dir()/"log.txt";
    const std::string cmd = "DRYER_DATA=" + data.string() + " " + env + " " + WINDTUNNELDRIFT + std::string(" ") + args + " > " + log.string() + " 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream in(log);
    std::stringstream ss;
    ss << in.rdbuf();
    return {rc, ss.str()};
}

std::map<int, double> readPred(const fs::path& f)
{
    std::map<int, double> m;
    io::CSVReader<2> in(f.string());
    in.read_header(io::ignore_no_column, "test", "mean_advance_m");
    int t;
    double v;
    while (in.read_row(t, v)) m[t] = v;
    return m;
}

std::map<int, std::pair<double, double>> reference()
{
    std::map<int, std::pair<double, double>> m;
    io::CSVReader<3> in((data/"windtunnel_reference_predictions.csv").string());
    in.read_header(io::ignore_extra_column, "test", "pred_a_m", "pred_b_m");
    int t;
    double a, b;
    while (in.read_row(t, a, b)) m[t] = {a, b};
    return m;
}

//- Each model's overall row (fall_height_m "all") of a -score CSV: count and RMS ln;
//  the rows per fall height counted in `perHeight`
std::map<std::string, std::pair<int, double>> overallScores(const fs::path& csv, int* perHeight = nullptr)
{
    std::map<std::string, std::pair<int, double>> all;
    io::CSVReader<4> in(csv.string());
    in.read_header(io::ignore_extra_column, "model", "fall_height_m", "count", "rms_ln");
    std::string m, y;
    int n;
    double rms;
    while (in.read_row(m, y, n, rms))
    {
        if (y == "all") all[m] = {n, rms};
        else if (perHeight) ++*perHeight;
    }
    return all;
}

std::string text(const fs::path& f)
{
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

//- A stand-in curtainCase in dir()/BIN that appends its arguments to argsFile
//  (emptied first) and fails; returns the PATH setting that puts it first
std::string recordingCurtainCase(const std::string& bin, const fs::path& argsFile)
{
    const fs::path b = dir()/bin;
    fs::create_directories(b);
    std::ofstream(b/"curtainCase") << "#!/bin/sh\necho \"$@\" >> " << argsFile.string() << "\nexit 3\n";
    fs::permissions(b/"curtainCase", fs::perms::owner_all);
    fs::remove(argsFile);
    return "PATH=" + b.string() + ":$PATH";
}

// A table covering the wind tunnel with a uniform V_c/V_g = r; its tunnel
// reading (tunnel_drift_m) is `tunnelShare` times its drift_m
fs::path uniformTable(double r, double tunnelShare = 1)
{
    std::array<std::vector<double>, 6> g{{{1, 9}, {5, 45}, {3, 11}, {0.9, 2.1}, {1100, 2700}, {40e-6, 4e-3}}};
    const fs::path f = dir()/("uniform" + std::to_string(r) + "_" + std::to_string(tunnelShare) + ".csv");
    const particleDrag::Gas air = particleDrag::Gas::air(20);
    synthetic::write(f, synthetic::table(g, [&](const synthetic::Point& p) -> synthetic::Values
    {
        const double drift = particleDrag::loneParticleAdvance({}, {p[5], p[4]}, air, r*p[0], p[2]);
        return {r, drift, 1.0, tunnelShare*drift};
    }));
    return f;
}

const std::string tests = (data/"windtunnel_tests.csv").string();

} // namespace


TEST(WindTunnelDriftCli, IsolatedAndSherrittReproduceTheSharedReferencePredictions)
{
    const auto ref = reference();
    for (const char* model : {"isolated", "sherritt"})
    {
        const fs::path out = dir()/(std::string(model) + ".csv");
        const CliRun r = run("-tests " + tests + " -out " + out.string() + " -model " + model);
        ASSERT_EQ(r.rc, 0) << r.out;
        const auto p = readPred(out);
        ASSERT_EQ(p.size(), 69u);
        for (const auto& [t, v] : p)
        {
            const double e = std::string(model) == "isolated" ? ref.at(t).first : ref.at(t).second;
            EXPECT_NEAR(v, e, 2e-4) << model << " test " << t;
        }
    }
}


TEST(WindTunnelDriftCli, TableVcWithUniformRatioIsTheLoneParticleAtThatVelocity)
{
    const auto ref = reference();
    const fs::path out = dir()/"tableVc.csv";
    CliRun r = run("-tests " + tests + " -out " + out.string() + " -model tableVc -table " + uniformTable(1.0).string());
    ASSERT_EQ(r.rc, 0) << r.out;
    for (const auto& [t, v] : readPred(out)) EXPECT_NEAR(v, ref.at(t).first, 2e-4) << t;
    // table model: drift interpolated, within the interpolation error of the lone particle
    r = run("-tests " + tests + " -out " + out.string() + " -model table -table " + uniformTable(1.0).string());
    ASSERT_EQ(r.rc, 0) << r.out;
    for (const auto& [t, v] : readPred(out)) EXPECT_NEAR(v/ref.at(t).first, 1.0, 0.25) << t;
}


TEST(WindTunnelDriftCli, TunnelReadingAppliesTheCollectionRuleToEachClassAtEveryHeight)
{
    // two heights, two classes released at 1.5 m: at 4 m class c0 half on the suspended
    // platform at 2.1 m and half on the fixed one, class c1 all at 3.0 m, less a net
    // 0.01 crossing back up at 0.6 m (counted net; the feed's balance puts it at 11.3 m),
    // plus a denormal flux beyond 7.5 m, as OpenFOAM prints one; at 10.3 m c0 0.4 at 6 m and 0.2 on the
    // fixed platform (0.4 lost: the feed's balance, whatever the outlet row says), c1 all lost
    const fs::path landing = dir()/"curtainLanding.csv", reading = dir()/"reading.csv";
    std::ofstream(landing) <<
        "fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m\n"
        "4,c0,slot,slot,1,1,1.5\n4,c0,2,2.25,0.5,0.5,2.1\n4,c0,8,8.25,0.5,0.5,8.1\n4,c0,lost,lost,0,0,nan\n"
        "4,c1,slot,slot,1,1,1.5\n4,c1,0.5,0.75,-0.01,-0.01,0.6\n4,c1,2.75,3,1,1,3.0\n"
        "4,c1,9,9.25,1.3e-320,1.5e-320,nan\n"
        "10.3,c0,slot,slot,1,1,1.5\n10.3,c0,5.75,6,0.4,0.4,6\n10.3,c0,10,10.25,0.2,0.2,10.1\n"
        "10.3,c0,lost,lost,0.3,0.3,nan\n"
        "10.3,c1,slot,slot,1,1,1.5\n10.3,c1,0,0.25,0,0,nan\n10.3,c1,lost,lost,1,1,nan\n";
    CliRun r = run("-tunnelReading " + landing.string() + " -out " + reading.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    std::map<std::pair<double, int>, std::array<double, 4>> got;
    {
        io::CSVReader<6> in(reading.string());
        in.read_header(io::ignore_no_column, "fall_height_m", "class_index", "tunnel_drift_m", "suspended_fraction",
                       "fixed_fraction", "lost_fraction");
        double y, i, a, su, fi, lo;
        while (in.read_row(y, i, a, su, fi, lo)) got[{y, int(i)}] = {a, su, fi, lo};
    }
    ASSERT_EQ(got.size(), 4u);
    const auto expect = [&](double y, int c, double advance, double su, double fi, double lo)
    {
        const auto& g = got.at({y, c});
        EXPECT_NEAR(g[0], advance, 1e-12) << y << " c" << c;
        EXPECT_NEAR(g[1], su, 1e-15) << y << " c" << c;
        EXPECT_NEAR(g[2], fi, 1e-15) << y << " c" << c;
        EXPECT_NEAR(g[3], lo, 1e-15) << y << " c" << c;
    };
    expect(4, 0, 0.5*2.1 + 0.5*9.4 - 1.5, 0.5, 0.5, 0);
    expect(4, 1, 3.0 - 0.01*0.6 + 0.01*11.3 - 1.5, 1 - 0.01, 0, 0.01);
    expect(10.3, 0, 0.4*6 + 0.2*9.4 + 0.4*11.3 - 1.5, 0.4, 0.2, 0.4);
    expect(10.3, 1, 11.3 - 1.5, 0, 0, 1);
    // a bin carrying more than the feed back up, a class whose net crossing is an upflow
    // (the signs flipped), a bin across the suspended platform's end, a malformed number:
    // refused naming the file
    std::ofstream(landing) << "fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m\n"
                              "4,c0,slot,slot,1,1,1.5\n4,c0,1,1.25,-1.5,-1.5,1.1\n4,c0,2,2.25,2.5,2.5,2.1\n";
    r = run("-tunnelReading " + landing.string() + " -out " + reading.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("outside [-1, 1.01]"), std::string::npos) << r.out;
    std::ofstream(landing) << "fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m\n"
                              "4,c0,slot,slot,1,1,1.5\n4,c0,2,2.25,-0.5,-0.5,2.1\n4,c0,8,8.25,-0.5,-0.5,8.1\n";
    r = run("-tunnelReading " + landing.string() + " -out " + reading.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("-1 of its feed caught (a net upflow"), std::string::npos) << r.out;
    std::ofstream(landing) << "fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m\n"
                              "4,c0,slot,slot,1,1,1.5\n4,c0,7.4,7.6,1,1,7.5\n";
    r = run("-tunnelReading " + landing.string() + " -out " + reading.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("straddles"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(landing.string()), std::string::npos) << r.out;
    std::ofstream(landing) << "fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m\n"
                              "4,c0,slot,slot,1,1,1.5\n4,c0,2,2.25,1,one,2.1\n";
    r = run("-tunnelReading " + landing.string() + " -out " + reading.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("line 3"), std::string::npos) << r.out;
}


TEST(WindTunnelDriftCli, TheTableModelAnswersTheTunnelsReadingOrWithCollectionLandedTheCrossedDrift)
{
    // tunnel_drift_m is twice drift_m at every node: the interpolated answers
    // differ by that factor (exactly; the predictions file prints 10 digits)
    const fs::path table = uniformTable(0.7, 2.0).string();
    const fs::path tunnel = dir()/"tunnel.csv", landed = dir()/"landed.csv";
    CliRun r = run("-tests " + tests + " -out " + tunnel.string() + " -model table -table " + table.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    r = run("-tests " + tests + " -out " + landed.string() + " -model table -collection landed -table " + table.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    const auto t = readPred(tunnel), l = readPred(landed);
    ASSERT_EQ(t.size(), 69u);
    ASSERT_EQ(l.size(), 69u);
    for (const auto& [test, v] : l) EXPECT_NEAR(t.at(test), 2*v, 1e-9*v) << test;
    // a table without the column cannot give the tunnel's reading: refused, naming the
    // file and the column; with -collection landed it answers
    const fs::path old = dir()/"noTunnelColumn.csv";
    {
        std::array<std::vector<double>, 6> g{{{1, 9}, {5, 45}, {3, 11}, {0.9, 2.1}, {1100, 2700}, {40e-6, 4e-3}}};
        synthetic::write(old, synthetic::table(g, [](const synthetic::Point& p) -> synthetic::Values
        {
            return {0.7, 0.1*p[2], 1.0};
        }));
    }
    std::ofstream(tunnel) << "keep\n";
    r = run("-tests " + tests + " -out " + tunnel.string() + " -model table -table " + old.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find(old.string()), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("tunnel_drift_m"), std::string::npos) << r.out;
    EXPECT_EQ(text(tunnel), "keep\n");
    r = run("-tests " + tests + " -out " + landed.string() + " -model table -collection landed -table " + old.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    // -collection is an option of the models that have a landing distribution
    r = run("-tests " + tests + " -out " + landed.string() + " -model tableVc -collection landed -table " + table.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("-collection"), std::string::npos) << r.out;
}


// A copy of `table` whose header names a material (buildDriftTable's `material` entry)
fs::path materialTable(const fs::path& table, const std::string& material, const std::string& name)
{
    std::string t = text(table);
    const auto at = t.find("# axes:");
    t.insert(at, "# material: " + material + "\n");
    const fs::path f = dir()/name;
    std::ofstream(f) << t;
    return f;
}

std::map<int, std::string> materialOfTest()
{
    std::map<int, std::string> m;
    io::CSVReader<2> in(tests);
    in.read_header(io::ignore_extra_column, "test", "material");
    int t;
    std::string name;
    while (in.read_row(t, name)) m[t] = name;
    return m;
}


TEST(WindTunnelDriftCli, MaterialTablesServeTheirMaterialAndAGenericTableTheRest)
{
    const auto mat = materialOfTest();
    const fs::path half = dir()/"half.csv", full = dir()/"full.csv", both = dir()/"both.csv";
    ASSERT_EQ(run("-tests " + tests + " -out " + half.string() + " -model tableVc -table " + uniformTable(0.5).string()).rc, 0);
    ASSERT_EQ(run("-tests " + tests + " -out " + full.string() + " -model tableVc -table " + uniformTable(1.0).string()).rc, 0);
    const fs::path sand = materialTable(uniformTable(0.5), "sand", "sandTable.csv");
    // sand rows from the sand table (V_c/V_g 0.5), the others from the generic one (1.0); order free
    for (const std::string& list : {sand.string() + "," + uniformTable(1.0).string(),
                                   uniformTable(1.0).string() + "," + sand.string()})
    {
        const CliRun r = run("-tests " + tests + " -out " + both.string() + " -model tableVc -table " + list);
        ASSERT_EQ(r.rc, 0) << r.out;
        const auto h = readPred(half), f = readPred(full), b = readPred(both);
        ASSERT_EQ(b.size(), 69u);
        int nSand = 0;
        for (const auto& [t, v] : b)
        {
            const bool isSand = mat.at(t) == "sand";
            nSand += isSand;
            EXPECT_DOUBLE_EQ(v, isSand ? h.at(t) : f.at(t)) << "test " << t << " " << mat.at(t);
        }
        EXPECT_EQ(nSand, 29);
    }
    // a material table alone serves its own rows only: the others are refused, or left out on request
    const fs::path out = dir()/"keep.csv";
    std::ofstream(out) << "keep\n";
    CliRun r = run("-tests " + tests + " -out " + out.string() + " -model table -table " + sand.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("none of the -table files serves this material"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material raw_shale"), std::string::npos) << r.out;
    EXPECT_EQ(text(out), "keep\n");
    r = run("-tests " + tests + " -out " + out.string() + " -model table -skipFailed -table " + sand.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    EXPECT_EQ(readPred(out).size(), 29u);
    // ambiguous or unknown: refused, output untouched
    std::ofstream(out) << "keep\n";
    const fs::path sand2 = materialTable(uniformTable(0.8), "sand", "sandTable2.csv");
    const fs::path clay = materialTable(uniformTable(0.8), "clay", "clayTable.csv");
    for (const auto& [list, needle] : std::vector<std::pair<std::string, std::string>>{
             {sand.string() + "," + sand2.string(), "a second table for 'sand'"},
             {uniformTable(0.8).string() + "," + uniformTable(1.0).string(), "two tables without a '# material:' header"},
             {clay.string(), "'clay' is not a material of the materials file"},
             {sand.string() + ",", "empty item"}})
    {
        r = run("-tests " + tests + " -out " + out.string() + " -model tableVc -table " + list);
        EXPECT_NE(r.rc, 0) << list;
        EXPECT_NE(r.out.find(needle), std::string::npos) << r.out;
        EXPECT_EQ(text(out), "keep\n") << list;
    }
}


TEST(WindTunnelDriftCli, ScoresMatchTheDataReadme)
{
    for (const char* model : {"isolated", "sherritt"})
    {
        ASSERT_EQ(run("-tests " + tests + " -out " + (dir()/(std::string(model) + ".csv")).string() + " -model " + model).rc, 0);
    }
    const fs::path csv = dir()/"scores.csv", byMat = dir()/"scoresByMaterial.csv";
    const CliRun r = run("-score -tests " + tests + " -predictions isolated=" + (dir()/"isolated.csv").string()
                      + ",sherritt=" + (dir()/"sherritt.csv").string() + " -out " + csv.string()
                      + " -byMaterial " + byMat.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    int rowsPerHeight = 0;
    std::map<std::string, double> overall;
    for (const auto& [model, score] : overallScores(csv, &rowsPerHeight))
    {
        overall[model] = score.second;
        EXPECT_EQ(score.first, 69) << model;
    }
    EXPECT_EQ(rowsPerHeight, 4);   // 6.6 and 10.3 m for two models
    EXPECT_NEAR(overall.at("isolated"), 0.88, 0.005);   // data/README.md
    EXPECT_NEAR(overall.at("sherritt"), 0.34, 0.005);
    // per material: the shared rows' counts, and the squares add up to the overall RMS
    io::CSVReader<4> bm(byMat.string());
    bm.read_header(io::ignore_extra_column, "model", "material", "count", "rms_ln");
    std::map<std::string, int> count;
    std::map<std::string, double> sumSq;
    std::string m, y;
    int n;
    double rms;
    while (bm.read_row(m, y, n, rms))
    {
        if (m == "sherritt") count[y] = n;
        sumSq[m] += n*rms*rms;
    }
    EXPECT_EQ(count, (std::map<std::string, int>{{"raw_shale", 19}, {"sand", 29}, {"spent_shale", 21}}));
    for (const auto& [model, ss] : sumSq)
    {
        EXPECT_NEAR(std::sqrt(ss/69), overall.at(model), 2e-3) << model;   // 4 printed digits
    }
    // -pngModels selects the models drawn, every model is still scored; a name that is
    // not a prediction, or the option without -png, is refused and nothing is written
    const std::string preds = " -predictions isolated=" + (dir()/"isolated.csv").string()
                              + ",sherritt=" + (dir()/"sherritt.csv").string();
    const fs::path csv2 = dir()/"scores2.csv", png = dir()/"scores2.png";
    CliRun d = run("-score -tests " + tests + preds + " -out " + csv2.string() + " -png " + png.string()
                   + " -pngModels sherritt");
    ASSERT_EQ(d.rc, 0) << d.out;
    EXPECT_EQ(text(csv2), text(csv));
    fs::remove(csv2);
    d = run("-score -tests " + tests + preds + " -out " + csv2.string() + " -png " + png.string()
            + " -pngModels sherritt,table");
    EXPECT_NE(d.rc, 0);
    EXPECT_NE(d.out.find("'table' is not one of the -predictions names"), std::string::npos) << d.out;
    d = run("-score -tests " + tests + preds + " -out " + csv2.string() + " -pngModels sherritt");
    EXPECT_NE(d.rc, 0);
    EXPECT_NE(d.out.find("belongs to -png"), std::string::npos) << d.out;
    EXPECT_FALSE(fs::exists(csv2));
}


TEST(WindTunnelDriftCli, ApparentVcIsEq141OnEachModelsClassAdvancesScoredAgainstTheTunnelsVc)
{
    // the lone particle in V_g gives back V_g; Eq 142's gives back C_V V_g, and its
    // score against the tunnel's V_c is Eq 142's own error on the rows that have one
    const fs::path iso = dir()/"vcIsolated.csv", sh = dir()/"vcSherritt.csv";
    CliRun r = run("-tests " + tests + " -out " + iso.string() + " -model isolated -quantity apparentVc");
    ASSERT_EQ(r.rc, 0) << r.out;
    ASSERT_EQ(run("-tests " + tests + " -out " + sh.string() + " -model sherritt -quantity apparentVc").rc, 0);
    EXPECT_EQ(text(iso).substr(0, 15), "test,vc_m_s\n11,");
    const auto measuredVc = drum::readMeasured(data/"windtunnel_tests.csv", "vc_m_s", true);
    std::map<int, double> vg, cv;
    {
        io::CSVReader<6> in((data/"windtunnel_tests.csv").string());
        in.read_header(io::ignore_extra_column, "test", "air_velocity_m_s", "fall_height_m", "spill_rate_kg_m_s",
                       "flight_length_m", "vc_m_s");
        int t;
        double v, y, spill, l;
        std::string vc;
        while (in.read_row(t, v, y, spill, l, vc))
        {
            vg[t] = v;
            cv[t] = particleDrag::sherrittSheetVelocityRatio(y, spill, l);
        }
    }
    const auto isoVc = drum::readMeasured(iso, "vc_m_s"), shVc = drum::readMeasured(sh, "vc_m_s");
    ASSERT_EQ(isoVc.size(), 69u);
    double sum2 = 0;
    for (const auto& [t, v] : vg)
    {
        EXPECT_NEAR(isoVc.at(t), v, 1e-6*v) << "test " << t;
        EXPECT_NEAR(shVc.at(t), cv.at(t)*v, 1e-6*v) << "test " << t;
        if (measuredVc.count(t)) sum2 += std::pow(std::log(cv.at(t)*v/measuredVc.at(t)), 2);
    }
    // Eq 141 is evaluated in Sherritt's air (1 atm) whatever the model breathed: the lone
    // particle in the site's lighter air drifts less, so its apparent V_c lies below V_g
    const fs::path thin = dir()/"vcIsolated89.csv";
    ASSERT_EQ(run("-tests " + tests + " -out " + thin.string() + " -model isolated -quantity apparentVc "
                  "-gasPressure 89").rc, 0);
    for (const auto& [t, v] : drum::readMeasured(thin, "vc_m_s"))
    {
        EXPECT_LT(v, 0.995*vg.at(t)) << "test " << t;
        EXPECT_GT(v, 0.85*vg.at(t)) << "test " << t;
    }
    const fs::path csv = dir()/"vcScores.csv";
    r = run("-score -quantity apparentVc -tests " + tests + " -predictions sherritt=" + sh.string() + " -out "
            + csv.string());
    ASSERT_EQ(r.rc, 0) << r.out;
    const auto all = overallScores(csv);
    ASSERT_EQ(all.count("sherritt"), 1u);
    EXPECT_EQ(all.at("sherritt").first, 67);   // tests 73 and 74 have no V_c
    EXPECT_NEAR(all.at("sherritt").second, std::sqrt(sum2/67), 1e-3);   // 4 printed digits
    // an advance file is not a V_c file; unknown or repeated quantities are refused
    // and write nothing
    const fs::path advance = dir()/"advanceIsolated.csv";
    ASSERT_EQ(run("-tests " + tests + " -out " + advance.string() + " -model isolated").rc, 0);
    r = run("-score -quantity apparentVc -tests " + tests + " -predictions iso=" + advance.string()
            + " -out " + (dir()/"vcBad.csv").string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("vc_m_s"), std::string::npos) << r.out;
    r = run("-tests " + tests + " -out " + (dir()/"vcBad.csv").string() + " -model isolated -quantity drift");
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("'drift': valid names are advance, apparentVc"), std::string::npos) << r.out;
    r = run("-tests " + tests + " -out " + (dir()/"vcBad.csv").string() + " -model isolated "
            "-quantity apparentVc,apparentVc");
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("'apparentVc' given twice"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir()/"vcBad.csv"));
}

TEST(WindTunnelDriftCli, CfdRunsCurtainCasePerRow)
{
    // Stand-in curtainCase: drift of a class = 1000 d (a function of its arguments)
    const fs::path bin = dir()/"bin";
    fs::create_directories(bin);
    std::ofstream(bin/"curtainCase") <<
        "#!/bin/sh\nwhile [ $# -gt 0 ]; do case $1 in -dir) D=$2;; -diameters) DS=$2;; -fractions) WS=$2;;"
        " -heights) HS=$2;; -level) L=$2;; esac; shift; shift; done\n"
        "[ \"$L\" = coarse ] || exit 3\nmkdir -p $D\n"
        "echo class,diameter_m,mass_fraction,fall_height_m,drift_m,captured_fraction,vc_over_vg,gas_velocity_m_s,"
        "cells,iterations,wall_time_s,converged > $D/curtainResult.csv\n"
        "for h in $(echo $HS | tr , ' '); do i=0; for d in $(echo $DS | tr , ' '); do i=$((i+1));"
        " echo $i,$d,0.1,$h,$(awk \"BEGIN{print 1000*$d}\"),1,0.5,1,100,10,1,1 >> $D/curtainResult.csv; done;"
        " echo bulk,,,$h,0,1,0.5,1,100,10,1,1 >> $D/curtainResult.csv; done\n"
        // landing: half of every class on the suspended platform at x = 2.1 m, a quarter on
        // the fixed one, the rest lost; released at 1.5 m
        "echo fall_height_m,class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m > $D/curtainLanding.csv\n"
        "for h in $(echo $HS | tr , ' '); do i=0; for d in $(echo $DS | tr , ' '); do"
        " echo $h,c$i,slot,slot,1,1,1.5 >> $D/curtainLanding.csv;"
        " echo $h,c$i,2,2.25,0.5,0.5,2.1 >> $D/curtainLanding.csv;"
        " echo $h,c$i,7.25,7.5,0,0,nan >> $D/curtainLanding.csv;"
        " echo $h,c$i,8,8.25,0.25,0.25,8.2 >> $D/curtainLanding.csv;"
        " echo $h,c$i,lost,lost,0.1,0.1,nan >> $D/curtainLanding.csv; i=$((i+1)); done; done\n";
    fs::permissions(bin/"curtainCase", fs::perms::owner_all);
    // three rows of the shared tests, one per material
    const fs::path few = dir()/"few.csv";
    {
        std::ifstream in(tests);
        std::ofstream out(few);
        std::string l;
        std::getline(in, l);
        out << l << "\n";
        std::map<std::string, int> seen;
        while (std::getline(in, l))
        {
            const std::string mat = l.substr(l.find(',') + 1, l.find(',', l.find(',') + 1) - l.find(',') - 1);
            if (!seen[mat]++) out << l << "\n";
        }
    }
    const fs::path out = dir()/"cfd.csv";
    const std::string path = "PATH=" + bin.string() + ":$PATH";
    const CliRun r = run("-tests " + few.string() + " -out " + out.string() + " -model cfd -collection landed -work "
                         + (dir()/"work").string(), path);
    ASSERT_EQ(r.rc, 0) << r.out;
    EXPECT_NE(r.out.find("cfd 3/3"), std::string::npos) << r.out;
    const auto materials = drum::readWindTunnelMaterials(data/"windtunnel_materials.csv");
    const auto rows = drum::readWindTunnelTests(few, materials);
    const auto p = readPred(out);
    ASSERT_EQ(p.size(), 3u);
    for (const auto& t : rows)
    {
        double e = 0;
        for (const auto& c : materials.at(t.material).classes) e += c.massFraction*1000*c.diameter;
        EXPECT_NEAR(p.at(t.test), e, 1e-6*e) << t.test;
    }
    EXPECT_FALSE(fs::exists(dir()/"work"));
    // the wind tunnel's collection rule (Sherritt 1991 section 4.3.1, the default): the
    // suspended platform's exact centre, the fixed platform's centre (9.4 m), the lost part
    // (the feed's balance, not the outlet row) at 11.3 m, minus the release:
    // 0.5 x 2.1 + 0.25 x 9.4 + 0.25 x 11.3 - 1.5 = 4.725 m for every class
    fs::remove(out);
    // (two rows at a time: every row answered once)
    const CliRun rule = run("-tests " + few.string() + " -out " + out.string() + " -model cfd -jobs 2 -work "
                            + (dir()/"workRule").string(), path);
    ASSERT_EQ(rule.rc, 0) << rule.out;
    const auto ruled = readPred(out);
    EXPECT_EQ(ruled.size(), 3u);
    for (const auto& [test, advance] : ruled)
    {
        EXPECT_NEAR(advance, 4.725, 1e-9) << test;
    }
    EXPECT_NE(rule.out.find("cfd 3/3"), std::string::npos) << rule.out;
    // both quantities from one run: the same advances, and Eq 141 (in Sherritt's air) on
    // the classes' readings, 4.725 m each
    const fs::path both = dir()/"cfdBoth.csv";
    const CliRun twice = run("-tests " + few.string() + " -out " + both.string() + " -model cfd "
                             "-quantity advance,apparentVc -gasPressure 89 -work " + (dir()/"workBoth").string(), path);
    ASSERT_EQ(twice.rc, 0) << twice.out;
    EXPECT_EQ(drum::readMeasured(both, "mean_advance_m"), ruled);
    const auto vc = drum::readMeasured(both, "vc_m_s");
    ASSERT_EQ(vc.size(), 3u);
    for (const auto& t : rows)
    {
        const auto& m = materials.at(t.material);
        const double expected = drum::apparentSheetVelocity(t, m, std::vector<double>(m.classes.size(), 4.725),
                                                            particleDrag::Gas::air(20));
        EXPECT_NEAR(vc.at(t.test), expected, 1e-9*expected) << t.test;
    }

    const CliRun badName = run("-tests " + few.string() + " -out " + out.string() + " -model cfd -collection hopper",
                               path);
    EXPECT_NE(badName.rc, 0);
    EXPECT_NE(badName.out.find("-collection"), std::string::npos) << badName.out;
    // a failing case: error naming the test, no output
    fs::remove(out);
    const CliRun bad = run("-tests " + few.string() + " -out " + out.string() + " -model cfd -level medium -work "
                        + (dir()/"work2").string(), path);
    EXPECT_NE(bad.rc, 0);
    EXPECT_NE(bad.out.find("curtainCase failed"), std::string::npos) << bad.out;
    EXPECT_FALSE(fs::exists(out));
    // -skipFailed leaves failed rows out; with every row failed nothing is written
    const CliRun skipped = run("-tests " + few.string() + " -out " + out.string() + " -model cfd -level medium -skipFailed"
                               " -work " + (dir()/"work3").string(), path);
    EXPECT_NE(skipped.rc, 0);
    EXPECT_NE(skipped.out.find("left out"), std::string::npos) << skipped.out;
    EXPECT_NE(skipped.out.find("every cfd row failed"), std::string::npos) << skipped.out;
    EXPECT_FALSE(fs::exists(out));
}


TEST(WindTunnelDriftCli, GasPressureThinsTheTunnelsAirForEveryModel)
{
    // the lone particle in thinner air (89 kPa: Calgary) drifts less on every row
    const fs::path atm = dir()/"isolatedAtm.csv", thin = dir()/"isolated89.csv", vc = dir()/"tableVc89.csv";
    ASSERT_EQ(run("-tests " + tests + " -out " + atm.string() + " -model isolated").rc, 0);
    CliRun r = run("-tests " + tests + " -out " + thin.string() + " -model isolated -gasPressure 89");
    ASSERT_EQ(r.rc, 0) << r.out;
    const auto a = readPred(atm), b = readPred(thin);
    ASSERT_EQ(b.size(), 69u);
    for (const auto& [t, v] : b) EXPECT_LT(v, a.at(t)) << t;
    // the same air reaches a table model's lone particle: tableVc at V_c/V_g = 1 is isolated
    r = run("-tests " + tests + " -out " + vc.string() + " -model tableVc -gasPressure 89 -table "
            + uniformTable(1.0).string());
    ASSERT_EQ(r.rc, 0) << r.out;
    for (const auto& [t, v] : readPred(vc)) EXPECT_NEAR(v, b.at(t), 2e-4) << t;
    // a table swept in air at 1 atm is refused in 89 kPa air (12 % lighter), naming the table
    std::string t = text(uniformTable(0.8));
    t.replace(t.find("# fixed: "), 9, "# fixed: gas=air(rho=1.2086,nu=1.50534e-05) ");
    const fs::path atmTable = dir()/"atmTable.csv";
    std::ofstream(atmTable) << t;
    const fs::path out = dir()/"refused.csv";
    r = run("-tests " + tests + " -out " + out.string() + " -model table -gasPressure 89 -table " + atmTable.string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("atmTable.csv"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("gasPressure"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out));
    ASSERT_EQ(run("-tests " + tests + " -out " + out.string() + " -model table -table " + atmTable.string()).rc, 0);
    fs::remove(out);
    // the cfd rows run curtainCase in that air
    r = run("-tests " + tests + " -out " + out.string() + " -model cfd -gasPressure 89 -work " + (dir()/"pwork").string(),
            recordingCurtainCase("pbin", dir()/"pargs.txt"));
    EXPECT_NE(r.rc, 0);
    const std::string args = text(dir()/"pargs.txt");
    EXPECT_NE(args.find("-gasPressure 89"), std::string::npos) << args;
    // out of range
    for (const char* bad : {"5", "2000", "thin"})
    {
        r = run("-tests " + tests + " -out " + out.string() + " -model isolated -gasPressure " + bad);
        EXPECT_NE(r.rc, 0);
        EXPECT_NE(r.out.find("-gasPressure"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("[10, 1000]"), std::string::npos) << r.out;
        EXPECT_FALSE(fs::exists(out));
    }
}


TEST(WindTunnelDriftCli, WithoutTablesEachMaterialIsServedByTheShippedTableSweptInTheRunsAir)
{
    // the shipped material tables: at 1 atm those of materialTables/, in the tunnel's
    // site air (89 kPa) those of materialTables/siteAir/; each answer is the one the
    // explicit -table list of that air gives, bit for bit
    const fs::path mt = drum::defaultsDir()/"driftTables"/"materialTables";
    const auto list = [&](const fs::path& folder)
    {
        return (folder/"rawShaleTable.csv").string() + "," + (folder/"sandTable.csv").string() + ","
            + (folder/"spentShaleTable.csv").string();
    };
    for (const auto& [pressure, folder] : {std::pair<std::string, fs::path>{"", mt}, {" -gasPressure 89", mt/"siteAir"}})
    {
        const fs::path implicit = dir()/"implicit.csv", given = dir()/"given.csv";
        CliRun r = run("-tests " + tests + " -out " + implicit.string() + " -model table -outside clamp" + pressure);
        ASSERT_EQ(r.rc, 0) << r.out;
        r = run("-tests " + tests + " -out " + given.string() + " -model table -outside clamp" + pressure
                + " -table " + list(folder));
        ASSERT_EQ(r.rc, 0) << r.out;
        EXPECT_EQ(readPred(implicit), readPred(given)) << pressure;
        ASSERT_EQ(readPred(implicit).size(), 69u);
    }
    // air no shipped table was swept in: refused, naming the folder searched
    const fs::path out = dir()/"none.csv";
    const CliRun r = run("-tests " + tests + " -out " + out.string() + " -model table -gasPressure 50");
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.out.find("no shipped table was swept in this air"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("materialTables"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out));
}


TEST(WindTunnelDriftCli, CfdRowsPassThePackedLayerWithTheMaterialsBulkDensity)
{
    // -layerThickness packed: curtainCase sizes each row's layer from the material's
    // bulk density (Table A.1: sand 1600, the shales 860 kg/m3)
    const fs::path argsFile = dir()/"largs.txt", out = dir()/"packed.csv";
    const CliRun r = run("-tests " + tests + " -out " + out.string() + " -model cfd -skipFailed -layerThickness packed -work "
                         + (dir()/"lwork").string(), recordingCurtainCase("lbin", argsFile));
    EXPECT_NE(r.rc, 0);
    std::istringstream lines(text(argsFile));
    std::size_t n = 0;
    for (std::string line; std::getline(lines, line); ++n)
    {
        const bool sand = line.find("-density 2650") != std::string::npos;
        EXPECT_NE(line.find(sand ? "-layerThickness packed -bulkDensity 1600" : "-layerThickness packed -bulkDensity 860"),
                  std::string::npos) << line;
    }
    EXPECT_EQ(n, 69u);
}


TEST(WindTunnelDriftCli, BadInputGivesClearErrorsAndNoOutput)
{
    const fs::path out = dir()/"keep.csv";
    const auto expectFail = [&](const std::string& args, const std::string& needle)
    {
        std::ofstream(out) << "keep\n";
        const CliRun r = run(args + " -out " + out.string());
        EXPECT_NE(r.rc, 0) << args;
        EXPECT_NE(r.out.find(needle), std::string::npos) << r.out;
        EXPECT_EQ(text(out), "keep\n") << "output touched by a failed run: " << args;
    };
    const auto edited = [&](const std::string& name, const std::function<std::string(std::string)>& f)
    {
        const fs::path p = dir()/name;
        std::ofstream(p) << f(text(tests));
        return p.string();
    };
    for (const char* name : {"valid names are isolated", "sherritt", "tableVc", "porousSheet", "cfd"})
    {
        expectFail("-tests " + tests + " -model magic", name);
    }
    expectFail("-tests " + (dir()/"absent.csv").string() + " -model isolated", "not found");
    expectFail("-tests " + edited("nocol.csv", [](std::string s) { return s.replace(s.find("air_velocity_m_s"), 3, "gas"); })
               + " -model isolated", "air_velocity_m_s");
    expectFail("-tests " + edited("nonnum.csv", [](std::string s) { return s.replace(s.find(",5.2,"), 5, ",x5,"); })
               + " -model isolated", "line 2, column air_velocity_m_s");
    expectFail("-tests " + edited("material.csv", [](std::string s) { return s.replace(s.find("raw_shale"), 9, "rawShale"); })
               + " -model isolated", "unknown material 'rawShale'");
    expectFail("-tests " + edited("range.csv", [](std::string s) { return s.replace(s.find(",5.2,"), 5, ",95,"); })
               + " -model isolated", "test 11");
    expectFail("-tests " + edited("cut.csv", [](std::string s) { return s.substr(0, s.size()/2) + "\n12,sand\n"; })
               + " -model isolated", "");
    const std::string table = uniformTable(0.8).string();
    {
        std::string t = text(table);
        std::ofstream(dir()/"v2.csv") << std::string(t).replace(t.find("Table 1"), 7, "Table 2");
        std::ofstream(dir()/"short.csv") << t.substr(0, t.size() - 30);
    }
    expectFail("-tests " + tests + " -model table -table " + (dir()/"v2.csv").string(), "version '2'");
    expectFail("-tests " + tests + " -model tableVc -table " + (dir()/"short.csv").string(), "truncated");
    expectFail("-tests " + tests + " -model table -table " + (dir()/"none.csv").string(), "not found");
    expectFail("-tests " + tests + " -model table -table " + table + " -outside sometimes", "refuse, clamp");
    // the open top bin (3.37 mm) is outside a table up to 2 mm: refused, or clamped on request
    std::array<std::vector<double>, 6> g{{{1, 9}, {5, 45}, {3, 11}, {0.9, 2.1}, {1100, 2700}, {1e-4, 2e-3}}};
    synthetic::write(dir()/"narrow.csv", synthetic::table(g, [](const synthetic::Point&) -> synthetic::Values { return {1, 1, 1, 1}; }));
    expectFail("-tests " + tests + " -model table -table " + (dir()/"narrow.csv").string(),
               "particle_diameter_m = 0.00336583 is outside the table");
    std::ofstream(out) << "keep\n";
    const CliRun clamp = run("-tests " + tests + " -model table -outside clamp -table " + (dir()/"narrow.csv").string()
                          + " -out " + out.string());
    EXPECT_EQ(clamp.rc, 0) << clamp.out;
    EXPECT_NE(clamp.out.find("warning"), std::string::npos);
    EXPECT_NE(clamp.out.find("class queries clamped on particle_diameter_m"), std::string::npos) << clamp.out;
    EXPECT_EQ(readPred(out).size(), 69u);
}

TEST(WindTunnelDriftCli, RepeatedMissingAndUnknownTestsAreRefusedNamingFileLineAndTest)
{
    const fs::path out = dir()/"keepRows.csv";
    const auto expectFail = [&](const std::string& args, const std::vector<std::string>& needles)
    {
        std::ofstream(out) << "keep\n";
        const CliRun r = run(args + " -out " + out.string());
        EXPECT_NE(r.rc, 0) << args;
        for (const auto& n : needles) EXPECT_NE(r.out.find(n), std::string::npos) << n << " not in: " << r.out;
        EXPECT_EQ(r.out.find("-skipFailed"), std::string::npos) << r.out;
        EXPECT_EQ(text(out), "keep\n") << "output touched by a failed run: " << args;
    };
    // a test id given twice in the tests file (its second row lost its prediction before)
    std::string t = text(tests);
    const std::size_t l2 = t.find('\n') + 1, l3 = t.find('\n', l2) + 1;
    const fs::path dup = dir()/"dupTests.csv";
    std::ofstream(dup) << t.substr(0, l3) + t.substr(l2, l3 - l2) + t.substr(l3);
    expectFail("-tests " + dup.string() + " -model sherritt", {dup.string(), "test 11", "line 3", "also on line 2"});
    const fs::path frac = dir()/"fracTests.csv";
    std::ofstream(frac) << t.substr(0, l2) + "11.5" + t.substr(l2 + 2);
    expectFail("-tests " + frac.string() + " -model sherritt", {frac.string(), "line 2, column test", "'11.5'"});

    // -score: a prediction file that repeats a test, predicts an unknown one, or leaves
    // a measured one out is refused; -allowMissing scores on the rows given, and says so
    const fs::path pred = dir()/"sherrittRows.csv";
    ASSERT_EQ(run("-tests " + tests + " -model sherritt -out " + pred.string()).rc, 0);
    const std::string p = text(pred);
    const std::size_t p2 = p.find('\n') + 1, p3 = p.find('\n', p2) + 1;
    const fs::path twice = dir()/"twice.csv", unknown = dir()/"unknown.csv", fewer = dir()/"fewer.csv";
    std::ofstream(twice) << p + p.substr(p2, p3 - p2);
    std::ofstream(unknown) << p + "9999,1.5\n";
    std::ofstream(fewer) << p.substr(0, p2) + p.substr(p3);
    const std::string sc = "-score -tests " + tests + " -predictions m=";
    expectFail(sc + twice.string(), {twice.string(), "line 71", "also on line 2"});
    expectFail(sc + unknown.string(), {unknown.string(), "test 9999 (line 71)", "not a test of"});
    expectFail(sc + fewer.string(), {fewer.string(), "no prediction for 1 measured test(s)", "(11)", "-allowMissing"});
    const fs::path csv = dir()/"fewerScores.csv";
    const CliRun ok = run(sc + fewer.string() + " -allowMissing -out " + csv.string());
    ASSERT_EQ(ok.rc, 0) << ok.out;
    EXPECT_NE(ok.out.find("m predicts 68 of 69 measured tests (-allowMissing)"), std::string::npos) << ok.out;
    EXPECT_EQ(overallScores(csv).at("m").first, 68);
    // an option given twice is refused, not the last one taken
    expectFail("-tests " + tests + " -tests " + tests + " -model sherritt", {"-tests", "given twice"});
}
