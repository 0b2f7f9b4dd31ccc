// Flight-table generators: the tabulated horizontal lengths against
// geometry computed independently (closed forms, shoelace areas).
#include "drum/flights/sherritt/sherrittFlightShapes.hpp"
#include "drum/flights/sherritt/sherrittFlightSurface.hpp"
#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace drum;

namespace
{
using drum::pi;
using drum::deg;

Eigen::Vector2d world(const Eigen::Vector2d& p, double theta)
{
    return {p.x()*std::cos(theta) + p.y()*std::sin(theta), -p.x()*std::sin(theta) + p.y()*std::cos(theta)};
}
} // namespace

TEST(SherrittFlightShapes, EadFlightGivesConstantDischargeOverItsArc)
{
    // Kelly's drum: 0.305 m, 8 EAD flights; design angle 45.6 deg
    const double phi = 45.6*deg;
    const double r = 0.05;
    const auto shape = eadFlightShape(0.305, r, phi, 0, 720);  // fine arc: chords within 5e-6 of r
    EXPECT_NEAR(shape.tipDiameter(), 0.305 - 2*r, 1e-12);
    for (bool interference : {false, true})
    {
        const auto prof = tabulateSherrittFlight(shape, 8, 1.69, 0.5*deg, interference);
        const SherrittFlightSurface s(prof, phi);
        const double n = 8.0/60;
        const double rate0 = pi*n*591*r*r;  // Eq 40 with l = r
        for (double theta = 181*deg; theta < 359*deg; theta += 2*deg)
        {
            EXPECT_NEAR(s.dischargeRate(theta, n, 591), rate0, 1e-5*rate0) << theta/deg << " " << interference;
        }
        // design loaded: the flight holds the half disc of radius r
        EXPECT_NEAR(s.holdupVolume(pi), 0.5*pi*r*r, 2e-3*0.5*pi*r*r);
        // and is empty at 2 pi
        EXPECT_NEAR(s.holdupVolume(2*pi), 0.0, 1e-15);
        EXPECT_NEAR(s.initialDischargeAngle(0.25*pi*r*r), 1.5*pi, 0.5*deg);  // within the table step
    }
}

TEST(SherrittFlightShapes, CbdFlightPeaksAtTheTop)
{
    const double phi = 45.6*deg;
    const auto shape = cbdFlightShape(0.3048, 0.045, 0.4, phi, 0.3048 - 2*0.075);
    const auto prof = tabulateSherrittFlight(shape, 8, 1.688, 0.5*deg, false);
    const SherrittFlightSurface s(prof, phi);
    const double top = s.length(270*deg);
    EXPECT_NEAR(top, 0.045*1.4, 1e-3);  // r (1 + bias)
    EXPECT_LT(s.length(190*deg), top);
    EXPECT_LT(s.length(350*deg), top);
    EXPECT_NEAR(s.length(200*deg), s.length(340*deg), 2e-3);  // symmetric about the top
}

TEST(SherrittFlightShapes, RadialPlateMatchesClosedForm)
{
    const double D = 1.0;
    const double len = 0.1;
    const auto prof = tabulateSherrittFlight(straightRadialFlightShape(D, len), 1, 1.0, 1*deg, false);
    const double Ro = 0.5*D;
    const double Rt = Ro - len;
    for (double th = 95*deg; th < 179.5*deg; th += 5*deg)
    {
        // horizontal from the tip (-x) to the shell
        const double expect = Rt*std::cos(th) + std::sqrt(Ro*Ro - Rt*Rt*std::sin(th)*std::sin(th));
        EXPECT_NEAR(prof.horizontalLength(th), expect, 1e-12) << th/deg;
    }
    // beyond the centreline the plate slopes down to its tip: nothing held
    for (double th = 181*deg; th < 359*deg; th += 5*deg)
    {
        EXPECT_NEAR(prof.horizontalLength(th), 0.0, 1e-12) << th/deg;
    }
}

TEST(SherrittFlightShapes, OverloadBedChordBelowTheAxis)
{
    // Sheikh's 90 deg two-sided flight: with the tip low in the drum the tip
    // plate rises from the tip, so the pocket holds nothing of its own, but
    // the material under the horizontal through the tip lies on the shell:
    // the overload bed (Sherritt 1991 Fig 3.1c). Its surface runs from the
    // tip to the shell: R cos a + sqrt(Ro^2 - R^2 sin^2 a) (no interference).
    const double D = 0.385;
    const double Ro = 0.5*D;
    const auto shape = twoSidedFlightShape(D, 0.04, 0.04, 90*deg);
    const auto prof = tabulateSherrittFlight(shape, 12, 2.1, 1*deg, false);
    const double R = 0.5*shape.tipDiameter();
    for (double a = 10*deg; a < 100.5*deg; a += 10*deg)
    {
        const Eigen::Vector2d tip = world(shape.points.back(), a);
        const Eigen::Vector2d p1 = world(shape.points[1], a);
        if (!(p1.y() > tip.y())) continue;  // only where the tip plate rises
        const double expect = R*std::cos(a) + std::sqrt(Ro*Ro - R*R*std::sin(a)*std::sin(a));
        EXPECT_NEAR(prof.horizontalLength(a), expect, 1e-9) << a/deg;
    }
    EXPECT_GT(prof.horizontalLength(40*deg), 5*0.04);  // across the drum, not a pocket
    // above the axis a rising tip plate still holds nothing (flight empty)
    EXPECT_EQ(prof.horizontalLength(355*deg), 0.0);
}

