// Size classes in the compartment network: every class shares the slices'
// flights and kilning bed, but its curtains drift by its own size. A
// slice's release F_a = min(M_p, M_des)/t_p (Eq 3.2) and its kilning F_k are
// those of its whole passive mass M_p = sum_k M_p,k, and each class leaves
// in proportion to its share x_k = M_p,k/M_p (flights and bed well mixed);
// class k's curtain then splits with its own C_F,k, C_B,k (Eqs 3.7-3.8 per
// class, as Sherritt 1991 Eq 139 treats each class in its own curtain).
//
// Steady state, slice by slice from the discharge end as for one class:
// across the downstream face of slice i each class passes its feed,
//   x_k (F_k(M_p) + C_F,k F_a(M_p)) = w_k F + F_b,k,i+1,
// and sum_k x_k = 1 fixes M_p (the left side grows with M_p; bisection).
// With one class this is CompartmentNetwork::steadyState.
//
// The tracer labels all classes in proportion to their feed (mass-weighted
// injection); class k's tracer network is the one-class network's with the
// class's flows and masses, so E(t) = sum_k w_k E_k(t) and the mean
// residence time is the total holdup over the feed, as for the bulk.
#ifndef DRUM_TRANSPORT_COMPARTMENT_COMPARTMENTSIZECLASSES_HPP
#define DRUM_TRANSPORT_COMPARTMENT_COMPARTMENTSIZECLASSES_HPP

#include "drum/transport/compartment/compartmentNetwork.hpp"

#include <vector>

namespace drum
{

//- One size class's feed share and per-slice curtain shares
struct SizeClassSplits
{
    double feedShare = 0;             //!< w_k, sums to 1 over the classes
    std::vector<double> forward;      //!< C_F,k per slice
    std::vector<double> back;         //!< C_B,k per slice
};

struct SizeClassSteadyState
{
    CompartmentSteadyState total;                 //!< the slices' sums over the classes
    std::vector<CompartmentSteadyState> classes;  //!< each class's masses and flows
};

//- Steady state of the network with size classes (the slices' own C_F, C_B
//  are not used). InputError for shares that do not sum to 1, splits of the
//  wrong length or with C_F + C_B > 1, or a slice that cannot pass its feed.
SizeClassSteadyState sizeClassSteadyState
(
    const CompartmentNetwork& network,
    const std::vector<SizeClassSplits>& classes
);

//- The classes' tracer networks side by side (class k's states at offset
//  2 N k), the injection split by feed share: one system whose E(t) and
//  moments are those of the mixture
TracerSystem sizeClassTracerSystem
(
    const CompartmentNetwork& network,
    const SizeClassSteadyState& state,
    const std::vector<SizeClassSplits>& classes
);

} // namespace drum

#endif
