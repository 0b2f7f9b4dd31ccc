// Tracer network of Sherritt's (1991) two-phase model, so the model gives a
// residence-time distribution and not only the mean (Eqs 138-140).
//
// The drum is cut into N axial slices of length dz. In each slice and for
// each size class k there is a dense compartment (material in the flights
// and any overload bed, bulk holdup H - H_1) and an airborne compartment
// (the curtains, H_1, Eq 91). The steady two-phase solution (profile of
// the axial or constant-holdup solve) gives every flow:
//   * circulation dense -> airborne  x_d,k Q dz, Q = n rho_b/2 (N_ex int
//     l_ex^2 + N_in int l_in^2) (Eqs 40/41 summed over the discharge arcs);
//   * every fall lands in the dense phase, advanced by the mass-weighted
//     mean advance per fall delta_k = A_k/Q, A_k = F_1,k/x_d,k (Eq 51): the
//     landing is split between the slices j and j+1 that bracket
//     delta_k/dz, so the axial airborne flux is x_d,k A_k = F_1,k exactly;
//   * the dense flow x_d,k F_2 (Eqs 79/86 or imposed) goes to the next
//     slice (upwind), F_2 being size independent (Eq 52);
//   * optional dense-phase axial dispersion D_z (Sherritt 2001 Eq 27, e.g.
//     from the Eq 51/84 correlation) as a symmetric exchange
//     D_eff M/dz^2 between neighbouring dense compartments, with the
//     upwind scheme's numerical part u_2 dz/2 subtracted (Sherritt 2001
//     docs/errata.md, coupling note).
// Feed enters the first slice's dense phase; what passes the last slice
// leaves. Falls that would land before the feed end stay in the first slice.
// Per class the network's holdup/feed equals Sherritt's T_k (Eq 139) up to
// the slice sampling of the profile (and that reflection).
//
// With dz equal to the mean advance per fall, each fall moves the tracer
// about one slice: the spread then comes from the random number of
// lift-and-fall cycles (exponential holding times), which is the only
// dispersion mechanism the two-phase model has. A coarser slicing adds the
// upwind scheme's dispersion u dz/2.
#ifndef DRUM_TRANSPORT_TWOPHASETRACER_HPP
#define DRUM_TRANSPORT_TWOPHASETRACER_HPP

#include "drum/rtd/tracerSystem.hpp"
#include "drum/transport/twoPhase/twoPhaseModel.hpp"

#include <vector>

namespace drum
{

struct TwoPhaseTracerOptions
{
    //- Axial slices; 0: L over the feed-weighted mean advance per fall,
    //  clamped to [minSlices, maxSlices]
    int slices = 0;
    int minSlices = 20;
    int maxSlices = 400;

    //- Dense-phase axial dispersion coefficient D_z [m2/s] (0: none)
    double denseDispersion = 0;

    //- Subtract the upwind scheme's numerical dispersion u_2 dz/2 from D_z
    bool subtractNumericalDispersion = true;
};

struct TwoPhaseTracerNetwork
{
    //- All size classes, one block each (2 N states: dense, airborne per
    //  slice, feed end first); b carries the feed fractions x_f,k, so c y is
    //  the overall E(t) of a tracer with the feed's size distribution
    TracerSystem system;

    //- One system per size class (b = unit injection), for T_k and E_k(t);
    //  classes with x_f,k = 0 have an empty system
    std::vector<TracerSystem> classSystems;
    std::vector<double> feedFractions;   //!< x_f,k (normalised)

    int slices = 0;
    double sliceLength = 0;               //!< dz, m
    bool slicesClamped = false;           //!< auto slicing hit min/max
    std::vector<double> meanAdvance;      //!< delta_k per fall at the feed end, m
    double effectiveDenseDispersion = 0;  //!< D_z after subtracting u_2 dz/2 (mean), m2/s
    double numericalDenseDispersion = 0;  //!< u_2 dz/2 (mean over slices), m2/s
};

//- Build the network from a solution of the model (solveAxial or
//  solveConstantHoldup; a DRUM1 result without profile is taken as
//  constant along the drum). Throws InputError for a profile the network
//  cannot represent (negative holdup or circulation).
TwoPhaseTracerNetwork twoPhaseTracerNetwork
(
    const TwoPhaseModel& model,
    const TwoPhaseResult& result,
    const TwoPhaseTracerOptions& options = {}
);

} // namespace drum

#endif
