// Axial dispersion of the passive (dense/kilning) phase in Lee's compartment
// network, Sherritt (2001) Eq 27 dc/dt = D_z d2c/dz2 - u dc/dz discretised
// as a symmetric exchange between neighbouring passive cells:
//
//   G_i+1/2 = D_z M_b/dz^2   kg/s each way between P_i and P_i+1,
//
// M_b the bed mass per slice at the face (mean of the two slices). The bed is
// the kilning bed M_p - M_des (default: the rolling bed at the drum bottom;
// the flights' own load is lifted, not dispersed) or the whole passive cell.
// Tracer is well mixed in each cell, so the tracer rate P_i -> P_i+1 is
// (G/M_p,i) y_i. No net mass flows: the steady holdup is unchanged and only
// the RTD changes. No exchange across the feed end or into the product
// (closed-closed ends, Sherritt 2001 Eq 32), so the mean residence time stays
// holdup/feed exactly.
//
// Numerical dispersion: the kilning flow P_i -> P_i+1 is an upwind step of
// the bed, whose own dispersion is u_b dz/2 with u_b = F_k dz/M_b (for the
// kilning bed dz/t_kiln). Lee's slice count and fitted parameters belong
// together (his N is a model parameter, Table 7.2), so by default D_z is
// added on top of the network's own mixing; subtractNumerical takes u_b dz/2
// off as the two-phase network does (twoPhaseTracer.hpp). Either way the
// summary reports both so the caller can warn when the slicing alone
// disperses more than D_z.
#ifndef DRUM_TRANSPORT_COMPARTMENTDISPERSION_HPP
#define DRUM_TRANSPORT_COMPARTMENTDISPERSION_HPP

#include "drum/rtd/tracerSystem.hpp"
#include "drum/transport/axialDispersion.hpp"
#include "drum/transport/compartment/compartmentNetwork.hpp"

#include <string>
#include <vector>

namespace drum
{

//- Which passive mass the dispersion acts on
enum class DispersionBed
{
    kiln,     //!< the kilning bed M_p - M_des (0 below the design load)
    passive   //!< the whole passive cell M_p (flights + bed)
};

std::string toString(DispersionBed bed);

//- "kiln" | "passive"; InputError naming `entry` otherwise
DispersionBed parseDispersionBed(const std::string& word, const std::string& entry, const std::string& file = "");

//- Bed mass per slice the exchange acts on, kg
Eigen::VectorXd dispersionBedMass(const CompartmentSteadyState& st, DispersionBed bed);

struct PassiveDispersion
{
    std::vector<double> coefficient;   //!< D_z per slice, m2/s (one value: all slices); empty: none
    double sliceLength = 0;            //!< dz = L/N, m
    DispersionBed bed = DispersionBed::kiln;
    bool subtractNumerical = false;    //!< take the kiln flow's upwind part u_b dz/2 off D_z
};

//- What was applied, over the slice boundaries with a bed on either side
struct PassiveDispersionSummary
{
    int boundaries = 0;
    double meanCoefficient = 0;  //!< mean D_z at the faces, m2/s
    double meanNumerical = 0;    //!< mean u_b dz/2 at the faces with a bed flow, m2/s
    double meanAdded = 0;        //!< mean D_z exchanged (after any subtraction), m2/s
    int numericalExceeds = 0;    //!< faces where u_b dz/2 > D_z
};

//- `sys` (the network's tracer system, optionally with stagnant zones
//  appended after the 2N slice states) with the passive exchange added.
//  Throws InputError naming model.denseDispersion for a coefficient outside
//  [0, 1] m2/s, a wrong count or a non-positive slice length.
TracerSystem withPassiveDispersion
(
    const TracerSystem& sys,
    const CompartmentSteadyState& st,
    const PassiveDispersion& dispersion,
    PassiveDispersionSummary* summary = nullptr,
    const std::string& file = ""
);

//- Drum data for Sherritt's correlation in the compartment model
struct PassiveDispersionDrum
{
    double drumDiameter = 0;      //!< 2R, m
    double speed = 0;             //!< n, rev/s
    double particleDiameter = 0;  //!< d_p, m (dispersionParticleDiameter)
    double bulkDensity = 0;       //!< rho_b, kg/m3
    double sliceLength = 0;       //!< dz, m
};

struct PassiveSherritt2001
{
    std::vector<double> coefficient;     //!< D_z per slice (0 without a bed), m2/s
    std::vector<double> fill;            //!< X = M_b/(rho_b pi D^2/4 dz) per slice
    AxialDispersionResult reference;     //!< regime and n/n_c (the same in every slice)
    int bedSlices = 0;                   //!< slices with a bed
    double minFill = 0, maxFill = 0, minDz = 0, maxDz = 0;  //!< over the bed slices
    std::vector<std::string> warnings;   //!< departures from the fitted range, each once
    std::string note;                    //!< one-line description
};

//- Eq 51 by regime (n/n_c, Eq 1) in every slice with X from its bed mass.
//  Slices without a bed get D_z = 0. Throws InputError (n >= n_c, bad
//  drum data) or when no slice has a bed.
PassiveSherritt2001 sherritt2001PassiveDispersion
(
    const CompartmentSteadyState& st,
    DispersionBed bed,
    const PassiveDispersionDrum& drum,
    const std::string& file = ""
);

} // namespace drum

#endif
