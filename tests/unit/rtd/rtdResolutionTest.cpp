// A tracer step that cannot resolve the RTD is refused before the run, and a run
// whose sampled moments part from the exact ones is refused after it
#include "drum/rtd/rtdResolution.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/io/inputError.hpp"
#include "rtdTestNetworks.hpp"

#include <gtest/gtest.h>

using namespace drum;

namespace
{

RtdMoments sampledAt(const TracerSystem& s, double h, double recovery, RtdIntegrator i = RtdIntegrator::exact)
{
    RtdOptions o;
    o.integrator = i;
    o.timeStep = h;
    o.recovery = recovery;
    const RtdResult r = simulateRtd(s, o);
    return sampledMoments(r.time, r.E);
}

std::string refusal(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(e.file(), "case/drumDict");
        return e.entry() + ": " + e.what();
    }
    return "";
}

} // namespace


TEST(RtdResolution, LargestStepIsHalfTheExactSd)
{
    // Gamma(4, 30 s): SD 60 s
    const RtdMoments ex = exactMoments(tanksInSeries(4, 30.0), 0.0);
    EXPECT_NEAR(largestResolvingStep(ex), 30.0, 1e-9);
    EXPECT_NO_THROW(requireResolvingStep(ex, 30.0, "case/drumDict"));
    const std::string why = refusal([&] { requireResolvingStep(ex, 30.01, "case/drumDict"); });
    EXPECT_NE(why.find("rtd.timeStep"), std::string::npos) << why;
    EXPECT_NE(why.find("allowed (0, 30]"), std::string::npos) << why;
    // a step far above the mean (the case that wrote a mean of 0) and NaN are refused
    EXPECT_NE(refusal([&] { requireResolvingStep(ex, 1e5, "case/drumDict"); }), "");
    EXPECT_NE(refusal([&] { requireResolvingStep(ex, std::nan(""), "case/drumDict"); }), "");
}

TEST(RtdResolution, ResolvedRunsPassAndCoarseOrCutRunsAreRefused)
{
    const TracerSystem s = tanksInSeries(4, 30.0);
    const RtdMoments ex = exactMoments(s, 0.0);
    // a fine step and a high recovery: the sampled moments match
    EXPECT_NO_THROW(requireSampledMomentsMatch(sampledAt(s, 1.0, 0.9999), ex, 1.0, 0.9999, "case/drumDict"));
    // backward Euler at the largest accepted step: first order, the moments part
    const RtdMoments be = sampledAt(s, 30.0, 0.9999, RtdIntegrator::backwardEuler);
    EXPECT_GT(std::abs(be.sd()/ex.sd() - 1), sdTolerance);
    const std::string coarse = refusal([&] { requireSampledMomentsMatch(be, ex, 30.0, 0.9999, "case/drumDict"); });
    EXPECT_NE(coarse.find("rtd.timeStep"), std::string::npos) << coarse;
    // a recovery that cuts off the tail: the SD falls short
    const RtdMoments cut = sampledAt(s, 1.0, 0.9);
    EXPECT_NE(refusal([&] { requireSampledMomentsMatch(cut, ex, 1.0, 0.9, "case/drumDict"); }).find("rtd.recovery"),
              std::string::npos);
    // NaN or empty moments never pass
    RtdMoments bad = ex;
    bad.mean = std::nan("");
    EXPECT_NE(refusal([&] { requireSampledMomentsMatch(bad, ex, 1.0, 0.9999, "case/drumDict"); }), "");
    EXPECT_NE(refusal([&] { requireSampledMomentsMatch(RtdMoments{}, ex, 1.0, 0.9999, "case/drumDict"); }), "");
}
