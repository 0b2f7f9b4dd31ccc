// Tracer integrators against closed forms: exact propagator, TR-BDF2 and
// backward Euler orders, forward Euler stability detection.
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/io/inputError.hpp"
#include "rtdTestNetworks.hpp"

#include <gtest/gtest.h>
#include <algorithm>

using namespace drum;

namespace
{
double maxError(const RtdResult& r, int n, double tau)
{
    double e = 0;
    for (std::size_t k = 1; k < r.time.size(); ++k)
    {
        e = std::max(e, std::abs(r.E[k] - gammaE(n, tau, r.time[k])));
    }
    return e;
}
} // namespace

TEST(RtdSimulation, ExactPropagatorMatchesTanksInSeries)
{
    const TracerSystem s = tanksInSeries(5, 20.0);
    RtdOptions o;
    o.timeStep = 7.3;       // any step: the propagator is exact
    o.recovery = 0.9999;
    const RtdResult r = simulateRtd(s, o);
    EXPECT_LT(maxError(r, 5, 20.0), 1e-12);
    EXPECT_GE(r.recovered, 0.9999);
    // Recovery from the inventory agrees with the integral of E
    EXPECT_NEAR(sampledMoments(r.time, r.E).area, r.recovered, 2e-3);
}

TEST(RtdSimulation, ExactPulseResponseMatchesConvolution)
{
    // One CSTR, pulse of length T: E = (1 - e^{-t/tau})/T inside,
    // (e^{T/tau} - 1) e^{-t/tau}/T after
    const double tau = 10.0, T = 4.0;
    const TracerSystem s = tanksInSeries(1, tau);
    const std::vector<double> times = {1.0, 4.0, 9.0, 30.0};
    const std::vector<double> E = exactRtdAt(s, T, times);
    EXPECT_NEAR(E[0], (1 - std::exp(-1.0/tau))/T, 1e-13);
    EXPECT_NEAR(E[1], (1 - std::exp(-4.0/tau))/T, 1e-13);
    EXPECT_NEAR(E[2], (std::exp(T/tau) - 1)*std::exp(-9.0/tau)/T, 1e-13);
    EXPECT_NEAR(E[3], (std::exp(T/tau) - 1)*std::exp(-30.0/tau)/T, 1e-13);
    RtdOptions o;
    o.pulseDuration = T;
    o.timeStep = 1.0;
    const RtdResult r = simulateRtd(s, o);
    EXPECT_NEAR(r.E[9], E[2], 1e-13);
}

TEST(RtdSimulation, ImplicitIntegratorsConvergeAtTheirOrder)
{
    const TracerSystem s = tanksInSeries(4, 10.0);
    auto err = [&](RtdIntegrator i, double h)
    {
        RtdOptions o;
        o.integrator = i;
        o.timeStep = h;
        o.recovery = 0.999;
        return maxError(simulateRtd(s, o), 4, 10.0);
    };
    const double be1 = err(RtdIntegrator::backwardEuler, 1.0);
    const double be2 = err(RtdIntegrator::backwardEuler, 0.5);
    EXPECT_NEAR(be1/be2, 2.0, 0.25);         // first order
    const double tr1 = err(RtdIntegrator::trbdf2, 1.0);
    const double tr2 = err(RtdIntegrator::trbdf2, 0.5);
    EXPECT_NEAR(tr1/tr2, 4.0, 0.5);          // second order
    EXPECT_LT(tr2, be2);
}

