// Full RTD (impulse, to 99.9 % tracer recovery, E sampled every 5 s,
// trapezoidal moments) and the steady state of a 100-slice Lee network:
// our exact propagator / TR-BDF2 / closed-form steady state against
// SUNDIALS CVODE (BDF, banded direct solver with the exact Jacobian) on the
// same equations. Every method samples E every 5 s to 99.9 % recovery and
// takes trapezoidal moments, so they share the sampling/truncation error
// (counters *_vs_analytic, ~4e-4 mean and ~7e-3 SD against the moments
// from linear algebra). The integration error proper is *_vs_exactgrid:
// the difference from the exact propagator's moments on the same grid.
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"

#include <benchmark/benchmark.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <cmath>
#include <stdexcept>

using namespace drum;

namespace
{

constexpr int nSlices = 100;
constexpr double outputStep = 5.0;      // s
constexpr double recovery = 0.999;

const CompartmentNetwork& network()
{
    static const CompartmentNetwork net = []
    {
        LeeDryer d;     // Invicta, phi from the moisture profile
        return leeNetwork(d, nSlices, {9.0, 0.3, 0.2});
    }();
    return net;
}

const TracerSystem& tracer()
{
    static const TracerSystem sys = network().tracerSystem(network().steadyState());
    return sys;
}

const RtdMoments& reference()
{
    static const RtdMoments m = exactMoments(tracer(), 0.0);
    return m;
}

RtdMoments exactGrid()
{
    RtdOptions o;
    o.timeStep = outputStep;
    o.recovery = recovery;
    const RtdResult r = simulateRtd(tracer(), o);
    return sampledMoments(r.time, r.E);
}

void accuracyCounters(benchmark::State& state, const RtdMoments& m)
{
    static const RtdMoments grid = exactGrid();
    state.counters["mean_vs_exactgrid"] = std::abs(m.mean/grid.mean - 1);
    state.counters["sd_vs_exactgrid"] = std::abs(m.sd()/grid.sd() - 1);
    state.counters["mean_vs_analytic"] = std::abs(m.mean/reference().mean - 1);
    state.counters["sd_vs_analytic"] = std::abs(m.sd()/reference().sd() - 1);
}

// ------------------------------------------------------------------ ours

void BM_RtdExactPropagator(benchmark::State& state)
{
    RtdOptions o;
    o.timeStep = outputStep;
    o.recovery = recovery;
    RtdMoments m;
    for (auto _ : state)
    {
        const RtdResult r = simulateRtd(tracer(), o);
        m = sampledMoments(r.time, r.E);
        benchmark::DoNotOptimize(m);
    }
    accuracyCounters(state, m);
}
BENCHMARK(BM_RtdExactPropagator)->Unit(benchmark::kMillisecond);

void BM_RtdTrBdf2(benchmark::State& state)
{
    RtdOptions o;
    o.integrator = RtdIntegrator::trbdf2;
    o.timeStep = outputStep;
    o.recovery = recovery;
    RtdMoments m;
    for (auto _ : state)
    {
        const RtdResult r = simulateRtd(tracer(), o);
        m = sampledMoments(r.time, r.E);
        benchmark::DoNotOptimize(m);
    }
    accuracyCounters(state, m);
}
BENCHMARK(BM_RtdTrBdf2)->Unit(benchmark::kMillisecond);

void BM_MomentsExactLinearAlgebra(benchmark::State& state)
{
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(exactMoments(tracer(), 0.0));
    }
}
BENCHMARK(BM_MomentsExactLinearAlgebra)->Unit(benchmark::kMicrosecond);

void BM_SteadyStateClosedForm(benchmark::State& state)
{
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(network().steadyState());
    }
}
BENCHMARK(BM_SteadyStateClosedForm)->Unit(benchmark::kMicrosecond);

// ------------------------------------------------------------------ CVODE

struct Cvode
{
    SUNContext ctx = nullptr;
    N_Vector y = nullptr;
    SUNMatrix A = nullptr;
    SUNLinearSolver LS = nullptr;
    void* mem = nullptr;

    Cvode(int n, CVRhsFn f, CVLsJacFn jac, void* user, double rtol, double atol, const Eigen::VectorXd& y0)
    {
        SUNContext_Create(nullptr, &ctx);
        y = N_VNew_Serial(n, ctx);
        for (int i = 0; i < n; ++i) NV_Ith_S(y, i) = y0(i);
        mem = CVodeCreate(CV_BDF, ctx);
        CVodeInit(mem, f, 0.0, y);
        CVodeSStolerances(mem, rtol, atol);
        CVodeSetUserData(mem, user);
        CVodeSetMaxNumSteps(mem, 1000000);
        A = SUNBandMatrix(n, 3, 2, ctx);     // P1, A1, P2, A2 ...: upper 3, lower 2
        LS = SUNLinSol_Band(y, A, ctx);
        CVodeSetLinearSolver(mem, LS, A);
        if (jac) CVodeSetJacFn(mem, jac);
    }
    ~Cvode()
    {
        CVodeFree(&mem);
        SUNLinSolFree(LS);
        SUNMatDestroy(A);
        N_VDestroy(y);
        SUNContext_Free(&ctx);
    }
};

