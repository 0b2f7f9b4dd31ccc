// Lee's Ch. 7 estimation redone by least squares on the Invicta tracer
// curve (invicta_rtd.csv): fit (t_kiln, C_B, C_F^G) at N = 30 and compare
// with Lee's Table 7.2 fit on the same objective. The moments of the fit
// are printed; the model's SD is structurally far below the measured one.
#include "drum/io/projectPaths.hpp"
#include "drum/transport/compartment/compartmentLeeEstimation.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/io/csv.hpp"

#include <gtest/gtest.h>
#include <cstdlib>

using namespace drum;

namespace
{
} // namespace

TEST(InvictaEstimation, LeastSquaresFitAtLeastAsGoodAsTable72)
{
    std::vector<double> t, E;
    {
        io::CSVReader<2> in((drum::dataDir()/"invicta_rtd.csv").string());
        in.read_header(io::ignore_extra_column, "t_after_pulse_start_s", "E_per_h");
        double a, b;
        while (in.read_row(a, b))
        {
            if (a >= 0) { t.push_back(a); E.push_back(b); }
        }
    }
    const LeeDryer dryer;
    const int n = 30;
    // Table 7.2, N = 30 (lee_model_results.csv)
    const LeeParameters lee{9.95, 0.41, 0.11};
    const std::vector<std::string> names = {"kilnTime", "backFraction", "forwardShare"};
    const PredictionModel model = leeRtdModel(dryer, n, lee, names, 39.6, t);
    const PredictionModel leeModel = leeRtdModel(dryer, n, lee, {"kilnTime"}, 39.6, t);
    const std::vector<double> yLee = leeModel({lee.kilnTime});
    double sseLee = 0;
    for (std::size_t i = 0; i < t.size(); ++i) sseLee += (yLee[i] - E[i])*(yLee[i] - E[i]);

    const std::vector<FitResult> runs = multiStartFit(model, E,
        {{"kilnTime", 8.5, 0.01, 1e30}, {"backFraction", 0.65, 0.0, 1.0}, {"forwardShare", 0.5, 0.0, 1.0}}, 4);
    ASSERT_FALSE(runs.empty());
    const FitResult& best = runs.front();
    EXPECT_LE(best.sse, sseLee);
    // Most starts reach the best minimum (within 1 % in SSE); the other
    // minimum found has C_F = 0 (all transport by kilning), SSE ~ 4.17
    int same = 0;
    for (const FitResult& r : runs) same += r.sse < 1.01*best.sse;
    EXPECT_GE(same, 2);
    for (const FitResult& r : runs)
    {
        std::printf("  start (%.3g, %.3g, %.3g) -> SSE %.4f\n", r.initial[0], r.initial[1], r.initial[2], r.sse);
    }

    const LeeParameters p = leeParametersFrom(dryer, n, lee, names, best.values);
    const CompartmentNetwork net = leeNetwork(dryer, n, p);
    const RtdMoments m = exactMoments(net.tracerSystem(net.steadyState()), 39.6);
    std::printf("Invicta N=30 fit: t_kiln %.3f s, C_B %.4f, C_F^G %.4f (share %.4f%s), SSE %.4f (Table 7.2: %.4f); "
                "mean %.2f min, SD %.2f min (measured 11.08, 6.73)\n",
        p.kilnTime, p.backFraction, p.dragFactor, best.values[2], best.atBound[2] ? ", at bound" : "",
        best.sse, sseLee, m.mean/60, m.sd()/60);
    // The fit keeps the mean within 15 % of the measured 11.08 min
    EXPECT_NEAR(m.mean/60, 11.08, 0.15*11.08);
}

TEST(InvictaEstimation, StagnantZoneExtensionWithLogObjectiveMatchesMoments)
{
    // Beyond Lee: stagnant zones exchanging with the passive cells, fitted
    // with residuals of ln(E + 0.01/h) so the tail counts. Moments compared
    // on the measured sampling (both truncated at 74 min).
    std::vector<double> t, E;
    {
        io::CSVReader<2> in((drum::dataDir()/"invicta_rtd.csv").string());
        in.read_header(io::ignore_extra_column, "t_after_pulse_start_s", "E_per_h");
        double a, b;
        while (in.read_row(a, b))
        {
            if (a >= 0) { t.push_back(a); E.push_back(b); }
        }
    }
    const LeeDryer dryer;
    const int n = 30;
    const LeeParameters start{8.5, 0.6, 0.3};
    const std::vector<std::string> names = {"kilnTime", "backFraction", "forwardShare", "stagnantRatio", "exchangeTime"};
    const RtdObjective logObj{true, 0.01};
    const PredictionModel model = leeRtdModel(dryer, n, start, names, 39.6, t, {}, logObj);
    const std::vector<FitResult> runs = multiStartFit(model, transformForObjective(E, logObj),
        {{"kilnTime", 8.5, 0.01, 1e30}, {"backFraction", 0.6, 0.0, 1.0}, {"forwardShare", 0.9, 0.0, 1.0},
         {"stagnantRatio", 0.1, 0.0, 5.0}, {"exchangeTime", 600.0, 1.0, 1e5}}, 2);
    ASSERT_FALSE(runs.empty());
    const FitResult& best = runs.front();
    const LeeParameters p = leeParametersFrom(dryer, n, start, names, best.values);
    const StagnantExchange z = stagnantFrom({}, names, best.values);
    const CompartmentNetwork net = leeNetwork(dryer, n, p);
    const TracerSystem sys = net.tracerSystem(net.steadyState(), z);
    const RtdMoments grid = sampledMoments(t, exactRtdAt(sys, 39.6, t));
    const RtdMoments ex = exactMoments(sys, 39.6);
    const RtdMoments meas = [&] { std::vector<double> e; for (double v : E) e.push_back(v/3600); return sampledMoments(t, e); }();
    std::printf("stagnant fit: t_kiln %.3f, C_B %.4f, share %.3f, M_s/M_p %.4f, t_x %.1f s; SSE(log) %.3f;\n"
                "  on the measured grid: mean %.2f min, SD %.2f min; untruncated: mean %.2f, SD %.2f (measured %.2f, %.2f)\n",
        p.kilnTime, p.backFraction, best.values[2], z.massRatio, z.exchangeTime, best.sse,
        grid.mean/60, grid.sd()/60, ex.mean/60, ex.sd()/60, meas.mean/60, meas.sd()/60);
    EXPECT_LT(std::abs(grid.mean/meas.mean - 1), 0.05);
    EXPECT_LT(std::abs(grid.sd()/meas.sd() - 1), 0.20);
}
