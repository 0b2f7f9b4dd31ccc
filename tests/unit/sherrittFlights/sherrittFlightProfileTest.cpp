// Sherritt 1991 flight table: interpolation, Eq 40 discharge rate, holdup as
// the integral of discharge (Eq 97), initial discharge angle, bad input.
#include "drum/flights/sherritt/sherrittFlightProfile.hpp"
#include "drum/flights/sherritt/sherrittFlightSurface.hpp"
#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace drum;

namespace
{
using drum::pi;
using drum::deg;

// A flight whose horizontal length falls linearly from 0.2 m at 60 deg to 0
// at 300 deg (a hand-checkable triangle)
SherrittFlightProfile triangle()
{
    return SherrittFlightProfile({60*deg, 300*deg}, {0.2, 0.0}, FlightSide::exterior, 1.0, 8, 2.0);
}

// Composite Simpson on a fine grid: an independent check of the exact integrals
template<class F>
double simpson(F f, double a, double b, int n = 20000)
{
    const double h = (b - a)/n;
    double s = f(a) + f(b);
    for (int i = 1; i < n; ++i)
    {
        s += (i % 2 ? 4 : 2)*f(a + i*h);
    }
    return s*h/3;
}
} // namespace

TEST(SherrittFlightProfile, InterpolatesAndExtrapolatesLinearly)
{
    const SherrittFlightProfile p({1.0, 2.0, 4.0}, {0.1, 0.3, 0.1}, FlightSide::exterior, 1.0, 4, 1.0);
    EXPECT_NEAR(p.horizontalLength(1.5), 0.2, 1e-15);
    EXPECT_NEAR(p.horizontalLength(3.0), 0.2, 1e-15);
    EXPECT_NEAR(p.horizontalLength(0.5), 0.0, 1e-15);   // extrapolated
    EXPECT_NEAR(p.horizontalLength(5.0), 0.0, 1e-15);
    EXPECT_NEAR(p.horizontalLength(6.0), -0.1, 1e-15);  // not clamped in the table
    EXPECT_DOUBLE_EQ(p.emptyAngle(), 2*pi);
}

TEST(SherrittFlightSurface, SurfaceLengthIsTableShiftedByReposeAndClamped)
{
    const auto p = triangle();
    const double phi = 40*deg;
    const SherrittFlightSurface s(p, phi);
    for (double t = 0; t <= 2*pi; t += 0.1)
    {
        EXPECT_NEAR(s.length(t), std::max(0.0, p.horizontalLength(t - phi)), 1e-14) << t;
    }
    // dm/dt = pi n rho_b l^2, Eq 40
    const double theta = 200*deg;
    const double l = p.horizontalLength(theta - phi);
    EXPECT_NEAR(s.dischargeRate(theta, 0.1, 1500), pi*0.1*1500*l*l, 1e-12);
}

TEST(SherrittFlightSurface, ExactIntegralsMatchQuadrature)
{
    const SherrittFlightProfile p({0, 1, 2.5, 4, 5.5, 6.3}, {0.0, 0.3, 0.1, 0.25, 0.05, 0.0},
        FlightSide::exterior, 1.0, 6, 1.0);
    const SherrittFlightSurface s(p, 35*deg);
    auto l = [&](double t) { return s.length(t); };
    const double a = 0.7;
    const double b = 5.9;
    // the integrands have kinks: Simpson converges slowly but surely
    EXPECT_NEAR(s.integralL2(a, b), simpson([&](double t) { return l(t)*l(t); }, a, b), 1e-6);
    EXPECT_NEAR(s.integralL3(a, b), simpson([&](double t) { return std::pow(l(t), 3); }, a, b), 1e-6);
    const double E = 2*pi;
    const double iter = simpson([&](double t) { return s.integralL2(t, E); }, a, b, 4000);
    EXPECT_NEAR(s.iteratedDischarge(a, b), iter, 1e-6);
}

