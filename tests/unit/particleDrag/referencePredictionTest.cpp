// The lone-particle model against the reference predictions of
// data/windtunnel_reference_predictions.csv (Sherritt's ADVANCE.C
// falladvance(), computed independently): methods (a) V = V_g and
// (b) V = Eq 142 ratio x V_g, on every shared wind-tunnel test.
#include "drum/io/projectPaths.hpp"
#include "particleDrag/gasProperties.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "particleDrag/sheetVelocity.hpp"

#include <libfccp/csv.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

using namespace particleDrag;

namespace
{


struct SizeClass
{
    double diameter;  // m
    double fraction;  // mass fraction, renormalised
};

struct Material
{
    double density = 0;
    std::vector<SizeClass> classes;
};

// Table A.1 with the reference's closure of the open bins (README 1)
std::map<std::string, Material> readMaterials()
{
    io::CSVReader<5, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in
    (
        (drum::dataDir()/"windtunnel_materials.csv").string()
    );
    in.read_header(io::ignore_extra_column, "material", "particle_density_kg_m3",
                   "psd_lower_um", "psd_upper_um", "psd_wt_pct");
    std::map<std::string, Material> materials;
    std::string name, lower, upper;
    double density, pct;
    while (in.read_row(name, density, lower, upper, pct))
    {
        const double lo = lower.empty() ? 37.0 : std::stod(lower);
        const double hi = upper.empty() ? 4760.0 : std::stod(upper);
        Material& m = materials[name];
        m.density = density;
        m.classes.push_back({std::sqrt(lo*hi)*1e-6, pct});
    }
    for (auto& kv : materials)
    {
        double sum = 0;
        for (const auto& c : kv.second.classes) sum += c.fraction;
        for (auto& c : kv.second.classes) c.fraction /= sum;
    }
    return materials;
}

double bulkAdvance(const Material& m, double V, double y)
{
    const DragLaw law = dragLawFromName("SchillerNaumann");
    const Gas air = Gas::air(20.0);
    double sum = 0;
    for (const auto& c : m.classes)
    {
        sum += c.fraction*loneParticleAdvance(law, Particle{c.diameter, m.density}, air, V, y);
    }
    return sum;
}

} // namespace

TEST(ReferencePredictions, AirAt20C)
{
    // README: rho_g = 1.2086 kg/m3 and mu_g = 1.8194e-5 Pa s from airdens/airvisc
    EXPECT_NEAR(airDensity(20.0), 1.2086, 5e-5);
    EXPECT_NEAR(airViscosity(20.0), 1.8194e-5, 5e-9);
}

TEST(ReferencePredictions, AirAtAnotherPressureIsAnIdealGas)
{
    // density in proportion to the pressure, viscosity unchanged
    EXPECT_DOUBLE_EQ(airDensity(20.0, 89.0), airDensity(20.0)*89.0/101.325);
    EXPECT_DOUBLE_EQ(airDensity(20.0, 101.325), airDensity(20.0));
    EXPECT_DOUBLE_EQ(Gas::air(80.0, 50.0).viscosity, Gas::air(80.0).viscosity);
    EXPECT_DOUBLE_EQ(Gas::air(80.0, 50.0).density, airDensity(80.0)*50.0/101.325);
    EXPECT_THROW(airDensity(20.0, 0.0), std::invalid_argument);
    EXPECT_THROW(airDensity(20.0, -1.0), std::invalid_argument);
}

TEST(ReferencePredictions, IsolatedAndSherrittCorrection)
{
    const auto materials = readMaterials();
    ASSERT_EQ(materials.size(), 3u);

    std::map<int, std::array<double, 4>> tests;  // Vg, spill, L, y
    {
        io::CSVReader<6> in((drum::dataDir()/"windtunnel_tests.csv").string());
        in.read_header(io::ignore_extra_column, "test", "air_velocity_m_s",
                       "spill_rate_kg_m_s", "flight_length_m", "fall_height_m", "material");
        int test;
        double Vg, spill, L, y;
        std::string material;
        while (in.read_row(test, Vg, spill, L, y, material))
        {
            tests[test] = {Vg, spill, L, y};
        }
    }

    io::CSVReader<5> in((drum::dataDir()/"windtunnel_reference_predictions.csv").string());
    in.read_header(io::ignore_extra_column, "test", "material", "fall_height_m",
                   "pred_a_m", "pred_b_m");
    int test, rows = 0;
    std::string material;
    double y, predA, predB;
    while (in.read_row(test, material, y, predA, predB))
    {
        ASSERT_TRUE(tests.count(test)) << "test " << test;
        const auto& t = tests.at(test);
        const Material& m = materials.at(material);
        EXPECT_NEAR(t[3], y, 1e-9);
        // Printed to 4 decimals
        EXPECT_NEAR(bulkAdvance(m, t[0], y), predA, 1.5e-4) << "test " << test << " (a)";
        const double ratio = sherrittSheetVelocityRatio(y, t[1], t[2]);
        EXPECT_NEAR(bulkAdvance(m, ratio*t[0], y), predB, 1.5e-4) << "test " << test << " (b)";
        ++rows;
    }
    EXPECT_EQ(rows, 69);
}
