#include "drum/flights/angleOfRepose.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
double spread(double mu, double fr)
{
    double lo = 1e9, hi = -1e9;
    for (int i = 0; i <= 3600; ++i)
    {
        const double p = drum::schofieldGlikinAngleDeg(mu, fr, i*0.1);
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    }
    return hi - lo;
}
} // namespace


TEST(AngleOfRepose, SchofieldGlikinSpreadMatchesSherritt)
{
    // Sherritt 1991 §3.1.4: 4.6 deg at Fr = 0.04, 0.3 deg at Fr = 0.0025
    // (hand recheck 4.58 / 0.29, independent of mu)
    for (double mu : {0.5, 0.8, 1.2})
    {
        EXPECT_NEAR(spread(mu, 0.04), 4.58, 0.02);
        EXPECT_NEAR(spread(mu, 0.0025), 0.29, 0.01);
    }
    // No rotation: phi = atan(mu)
    EXPECT_NEAR(drum::schofieldGlikinAngleDeg(0.7, 0.0, 123.0), std::atan(0.7)*180/M_PI, 1e-12);
    EXPECT_NEAR(drum::drumFroudeNumber(2.5, 3.0), 2.5*std::pow(0.1*M_PI, 2)/9.81, 1e-15);
    EXPECT_NEAR(drum::sherrittThetaDeg(90.0), 180.0, 1e-12);
    EXPECT_NEAR(drum::sherrittThetaDeg(270.0), 0.0, 1e-12);
}


TEST(AngleOfRepose, BrittonMoistureRelation)
{
    // Lee 2008 Eq 7.2 with the code's w = 0.02 -> 0.002 kg/kg: 58.9 and 36.9 deg
    EXPECT_NEAR(drum::brittonMoistureAngleDeg(0.02), 58.944, 1e-9);
    EXPECT_NEAR(drum::brittonMoistureAngleDeg(0.002), 36.9444, 1e-9);
    EXPECT_THROW(drum::brittonMoistureAngleDeg(-0.01), drum::InputError);
    EXPECT_THROW(drum::brittonMoistureAngleDeg(0.05), drum::InputError);
    // Eq 7.3 ends and geometric middle
    EXPECT_NEAR(drum::moistureProfile(1, 33, 0.02, 0.002), 0.02, 1e-15);
    EXPECT_NEAR(drum::moistureProfile(33, 33, 0.02, 0.002), 0.002, 1e-15);
    EXPECT_NEAR(drum::moistureProfile(17, 33, 0.02, 0.002), std::sqrt(0.02*0.002), 1e-15);
}
