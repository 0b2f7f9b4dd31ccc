// The isolated-particle fall through a horizontal gas stream,
// Sherritt 1991 section 2.4.1 and Chapter 4 (code ADVANCE.C).
//
// A particle released at rest falls a height y in t = sqrt(2y/g) (Eq 19,
// vertical drag neglected) while the gas V_g and the drum incline alpha push
// it along the drum axis (Eq 12):
//     dV_x/dt = g sin(alpha) + K (V_g - V_x)|V_g - V_x|,
//     K = 3 Cd rho_g / (4 D_p rho_p)                              (Eq 14)
// With K held at its value for the full slip (V_x = 0), Eq 12 integrates
// in closed form: Eq 13 (alpha < 0), Eq 16 (alpha > 0), Eq 17 (alpha = 0).
#ifndef PARTICLEDRAG_LONEPARTICLEFALL_HPP
#define PARTICLEDRAG_LONEPARTICLEFALL_HPP

#include "particleDrag/dragLaw.hpp"
#include "particleDrag/gasProperties.hpp"

namespace particleDrag
{

//- A particle: diameter used in the drag law (sieve size x sphericity in
//  Sherritt's code) and its density
struct Particle
{
    double diameter = 1e-3;  //!< m
    double density = 2650.0; //!< kg/m3
};

//- Fall time from rest over height y [m], Eq 19
double fallTime(double height);

//- Drag parameter K [1/m] of Eq 14, with Cd evaluated once at the slip
//  velocity |slip| (Sherritt's code evaluates it at the full gas velocity)
double dragParameter(const DragLaw& law, const Particle& p, const Gas& gas, double slip);

//- Axial displacement [m] in time t [s] of a particle starting at rest, gas
//  velocity Vg [m/s] along +x, drum incline alpha [rad] (positive: slopes
//  down along the gas flow), constant K [1/m]. Closed forms Eqs 13, 16, 17;
//  with Vg = 0 and K = 0 it is the free slide g sin(alpha) t^2 / 2.
double axialAdvance(double K, double Vg, double alpha, double t);

//- The whole of Sherritt's lone-particle model for one particle: Cd at the
//  full slip Vg, K from Eq 14, fall time from Eq 19, advance from Eqs 13/16/17.
//  With Vg = 0 returns y sin(alpha) as Sherritt's code does.
double loneParticleAdvance
(
    const DragLaw& law,
    const Particle& p,
    const Gas& gas,
    double Vg,
    double height,
    double alpha = 0.0
);

//- Options for the numerical integration of Eq 12
struct FallIntegration
{
    //- Hold K at its initial value (true: Eq 12 as Sherritt solved it;
    //  false: Cd re-evaluated from the instantaneous slip)
    bool constantK = true;

    //- Also integrate the vertical motion with drag (true) or use the
    //  drag-free fall of Eq 19 (false)
    bool verticalDrag = false;

    //- Number of RK4 steps over the fall (refined automatically where the
    //  drag is stiff, so that h lambda <= 0.5 with lambda the fastest rate
    //  of the linearised drag)
    int steps = 4000;

    //- Most steps the stiff-drag refinement may take; beyond it the call
    //  throws (the particle follows the gas; see integrateFall)
    long maxStiffSteps = 5000000;

    //- Downward speed at release [m/s], >= 0 (a curtain leaves its slot
    //  at the release velocity, not at rest); 0 is Sherritt's start
    double releaseVelocity = 0.0;
};

//- Result of a numerical fall
struct FallResult
{
    double advance = 0;       //!< axial displacement at the floor, m
    double time = 0;          //!< fall time, s
    double axialVelocity = 0; //!< V_x at the floor, m/s
    long steps = 0;           //!< RK4 steps taken (> requested when stiff)
};

//- RK4 integration of Eq 12 (and optionally the vertical momentum balance
//  with drag on the full slip vector) from rest down a height y.
FallResult integrateFall
(
    const DragLaw& law,
    const Particle& p,
    const Gas& gas,
    double Vg,
    double height,
    double alpha = 0.0,
    const FallIntegration& options = FallIntegration()
);

//- Terminal settling velocity [m/s] of a particle in still gas (drag = net
//  weight), by bracketed root finding on Cd(Re)
double terminalVelocity(const DragLaw& law, const Particle& p, const Gas& gas);

} // namespace particleDrag

#endif
