// The RTD's shape as a tracer test reads it, against the closed forms of the
// two-tank Erlang curve E(t) = t e^-t: F(t) = 1 - (1 + t) e^-t
#include "drum/rtd/rtdShape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace drum;

TEST(RtdShape, QuantilesBodyAndTailOfTheErlangCurve)
{
    std::vector<double> t, E;
    for (int i = -10; i <= 40000; ++i)   // samples before 0 (the pulse's lead) are left out
    {
        t.push_back(1e-3*i);
        E.push_back(i < 0 ? 5.0 : t.back()*std::exp(-t.back()));
    }
    const double T = 3;
    const RtdShape s = rtdShape(t, E, T);
    const auto F = [](double x) { return 1 - (1 + x)*std::exp(-x); };
    EXPECT_NEAR(F(s.t10), 0.1, 1e-5);
    EXPECT_NEAR(F(s.t50), 0.5, 1e-5);
    EXPECT_NEAR(F(s.t90), 0.9, 1e-5);
    EXPECT_NEAR(s.tailShare, (1 + T)*std::exp(-T), 1e-5);
    const double m0 = 1 - std::exp(-T)*(1 + T);
    const double m1 = 2 - std::exp(-T)*(T*T + 2*T + 2);
    const double m2 = 6 - std::exp(-T)*(T*T*T + 3*T*T + 6*T + 6);
    EXPECT_NEAR(s.bodyMean, m1/m0, 1e-5);
    EXPECT_NEAR(s.bodySd, std::sqrt(m2/m0 - m1*m1/(m0*m0)), 1e-5);
    // a curve with no area has no shape (NaN, never 0)
    const RtdShape z = rtdShape({0, 1, 2}, {0, 0, 0}, 1);
    EXPECT_TRUE(std::isnan(z.t50));
    EXPECT_TRUE(std::isnan(z.bodyMean));
}
