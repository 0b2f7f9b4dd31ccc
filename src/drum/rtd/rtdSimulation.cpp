#include "drum/rtd/rtdSimulation.hpp"

#include "drum/io/inputError.hpp"
#include "drum/rtd/metzlerExponential.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace drum
{

RtdIntegrator parseRtdIntegrator
(
    const std::string& name,
    const std::string& entry,
    const std::string& file
)
{
    if (name == "exact") return RtdIntegrator::exact;
    if (name == "trbdf2") return RtdIntegrator::trbdf2;
    if (name == "backwardEuler") return RtdIntegrator::backwardEuler;
    if (name == "forwardEuler") return RtdIntegrator::forwardEuler;
    throw InputError(file, entry,
        "unknown integrator '" + name + "'; allowed: exact, trbdf2, backwardEuler, forwardEuler");
}

std::string toString(const RtdIntegrator i)
{
    switch (i)
    {
        case RtdIntegrator::exact: return "exact";
        case RtdIntegrator::trbdf2: return "trbdf2";
        case RtdIntegrator::backwardEuler: return "backwardEuler";
        case RtdIntegrator::forwardEuler: return "forwardEuler";
    }
    return "?";
}


namespace
{

using SpMat = Eigen::SparseMatrix<double>;
using Vec = Eigen::VectorXd;

//- One-step propagator for a constant input rate u over a step h:
//  y_{n+1} = step(y_n)
class Stepper
{
public:
    virtual ~Stepper() = default;
    virtual Vec step(const Vec& y) const = 0;
};

//- Exact: z = (1, y) obeys z' = [[0, 0], [b u, K]] z, so
//  exp(M h) = [[1, 0], [Gamma, Phi]] (augmented matrix exponential, the
//  input state first so the band stays narrow), computed as a Metzler
//  exponential without cancellation (metzlerExponential.hpp)
BandedMatrix augmentedExponential(const TracerSystem& s, double h, double u)
{
    const Eigen::Index n = s.size();
    {
        std::vector<Eigen::Triplet<double>> t;
        for (int k = 0; k < s.K.outerSize(); ++k)
        {
            for (SpMat::InnerIterator it(s.K, k); it; ++it)
            {
                t.emplace_back(it.row() + 1, it.col() + 1, it.value());
            }
        }
        for (Eigen::Index i = 0; i < n; ++i)
        {
            if (s.b(i)*u != 0) t.emplace_back(i + 1, 0, s.b(i)*u);
        }
        SpMat M(n + 1, n + 1);
        M.setFromTriplets(t.begin(), t.end());
        return metzlerExponential(M, h);
    }
}

class ExactStepper : public Stepper
{
public:
    ExactStepper(const TracerSystem& s, double h, double u)
    :
        phi_(augmentedExponential(s, h, u))
    {}
    Vec step(const Vec& y) const override
    {
        Vec z(y.size() + 1);
        z(0) = 1.0;
        z.tail(y.size()) = y;
        return (phi_*z).tail(y.size());
    }
private:
    BandedMatrix phi_;
};

SpMat identityMinus(const SpMat& K, double a)
{
    SpMat I(K.rows(), K.cols());
    I.setIdentity();
    SpMat A = I - a*K;
    A.makeCompressed();
    return A;
}

class BackwardEulerStepper : public Stepper
{
public:
    BackwardEulerStepper(const TracerSystem& s, double h, double u)
    :
        g_(s.b*(u*h))
    {
        lu_.compute(identityMinus(s.K, h));
    }
    Vec step(const Vec& y) const override { return lu_.solve(y + g_); }
private:
    Vec g_;
    Eigen::SparseLU<SpMat> lu_;
};

//- TR-BDF2 (Bank et al. 1985; Hosea & Shampine 1996), gamma = 2 - sqrt 2
class TrBdf2Stepper : public Stepper
{
public:
    TrBdf2Stepper(const TracerSystem& s, double h, double u)
    :
        K_(s.K),
        h_(h),
        g_(s.b*u)
    {
        lu1_.compute(identityMinus(K_, 0.5*gam*h));
        lu2_.compute(identityMinus(K_, d()*h));
    }
    Vec step(const Vec& y) const override
    {
        // Trapezoid to t + gamma h
        const Vec yg = lu1_.solve(y + 0.5*gam*h_*(K_*y + 2.0*g_));
        // BDF2 from (t, t + gamma h) to t + h
        const double a = 1.0/(gam*(2.0 - gam));
        const double b = (1.0 - gam)*(1.0 - gam)/(gam*(2.0 - gam));
        return lu2_.solve(a*yg - b*y + d()*h_*g_);
    }
private:
    static constexpr double gam = 0.58578643762690495;  // 2 - sqrt(2)
    static double d() { return (1.0 - gam)/(2.0 - gam); }
    SpMat K_;
    double h_;
    Vec g_;
    Eigen::SparseLU<SpMat> lu1_, lu2_;
};

class ForwardEulerStepper : public Stepper
{
public:
    ForwardEulerStepper(const TracerSystem& s, double h, double u)
    :
        K_(s.K), h_(h), g_(s.b*(u*h))
    {}
    Vec step(const Vec& y) const override { return y + h_*(K_*y) + g_; }
private:
    SpMat K_;
    double h_;
    Vec g_;
};

std::unique_ptr<Stepper> makeStepper(RtdIntegrator i, const TracerSystem& s, double h, double u)
{
    switch (i)
    {
        case RtdIntegrator::exact: return std::make_unique<ExactStepper>(s, h, u);
        case RtdIntegrator::trbdf2: return std::make_unique<TrBdf2Stepper>(s, h, u);
        case RtdIntegrator::backwardEuler: return std::make_unique<BackwardEulerStepper>(s, h, u);
        case RtdIntegrator::forwardEuler: return std::make_unique<ForwardEulerStepper>(s, h, u);
    }
    return nullptr;
}

std::string str(double v)
{
    std::ostringstream o;
    o.precision(6);
    o << v;
    return o.str();
}

} // namespace


double forwardEulerStepLimit(const TracerSystem& sys)
{
    const Eigen::EigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(sys.K), false);
    double hmax = std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < es.eigenvalues().size(); ++k)
    {
        const std::complex<double> l = es.eigenvalues()(k);
        const double a2 = std::norm(l);
        if (a2 == 0)
        {
            continue;
        }
        if (l.real() >= 0)
        {
            return 0;   // no step is stable
        }
        // |1 + h l| <= 1  <=>  h <= -2 Re(l)/|l|^2
        hmax = std::min(hmax, -2.0*l.real()/a2);
    }
    return hmax;
}