TEST(RtdSimulation, ImplicitIntegratorsStayStableFarBeyondTheExplicitLimit)
{
    // Stiff: one fast (0.1 s) and one slow (100 s) tank
    TracerSystem s = tanksInSeries(2, 1.0);
    Eigen::MatrixXd K(2, 2);
    K << -10.0, 0.0, 10.0, -0.01;
    s.K = K.sparseView();
    s.c << 0.0, 0.01;
    const double hmax = forwardEulerStepLimit(s);
    EXPECT_NEAR(hmax, 0.2, 1e-12);
    RtdOptions o;
    o.timeStep = 50.0*hmax;
    o.integrator = RtdIntegrator::trbdf2;
    const RtdResult r = simulateRtd(s, o);
    // L-stable: the fast mode is damped, not amplified (at most a small
    // undershoot from the trapezoidal stage)
    const double eMax = *std::max_element(r.E.begin(), r.E.end());
    for (double e : r.E) EXPECT_GE(e, -1e-3*eMax);
    EXPECT_LT(eMax, 0.01);
    // Closed form: E = 10*0.01/(10 - 0.01) (e^{-0.01 t} - e^{-10 t})
    for (std::size_t k = 2; k < r.time.size(); ++k)
    {
        const double t = r.time[k];
        const double exact = 0.1/9.99*(std::exp(-0.01*t) - std::exp(-10.0*t));
        EXPECT_NEAR(r.E[k], exact, 1e-2*exact) << "t = " << t;
    }
}

TEST(RtdSimulation, ForwardEulerBelowItsLimitIsFineAndBeyondItFails)
{
    // Five 2-s tanks: every eigenvalue is -0.5 1/s, so h_max = 4 s
    const TracerSystem s = tanksInSeries(5, 2.0);
    const double hmax = forwardEulerStepLimit(s);
    EXPECT_NEAR(hmax, 4.0, 1e-9);

    RtdOptions o;
    o.integrator = RtdIntegrator::forwardEuler;
    o.recovery = 0.999;
    o.timeStep = 0.02;
    const RtdResult fine = simulateRtd(s, o);
    EXPECT_LT(maxError(fine, 5, 2.0), 2e-3);
    EXPECT_TRUE(fine.warnings.empty());

    // Beyond the limit, unchecked: the "solution" grows without bound
    o.timeStep = 1.25*hmax;
    o.onUnstable = UnstableStepPolicy::unchecked;
    o.maxSteps = 400;
    RtdResult wild;
    try
    {
        wild = simulateRtd(s, o);
    }
    catch (const InputError&)
    {
        // recovery never reached: also a failure
    }
    o.maxSteps = 200;
    double worst = 0;
    {
        // Re-run a fixed number of steps to look at the blow-up
        Eigen::VectorXd y = s.b;
        for (int k = 0; k < 200; ++k) y = y + o.timeStep*(s.K*y);
        worst = y.cwiseAbs().maxCoeff();
    }
    EXPECT_GT(worst, 1e3);

    // Checked (default): a clear error naming the step and its limit
    o.onUnstable = UnstableStepPolicy::error;
    try
    {
        simulateRtd(s, o);
        FAIL() << "forward Euler beyond its stable step must not return";
    }
    catch (const InputError& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("unstable"), std::string::npos) << msg;
        EXPECT_NE(msg.find("stability limit 4"), std::string::npos) << msg;
    }

    // Fallback: switches to TR-BDF2 and says so
    o.onUnstable = UnstableStepPolicy::fallback;
    o.maxSteps = 10000000;
    const RtdResult fb = simulateRtd(s, o);
    EXPECT_EQ(fb.used, RtdIntegrator::trbdf2);
    ASSERT_EQ(fb.warnings.size(), 1u);
    EXPECT_NE(fb.warnings[0].find("fell back"), std::string::npos);
    EXPECT_LT(maxError(fb, 5, 2.0), 0.02);
}

TEST(RtdSimulation, RunTimeGuardCatchesGrowthTheEigenCheckDidNotSee)
{
    // A network with an unstable (source-like) mode: the inventory grows
    TracerSystem s = tanksInSeries(1, 1.0);
    Eigen::MatrixXd K(1, 1);
    K << 0.01;
    s.K = K.sparseView();
    RtdOptions o;
    o.integrator = RtdIntegrator::exact;
    o.timeStep = 1.0;
    EXPECT_THROW(simulateRtd(s, o), InputError);
}

TEST(RtdSimulation, UnknownIntegratorNameThrows)
{
    EXPECT_EQ(parseRtdIntegrator("trbdf2"), RtdIntegrator::trbdf2);
    EXPECT_THROW(parseRtdIntegrator("rk45", "integrator", "drumDict"), InputError);
}
