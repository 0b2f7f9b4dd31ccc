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

//- The Invicta flight's unloading over one of n slices of the 12 m drum (phi 40 deg)
UnloadingModel invictaSliceUnloading(int n)
{
    UnloadingSettings us;
    us.bulkDensity = 940;
    us.speedRpm = 3;
    us.flightLength = 12.0/n;
    us.drumSlopeDeg = 2.8;
    return UnloadingModel(LeeFlight(FlightGeometry{2.5, 0.195, 0.183, 90.0, 117.0, 28}, 40.0), us);
}
} // namespace

TEST(CompartmentFlightModel, StillGasGivesTheSlopeStepOfEq37)
{
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    const int n = 30;
    const auto s = flightModelSliceData(d, n, partition(0.0));
    // Independent: the flight model's own mass-averaged fall height
    const UnloadingModel um = invictaSliceUnloading(n);
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

TEST(CompartmentFlightModel, BedFilledFlightsRideTheirLoadOverTheirFlow)
{
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    const int n = 10;
    FlightModelPartition p = partition(1.0);
    const auto mirror = flightModelSliceData(d, n, p);
    p.holdup = FlightHoldup::bedFilled;
    p.pickupDeg = 0.0;
    const auto filled = flightModelSliceData(d, n, p);
    const UnloadingModel um = invictaSliceUnloading(n);
    const LeeFlight& f = um.flight();
    EXPECT_NEAR(filled[0].slice.designLoad, um.bedFilledLoad(0.0), 1e-9*um.bedFilledLoad(0.0));
    EXPECT_NEAR(filled[0].slice.passiveTime, um.bedFilledLoad(0.0)/um.curtainFlow(), 1e-12);
    // the release at the design load is the flights' flow in both pictures,
    // to Eq 3.4's tip-offset difference for Lee's mirrored load
    EXPECT_NEAR(filled[0].slice.designLoad/filled[0].slice.passiveTime, um.curtainFlow(), 1e-9*um.curtainFlow());
    EXPECT_NEAR(mirror[0].slice.designLoad/mirror[0].slice.passiveTime/um.curtainFlow(), 1.0, 0.15);
    // the curtains themselves (C_F, C_B, fall) do not depend on the holdup picture
    EXPECT_DOUBLE_EQ(filled[0].slice.forwardFraction, mirror[0].slice.forwardFraction);
    EXPECT_DOUBLE_EQ(filled[0].slice.activeTime, mirror[0].slice.activeTime);
    // the kilning bed rolls over the full pockets: in the flight-tip circle
    EXPECT_DOUBLE_EQ(filled[0].kilnBedDiameter, 2.0*f.tipRadius());
    EXPECT_DOUBLE_EQ(mirror[0].kilnBedDiameter, 5.0);
}

TEST(CompartmentFlightModel, KilnBedSpanIsTheSegmentAtPhi)
{
    LeeDryer d;
    d.constantPhiDeg = 40.0;
    FlightModelPartition p = partition(1.0);
    p.holdup = FlightHoldup::bedFilled;
    const auto s = flightModelSliceData(d, 4, p);
    const double dz = 3.0, D = s[0].kilnBedDiameter;
    // a bed of fill angle 60 deg: area D^2/8 (beta - sin beta)
    const double beta = M_PI/3;
    const double mass = 940*dz*D*D/8*(beta - std::sin(beta));
    const auto spans = kilnBedSpansDeg(d, s, {mass, 0.0, mass, 1e6}, dz);
    EXPECT_NEAR(spans[0].first, 10.0, 1e-9);
    EXPECT_NEAR(spans[0].second, 70.0, 1e-9);
    EXPECT_NEAR(spans[1].first, 40.0, 1e-12);     // no bed: the span closes at phi
    EXPECT_NEAR(spans[1].second, 40.0, 1e-12);
    // a bed past the tip horizontal is held there
    const double psi0 = LeeFlight(FlightGeometry{2.5, 0.195, 0.183, 90.0, 117.0, 28}, 40.0).curtainStartDeg();
    EXPECT_NEAR(spans[3].second, psi0, 1e-12);
    EXPECT_LT(spans[3].first, spans[3].second);
    // the spans feed back: pockets under a 60 deg bed add 60 deg of full flights
    p.bedSpanDeg = {spans[0], spans[0], spans[0], spans[0]};
    const auto withBed = flightModelSliceData(d, 4, p);
    p.bedSpanDeg.clear();
    p.pickupDeg = 70.0;
    EXPECT_GT(withBed[0].slice.designLoad, flightModelSliceData(d, 4, p)[0].slice.designLoad);
    p.bedSpanDeg = {spans[0]};
    EXPECT_THROW(flightModelSliceData(d, 4, p), InputError);
}