RtdResult simulateRtd(const TracerSystem& sys, const RtdOptions& opt)
{
    requirePositive(opt.timeStep, "RTD time step (s)");
    requireInRange(opt.recovery, 0.0, 1.0 - 1e-12, "tracer recovery to reach");
    if (!(opt.pulseDuration >= 0))
    {
        throw InputError("", "tracer pulse duration (s)", "must be >= 0");
    }

    RtdResult res;
    res.used = opt.integrator;

    const double h = opt.timeStep;
    const int nPulse = opt.pulseDuration > 0 ? std::max(1, int(std::ceil(opt.pulseDuration/h - 1e-9))) : 0;
    const double hPulse = nPulse > 0 ? opt.pulseDuration/nPulse : 0.0;
    const double u = nPulse > 0 ? 1.0/opt.pulseDuration : 0.0;

    if (opt.integrator == RtdIntegrator::forwardEuler && opt.onUnstable != UnstableStepPolicy::unchecked)
    {
        // Sufficient (positivity) bound first: h max|K_jj| <= 1 makes I + hK
        // non-negative with column sums <= 1, so no eigenvalue check is needed
        const double diagMax = (-Eigen::VectorXd(sys.K.diagonal())).maxCoeff();
        if (h*diagMax > 1.0)
        {
            const double hmax = forwardEulerStepLimit(sys);
            if (h > hmax)
            {
                const std::string msg = "forward Euler is unstable: time step " + str(h)
                  + " s exceeds its stability limit " + str(hmax)
                  + " s (-2 Re(l)/|l|^2 over the eigenvalues of the network); use a step <= "
                  + str(hmax) + " s or the exact / trbdf2 / backwardEuler integrator";
                if (opt.onUnstable == UnstableStepPolicy::error)
                {
                    throw InputError("", "integrator timeStep", msg);
                }
                res.used = RtdIntegrator::trbdf2;
                res.warnings.push_back(msg + "; fell back to trbdf2");
            }
            else
            {
                res.warnings.push_back("forward Euler step " + str(h)
                  + " s is stable but above the positivity bound " + str(1.0/diagMax)
                  + " s: E(t) may oscillate");
            }
        }
    }

    const Eigen::Index n = sys.size();
    Vec y = Vec::Zero(n);
    double t = 0;
    res.time.push_back(0);
    if (nPulse == 0)
    {
        y = sys.b;      // impulse
    }
    res.E.push_back(sys.c.dot(y));

    const bool guard = opt.onUnstable != UnstableStepPolicy::unchecked;
    auto check = [&](double injected)
    {
        if (!guard)
        {
            return;
        }
        const double inventory = y.sum();
        const double scale = 1e-8 + 1e-6*injected;
        if (!std::isfinite(inventory) || inventory > injected + scale || y.minCoeff() < -0.1*injected - 1e-12)
        {
            throw InputError("", "integrator timeStep",
                toString(res.used) + " run became unstable at t = " + str(t)
              + " s (tracer inventory " + str(inventory) + " of " + str(injected)
              + " injected); reduce the time step or use the exact integrator");
        }
    };

    if (nPulse > 0)
    {
        const auto pulse = makeStepper(res.used, sys, hPulse, u);
        for (int k = 0; k < nPulse; ++k)
        {
            y = pulse->step(y);
            t = (k + 1)*hPulse;
            res.time.push_back(t);
            res.E.push_back(sys.c.dot(y));
            check(t*u);
        }
    }

    const auto stepper = makeStepper(res.used, sys, h, 0.0);
    const double target = 1.0 - opt.recovery;
    long steps = 0;
    double lastReport = -1;
    while (y.sum() > target)
    {
        if (++steps > opt.maxSteps)
        {
            throw InputError("", "RTD recovery",
                "recovery " + str(opt.recovery) + " not reached within " + std::to_string(opt.maxSteps)
              + " steps of " + str(h) + " s (only " + str(1.0 - y.sum()) + " recovered)");
        }
        y = stepper->step(y);
        t += h;
        res.time.push_back(t);
        res.E.push_back(sys.c.dot(y));
        check(1.0);
        if (opt.progress && 1.0 - y.sum() - lastReport > 0.05)
        {
            lastReport = 1.0 - y.sum();
            opt.progress(lastReport/opt.recovery);
        }
        if (!guard && !std::isfinite(y.sum()))
        {
            break;
        }
    }
    res.recovered = 1.0 - y.sum();
    if (opt.progress)
    {
        opt.progress(1.0);
    }
    return res;
}