TEST(SherrittFlightSurface, HoldupIsTheIntegralOfTheDischargeRate)
{
    // h(theta) rho_b must equal the mass shed from theta to 2 pi:
    // int dm/dt dt with dt = dtheta/(2 pi n)
    const auto p = triangle();
    const SherrittFlightSurface s(p, 38*deg);
    const double n = 5.7/60;
    const double rhoB = 1517;
    for (double theta : {100*deg, 180*deg, 250*deg, 330*deg})
    {
        const double shed = simpson
        (
            [&](double t) { return s.dischargeRate(t, n, rhoB)/(2*pi*n); }, theta, 2*pi
        );
        EXPECT_NEAR(s.holdupMass(theta, rhoB), shed, 1e-6*shed + 1e-12) << theta;
        // hand value: l(t) = 0.2 (1 - (t - phi - 60deg)/240deg) on the arc
        EXPECT_GT(s.holdupVolume(theta), 0);
    }
    // the triangle holds 1/2 * int l^2 = 1/2 * 0.2^2 * (240 deg)/3 at theta = 60 deg + phi
    const double full = 0.5*0.04*(240*deg)/3;
    EXPECT_NEAR(s.holdupVolume(60*deg + 38*deg), full, 1e-14);
}

TEST(SherrittFlightSurface, InitialDischargeAngleInvertsHoldup)
{
    const auto p = triangle();
    const SherrittFlightSurface s(p, 40*deg);
    for (double theta : {120*deg, 200*deg, 270*deg, 320*deg})
    {
        const double h = s.holdupVolume(theta);
        EXPECT_NEAR(s.initialDischargeAngle(h), theta, 1e-9);
    }
    EXPECT_THROW(s.initialDischargeAngle(-1e-3), InputError);
    EXPECT_THROW(s.initialDischargeAngle(1.0), InputError);
}

TEST(SherrittFlightSurface, InteriorFlightDischargesUpToPi)
{
    const SherrittFlightProfile p({-pi, pi}, {0.1, 0.1}, FlightSide::interior, 0.6, 6, 1.0);
    const SherrittFlightSurface s(p, 45*deg);
    EXPECT_DOUBLE_EQ(s.emptyAngle(), pi);
    EXPECT_NEAR(s.holdupVolume(0.0), 0.5*0.01*pi, 1e-14);
    EXPECT_EQ(s.dischargeRate(1.1*pi, 0.1, 200), 0.0);  // past the empty angle
    EXPECT_NEAR(s.initialDischargeAngle(0.5*0.01*pi/2), pi/2, 1e-9);
}

TEST(SherrittFlightProfile, RefusesBadInputNamingTheEntry)
{
    auto message = [](auto f) {
        try { f(); } catch (const InputError& e) { return std::string(e.what()); }
        return std::string("no error");
    };
    const std::string neg = message([] {
        SherrittFlightProfile({0, 1, 2}, {0.1, -0.2, 0.1}, FlightSide::exterior, 1, 4, 1);
    });
    EXPECT_NE(neg.find("flight table length[1]"), std::string::npos) << neg;
    EXPECT_NE(neg.find("[0, inf)"), std::string::npos) << neg;

    const std::string order = message([] {
        SherrittFlightProfile({0, 2, 1}, {0.1, 0.2, 0.1}, FlightSide::exterior, 1, 4, 1);
    });
    EXPECT_NE(order.find("flight table angle[2]"), std::string::npos) << order;

    const auto p = triangle();
    const std::string phiLow = message([&] { SherrittFlightSurface(p, -0.1); });
    EXPECT_NE(phiLow.find("repose angle"), std::string::npos) << phiLow;
    EXPECT_NE(phiLow.find("(0, 90)"), std::string::npos) << phiLow;
    EXPECT_THROW(SherrittFlightSurface(p, 0.5*pi), InputError);
    EXPECT_THROW(SherrittFlightSurface(p, 100*deg), InputError);

    const std::string outside = message([&] { p.checkTipsAgainst(0.9, "exterior tip diameter"); });
    EXPECT_NE(outside.find("exterior tip diameter"), std::string::npos) << outside;
    EXPECT_NE(outside.find("(0, 0.9)"), std::string::npos) << outside;
    EXPECT_NO_THROW(p.checkTipsAgainst(1.2, "exterior tip diameter"));
    EXPECT_THROW(SherrittFlightProfile({0, 1}, {0.1, 0.1}, FlightSide::exterior, -1, 4, 1), InputError);
    EXPECT_THROW(SherrittFlightProfile({0, 1}, {0.1, 0.1}, FlightSide::exterior, 1, 0, 1), InputError);
    EXPECT_THROW(SherrittFlightProfile({0, 1}, {0.1}, FlightSide::exterior, 1, 4, 1), InputError);
}
