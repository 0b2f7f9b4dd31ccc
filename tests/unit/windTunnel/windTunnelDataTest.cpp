// Reading Sherritt's wind-tunnel tables, and refusing malformed ones
#include "drum/io/projectPaths.hpp"
#include "drum/io/inputError.hpp"
#include "scoring/windTunnelData.hpp"
#include "expectInputError.hpp"

#include "particleDrag/loneParticleFall.hpp"
#include "particleDrag/sheetVelocity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

using namespace drum;
namespace fs = std::filesystem;

namespace
{


// A scratch file with the given text, removed at scope exit; named by the
// process and a counter (CTest runs each test in its own process, two at a
// time: an unseeded rand() gave both the same name)
struct TempCsv
{
    fs::path path;
    explicit TempCsv(const std::string& text)
    :
        path(fs::temp_directory_path()
           / ("windTunnelTest_" + std::to_string(::getpid()) + "_" + std::to_string(next()) + ".csv"))
    {
        std::ofstream(path) << text;
    }
    ~TempCsv() { fs::remove(path); }
    static int next() { static int n = 0; return ++n; }
};

} // namespace

TEST(WindTunnelData, ReadsSharedTables)
{
    const auto materials = readWindTunnelMaterials(drum::dataDir()/"windtunnel_materials.csv");
    ASSERT_EQ(materials.size(), 3u);
    const auto& sand = materials.at("sand");
    EXPECT_DOUBLE_EQ(sand.particleDensity, 2650.0);
    ASSERT_EQ(sand.classes.size(), 7u);
    // Open top bin closed at 4760 um: geometric mean 3366 um
    EXPECT_NEAR(sand.classes.front().diameter, std::sqrt(2380.0*4760.0)*1e-6, 1e-12);
    EXPECT_NEAR(sand.classes.back().diameter, std::sqrt(37.0*74.0)*1e-6, 1e-10);
    double sum = 0;
    for (const auto& c : sand.classes) sum += c.massFraction;
    EXPECT_NEAR(sum, 1.0, 1e-12);

    const auto tests = readWindTunnelTests(drum::dataDir()/"windtunnel_tests.csv", materials);
    EXPECT_EQ(tests.size(), 69u);
    for (const auto& t : tests)
    {
        EXPECT_TRUE(t.fallHeight == 10.3 || t.fallHeight == 6.6) << t.test;
    }
    EXPECT_EQ(readMeasuredAdvance(drum::dataDir()/"windtunnel_tests.csv").size(), 69u);
}

TEST(WindTunnelData, TestReaderIgnoresTheMeasuredAdvance)
{
    // A tests file without any measured column is complete input
    const auto materials = readWindTunnelMaterials(drum::dataDir()/"windtunnel_materials.csv");
    TempCsv f("test,material,air_velocity_m_s,spill_rate_kg_m_s,flight_length_m,fall_height_m\n"
              "1,sand,4.0,24.0,1.0,10.3\n");
    const auto tests = readWindTunnelTests(f.path, materials);
    ASSERT_EQ(tests.size(), 1u);
    EXPECT_DOUBLE_EQ(tests[0].spillRate, 24.0);
}

TEST(WindTunnelData, MalformedFilesAreRefusedNamingTheProblem)
{
    const auto materials = readWindTunnelMaterials(drum::dataDir()/"windtunnel_materials.csv");
    const std::string header =
        "test,material,air_velocity_m_s,spill_rate_kg_m_s,flight_length_m,fall_height_m\n";

    {
        TempCsv f(header + "7,granite,4.0,24.0,1.0,10.3\n");
        const auto msg = expectInputError([&] { readWindTunnelTests(f.path, materials); });
        EXPECT_NE(msg.find("unknown material 'granite'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("test 7"), std::string::npos) << msg;
        EXPECT_NE(msg.find(f.path.string()), std::string::npos) << msg;
    }
    {
        TempCsv f(header + "8,sand,-4.0,24.0,1.0,10.3\n");
        const auto msg = expectInputError([&] { readWindTunnelTests(f.path, materials); });
        EXPECT_NE(msg.find("air_velocity_m_s"), std::string::npos) << msg;
        EXPECT_NE(msg.find("allowed range"), std::string::npos) << msg;
    }
    {
        TempCsv f(header + "9,sand,4.0,abc,1.0,10.3\n");
        const auto msg = expectInputError([&] { readWindTunnelTests(f.path, materials); });
        EXPECT_NE(msg.find("spill_rate_kg_m_s"), std::string::npos) << msg;
        EXPECT_NE(msg.find("not a number"), std::string::npos) << msg;
    }
    {
        // A column missing from the header
        TempCsv f("test,material,air_velocity_m_s,flight_length_m,fall_height_m\n1,sand,4,1,10.3\n");
        const auto msg = expectInputError([&] { readWindTunnelTests(f.path, materials); });
        EXPECT_NE(msg.find("spill_rate_kg_m_s"), std::string::npos) << msg;
    }
    {
        // Truncated row
        TempCsv f(header + "10,sand,4.0\n");
        const auto msg = expectInputError([&] { readWindTunnelTests(f.path, materials); });
        EXPECT_NE(msg.find("malformed CSV"), std::string::npos) << msg;
    }
    {
        TempCsv f(header);
        const auto msg = expectInputError([&] { readWindTunnelTests(f.path, materials); });
        EXPECT_NE(msg.find("no test rows"), std::string::npos) << msg;
    }
    const auto msg = expectInputError([&] { readWindTunnelTests("/nonexistent/tests.csv", materials); });
    EXPECT_NE(msg.find("file not found"), std::string::npos) << msg;
}

TEST(WindTunnelData, MeasuredColumnsAndTheTestsThatDidNotMeasureThem)
{
    // the shared rows: every test has its advance, 67 of 69 their V_c (Eq 141)
    const fs::path data = drum::dataDir()/"windtunnel_tests.csv";
    EXPECT_EQ(readMeasured(data, "mean_advance_m").size(), 69u);
    const auto vc = readMeasured(data, "vc_m_s", true);
    EXPECT_EQ(vc.size(), 67u);
    EXPECT_DOUBLE_EQ(vc.at(26), 0.66);   // Table A.2, test 26
    EXPECT_EQ(vc.count(73) + vc.count(74), 0u);   // printed without V_c

    TempCsv f("test,mean_advance_m,vc_m_s\n1,0.5,0.3\n2,0.7,\n");
    EXPECT_EQ(readMeasured(f.path, "vc_m_s", true).size(), 1u);
    // an empty cell is an error unless the column may go unmeasured
    const auto msg = expectInputError([&] { readMeasured(f.path, "vc_m_s"); });
    EXPECT_NE(msg.find("vc_m_s"), std::string::npos) << msg;
    EXPECT_NE(msg.find("not a number"), std::string::npos) << msg;
    EXPECT_NE(msg.find(f.path.string()), std::string::npos) << msg;
    const auto missing = expectInputError([&] { readMeasured(f.path, "drift_m"); });
    EXPECT_NE(missing.find("drift_m"), std::string::npos) << missing;
}