std::vector<double> exactRtdAt
(
    const TracerSystem& sys,
    const double T,
    const std::vector<double>& times
)
{
    const Eigen::Index n = sys.size();

    // Response inside the pulse: integrate from 0 with input 1/T
    auto insidePulse = [&](double t)
    {
        Vec z = Vec::Zero(n + 1);
        z(0) = 1.0;
        return Vec((augmentedExponential(sys, t, 1.0/T)*z).tail(n));
    };

    // State at the end of the pulse (or the impulse at t = 0)
    const Vec yT = T > 0 ? insidePulse(T) : Vec(sys.b);

    // Samples after the pulse: intervals between them are usually multiples
    // of a common step (a logger's clock), so one propagator exp(K g) and
    // matrix-vector products replace one matrix exponential per interval
    std::vector<double> after;
    for (const double t : times)
    {
        if (t >= T) after.push_back(t);
    }
    for (std::size_t j = 1; j < after.size(); ++j)
    {
        if (after[j] < after[j - 1])
        {
            throw InputError("", "RTD sample times", "times must be ascending");
        }
    }
    auto fgcd = [](double x, double y)
    {
        const double tol = 1e-6*std::max(1.0, std::max(x, y));
        while (y > tol)
        {
            double r = std::fmod(x, y);
            if (y - r < tol) r = 0;
            x = y;
            y = r;
        }
        return x;
    };
    double g = 0;
    for (std::size_t j = 1; j < after.size(); ++j)
    {
        const double d = after[j] - after[j - 1];
        if (d > 1e-9) g = g == 0 ? d : fgcd(std::max(g, d), std::min(g, d));
    }
    for (std::size_t j = 1; j < after.size() && g > 0; ++j)
    {
        const double k = (after[j] - after[j - 1])/g;
        if (std::abs(k - std::round(k)) > 1e-6) g = 0;
    }
    const double span = after.empty() ? 0.0 : after.back() - after.front();
    const bool stepping = g > 0 && span/g < 200.0*after.size() + 2000.0;

    std::map<double, BandedMatrix> cache;
    auto phi = [&](double dt) -> const BandedMatrix&
    {
        auto it = cache.find(dt);
        if (it == cache.end())
        {
            it = cache.emplace(dt, metzlerExponential(sys.K, dt)).first;
        }
        return it->second;
    };

    std::vector<double> E;
    E.reserve(times.size());
    double tPrev = T;
    Vec y = yT;
    bool first = true;
    for (const double t : times)
    {
        if (t < 0)
        {
            E.push_back(0);
            continue;
        }
        if (t < T)
        {
            E.push_back(sys.c.dot(insidePulse(t)));
            continue;
        }
        const double dt = t - tPrev;
        if (dt > 0)
        {
            if (stepping && !first)
            {
                const long k = std::lround(dt/g);
                const BandedMatrix& P = phi(g);
                for (long s = 0; s < k; ++s) y = P*y;
            }
            else
            {
                y = phi(dt)*y;
            }
        }
        first = false;
        tPrev = t;
        E.push_back(sys.c.dot(y));
    }
    return E;
}

} // namespace drum
