#include "particleDrag/loneParticleFall.hpp"

#include <array>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace particleDrag
{

namespace
{

void requirePositive(double value, const char* what)
{
    if (!(value > 0.0) || !std::isfinite(value))
    {
        std::ostringstream os;
        os << what << " = " << value << " must be positive and finite";
        throw std::invalid_argument(os.str());
    }
}

void checkInputs(const Particle& p, const Gas& gas)
{
    requirePositive(p.diameter, "particle diameter");
    requirePositive(p.density, "particle density");
    requirePositive(gas.density, "gas density");
    requirePositive(gas.viscosity, "gas viscosity");
}

// Drag acceleration coefficient beta [1/s] such that the drag acceleration
// on a lone particle is beta * slip: beta = 3/4 Cd Re mu/(rho_p d^2)
double dragRate(const DragLaw& law, const Particle& p, const Gas& gas, double slipMag)
{
    const double Re = gas.density*slipMag*p.diameter/gas.viscosity;
    return 0.75*law.CdRe(Re)*gas.viscosity/(p.density*p.diameter*p.diameter);
}

} // namespace


double fallTime(double height)
{
    if (!(height >= 0.0) || !std::isfinite(height))
    {
        std::ostringstream os;
        os << "fall height " << height << " m outside [0, inf)";
        throw std::invalid_argument(os.str());
    }
    return std::sqrt(2.0*height/gravity);  // Eq 19
}

double dragParameter(const DragLaw& law, const Particle& p, const Gas& gas, double slip)
{
    checkInputs(p, gas);
    const double Re = gas.density*std::abs(slip)*p.diameter/gas.viscosity;
    const double Cd = law.Cd(Re);
    return 3.0*Cd*gas.density/(4.0*p.diameter*p.density);  // Eq 14
}

double axialAdvance(double K, double Vg, double alpha, double t)
{
    if (!(K >= 0.0) || !std::isfinite(K))
    {
        std::ostringstream os;
        os << "drag parameter K = " << K << " 1/m outside [0, inf)";
        throw std::invalid_argument(os.str());
    }
    const double gs = gravity*std::sin(std::abs(alpha));
    if (K == 0.0)
    {
        return Vg*t + 0.5*gravity*std::sin(alpha)*t*t;
    }
    // Horizontal drum, or an incline too small to resolve next to the drag
    if (gs <= 1e-14*K*Vg*Vg || alpha == 0.0)
    {
        return Vg*t + std::log(1.0/(K*Vg*t + 1.0))/K;  // Eq 17
    }

    const double a = std::sqrt(gs/K);  // Eq 15
    if (alpha < 0)
    {
        // Eq 13: gravity pulls back against the gas; the slip tends to a
        return (Vg - a)*t
            - std::log((a + Vg + (a - Vg)*std::exp(-2.0*a*K*t))/(2.0*a))/K;
    }

    // Eq 16: gravity and gas both push forward. Valid while the particle is
    // slower than the gas, t <= t0; past t0 the drag reverses (Eq 12 with
    // (V_g - V_x)|V_g - V_x|) and the slip tends to -a.
    const double c = std::atan(Vg/a);
    const double t0 = c/(a*K);
    if (t <= t0)
    {
        return Vg*t + std::log(std::cos(c)/std::cos(c - a*K*t))/K;
    }
    const double x0 = Vg*t0 + std::log(std::cos(c))/K;
    const double s = a*K*(t - t0);
    // ln cosh(s), written to avoid overflow for large s
    const double lnCosh = s + std::log1p(std::exp(-2.0*s)) - std::log(2.0);
    return x0 + Vg*(t - t0) + lnCosh/K;
}

double loneParticleAdvance
(
    const DragLaw& law,
    const Particle& p,
    const Gas& gas,
    double Vg,
    double height,
    double alpha
)
{
    const double t = fallTime(height);
    if (Vg == 0.0)
    {
        return height*std::sin(alpha);  // as Sherritt's falladvance()
    }
    const double K = dragParameter(law, p, gas, Vg);
    return axialAdvance(K, Vg, alpha, t);
}

FallResult integrateFall
(
    const DragLaw& law,
    const Particle& p,
    const Gas& gas,
    double Vg,
    double height,
    double alpha,
    const FallIntegration& options
)
{
    checkInputs(p, gas);
    if (options.steps < 1)
    {
        throw std::invalid_argument("integrateFall: steps must be >= 1");
    }
    if (!(options.releaseVelocity >= 0.0))
    {
        throw std::invalid_argument("integrateFall: releaseVelocity must be >= 0");
    }
    const double w0 = options.releaseVelocity;
    // Drag-free fall time from height = w0 t + g t^2/2 (Eq 19 when w0 = 0)
    const double tFree = w0 > 0.0
        ? (std::sqrt(w0*w0 + 2.0*gravity*height) - w0)/gravity
        : fallTime(height);
    FallResult result;
    if (height == 0.0)
    {
        return result;
    }

    const double gAxial = gravity*std::sin(alpha);
    const double K0 = options.constantK ? dragParameter(law, p, gas, Vg) : 0.0;

    // State: x (axial), u (axial velocity), z (distance fallen), w (fall speed)
    using State = std::array<double, 4>;
    auto rhs = [&](const State& s) -> State
    {
        const double ux = Vg - s[1];
        if (!options.verticalDrag)
        {
            const double ax = options.constantK
                ? gAxial + K0*ux*std::abs(ux)                    // Eq 12
                : gAxial + dragRate(law, p, gas, std::abs(ux))*ux;
            return {s[1], ax, s[3], gravity};
        }
        const double slip = std::hypot(ux, s[3]);
        const double beta = dragRate(law, p, gas, slip);
        return {s[1], gAxial + beta*ux, s[3], gravity - beta*s[3]};
    };
    auto rk4 = [&](const State& s, double h) -> State
    {
        auto add = [](const State& a, const State& b, double f)
        {
            return State{a[0] + f*b[0], a[1] + f*b[1], a[2] + f*b[2], a[3] + f*b[3]};
        };
        const State k1 = rhs(s);
        const State k2 = rhs(add(s, k1, 0.5*h));
        const State k3 = rhs(add(s, k2, 0.5*h));
        const State k4 = rhs(add(s, k3, h));
        State r;
        for (int i = 0; i < 4; ++i)
        {
            r[i] = s[i] + h/6.0*(k1[i] + 2*k2[i] + 2*k3[i] + k4[i]);
        }
        return r;
    };

    // Stiff drag (fine particles): the fastest rate of the linearised
    // drag, lambda, bounds the RK4 step (stable for h lambda < 2.78, five
    // significant figures need h lambda <= 0.5). The requested step count
    // is refined automatically; beyond maxStiffSteps the particle follows
    // the gas and the call refuses rather than return an unstable answer.
    const double slipMax = options.verticalDrag
        ? std::hypot(Vg, w0 + gravity*tFree) + std::abs(gAxial)*tFree
        : Vg + std::abs(gAxial)*tFree;
    const double lambda = options.constantK
        ? 2.0*K0*std::max(Vg, std::sqrt(std::abs(gAxial)/std::max(K0, 1e-300)))
        : 2.0*dragRate(law, p, gas, std::max(slipMax, 1e-12));
    double h = tFree/options.steps;
    if (lambda*h > 0.5)
    {
        h = 0.5/lambda;
    }
    const long nFixed = std::lround(std::ceil(tFree/h - 1e-9));
    if (nFixed > options.maxStiffSteps)
    {
        std::ostringstream os;
        os << "integrateFall: stiff drag: the particle (d = " << p.diameter
           << " m) relaxes to the gas in 1/lambda = " << 1.0/lambda
           << " s, " << tFree*lambda << " times shorter than its fall; the"
           << " stable step count " << nFixed << " exceeds maxStiffSteps "
           << options.maxStiffSteps << ". Such a particle follows the gas:"
           << " its advance is the gas velocity times its settling time.";
        throw std::runtime_error(os.str());
    }
    h = tFree/std::max<long>(nFixed, options.steps);
    State s{0, 0, 0, w0};
    double t = 0;
    long stepsTaken = 0;

    if (!options.verticalDrag)
    {
        // The fall time is Eq 19 exactly: fixed steps land on it
        const long n = std::max<long>(nFixed, options.steps);
        for (long i = 0; i < n; ++i)
        {
            s = rk4(s, h);
        }
        t = tFree;
        stepsTaken = n;
    }
    else
    {
        // Step until the floor is passed, then bisect the last step
        const long maxSteps =
            std::max<long>(1000L*options.steps, options.maxStiffSteps);
        long n = 0;
        for (;;)
        {
            const State next = rk4(s, h);
            if (next[2] >= height)
            {
                double lo = 0, hi = h;
                for (int it = 0; it < 200 && hi - lo > 1e-15*(t + h); ++it)
                {
                    const double mid = 0.5*(lo + hi);
                    (rk4(s, mid)[2] >= height ? hi : lo) = mid;
                }
                s = rk4(s, hi);
                t += hi;
                stepsTaken = n + 1;
                break;
            }
            s = next;
            t += h;
            stepsTaken = n + 1;
            if (++n > maxSteps)
            {
                throw std::runtime_error
                (
                    "integrateFall: particle did not reach the floor "
                    "(terminal velocity too small for the step count)"
                );
            }
        }
    }

    result.advance = s[0];
    result.time = t;
    result.steps = stepsTaken;
    result.axialVelocity = s[1];
    return result;
}

double terminalVelocity(const DragLaw& law, const Particle& p, const Gas& gas)
{
    checkInputs(p, gas);
    if (p.density <= gas.density)
    {
        throw std::invalid_argument
        (
            "terminalVelocity: particle density must exceed gas density"
        );
    }
    // drag pi/8 d mu v CdRe(Re) = net weight (rho_p - rho_g) g pi d^3/6
    const double weight = (p.density - gas.density)*gravity*p.diameter*p.diameter/6.0;
    auto excess = [&](double v)
    {
        const double Re = gas.density*v*p.diameter/gas.viscosity;
        return 0.125*gas.viscosity*v*law.CdRe(Re) - weight;
    };
    double lo = 0, hi = 1e-3;
    while (excess(hi) < 0)
    {
        lo = hi;
        hi *= 2;
        if (hi > 1e6)
        {
            throw std::runtime_error("terminalVelocity: no root below 1e6 m/s");
        }
    }
    for (int i = 0; i < 200 && hi - lo > 1e-14*hi; ++i)
    {
        const double mid = 0.5*(lo + hi);
        (excess(mid) < 0 ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}

} // namespace particleDrag
