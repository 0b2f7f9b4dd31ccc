// Flight-model partition: limits against hand values from the flight model
#include "drum/transport/compartment/compartmentFlightModel.hpp"
#include "drum/flights/unloadingModel.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace drum;

namespace
{
FlightModelPartition partition(double vg)
{
    FlightModelPartition p;
    p.drift = makeDriftModel("isolated", particleDrag::Gas::air(20.0));
    p.gasVelocity = vg;
    p.sizes = {850e-6};
    p.fractions = {1.0};
    p.particleDensity = 1590;
    p.flightAxialLength = 1.133;
    return p;
}
} // namespace

TEST(CompartmentFlightModel, StillGasGivesTheSlopeStepOfEq37)
{
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    const int n = 30;
    const auto s = flightModelSliceData(d, n, partition(0.0));
    // Independent: the flight model's own mass-averaged fall height
    FlightGeometry g{2.5, 0.195, 0.183, 90.0, 117.0, 28};
    UnloadingSettings us;
    us.bulkDensity = 940;
    us.speedRpm = 3;
    us.flightLength = 12.0/n;
    us.drumSlopeDeg = 2.8;
    const UnloadingModel um(LeeFlight(g, 40.0), us);
    const double dL = 12.0/n;
    // C_F^0 = h sin(theta)/dL (Eq 3.7), no backmixing without gas
    EXPECT_NEAR(s[0].slice.forwardFraction, um.meanFallHeight()*std::sin(2.8*M_PI/180)/dL, 0.01*s[0].slice.forwardFraction);
    EXPECT_DOUBLE_EQ(s[0].slice.backFraction, 0.0);
    EXPECT_NEAR(s[0].slice.designLoad, um.designLoad(), 1e-9);
    EXPECT_NEAR(s[0].slice.passiveTime, (2*um.meanReleaseAngleDeg() - 180)/18.0, 1e-12);   // Eq 3.4, 3 rpm = 18 deg/s
    EXPECT_NEAR(s[0].slice.activeTime, um.meanFallTime(), 1e-12);
}

TEST(CompartmentFlightModel, CountercurrentGasMovesSolidsBack)
{
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    const auto still = flightModelSliceData(d, 10, partition(0.0));
    const auto windy = flightModelSliceData(d, 10, partition(2.0));
    EXPECT_LT(windy[0].slice.forwardFraction, still[0].slice.forwardFraction);
    EXPECT_GT(windy[0].slice.backFraction, 0.0);
    // Cocurrent gas pushes forward
    FlightModelPartition co = partition(2.0);
    co.counterCurrent = false;
    EXPECT_GT(flightModelSliceData(d, 10, co)[0].slice.forwardFraction, still[0].slice.forwardFraction);
}

TEST(CompartmentFlightModel, TooManySlicesViolatesNearestNeighbourRule)
{
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    EXPECT_THROW(flightModelSliceData(d, 200, partition(0.0)), InputError);
    FlightModelPartition none = partition(0.0);
    none.drift = nullptr;
    EXPECT_THROW(flightModelSliceData(d, 30, none), InputError);
}
