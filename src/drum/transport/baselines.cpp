#include "drum/transport/baselines.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>

namespace drum
{
namespace baselines
{

namespace
{
constexpr double g = 9.81;
constexpr double ft = 0.3048;
double sign(GasFlow f) { return f == GasFlow::counterCurrent ? 1.0 : -1.0; }
}

double friedmanMarshall
(
    const double L, const double D, const double slope, const double rpm,
    const double G, const double F, const double Dp, const GasFlow flow
)
{
    requirePositive(L, "drum length (m)");
    requirePositive(D, "drum diameter (m)");
    requirePositive(slope, "drum slope (rad), Friedman-Marshall needs an inclined drum");
    requirePositive(rpm, "drum speed (rpm)");
    requirePositive(F, "solids mass flux");
    requirePositive(Dp, "particle diameter (m)");
    if (G < 0) throw InputError("", "gas mass flux", "must be >= 0");
    const double S = std::tan(slope);
    const double B = 5.0*std::pow(Dp*1e6, -0.5);
    const double tMin = 0.23*(L/ft)/(S*std::pow(rpm, 0.9)*(D/ft)) + sign(flow)*0.6*B*(L/ft)*G/F;
    if (tMin <= 0)
    {
        throw InputError("", "gas mass flux", "Friedman-Marshall gives a non-positive residence time: gas rate outside its range");
    }
    return 60.0*tMin;
}

double saemanMitchell
(
    const double L, const double D, const double n, const double slope,
    const double f, const double m, const double Vg, const GasFlow flow
)
{
    requirePositive(L, "drum length (m)");
    requirePositive(D, "drum diameter (m)");
    requirePositive(n, "drum speed (rev/s)");
    requirePositive(f, "cascade factor f(H)");
    const double denom = std::tan(slope) - sign(flow)*m*Vg;
    if (denom <= 0)
    {
        throw InputError("", "gas velocity", "Saeman-Mitchell: tan(alpha) -+ m V_g must be > 0");
    }
    return L/(f*D*n*denom);
}

double matchettBaker
(
    const double L, const double D, const double n, const double slope,
    const double ta, const double vs, const double alpha
)
{
    requirePositive(L, "drum length (m)");
    requirePositive(n, "drum speed (rev/s)");
    requirePositive(ta, "fall time (s)");
    const double v = vs + alpha*D*std::tan(slope)/(2.0*ta);
    if (v <= 0)
    {
        throw InputError("", "airborne velocity", "Matchett-Baker: net axial velocity must be > 0");
    }
    // M_T/F, Lee Eq 2.10
    return L*(2.0*n*ta + 1.0)/(2.0*n*ta*v);
}

double schofieldGlikin
(
    const double L, const double slope, const double n, const double h, const double psiDeg,
    const double V, const GasFlow flow,
    const double Dp, const double rhoP, const double rhoG, const double muG
)
{
    requirePositive(L, "drum length (m)");
    requirePositive(n, "drum speed (rev/s)");
    requirePositive(h, "mean fall height (m)");
    requirePositive(Dp, "particle diameter (m)");
    requirePositive(rhoP, "particle density (kg/m3)");
    const double tf = std::sqrt(2.0*h/g);                  // Sherritt Eq 19
    double K = 0;
    if (V > 0)
    {
        const double Re = rhoG*V*Dp/muG;
        const double Cd = 24.0/Re*(1.0 + 0.15*std::pow(Re, 0.687));   // Lee Eq 2.13
        K = 3.0*Cd*rhoG/(4.0*Dp*rhoP);
    }
    const double advance = h*std::sin(slope) - sign(flow)*0.5*K*V*V*tf*tf;
    if (advance <= 0)
    {
        throw InputError("", "gas velocity",
            "Schofield-Glikin: countercurrent drag stops the advance (h sin(theta) <= K V^2 t^2/2)");
    }
    const double cycle = tf + psiDeg/(180.0*n);
    return L*cycle/advance;
}

double tanksInSeriesE(const double t, const double tau, const double N)
{
    requirePositive(tau, "mean residence time (s)");
    requireInRange(N, 1.0, 1e6, "number of tanks");
    if (t <= 0)
    {
        return N == 1.0 && t == 0 ? 1.0/tau : 0.0;
    }
    const double x = t/tau;
    return std::exp(N*std::log(N) - std::lgamma(N) + (N - 1.0)*std::log(x) - N*x)/tau;
}

double tanksInSeriesN(const double mean, const double sd)
{
    requirePositive(mean, "mean residence time");
    requirePositive(sd, "residence time SD");
    return (mean/sd)*(mean/sd);
}

} // namespace baselines
} // namespace drum
