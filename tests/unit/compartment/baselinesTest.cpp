// Literature baselines: hand values, limits, sign conventions
#include "drum/transport/baselines.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace drum;
using namespace drum::baselines;

TEST(Baselines, FriedmanMarshallHandValue)
{
    // L = 30 ft, D = 3 ft, S = 0.05, N = 5 rpm, no gas:
    // T = 0.23*30/(0.05*5^0.9*3) min
    const double slope = std::atan(0.05);
    const double T = friedmanMarshall(30*0.3048, 3*0.3048, slope, 5.0, 0.0, 1.0, 500e-6, GasFlow::counterCurrent);
    EXPECT_NEAR(T, 60*0.23*30/(0.05*std::pow(5.0, 0.9)*3), 1e-9);
    // Gas lengthens countercurrent, shortens cocurrent, by 0.6 B L G/F
    const double cc = friedmanMarshall(30*0.3048, 3*0.3048, slope, 5.0, 0.5, 1.0, 400e-6, GasFlow::counterCurrent);
    const double co = friedmanMarshall(30*0.3048, 3*0.3048, slope, 5.0, 0.5, 1.0, 400e-6, GasFlow::coCurrent);
    EXPECT_NEAR(cc - T, 60*0.6*5/20.0*30*0.5, 1e-9);
    EXPECT_NEAR(T - co, cc - T, 1e-9);
}

TEST(Baselines, SaemanMitchellReducesToGeometry)
{
    // No gas: T = L/(f D n tan(alpha))
    EXPECT_NEAR(saemanMitchell(10, 2, 0.05, std::atan(0.04), M_PI, 0.1, 0.0, GasFlow::coCurrent),
                10/(M_PI*2*0.05*0.04), 1e-9);
    EXPECT_THROW(saemanMitchell(10, 2, 0.05, std::atan(0.04), M_PI, 0.1, 1.0, GasFlow::counterCurrent), InputError);
}

TEST(Baselines, SchofieldGlikinWithoutGas)
{
    // T = L (t_f + psi/(180 n))/(h sin(theta)), t_f = sqrt(2h/9.81)
    const double h = 4.0, n = 0.05, psi = 180.0, th = 2.8*M_PI/180;
    const double T = schofieldGlikin(12, th, n, h, psi, 0.0, GasFlow::counterCurrent, 1e-3, 1590, 1.0, 2e-5);
    EXPECT_NEAR(T, 12*(std::sqrt(2*h/9.81) + psi/(180*n))/(h*std::sin(th)), 1e-9);
    // Countercurrent gas slows the solids, cocurrent speeds them
    EXPECT_GT(schofieldGlikin(12, th, n, h, psi, 0.5, GasFlow::counterCurrent, 1e-3, 1590, 1.0, 2e-5), T);
    EXPECT_LT(schofieldGlikin(12, th, n, h, psi, 0.5, GasFlow::coCurrent, 1e-3, 1590, 1.0, 2e-5), T);
}

TEST(Baselines, MatchettBakerAirborneOnlyLimit)
{
    // alpha = 0: M_T/F = L/v_s x (t_a + t_p)/t_a with t_p = 1/(2n)
    const double n = 0.05, ta = 0.8, vs = 0.02;
    EXPECT_NEAR(matchettBaker(12, 5, n, 0.05, ta, vs, 0.0), 12/vs*(ta + 1/(2*n))/ta, 1e-9);
}

TEST(Baselines, TanksInSeriesIsANormalisedDistribution)
{
    const double tau = 600, N = 7.3;
    double area = 0, m1 = 0, m2 = 0;
    const double h = 0.5;
    for (double t = h/2; t < 20*tau; t += h)
    {
        const double e = tanksInSeriesE(t, tau, N);
        area += e*h;
        m1 += t*e*h;
        m2 += t*t*e*h;
    }
    EXPECT_NEAR(area, 1.0, 1e-6);
    EXPECT_NEAR(m1, tau, 1e-3);
    EXPECT_NEAR(m2 - m1*m1, tau*tau/N, 1e-1);
    // One tank: E = e^{-t/tau}/tau
    EXPECT_NEAR(tanksInSeriesE(100, 50, 1.0), std::exp(-2.0)/50, 1e-15);
    // Invicta measured 11.08 / 6.73 min -> N = 2.71
    EXPECT_NEAR(tanksInSeriesN(11.08, 6.73), 2.7105, 1e-3);
}
