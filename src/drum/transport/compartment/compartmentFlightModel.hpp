// The "flight model" option of the compartment network: slice parameters
// from Lee's geometric unloading model (src/drum/flights, Lee 2008 Ch. 4)
// and a drift model (src/drum/drift) instead of the Invicta-only
// correlations and the fitted C_B, C_F^G:
//   design load        Eq 4.21 over the slice length (flightHoldup eq421),
//                      or the flights' load when they leave the bed full
//                      (bedFilled: UnloadingModel::bedFilledLoad)
//   fall time/height   mass averages over the release (Eqs 3.3, 3.5, 3.6)
//   passive time       eq421: Eq 3.4, (2 psi_bar - 180 deg)/omega, psi_bar
//                      the mass-averaged root angle of release (Eq 3.3);
//                      bedFilled: that load over the flights' curtain flow
//                      N_F H_0 n/60 (Little's law, so the release at and
//                      above the load is what the flights discharge)
//   C_F, C_B           per release angle psi and size class: axial advance
//                      d(psi, D_p) of the fall from the drift model (incline
//                      and gas drag, solids frame); C_F = sum w max(d, 0)/dL,
//                      C_B = sum w max(-d, 0)/dL, w the released mass share
// No parameter is fitted except t_kiln. As docs/errata.md L6 explains,
// the geometric release point is on the rising side and gives passive times
// of ~5 s, far from the ~11 s of Lee's correlations: this option is
// geometrically self-consistent, not a reproduction of Ch. 7.
#ifndef DRUM_TRANSPORT_COMPARTMENTFLIGHTMODEL_HPP
#define DRUM_TRANSPORT_COMPARTMENTFLIGHTMODEL_HPP

#include "drum/drift/driftModel.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace drum
{

//- What the flights hold at and above the design load
enum class FlightHoldup
{
    eq421,      //!< Lee Eq 4.21: the lower half mirrors the upper (flights fill from the curtains)
    bedFilled   //!< flights leave the bed full at the pickup angle and carry H(psi) to psi_5
};

struct FlightModelPartition
{
    std::shared_ptr<const DriftModel> drift;    //!< required
    double gasVelocity = 0;          //!< mean axial gas velocity, m/s (>= 0)
    bool counterCurrent = true;      //!< gas against the solids
    std::vector<double> sizes;       //!< particle (drag) diameters, m
    std::vector<double> fractions;   //!< mass fractions (sum 1)
    double particleDensity = 1500;   //!< kg/m3
    double flightAxialLength = 1.0;  //!< axial length of one flight, m (Eq 142's L)
    double angleStepDeg = 1.0;       //!< release-angle resolution
    FlightHoldup holdup = FlightHoldup::eq421;
    double pickupDeg = 0.0;          //!< bedFilled: root angle where a flight leaves the bed, deg
    //- bedFilled with the kilning bed's span per slice (root angles from, to;
    //  deg): pockets under it full, H(psi) after it. Empty: pickupDeg.
    std::vector<std::pair<double, double>> bedSpanDeg;
};

//- Span of each slice's kilning bed as root angles (deg) from its kiln mass
//  (kg) over the slice length: a segment of the circle of diameter
//  kilnBedDiameter whose chord is inclined at phi, so it is centred phi from
//  the drum bottom on the rising side, phi -+ beta/2 (beta its fill angle);
//  the end is held at the tip horizontal (a deeper bed is counted up to it)
std::vector<std::pair<double, double>> kilnBedSpansDeg
(
    const LeeDryer& dryer,
    const std::vector<LeeSliceData>& slices,
    const std::vector<double>& kilnMass,
    double sliceLength
);

//- Slice data from the flight and drift models (kilnTime goes into the
//  network only). Throws InputError when a fall would jump past the next
//  slice (C_F + C_B > 1: Lee's nearest-neighbour rule, Fig. 3.4).
std::vector<LeeSliceData> flightModelSliceData
(
    const LeeDryer& dryer,
    int nSlices,
    const FlightModelPartition& partition
);

CompartmentNetwork flightModelNetwork
(
    const LeeDryer& dryer,
    int nSlices,
    const FlightModelPartition& partition,
    double kilnTime
);

} // namespace drum

#endif
