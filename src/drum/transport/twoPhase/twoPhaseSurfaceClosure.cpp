#include "drum/transport/twoPhase/twoPhaseSurfaceClosure.hpp"
#include "drum/numerics/constants.hpp"

namespace drum
{

SlopedSurfaces sherrittSurfaceClosure(const SurfaceClosureInput& in)
{
    SlopedSurfaces out;
    out.chord = in.surfaceAtDischarge;  // Eq 77: c = l_ex(theta_i)
    const double N = in.exteriorCount;
    if (in.dischargeAngle <= pi)
    {
        out.count = 1;  // Eq 84, overloaded (and design loaded)
    }
    else if (in.centrefill && in.dischargeAngle >= in.thetaA && in.dischargeAngle <= in.thetaB)
    {
        out.count = N*(in.dischargeAngle - in.thetaD)/(2*pi) + 1;  // Eq 80
    }
    else
    {
        out.count = N*(in.dischargeAngle - in.thetaF)/(2*pi) + 1;  // Eq 83
    }
    return out;
}

} // namespace drum