int tracerRhs(sunrealtype, N_Vector y, N_Vector ydot, void* user)
{
    const TracerSystem& s = *static_cast<const TracerSystem*>(user);
    const Eigen::Map<const Eigen::VectorXd> Y(NV_DATA_S(y), s.size());
    Eigen::Map<Eigen::VectorXd> D(NV_DATA_S(ydot), s.size());
    D = s.K*Y;
    return 0;
}

int tracerJac(sunrealtype, N_Vector, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector)
{
    const TracerSystem& s = *static_cast<const TracerSystem*>(user);
    for (int k = 0; k < s.K.outerSize(); ++k)
    {
        for (Eigen::SparseMatrix<double>::InnerIterator it(s.K, k); it; ++it)
        {
            SM_ELEMENT_B(J, it.row(), it.col()) = it.value();
        }
    }
    return 0;
}

RtdMoments cvodeRtd(double rtol, double atol)
{
    const TracerSystem& s = tracer();
    Cvode cv(int(s.size()), tracerRhs, tracerJac, const_cast<TracerSystem*>(&s), rtol, atol, s.b);
    std::vector<double> t{0.0}, E{s.c.dot(s.b)};
    double tout = 0, tret = 0;
    for (;;)
    {
        tout += outputStep;
        if (CVode(cv.mem, tout, cv.y, &tret, CV_NORMAL) < 0) throw std::runtime_error("CVODE failed");
        const Eigen::Map<const Eigen::VectorXd> Y(NV_DATA_S(cv.y), s.size());
        t.push_back(tret);
        E.push_back(s.c.dot(Y));
        if (Y.sum() <= 1 - recovery) break;
    }
    return sampledMoments(t, E);
}

void BM_RtdCvode(benchmark::State& state)
{
    const double rtol = std::pow(10.0, -double(state.range(0)));
    RtdMoments m;
    for (auto _ : state)
    {
        m = cvodeRtd(rtol, rtol*1e-6);
        benchmark::DoNotOptimize(m);
    }
    accuracyCounters(state, m);
    state.counters["rtol_exp"] = double(state.range(0));
}
BENCHMARK(BM_RtdCvode)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMillisecond);

int massRhs(sunrealtype, N_Vector y, N_Vector ydot, void*)
{
    const Eigen::Map<const Eigen::VectorXd> Y(NV_DATA_S(y), 2*nSlices);
    Eigen::Map<Eigen::VectorXd>(NV_DATA_S(ydot), 2*nSlices) = network().massRates(Y);
    return 0;
}

void BM_SteadyStateCvode(benchmark::State& state)
{
    // Lee's initial state (gPROMS: uniform guesses), integrated until the
    // balances settle; the switch at M_des makes the right side only
    // piecewise smooth, so CVODE gets a difference-quotient band Jacobian
    const double rtol = std::pow(10.0, -double(state.range(0)));
    const CompartmentSteadyState ref = network().steadyState();
    double err = 0;
    for (auto _ : state)
    {
        Eigen::VectorXd m0(2*nSlices);
        for (int i = 0; i < nSlices; ++i) { m0(2*i) = 14000.0/nSlices; m0(2*i + 1) = 1400.0/nSlices; }
        Cvode cv(2*nSlices, massRhs, nullptr, nullptr, rtol, rtol*1e-3, m0);
        double tout = 0, tret = 0;
        for (;;)
        {
            tout += 600.0;
            if (CVode(cv.mem, tout, cv.y, &tret, CV_NORMAL) < 0) throw std::runtime_error("CVODE failed");
            const Eigen::Map<const Eigen::VectorXd> Y(NV_DATA_S(cv.y), 2*nSlices);
            const Eigen::VectorXd r = network().massRates(Y);
            if (r.cwiseAbs().maxCoeff() < 1e-6*network().feedRate() || tout > 1e6) break;
        }
        const Eigen::Map<const Eigen::VectorXd> Y(NV_DATA_S(cv.y), 2*nSlices);
        err = 0;
        for (int i = 0; i < nSlices; ++i)
        {
            err = std::max(err, std::abs(Y(2*i)/ref.passiveMass(i) - 1));
        }
    }
    state.counters["passive_rel_err"] = err;
}
BENCHMARK(BM_SteadyStateCvode)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
