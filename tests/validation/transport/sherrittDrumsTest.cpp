// Qualitative checks of Sherritt 1991 Ch 5 (§5.1). The
// thesis gives no plotted numbers; flight sizes are our assumptions
// (cases/sherrittDrums/README.md). The flights are built as drumSolver
// builds them from cases/sherrittDrums/*/drumDict (drum::buildSherrittFlight).
#include "drum/flights/sherritt/sherrittFlightSpec.hpp"
#include "drum/transport/twoPhase/twoPhaseModel.hpp"
#include "drum/numerics/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace drum;

namespace
{
using drum::pi;
using drum::deg;
} // namespace

TEST(SherrittDrums, SheikhTwelve90DegFlightsAirborneShares)
{
    // Sheikh: 0.385 m x 2.10 m, 12 two-sided 90 deg flights, sand (Table 5.1)
    TwoPhaseCase c;
    c.name = "sheikh";
    c.drum = {0.385, 2.10, 1*deg, 5.7/60, 0.0};
    SherrittFlightSpec f;
    f.type = SherrittFlightType::twoSided;
    f.count = 12;
    f.baseLength = 0.04;
    f.tipLength = 0.04;
    f.tipAngle = 90*deg;
    c.exterior = buildSherrittFlight(f, FlightSide::exterior, 0.385, 2.10, 1*deg);
    c.material = {2650, 1517, 35.69*deg, 1.0,
        {600e-6, 427e-6, 327e-6, 256e-6, 168e-6, 88e-6}, {11.6, 21.6, 12.0, 29.6, 22.1, 3.2}};
    const TwoPhaseModel m(c);
    for (double ti : {200*deg, 240*deg, 270*deg})
    {
        const auto s = m.atDischargeAngle(ti);
        ASSERT_TRUE(s.valid);
        const double h1 = s.airborneHoldup/s.holdup;
        const double f1 = s.airborneFlow/s.feedRate;
        // thesis: "only about 10%" airborne holdup; about 3/4 of the flow airborne
        EXPECT_GT(h1, 0.02) << ti/deg;
        EXPECT_LT(h1, 0.15) << ti/deg;
        EXPECT_GT(f1, 0.6) << ti/deg;
        EXPECT_LT(f1, 0.95) << ti/deg;
        std::printf("Sheikh 12x90 theta_i %.0f deg: H1/H = %.3f, F1/F0 = %.3f\n", ti/deg, h1, f1);
        // in the underloaded range most holdup sits in non-discharging flights
        EXPECT_GT(s.nonDischargingHoldup, s.dischargingHoldup);
    }
    // holdup follows from geometry alone: independent of incline
    auto c3 = c;
    c3.drum.slope = 3*deg;
    EXPECT_NEAR(TwoPhaseModel(c3).holdupAt(230*deg), m.holdupAt(230*deg), 1e-12);
}

TEST(SherrittDrums, KellyCountercurrentAirRaisesHoldup)
{
    // Kelly: 0.305 m x 1.69 m, 8 EAD flights, pumice (Table 5.2), 2 deg, 8 rpm
    TwoPhaseCase c;
    c.name = "kelly";
    c.drum = {0.305, 1.69, 2*deg, 8.0/60, 0.0};
    SherrittFlightSpec f;
    f.type = SherrittFlightType::ead;
    f.count = 8;
    f.radius = 0.04;
    f.designRepose = 45.6*deg;
    c.exterior = buildSherrittFlight(f, FlightSide::exterior, 0.305, 1.69, 1*deg);
    c.material = {1147, 591, 45.6*deg, 1.0, {1750e-6}, {1.0}};
    const double F0 = 0.005;
    const auto still = TwoPhaseModel(c).solveConstantHoldup(F0).front();
    c.gas = {0.02, 20, GasFlow::countercurrent};
    const auto air = TwoPhaseModel(c).solveConstantHoldup(F0).front();
    std::printf("Kelly EAD: holdup %.3f kg no air, %.3f kg countercurrent air; T %.0f / %.0f s\n",
        still.holdupMass, air.holdupMass, still.meanResidenceTime, air.meanResidenceTime);
    EXPECT_GT(air.holdupMass, still.holdupMass);
}
