// Speed against accuracy of the drum model's residence time distribution
// (issue 7, chart 2): Lee's Invicta network (App. 10.2.3 correlations,
// Table 7.2 parameters of N = 33 held fixed) for a range of slice counts and
// every integrator, at several time steps. For each run: CPU time, mean and
// SD of E(t), and three errors:
//   *_vs_model     against the exact moments of the same network (linear
//                  algebra, rtdMoments exactMoments): the integrator's error
// (Lee's slice parameters scale with the slice length, C_x ~ N: the slice
// count is part of his model, not a discretisation that converges, and at
// large N the forward fraction exceeds 1 and the library refuses the
// network - recorded as "refused")
//   *_vs_measured  against the Invicta tracer curve (invicta_rtd.csv,
//                  trapezoidal from the pulse start): what a user sees
// Forward Euler beyond its stable step is refused by the library (recorded
// as "refused" with the message), never run.
//
// Usage: rtdSpeedAccuracy DATA_DIR OUT.csv
#include "drum/io/csv.hpp"
#include "drum/io/atomicFile.hpp"
#include "drum/io/inputError.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace drum;

namespace
{

//- CPU-bound wall time of f, s: repeated until 0.2 s have passed, mean
template<class F>
double timeIt(F&& f)
{
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    int n = 0;
    double elapsed = 0;
    do
    {
        f();
        ++n;
        elapsed = std::chrono::duration<double>(clock::now() - t0).count();
    } while (elapsed < 0.2 && n < 1000);
    return elapsed/n;
}

RtdMoments measuredMoments(const std::string& dataDir)
{
    const std::string file = dataDir + "/invicta_rtd.csv";
    std::vector<double> t, E;
    io::CSVReader<2> in(file);
    in.read_header(io::ignore_extra_column, "t_after_pulse_start_s", "E_per_h");
    double ts, eh;
    while (in.read_row(ts, eh))
    {
        if (ts >= 0)
        {
            t.push_back(ts);
            E.push_back(eh/3600.0);
        }
    }
    if (t.size() < 10)
    {
        throw InputError(file, "t_after_pulse_start_s", "fewer than 10 rows after the pulse start");
    }
    return sampledMoments(t, E);
}

} // namespace

int main(int argc, char* argv[])
{
    if (argc != 3)
    {
        std::cerr << "Usage: rtdSpeedAccuracy DATA_DIR OUT.csv\n";
        return 2;
    }
    try
    {
        const RtdMoments measured = measuredMoments(argv[1]);
        const LeeDryer dryer;                  // Invicta Mill dryer No. 2
        const LeeParameters p{9.28, 0.57, 0.41};  // Table 7.2, N = 33
        const std::vector<int> slices{5, 10, 20, 33, 50, 100, 150, 200};
        const double pulse = 39.6;             // s, App. 10.4

        auto systemFor = [&](int n)
        {
            const CompartmentNetwork net = leeNetwork(dryer, n, p);
            return net.tracerSystem(net.steadyState());
        };

        std::ostringstream table;
        table << "slices,integrator,time_step_s,status,cpu_s,mean_min,sd_min,"
                 "mean_err_vs_model,sd_err_vs_model,"
                 "mean_err_vs_measured,sd_err_vs_measured,note\n";
        auto rel = [](double a, double b) { return std::abs(a/b - 1); };

        for (int n : slices)
        {
            TracerSystem sys;
            try
            {
                sys = systemFor(n);
            }
            catch (const InputError& e)
            {
                // Lee's forward fraction scales with the slice length: too
                // few slices give C_F > 1 and the library refuses the network
                std::string msg = e.what();
                for (char& c : msg) { if (c == ',' || c == '\n') c = ';'; }
                std::printf("N = %d refused: %s\n", n, e.what());
                table << n << ",network,,refused,,,,,,,," << msg.substr(0, 160) << "\n";
                continue;
            }
            const RtdMoments model = exactMoments(sys, pulse);
            const double hFE = forwardEulerStepLimit(sys);
            std::printf("N = %d: exact mean %.3f min, SD %.3f min; forward Euler limit %.3g s\n",
                        n, model.mean/60, model.sd()/60, hFE);
            std::fflush(stdout);
            for (RtdIntegrator integ : {RtdIntegrator::exact, RtdIntegrator::trbdf2,
                                        RtdIntegrator::backwardEuler, RtdIntegrator::forwardEuler})
            {
                for (double h : {1.0, 5.0, 20.0, 60.0})
                {
                    RtdOptions o;
                    o.integrator = integ;
                    o.timeStep = h;
                    o.pulseDuration = pulse;
                    o.recovery = 0.999;
                    o.onUnstable = UnstableStepPolicy::error;
                    std::vector<std::string> row{std::to_string(n), toString(integ),
                                                 std::to_string(h)};
                    try
                    {
                        RtdResult r;
                        const double cpu = timeIt([&] { r = simulateRtd(sys, o); });
                        const RtdMoments m = sampledMoments(r.time, r.E);
                        auto num = [](double v) { char b[32]; std::snprintf(b, 32, "%.6g", v); return std::string(b); };
                        row.insert(row.end(), {"ok", num(cpu), num(m.mean/60), num(m.sd()/60),
                            num(rel(m.mean, model.mean)), num(rel(m.sd(), model.sd())),
                            num(rel(m.mean, measured.mean)), num(rel(m.sd(), measured.sd())), ""});
                    }
                    catch (const std::exception& e)
                    {
                        std::string msg = e.what();
                        for (char& c : msg) { if (c == ',' || c == '\n') c = ';'; }
                        row.insert(row.end(), {"refused", "", "", "", "", "", "", "", msg.substr(0, 160)});
                    }
                    for (std::size_t k = 0; k < row.size(); ++k)
                    {
                        table << row[k] << (k + 1 < row.size() ? "," : "\n");
                    }
                }
            }
        }
        writeFileAtomically(argv[2], table.str());
        std::printf("measured (invicta_rtd.csv): mean %.2f min, SD %.2f min\n",
                    measured.mean/60, measured.sd()/60);
        std::printf("wrote %s\n", argv[2]);
    }
    catch (const std::exception& e)
    {
        std::cerr << "rtdSpeedAccuracy: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
