// Per-angle unloading of one Lee 2008 flight in a turning drum: holdup,
// discharge profile, release point, fall height and time, spill rate and the
// moving layer over the tip; plus the flight-level results of §4.3-4.4
// (mass-averaged release angle, design load, flight loading factor).
//
// All masses are per metre of flight unless named otherwise; angles in
// degrees; psi is the root angle from the drum bottom (see leeFlight.hpp).
#ifndef DRUM_FLIGHTS_UNLOADINGMODEL_HPP
#define DRUM_FLIGHTS_UNLOADINGMODEL_HPP

#include "drum/flights/leeFlight.hpp"

#include <string>
#include <vector>

namespace drum
{

struct UnloadingSettings
{
    double bulkDensity = 0.0;       //!< rho_b [kg/m^3] (Lee uses the consolidated value)
    double speedRpm = 0.0;          //!< drum speed [rev/min]
    double flightLength = 1.0;      //!< L [m], for the design load and totals
    double drumSlopeDeg = 0.0;      //!< theta [deg], Eq 3.5 factor 1/cos(theta)
    double bedDepth = 0.0;          //!< kilning-bed depth at the drum bottom [m] (0: none)
    double layerVelocity = 1.0;     //!< moving-layer speed over the tip [m/s] (Table 5.6: 0.67-1.67)
    double layerBulkDensity = 0.0;  //!< moving-layer bulk density [kg/m^3] (0: use bulkDensity)
    double gravity = 9.81;          //!< [m/s^2]
};

//- Everything the curtain and compartment models need at one release angle
struct ReleaseConditions
{
    double psiDeg = 0.0;           //!< root angle [deg]
    double tipAngleDeg = 0.0;      //!< psi + psi_ft [deg], tip from the drum bottom
    int phase = 0;                 //!< 0 full, 1-4 Lee phases I-IV, 5 empty
    bool toCurtain = false;        //!< tip above the horizontal (psi + psi_ft >= 90 deg)
    double holdup = 0.0;           //!< H [kg/m]
    double discharge = 0.0;        //!< -dH/dpsi [kg/(m rad)]
    double spillRate = 0.0;        //!< omega (-dH/dpsi) [kg/(m s)]
    double releaseX = 0.0;         //!< tip x [m] (drum centre at the origin)
    double releaseY = 0.0;         //!< tip y [m]
    double landingY = 0.0;         //!< where the vertical through the tip meets wall or bed [m]
    double fallHeight = 0.0;       //!< (releaseY - landingY)/cos(theta) [m], Eq 3.5 convention
    double fallTime = 0.0;         //!< sqrt(2 h/g) [s], Eq 3.6 (drag-free)
    double layerThickness = 0.0;   //!< spillRate/(rho_bl v) [m], Eq 5.4 per metre
    double layerVelocity = 0.0;    //!< v [m/s]
};

class UnloadingModel
{
public:
    //- Throws InputError (naming `file` and the entry) for bad settings
    UnloadingModel(const LeeFlight& flight, const UnloadingSettings& settings,
                   const std::string& file = "");

    const LeeFlight& flight() const { return flight_; }
    const UnloadingSettings& settings() const { return settings_; }

    double omega() const;                    //!< [rad/s]
    double holdup(double psiDeg) const;      //!< [kg/m]
    double discharge(double psiDeg) const;   //!< -dH/dpsi [kg/(m rad)]
    ReleaseConditions at(double psiDeg) const;

    //- Fall height [m] from (x, y) straight down to the wall or the bed
    //  surface, divided by cos(theta) (Lee 2008 Eq 3.5)
    double fallHeight(double x, double y) const;

    //- Profile from psiStart to psiEnd in steps of stepDeg; the transition
    //  points are inserted so the kinks of the profile are sampled exactly
    std::vector<ReleaseConditions> profile(double psiStartDeg, double psiEndDeg,
                                           double stepDeg) const;

    double maxHoldup() const;                //!< H_full [kg/m], Eq 4.8
    double designFlightHoldup() const;       //!< H_0,des at tip horizontal [kg/m] (§4.4)
    //- Mass released per metre while the tip is above the horizontal
    //  (= designFlightHoldup) and the mass-weighted means over that release:
    //  root angle (Eq 3.3), fall height and fall time
    double meanReleaseAngleDeg() const;
    double meanFallHeight() const;
    double meanFallTime() const;

    //- Dryer design load [kg] over flightLength: Eq 4.21 and Porter's Eq 4.19
    double designLoad() const;
    double porterDesignLoad() const;

    //- Flow the flights release into the curtains [kg/s] over flightLength
    //  once every flight is full at the tip horizontal: N_F H_0,des n/60
    //  (each flight empties H_0,des once per revolution)
    double curtainFlow() const;
    //- Mass the flights carry [kg] over flightLength in a dryer loaded past
    //  its design load, where each flight leaves the bed full at the root
    //  angle pickupDeg and carries H(psi) until it is empty at psi_5
    //  (phase-averaged: L N_F/(2 pi) int_pickup^psi5 H dpsi). Eq 4.21
    //  instead mirrors the upper half, as if flights filled only from the
    //  curtains; both over curtainFlow() give the flights' passive time by
    //  Little's law (checked against Eq 3.4 in the unit tests)
    double bedFilledLoad(double pickupDeg) const;
    //- The same with the bed's span on the rising side: the pockets under the
    //  bed (root angles bedFromDeg to bedToDeg) are full, H_full (Eq 4.8),
    //  and a flight leaving the bed at bedToDeg carries H(psi) from there:
    //  L N_F/(2 pi) [(to - from) H_full + int_to^psi5 H dpsi]
    double bedFilledLoad(double bedFromDeg, double bedToDeg) const;
    //- Flight loading factor f_load for a dryer loading d_load = M_p/M_p,des
    //  (Eq 4.22 solved for f_load; 1 for d_load >= 1)
    double loadingFactor(double dLoad) const;

    //- Integral over [a, b] (deg) of f(psi) d(psi in rad), split at the
    //  transition points (Gauss-Legendre, 10 points on 64 pieces per phase)
    template<class F> double integrate(F&& f, double aDeg, double bDeg) const;

private:
    LeeFlight flight_;
    UnloadingSettings settings_;
};

} // namespace drum

#include "drum/flights/unloadingModelI.hpp"

#endif
