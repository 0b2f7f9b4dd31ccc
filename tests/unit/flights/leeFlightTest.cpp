// Lee 2008 Ch. 4 geometric flight model: hand values from an independent
// implementation of Lee 2008 §4.2.3.1-4.2.3.2, the polygon-clipping cross-check,
// exact derivative, mass conservation and refusal of impossible flights.
#include "drum/flights/leeFlight.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace
{

drum::FlightGeometry invicta()
{
    // Lee 2008 Table 4.1
    return drum::FlightGeometry{2.5, 0.195, 0.183, 90.0, 117.0, 28};
}

// Adaptive Simpson, independent of the library's quadrature
double simpson(const std::function<double(double)>& f, double a, double b, double tol,
               double fa, double fm, double fb, double whole, int depth)
{
    const double m = 0.5*(a + b);
    const double lm = 0.5*(a + m), rm = 0.5*(m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a)/6.0*(fa + 4.0*flm + fm);
    const double right = (b - m)/6.0*(fm + 4.0*frm + fb);
    if (depth <= 0 || std::abs(left + right - whole) <= 15.0*tol)
    {
        return left + right + (left + right - whole)/15.0;
    }
    return simpson(f, a, m, tol/2, fa, flm, fm, left, depth - 1)
         + simpson(f, m, b, tol/2, fm, frm, fb, right, depth - 1);
}

double integrate(const std::function<double(double)>& f, double a, double b, double tol)
{
    const double fa = f(a), fb = f(b), fm = f(0.5*(a + b));
    return simpson(f, a, b, tol, fa, fm, fb, (b - a)/6.0*(fa + 4.0*fm + fb), 50);
}

} // namespace


TEST(LeeFlight, InvictaHelperValuesMatchHandCalculation)
{
    const drum::LeeFlight f(invicta(), 30.0);
    EXPECT_NEAR(f.tipRadius(), 2.2279, 1e-4);
    EXPECT_NEAR(f.tipOffsetDeg(), 4.197, 1e-3);
    EXPECT_NEAR(f.flightSpacingDeg(), 12.857, 1e-3);
    EXPECT_NEAR(f.tipChord(), 0.4989, 1e-4);
    EXPECT_NEAR(f.alphaFtDeg(), 29.23, 1e-2);
    EXPECT_NEAR(f.tipToNextElbow(), 0.3508, 1e-4);
    EXPECT_NEAR(f.alphaADeg(), 14.76, 1e-2);
    EXPECT_NEAR(f.tipToRoot(), 0.3224, 1e-4);
    EXPECT_NEAR(f.fullArea(), 0.14901, 1e-5);
    // psi_ft from the drawn tip position agrees with Eq 4.7
    const Eigen::Vector2d tip = f.tipPosition(0.0);
    EXPECT_NEAR(std::atan2(tip.x(), -tip.y())*180.0/M_PI, f.tipOffsetDeg(), 1e-10);
    EXPECT_NEAR(tip.norm(), f.tipRadius(), 1e-12);
}


TEST(LeeFlight, AreaMatchesIndependentTestVectors)
{
    // areas (m^2 per m) from an independent implementation of Lee 2008 §4.2.3.2
    const double psi[] = {0, 40, 60, 85.8, 90, 100, 120, 150, 170, 190};
    const double a30[] = {0.14901, 0.12019, 0.09180, 0.06212, 0.05875, 0.05144, 0.03828,
                          0.01625, 0.00438, 0.0};
    const double a40[] = {0.14901, 0.13152, 0.10757, 0.07131, 0.06721, 0.05875, 0.04476,
                          0.02448, 0.00907, 0.00090};
    const double a50[] = {0.14901, 0.14767, 0.12019, 0.08307, 0.07772, 0.06721, 0.05144,
                          0.03165, 0.01625, 0.00438};
    const drum::LeeFlight f30(invicta(), 30.0), f40(invicta(), 40.0), f50(invicta(), 50.0);
    for (int i = 0; i < 10; ++i)
    {
        EXPECT_NEAR(f30.area(psi[i]), a30[i], 6e-6) << "psi " << psi[i];
        EXPECT_NEAR(f40.area(psi[i]), a40[i], 6e-6) << "psi " << psi[i];
        EXPECT_NEAR(f50.area(psi[i]), a50[i], 6e-6) << "psi " << psi[i];
    }
}


TEST(LeeFlight, ClosedFormAgreesWithPolygonClipping)
{
    // Perpendicular Invicta flight, and non-perpendicular flights that test
    // the Eq 4.16 erratum (sin alpha2' and s1 s1', docs/errata.md L4)
    for (double a1 : {90.0, 80.0, 100.0, 110.0})
    {
        drum::FlightGeometry g = invicta();
        g.baseAngleDeg = a1;
        for (double phi : {30.0, 45.0, 60.0})
        {
            const drum::LeeFlight f(g, phi);
            const auto& p = f.transitionPoints();
            for (double psi = p[0] + 0.05; psi < p[4]; psi += 1.3)
            {
                const double poly = drum::polygonArea(f.materialPolygon(psi, 3000));
                EXPECT_NEAR(f.area(psi), poly, 1e-8)
                    << "alpha1 " << a1 << " phi " << phi << " psi " << psi
                    << " phase " << f.phase(psi);
            }
        }
    }
}


