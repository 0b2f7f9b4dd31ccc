// Sherritt (2001) dense-bed axial dispersion D_z (Eq 51 / Eq 84): constants
// against the shared CSV (Table 3-3), the thesis base case (Table 5-4, Black's
// Run 33: 3.88e-5 m2/s), the regime boundaries, and the scatter of the
// correlation over the tabulated experiments it was fitted to.
#include "drum/io/projectPaths.hpp"
#include "drum/io/csv.hpp"
#include "drum/io/inputError.hpp"
#include "drum/transport/axialDispersion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace drum;

namespace
{


} // namespace


TEST(AxialDispersion, ConstantsAreTable33)
{
    io::CSVReader<6> in((drum::dataDir()/"sherritt2001_correlation_constants.csv").string());
    in.read_header(io::ignore_extra_column, "bed_behaviour", "k", "a_speed_exp", "b_diameter_exp",
                   "c_particle_exp", "d_fill_exp");
    std::string name;
    double k, a, b, c, d;
    int n = 0;
    while (in.read_row(name, k, a, b, c, d))
    {
        const DispersionConstants got =
            name == "all_modes" ? sherritt2001AllModes()
          : name == "slumping" ? sherritt2001Constants(BedRegime::slumping)
          : name == "rolling_cascading" ? sherritt2001Constants(BedRegime::rollingCascading)
          : sherritt2001Constants(BedRegime::cataracting);
        EXPECT_DOUBLE_EQ(got.k, k) << name;
        EXPECT_DOUBLE_EQ(got.a, a) << name;
        EXPECT_DOUBLE_EQ(got.b, b) << name;
        EXPECT_DOUBLE_EQ(got.c, c) << name;
        EXPECT_DOUBLE_EQ(got.d, d) << name;
        ++n;
    }
    EXPECT_EQ(n, 4);
}


TEST(AxialDispersion, BaseCaseOfChapter5AndRegimes)
{
    // Table 5-2/5-4 base case: 19.2 % of critical speed, d_p 7 mm, X 0.24,
    // D_z 3.88e-5 m2/s (Black's Run 33; Sherritt 2001 Eq 84 with 7 mm)
    AxialDispersionInput in;
    in.drumDiameter = 0.45;
    in.particleDiameter = 0.007;
    in.fill = 0.24;
    in.speed = 0.192*criticalSpeed(in.drumDiameter);
    const AxialDispersionResult r = sherritt2001AxialDispersion(in);
    EXPECT_EQ(r.regime, BedRegime::rollingCascading);
    EXPECT_NEAR(r.speedRatio, 0.192, 1e-12);
    EXPECT_NEAR(r.Dz, 3.88e-5, 0.005*3.88e-5);

    EXPECT_EQ(bedRegime(0.01), BedRegime::slumping);
    EXPECT_EQ(bedRegime(0.1), BedRegime::rollingCascading);
    EXPECT_EQ(bedRegime(0.5), BedRegime::cataracting);
    EXPECT_EQ(bedRegime(1.0), BedRegime::centrifuging);
    // n_c = sqrt(g/R)/(2 pi), Eq 1
    EXPECT_NEAR(criticalSpeed(0.45), std::sqrt(9.81/0.225)/(2*M_PI), 1e-3);
}


TEST(AxialDispersion, ScatterOverTheFittedExperimentsIsAboutAFactorTwo)
{
    // Rows the regression used (X < 0.5), rolling/cascading regime: the
    // thesis quotes a scatter of about x2 for the correlation
    io::CSVReader<6, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(
        (drum::dataDir()/"sherritt2001_dispersion.csv").string());
    in.read_header(io::ignore_extra_column, "drum_diameter_m", "particle_diameter_numeric_mm",
                   "Dz_m2_s", "fill_fraction_X", "n_over_nc", "regime_by_speed");
    double D, dp, Dz, X, ratio;
    std::string regime;
    int n = 0, within2 = 0;
    double sumLn2 = 0;
    while (in.read_row(D, dp, Dz, X, ratio, regime))
    {
        if (regime != "rolling_cascading" || !(X < 0.5) || !(Dz > 0) || !(dp > 0))
        {
            continue;
        }
        AxialDispersionInput q;
        q.drumDiameter = D;
        q.particleDiameter = dp*1e-3;
        q.fill = X;
        q.speed = ratio*criticalSpeed(D);
        const double e = std::log(sherritt2001AxialDispersion(q).Dz/Dz);
        sumLn2 += e*e;
        within2 += std::abs(e) <= std::log(2.0);
        ++n;
    }
    ASSERT_GE(n, 10);
    const double rms = std::sqrt(sumLn2/n);
    std::printf("D_z rolling/cascading: %d rows, RMS ln %.3f, %d within x2\n", n, rms, within2);
    EXPECT_LT(rms, std::log(2.5));
    EXPECT_GE(within2, 0.6*n);
}

TEST(AxialDispersion, SharedInputsForBothTransportModels)
{
    // d_p: Sauter mean 1/sum(x_i/d_i) of the sieve sizes times the sphericity
    const double d32 = 1.0/(0.25/100e-6 + 0.75/400e-6);
    EXPECT_NEAR(dispersionParticleDiameter({100e-6, 400e-6}, {25, 75}, 0.8), 0.8*d32, 1e-15);
    // X of a bed of 0.5 m3/m in a 2 m drum: 0.5/pi
    EXPECT_NEAR(bedFillFraction(0.5, 2.0), 0.5/3.14159265358979323846, 1e-15);
    EXPECT_THROW(bedFillFraction(0.5, 0.0), InputError);
    AxialDispersionInput in{0.45, 12.1/60, 3e-3, 0.24, false};
    const AxialDispersionResult r = sherritt2001AxialDispersion(in);
    const std::string note = describeAxialDispersion(r, in);
    EXPECT_NE(note.find("rolling/cascading"), std::string::npos) << note;
    EXPECT_NE(note.find("3000 um"), std::string::npos) << note;
}
