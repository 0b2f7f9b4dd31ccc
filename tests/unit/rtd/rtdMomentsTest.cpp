// RTD moments: exact (linear algebra) against closed forms, and the
// sampled (trapezoidal) moments against the exact ones
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/io/inputError.hpp"
#include "rtdTestNetworks.hpp"

#include <gtest/gtest.h>

using namespace drum;

TEST(RtdMoments, ExactMomentsOfTanksInSeries)
{
    // Gamma(n, tau): mean n tau, variance n tau^2, skewness 2/sqrt(n);
    // a pulse of length T adds T/2 and T^2/12
    const int n = 6;
    const double tau = 15.0, T = 30.0;
    const RtdMoments m = exactMoments(tanksInSeries(n, tau), T);
    EXPECT_NEAR(m.area, 1.0, 1e-13);
    EXPECT_NEAR(m.mean, n*tau + T/2, 1e-9);
    const double var = n*tau*tau + T*T/12;
    EXPECT_NEAR(m.variance, var, 1e-7);
    EXPECT_NEAR(m.skewness, 2.0*n*std::pow(tau, 3)/std::pow(var, 1.5), 1e-10);
}

TEST(RtdMoments, SampledMomentsConvergeToExact)
{
    const TracerSystem s = tanksInSeries(3, 40.0);
    RtdOptions o;
    o.pulseDuration = 20.0;
    o.timeStep = 1.0;
    o.recovery = 1 - 1e-9;
    const RtdResult r = simulateRtd(s, o);
    const RtdMoments a = sampledMoments(r.time, r.E);
    const RtdMoments b = exactMoments(s, 20.0);
    EXPECT_NEAR(a.area, 1.0, 1e-4);
    EXPECT_NEAR(a.mean/b.mean, 1.0, 1e-4);
    EXPECT_NEAR(a.sd()/b.sd(), 1.0, 1e-4);
    EXPECT_NEAR(a.skewness/b.skewness, 1.0, 1e-3);
}

TEST(RtdMoments, SampledMomentsHandValues)
{
    // Triangle on [0, 2] peaking at 1: area 1, mean 1, variance 1/6, skew 0
    const RtdMoments m = sampledMoments({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0});
    EXPECT_DOUBLE_EQ(m.area, 1.0);
    EXPECT_DOUBLE_EQ(m.mean, 1.0);
    EXPECT_NEAR(m.skewness, 0.0, 1e-15);
    EXPECT_THROW(sampledMoments({0.0, 2.0, 1.0}, {0.0, 1.0, 0.0}), InputError);
    EXPECT_THROW(sampledMoments({0.0}, {0.0}), InputError);
}
