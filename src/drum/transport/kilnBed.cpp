#include "drum/transport/kilnBed.hpp"

#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

double saemanFlowScale(const SaemanKiln& k)
{
    requirePositive(k.drumDiameter, "kiln bed: drum diameter (m)");
    requirePositive(k.speed, "kiln bed: drum speed (rev/s)");
    requirePositive(k.bulkDensity, "kiln bed: bulk density (kg/m3)");
    requireInRange(k.repose, 1e-3, 0.5*pi, "kiln bed: angle of repose (rad)");
    const double advance = k.drumSlope + k.bedSlope*std::cos(k.repose);
    if (!(advance > 0))
    {
        std::ostringstream os;
        os << "alpha + gamma cos(phi) = " << advance << " rad: a level drum with a level bed does not "
              "advance its bed (Eq 22); give a drum slope or a bed slope > 0";
        throw InputError("", "kiln bed", os.str());
    }
    const double D = k.drumDiameter;
    return pi*k.speed*D*D*D*k.bulkDensity/6*advance/std::sin(k.repose);   // Eq 22 without sin^3(beta/2)
}


double saemanBedFlow(const SaemanKiln& k, double beta)
{
    const double s = std::sin(0.5*std::min(std::max(beta, 0.0), pi));
    return saemanFlowScale(k)*s*s*s;   // Eq 22, chord D sin(beta/2) (Eq 23)
}


double bedArea(double D, double beta)
{
    return D*D/8*(beta - std::sin(beta));
}


double fillAngle(double D, double area)
{
    // beta - sin(beta) = 8A/D^2 is monotone on [0, 2 pi]: bisection to round-off
    const double target = 8*area/(D*D);
    double lo = 0, hi = 2*pi;
    if (!(target > 0)) return 0;
    if (target >= 2*pi) return 2*pi;
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it)
    {
        const double mid = 0.5*(lo + hi);
        (mid - std::sin(mid) < target ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}


double saemanKilnMass(const SaemanKiln& k, double dz, double flow)
{
    if (!(flow > 0)) return 0;
    const double top = saemanFlowScale(k);
    if (flow > top)
    {
        std::ostringstream os;
        os << "the rolling bed cannot carry " << flow << " kg/s: Eq 22 gives at most " << top
           << " kg/s (half fill) at this drum's speed, slope and angle of repose";
        throw InputError("", "kiln bed", os.str());
    }
    const double beta = 2*std::asin(std::cbrt(flow/top));
    return k.bulkDensity*dz*bedArea(k.drumDiameter, beta);
}


double saemanKilnFlow(const SaemanKiln& k, double dz, double kilnMass)
{
    if (!(kilnMass > 0)) return 0;
    return saemanBedFlow(k, fillAngle(k.drumDiameter, kilnMass/(k.bulkDensity*dz)));
}

double bedDepth(double D, double beta)
{
    return 0.5*D*(1 - std::cos(0.5*beta));
}


namespace
{

// Eq 22 with gamma from the depths, no checks (may be <= 0)
double profileFlow(const SaemanKiln& k, double dz, double beta, double nextDepth)
{
    const double D = k.drumDiameter;
    const double gamma = (bedDepth(D, beta) - nextDepth)/dz;
    const double s = std::sin(0.5*std::min(std::max(beta, 0.0), pi));
    return pi*k.speed*D*D*D*k.bulkDensity/6*(k.drumSlope + gamma*std::cos(k.repose))/std::sin(k.repose)*s*s*s;
}

} // namespace


double saemanKilnMass(const SaemanKiln& k, double dz, double flow, double nextDepth)
{
    SaemanKiln level = k;
    level.bedSlope = 0;
    saemanFlowScale(level);   // checks the drum, bed and angle
    if (!(flow > 0)) return 0;
    if (profileFlow(k, dz, pi, nextDepth) < flow)
    {
        std::ostringstream os;
        os << "the rolling bed cannot carry " << flow << " kg/s: Eq 22 with the bed slope to the next slice gives at "
           << "most " << profileFlow(k, dz, pi, nextDepth) << " kg/s (half fill)";
        throw InputError("", "kiln bed", os.str());
    }
    // the flow rises with the fill (deeper bed, steeper surface): bisection to round-off
    double lo = 0, hi = pi;
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it)
    {
        const double mid = 0.5*(lo + hi);
        (profileFlow(k, dz, mid, nextDepth) < flow ? lo : hi) = mid;
    }
    return k.bulkDensity*dz*bedArea(k.drumDiameter, 0.5*(lo + hi));
}


double saemanKilnFlow(const SaemanKiln& k, double dz, double kilnMass, double nextDepth)
{
    if (!(kilnMass > 0)) return 0;
    const double beta = fillAngle(k.drumDiameter, kilnMass/(k.bulkDensity*dz));
    return std::max(profileFlow(k, dz, std::min(beta, pi), nextDepth), 0.0);
}

} // namespace drum
