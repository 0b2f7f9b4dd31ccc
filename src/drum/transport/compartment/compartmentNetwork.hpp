// Lee/Sheehan compartment ("slice") network of a flighted rotary dryer
// (Lee 2008 Ch. 3, App. 10.2 gPROMS code). N axial slices, each a passive
// cell (flights + kilning bed) and an active cell (falling curtain), both
// well mixed. Every flow is F = M/tau (Eq 3.1):
//
//   release    P_i -> A_i      F_a = min(M_p, M_des)/t_p           (Eq 3.2)
//   kilning    P_i -> P_{i+1}  F_k = max(M_p - M_des, 0)/t_kiln    (code law, errata 8)
//                              or, per slice, the rolling bed of that mass (Sherritt 1991 Eq 22)
//   return     A_i -> P_i      F_r = C_R M_a/t_a
//   forward    A_i -> P_{i+1}  F_x = C_F M_a/t_a                   (Eqs 3.7-3.8)
//   backmix    A_i -> P_{i-1}  F_b = C_B M_a/t_a ;  C_R + C_F + C_B = 1
//
// Boundaries as in the gPROMS connections: the backmix leaving A_1 goes back
// into P_1; the product is A_N's forward flow plus P_N's kilning flow.
#ifndef DRUM_TRANSPORT_COMPARTMENTNETWORK_HPP
#define DRUM_TRANSPORT_COMPARTMENTNETWORK_HPP

#include "drum/rtd/tracerSystem.hpp"
#include "drum/transport/kilnBed.hpp"

#include <Eigen/Dense>
#include <optional>
#include <vector>

namespace drum
{

//- Transport parameters of one slice
struct CompartmentSlice
{
    double designLoad;      //!< M_p,des: passive mass above which material kilns, kg
    double passiveTime;     //!< t_p: mean passive (flight) time, s
    double activeTime;      //!< t_a: mean fall time, s
    double forwardFraction; //!< C_F: share of the curtain landing in the next slice
    double backFraction;    //!< C_B: share pushed back into the previous slice
    //- Kilning from the rolling-bed equation (Sherritt 1991 Eq 22, kilnBed.hpp)
    //  instead of Lee's F_k = M_kiln/t_kiln: the kiln mass is this slice's
    //  bed of length `length`
    std::optional<SaemanKiln> saemanKiln = std::nullopt;
    double length = 0;      //!< slice length, m (with saemanKiln)
};

//- Steady state of the network: holdups and flows along the drum (slice 1 = feed end)
struct CompartmentSteadyState
{
    Eigen::VectorXd passiveMass;   //!< M_p per slice, kg
    Eigen::VectorXd activeMass;    //!< M_a per slice, kg
    Eigen::VectorXd kilnMass;      //!< M_p - M_des where positive, kg
    Eigen::VectorXd releaseFlow;   //!< F_a, P_i -> A_i, kg/s
    Eigen::VectorXd kilnFlow;      //!< F_k, P_i -> P_{i+1} (or product), kg/s
    Eigen::VectorXd forwardFlow;   //!< F_x, A_i -> P_{i+1} (or product), kg/s
    Eigen::VectorXd backFlow;      //!< F_b, A_i -> P_{i-1} (P_1 for i = 1), kg/s
    Eigen::VectorXd returnFlow;    //!< F_r, A_i -> P_i, kg/s

    double totalHoldup() const { return passiveMass.sum() + activeMass.sum(); }
    //- Active (airborne) mass over total holdup
    double airborneFraction() const { return activeMass.sum()/totalHoldup(); }
};

//- Extension beyond Lee's model (not in the thesis): each passive cell
//  exchanges material with a stagnant zone of mass massRatio*M_p at the
//  flow F_s = M_s/exchangeTime each way (no net flow, so the bulk steady
//  state is unchanged). A slowly exchanging zone gives the long RTD tail
//  that Lee's network cannot (his Ch. 8 asks for a revised structure).
struct StagnantExchange
{
    double massRatio = 0;       //!< M_s/M_p (0: none)
    double exchangeTime = 1;    //!< M_s/F_s, s
};

class CompartmentNetwork
{
public:
    //- feedRate in kg/s; kilnTime t_kiln in s (may be +inf: no kilning, or
    //  kilning only in the slices with a saemanKiln).
    //  Throws InputError for negative times, fractions outside [0,1] or
    //  C_F + C_B > 1.
    CompartmentNetwork(std::vector<CompartmentSlice> slices, double feedRate, double kilnTime);

    int nSlices() const { return int(slices_.size()); }
    const std::vector<CompartmentSlice>& slices() const { return slices_; }
    double feedRate() const { return feedRate_; }
    double kilnTime() const { return kilnTime_; }

    //- Exact steady state. At steady state the net axial flow across every
    //  slice boundary equals the feed, F_k,i + F_x,i - F_b,i+1 = F, solved
    //  slice by slice from the discharge end (each slice's outflow is a
    //  monotone piecewise-linear function of its passive mass). Throws
    //  InputError when no steady state exists (a slice cannot pass the flow).
    CompartmentSteadyState steadyState() const;

    //- Mass rates dM/dt of the dynamic network (Lee's Active/Passive
    //  models, App. 10.2.1-10.2.2) for masses ordered P_1, A_1, P_2, A_2, ...
    Eigen::VectorXd massRates(const Eigen::VectorXd& masses) const;

    //- Linear tracer network at bulk steady state: tracer is a label, so the
    //  flows stay those of `state` and the tracer balances (Lee's $(m x)
    //  equations) are linear in the tracer masses. Ordering P_1, A_1, ...
    TracerSystem tracerSystem(const CompartmentSteadyState& state) const;

    //- The same with stagnant zones appended (states 2N .. 3N-1: S_1 ... S_N)
    TracerSystem tracerSystem
    (
        const CompartmentSteadyState& state,
        const StagnantExchange& stagnant
    ) const;

    //- Kilning flow of slice i (0-based) holding kilnMass above its design
    //  load, the next slice's bed nextDepth deep (massRates' law: t_kiln, or
    //  the slice's rolling bed), kg/s
    double kilnFlow(int i, double kilnMass, double nextDepth) const;
    //- Depth of slice i's rolling bed holding kilnMass (0 without one), m
    double kilnBedDepth(int i, double kilnMass) const;

    //- Index of the passive / active cell of slice i (0-based) in the state vector
    static int passiveIndex(int i) { return 2*i; }
    static int activeIndex(int i) { return 2*i + 1; }

private:
    std::vector<CompartmentSlice> slices_;
    double feedRate_;
    double kilnTime_;
};

} // namespace drum

#endif
