// Least-squares estimation: recovers known parameters from a synthetic
// tracer curve; CIs cover the truth under noise; t quantiles against tables.
#include "drum/transport/compartment/compartmentLeeEstimation.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace drum;

namespace
{
const std::vector<double> sampleTimes = []
{
    std::vector<double> t;
    for (double s = 0; s <= 3000; s += 60) t.push_back(s);
    return t;
}();

LeeDryer smallDryer()
{
    LeeDryer d;
    d.constantPhiDeg = 45.0;
    return d;
}
} // namespace

TEST(RtdEstimation, StudentTQuantilesMatchTables)
{
    EXPECT_NEAR(studentTQuantile(0.05, 5), 2.5706, 2e-3);
    EXPECT_NEAR(studentTQuantile(0.05, 10), 2.2281, 5e-4);
    EXPECT_NEAR(studentTQuantile(0.05, 28), 2.0484, 2e-4);
    EXPECT_NEAR(studentTQuantile(0.05, 100000), 1.95996, 1e-4);
}

TEST(RtdEstimation, RecoversParametersFromNoiseFreeCurve)
{
    const std::vector<std::string> names = {"kilnTime", "backFraction", "forwardShare"};
    const PredictionModel model = leeRtdModel(smallDryer(), 10, {9.0, 0.3, 0.3}, names, 39.6, sampleTimes);
    const std::vector<double> truth = {12.0, 0.35, 0.6};
    const std::vector<double> data = model(truth);
    const FitResult r = fitLeastSquares(model, data,
        {{"kilnTime", 9.0, 0.1, 1e30}, {"backFraction", 0.5, 0.0, 1.0}, {"forwardShare", 0.4, 0.0, 1.0}});
    EXPECT_TRUE(r.converged) << r.message;
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_NEAR(r.values[k], truth[k], 1e-4*std::abs(truth[k])) << names[k];
    }
    EXPECT_LT(r.sse, 1e-12);
}

TEST(RtdEstimation, ConfidenceIntervalsCoverTheTruthUnderNoise)
{
    const std::vector<std::string> names = {"kilnTime", "backFraction"};
    const PredictionModel model = leeRtdModel(smallDryer(), 10, {9.0, 0.3, 0.4}, names, 39.6, sampleTimes);
    const std::vector<double> truth = {12.0, 0.35};
    std::vector<double> data = model(truth);
    // Deterministic pseudo-noise, 2 % of the peak
    double peak = 0;
    for (double e : data) peak = std::max(peak, e);
    unsigned s = 12345;
    for (double& e : data)
    {
        s = 1103515245u*s + 12345u;
        e += 0.02*peak*((s >> 8 & 0xffff)/65535.0 - 0.5)*std::sqrt(12.0);
    }
    const FitResult r = fitLeastSquares(model, data, {{"kilnTime", 8.0, 0.1, 1e30}, {"backFraction", 0.5, 0.0, 1.0}});
    for (int k = 0; k < 2; ++k)
    {
        EXPECT_TRUE(std::isfinite(r.standardErrors[k]));
        EXPECT_LT(r.ciLow[k], truth[k]) << names[k];
        EXPECT_GT(r.ciHigh[k], truth[k]) << names[k];
        EXPECT_LT(r.ciHigh[k] - r.ciLow[k], 0.5*truth[k]) << names[k];   // informative
    }
}

TEST(RtdEstimation, MultiStartEscapesTheLocalMinimumOfABadStart)
{
    // From (6, 0.6, 0.3) a single run ends on the bound C_F = 0 (everything
    // kilns), a local minimum; the quasi-random starts find the truth
    const std::vector<std::string> names = {"kilnTime", "backFraction", "forwardShare"};
    const PredictionModel model = leeRtdModel(smallDryer(), 10, {9.0, 0.3, 0.3}, names, 39.6, sampleTimes);
    const std::vector<double> data = model({12.0, 0.35, 0.6});
    const std::vector<FitResult> runs = multiStartFit(model, data,
        {{"kilnTime", 6.0, 0.1, 1e30}, {"backFraction", 0.6, 0.0, 1.0}, {"forwardShare", 0.3, 0.0, 1.0}}, 3);
    ASSERT_FALSE(runs.empty());
    const FitResult single = fitLeastSquares(model, data,
        {{"kilnTime", 6.0, 0.1, 1e30}, {"backFraction", 0.6, 0.0, 1.0}, {"forwardShare", 0.3, 0.0, 1.0}});
    EXPECT_GT(single.sse, 1e-4);
    EXPECT_TRUE(single.atBound[2]);
    EXPECT_LT(runs.front().sse, 1e-10);
    EXPECT_NEAR(runs.front().values[0], 12.0, 1e-3);
    for (std::size_t i = 1; i < runs.size(); ++i) EXPECT_GE(runs[i].sse, runs[i - 1].sse);
}

TEST(RtdEstimation, BadParameterInputThrows)
{
    EXPECT_THROW(leeRtdModel(smallDryer(), 10, {9.0, 0.3, 0.3}, {"slope"}, 39.6, sampleTimes), InputError);
    const PredictionModel model = leeRtdModel(smallDryer(), 10, {9.0, 0.3, 0.3}, {"kilnTime"}, 39.6, sampleTimes);
    EXPECT_THROW(fitLeastSquares(model, model({9.0}), {{"kilnTime", 20.0, 0.1, 10.0}}), InputError);
}