TEST(SherrittFlightShapes, HoldupFromDischargeEqualsPocketArea)
{
    // Sherritt's key idea (§3.2): integrating the discharge gives the
    // flight holdup. Check it against the shoelace area of the pocket under
    // the horizontal through the tip, for Sheikh-like 90 and 135 deg flights.
    const double D = 0.385;
    for (double tipAngle : {90*deg, 135*deg})
    {
        const auto shape = twoSidedFlightShape(D, 0.04, 0.03, tipAngle);
        const auto prof = tabulateSherrittFlight(shape, 1, 2.1, 0.1*deg, false);
        const double phi = 35.69*deg;
        const SherrittFlightSurface s(prof, phi);
        const double Ro = 0.5*D;
        for (double th = 105*deg; th <= 165*deg; th += 15*deg)
        {
            std::vector<Eigen::Vector2d> w;
            for (const auto& p : shape.points)
            {
                w.push_back(world(p, th));
            }
            const auto tip = w.back();
            const double xh = -std::sqrt(Ro*Ro - tip.y()*tip.y());
            ASSERT_NEAR(prof.horizontalLength(th), tip.x() - xh, 2e-3) << "line should end on the shell";
            // polygon: tip -> shell hit -> along the shell to P0 -> flight -> tip
            std::vector<Eigen::Vector2d> poly{tip, {xh, tip.y()}};
            const double a0 = std::atan2(tip.y(), xh);
            double a1 = std::atan2(w.front().y(), w.front().x());
            while (a1 - a0 > pi) a1 -= 2*pi;
            while (a0 - a1 > pi) a1 += 2*pi;
            for (int i = 1; i < 2000; ++i)
            {
                const double a = a0 + (a1 - a0)*i/2000;
                poly.push_back({Ro*std::cos(a), Ro*std::sin(a)});
            }
            for (const auto& p : w)
            {
                poly.push_back(p);
            }
            double area = 0;
            for (std::size_t i = 0; i < poly.size(); ++i)
            {
                const auto& p = poly[i];
                const auto& q = poly[(i + 1) % poly.size()];
                area += p.x()*q.y() - q.x()*p.y();
            }
            area = 0.5*std::abs(area);
            // surface at theta uses the table at theta - phi
            EXPECT_NEAR(s.holdupVolume(th + phi), area, 5e-3*area) << tipAngle/deg << " " << th/deg;
        }
    }
}

TEST(SherrittFlightShapes, SemiCircularFlightHoldsHalfDiscAtItsMouthLevel)
{
    // with the mouth horizontal (diameter horizontal) the pocket is the
    // half disc: pi r^2 / 2
    const double r = 0.05;
    const auto shape = semiCircularFlightShape(0.6, r, 400);
    const auto prof = tabulateSherrittFlight(shape, 1, 1.0, 0.05*deg, false);
    const SherrittFlightSurface s(prof, 40*deg);
    // the diameter is radial: it is horizontal with the tip at theta = pi
    EXPECT_NEAR(s.holdupVolume(pi + 40*deg), 0.5*pi*r*r, 2e-3*0.5*pi*r*r);
}

TEST(SherrittFlightShapes, RefusesTipsOutsideTheDrum)
{
    EXPECT_THROW(eadFlightShape(0.3, 0.2, 45*deg), InputError);            // no room for the tip
    EXPECT_THROW(eadFlightShape(0.3, 0.05, 45*deg, 0.29), InputError);     // arc beyond the shell
    EXPECT_THROW(eadFlightShape(0.3, 0.05, 95*deg), InputError);           // phi out of range
    EXPECT_THROW(twoSidedFlightShape(0.3, -0.01, 0.01, 90*deg), InputError);
    SherrittFlightShape bad;
    bad.shellDiameter = 0.3;
    bad.points = {{0.15, 0}, {0.2, 0.0}};
    EXPECT_THROW(tabulateSherrittFlight(bad, 4, 1.0), InputError);
    try
    {
        tabulateSherrittFlight(bad, 4, 1.0);
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("flight tip"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("(0, 0.15)"), std::string::npos) << e.what();
    }
}