TEST(LeeFlight, HoldupContinuousAtTransitionsAndFunctionOfPsiMinusPhi)
{
    const drum::LeeFlight f(invicta(), 42.0), g(invicta(), 30.0);
    for (double p : f.transitionPoints())
    {
        EXPECT_NEAR(f.area(p - 1e-9), f.area(p + 1e-9), 1e-10) << "at " << p;
    }
    for (double psi = 0.0; psi < 230.0; psi += 3.7)
    {
        EXPECT_NEAR(f.area(psi), g.area(psi - 12.0), 1e-12);
    }
    EXPECT_DOUBLE_EQ(f.area(f.transitionPoints()[4] + 1.0), 0.0);
    // psi4: only the tip triangle 1/2 s1 s2 sin(alpha2) is left (Fig. 4.15)
    EXPECT_NEAR(f.area(f.transitionPoints()[3]),
                0.5*0.195*0.183*std::sin(117.0*M_PI/180.0), 1e-12);
}


TEST(LeeFlight, SlopeIsDerivativeOfArea)
{
    const drum::LeeFlight f(invicta(), 37.0);
    const double h = 1e-5;
    for (double psi = 1.0; psi < 215.0; psi += 2.9)
    {
        if (f.phase(psi - h) != f.phase(psi + h)) continue;
        const double fd = (f.area(psi + h) - f.area(psi - h))/(2.0*h*M_PI/180.0);
        EXPECT_NEAR(f.areaSlope(psi), fd, 1e-7) << "psi " << psi;
    }
}


TEST(LeeFlight, DischargeIntegratesToMaximumHoldup)
{
    // int_{0}^{psi5+} -dA/dpsi dpsi = A_full: no mass is made or lost
    for (double phi : {25.0, 30.0, 40.0, 55.0, 70.0})
    {
        const drum::LeeFlight f(invicta(), phi);
        const auto& p = f.transitionPoints();
        double total = 0.0;
        double a = std::min(0.0, p[0] - 1.0);
        for (int k = 0; k <= 5; ++k)
        {
            const double b = k < 5 ? p[k] : p[4] + 10.0;
            total += integrate([&](double psiDeg)
                               { return -f.areaSlope(psiDeg)*M_PI/180.0; }, a, b, 1e-15);
            a = b;
        }
        EXPECT_NEAR(total/f.fullArea(), 1.0, 1e-9) << "phi " << phi;
    }
}


TEST(LeeFlight, SerratedTipLength)
{
    // Eq 4.18: 0.183 - 1/2 (0.03)(0.02)(20) = 0.177
    EXPECT_NEAR(drum::serratedTipLength(0.183, 0.03, 0.02, 20.0), 0.177, 1e-12);
    EXPECT_THROW(drum::serratedTipLength(0.183, 0.05, 0.2, 20.0), drum::InputError);
    EXPECT_THROW(drum::serratedTipLength(0.183, 0.03, -0.01, 20.0), drum::InputError);
}


namespace
{
std::string refusedEntry(drum::FlightGeometry g, double phi)
{
    try
    {
        drum::LeeFlight f(g, phi, "flight.yaml");
    }
    catch (const drum::InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("flight.yaml"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("range"), std::string::npos) << e.what();
        return e.entry();
    }
    return "<accepted>";
}
} // namespace


TEST(LeeFlight, RefusesFlightsThatCannotExist)
{
    auto g = invicta();
    g.baseLength = -0.1;
    EXPECT_EQ(refusedEntry(g, 40), "flight.baseLength");
    g = invicta();
    g.tipLength = 0.0;
    EXPECT_EQ(refusedEntry(g, 40), "flight.tipLength");
    g = invicta();
    g.baseLength = 2.6;                      // elbow beyond the centre
    EXPECT_EQ(refusedEntry(g, 40), "flight.baseLength");
    g = invicta();
    g.tipAngleDeg = 80.0;                    // tip bent back to the wall
    EXPECT_EQ(refusedEntry(g, 40), "flight.tipAngle");
    g = invicta();
    g.baseAngleDeg = 20.0;                   // base leans so far the tip leaves the drum
    EXPECT_NE(refusedEntry(g, 40), "<accepted>");
    g = invicta();
    g.drumRadius = 0.0;
    EXPECT_EQ(refusedEntry(g, 40), "drum.radius");
    EXPECT_EQ(refusedEntry(invicta(), 0.0), "material.dynamicAngleOfRepose");
    EXPECT_EQ(refusedEntry(invicta(), 90.0), "material.dynamicAngleOfRepose");
    EXPECT_EQ(refusedEntry(invicta(), -5.0), "material.dynamicAngleOfRepose");
    g = invicta();
    g.nFlights = 120;                        // tip reaches past the next root
    EXPECT_EQ(refusedEntry(g, 40), "drum.nFlights");
    g = invicta();
    g.nFlights = 2;
    EXPECT_EQ(refusedEntry(g, 40), "drum.nFlights");
    g = invicta();
    g.baseAngleDeg = 70.0;                   // surface would cut the flight's own tip
    EXPECT_EQ(refusedEntry(g, 40), "flight.tipAngle");
    g = invicta();
    g.nFlights = 4;                          // surface misses the next flight
    EXPECT_NE(refusedEntry(g, 40), "<accepted>");
}
