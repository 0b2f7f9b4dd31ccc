// Lee's App. 10.2.3 correlations: geometry hand values and limits
#include "drum/transport/compartment/compartmentCorrelations.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace drum;

TEST(LeeCorrelations, TipRadiusOfInvictaFlight)
{
    // Lee 2008 §4.2.3.1 helper values (data/lee_transition_points.csv): R_F = 2.22789 m
    EXPECT_NEAR(LeeFlightGeometry{}.tipRadius(), 2.22789, 5e-6);
    // L-shaped flight (alpha2 = 90 deg): R_F^2 = (R - s1)^2 + s2^2
    LeeFlightGeometry lShape;
    lShape.tipAngleDeg = 90.0;
    EXPECT_NEAR(lShape.tipRadius(), std::hypot(2.5 - 0.195, 0.183), 1e-12);
}

TEST(LeeCorrelations, ReleaseAngleAndPassiveTimeAreConsistent)
{
    const LeeCorrelationValues v = leeCorrelations(LeeFlightGeometry{}, 50.0, 1.0, 3.0, 940.0);
    // mafa = asin(h/2R_F) + pi/2 lies on the descending side (90..180 deg)
    EXPECT_NEAR(std::sin(v.releaseAngle - M_PI/2)*2.0*LeeFlightGeometry{}.tipRadius(), v.fallHeight, 1e-12);
    EXPECT_NEAR(v.flightTime + v.passiveTime, 20.0, 1e-12);   // one revolution at 3 rpm
    // §4.3 quotes h = 4.164 m, t_a = 0.824 s at phi = 50 (the correlations' values)
    EXPECT_NEAR(v.fallHeight, 4.164, 5e-4);
    EXPECT_NEAR(v.fallTime, 0.824, 5e-4);
}

TEST(LeeCorrelations, MoistureProfileEndsAndAngle)
{
    EXPECT_DOUBLE_EQ(leeMoistureProfile(0.02, 0.002, 1, 33), 0.02);
    EXPECT_NEAR(leeMoistureProfile(0.02, 0.002, 33, 33), 0.002, 1e-15);
    EXPECT_NEAR(leeSugarAngleOfRepose(0.02), 58.944, 1e-9);
}

TEST(LeeCorrelations, ForwardFractionScalesWithSliceCount)
{
    // C_F = C_F^G h sin(theta)/(L/N): doubling N doubles C_F
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    const auto a = leeSliceData(d, 10, {8.0, 0.2, 0.3});
    const auto b = leeSliceData(d, 20, {8.0, 0.2, 0.3});
    EXPECT_NEAR(b[0].slice.forwardFraction, 2.0*a[0].slice.forwardFraction, 1e-14);
    EXPECT_NEAR(a[0].slice.forwardFraction,
        0.3*a[0].correlations.fallHeight*std::sin(2.8*M_PI/180)/1.2, 1e-14);
}

TEST(LeeCorrelations, OutOfRangeInputThrows)
{
    EXPECT_THROW(leeCorrelations(LeeFlightGeometry{}, 10.0, 1.0, 3.0, 940.0), InputError);
    EXPECT_THROW(leeCorrelations(LeeFlightGeometry{}, 40.0, 1.5, 3.0, 940.0), InputError);
    EXPECT_THROW(leeCorrelations(LeeFlightGeometry{}, 40.0, 1.0, -3.0, 940.0), InputError);
}
