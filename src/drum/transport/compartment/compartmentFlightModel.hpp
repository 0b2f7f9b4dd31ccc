// The "flight model" option of the compartment network: slice parameters
// from Lee's geometric unloading model (src/drum/flights, Lee 2008 Ch. 4)
// and a drift model (src/drum/drift) instead of the Invicta-only
// correlations and the fitted C_B, C_F^G:
//   design load        Eq 4.21 over the slice length
//   fall time/height   mass averages over the release (Eqs 3.3, 3.5, 3.6)
//   passive time       Eq 3.4, (2 psi_bar - 180 deg)/omega, psi_bar the
//                      mass-averaged root angle of release (Eq 3.3)
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
#include <vector>

namespace drum
{

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
};

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
