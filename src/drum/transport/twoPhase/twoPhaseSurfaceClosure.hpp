// The dense-phase surface closure of Sherritt's two-phase model: how many
// non-discharging flights carry a rolling surface that slopes along the
// drum, and how long that surface (chord c) is. The thesis calls it the
// model's weakest point (Sherritt 1991 §3.5, §5.1.10), so it is pluggable.
#ifndef DRUM_TRANSPORT_TWOPHASESURFACECLOSURE_HPP
#define DRUM_TRANSPORT_TWOPHASESURFACECLOSURE_HPP

#include <functional>

namespace drum
{

struct SurfaceClosureInput
{
    double dischargeAngle = 0;   //!< theta_i, rad
    double thetaD = 0;           //!< Eq 70 (centrefill)
    double thetaF = 0;           //!< Eq 71, 2 pi - theta_i
    double thetaA = 0;           //!< Eq 35
    double thetaB = 0;           //!< Eq 36
    bool centrefill = false;
    int exteriorCount = 0;       //!< N_ex
    double surfaceAtDischarge = 0; //!< l_ex(theta_i), m
    double repose = 0;           //!< phi, rad
};

struct SlopedSurfaces
{
    double count = 0;  //!< N_ex,s
    double chord = 0;  //!< c on the sloped flights, m
};

using SurfaceClosure = std::function<SlopedSurfaces(const SurfaceClosureInput&)>;

//- Sherritt 1991: c = l_ex(theta_i) (Eq 77), c = 0 elsewhere (Eqs 76, 78);
//  N_ex,s from Eq 80 (discharge starting over the centrefill), Eq 83
//  (underloaded otherwise) or Eq 84 (overloaded: 1)
SlopedSurfaces sherrittSurfaceClosure(const SurfaceClosureInput& in);

} // namespace drum

#endif
