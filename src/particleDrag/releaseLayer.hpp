// The layer of solids a flight releases: a spill rate S [kg/(m s)] leaves
// through a layer of thickness b [m] at the release speed v [m/s] with solids
// fraction alpha, S = alpha rho_p b v (Lee 2008 Eq 5.4, per metre of flight).
// C++11-clean: the OpenFOAM library includes it.
#ifndef PARTICLEDRAG_RELEASELAYER_HPP
#define PARTICLEDRAG_RELEASELAYER_HPP

namespace particleDrag
{

//- The largest spill rate the curtain tools take, kg/(m s) (curtainInlet,
//  curtainCase, buildDriftTable, the segment table)
constexpr double maxSpillRate = 1000.0;

//- The solids fraction at the curtain's edge (Lee 2008's 5.6e-4): the gas inside
//  the curtain is read where the solids fraction reaches it (curtainSolids,
//  curtainGasVelocity, curtainEdges), and a curtain that never reaches it does not
//  shield the gas (the drift table's V_c/V_g 1; dryerStudy's lone-particle scene)
constexpr double curtainEdgeSolidsFraction = 5.6e-4;

//- Solids fraction at the slot, alpha = S/(rho_p b v)
inline double slotSolidsFraction(double spill, double rhoP, double thickness, double velocity)
{
    return spill/(rhoP*thickness*velocity);
}

//- Thickness of the layer that carries S at the solids density rho_s (the bulk
//  density: a packed layer), b = S/(rho_s v)
inline double releaseLayerThickness(double spill, double solidsDensity, double velocity)
{
    return spill/(solidsDensity*velocity);
}

} // namespace particleDrag

#endif
