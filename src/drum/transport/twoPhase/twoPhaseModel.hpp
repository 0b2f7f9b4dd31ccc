// Sherritt (1991) two-phase drum model (Chapter 3): solids move
// as an airborne phase (falling curtains, size dependent, Eqs 45-55) and a
// dense phase (rolling surfaces in the flights, size independent, Eqs
// 56-86); the holdup follows from integrating the flight discharge (Eqs
// 87-127). Loading is characterised by the exterior flights' initial
// discharge angle theta_i (§3.1).
//
//  * atDischargeAngle(theta_i): one DRUM1 step (constant holdup, gamma = 0)
//  * solveConstantHoldup(F0): DRUM1 inverted for the feed, every root
//  * solveAxial(F0): DRUM2/DRUM3, holdup varying along the drum (Eqs
//    134-139), integrated from the solids discharge end with the holdup H
//    as the state, so design loading (dH/dtheta_i = 0) is no singularity.
//
// All flows and slopes are in the solids frame (positive towards the solids
// discharge); see twoPhaseCase.hpp.
#ifndef DRUM_TRANSPORT_TWOPHASEMODEL_HPP
#define DRUM_TRANSPORT_TWOPHASEMODEL_HPP

#include "drum/flights/sherritt/sherrittFlightSurface.hpp"
#include "drum/transport/twoPhase/twoPhaseCase.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace drum
{

enum class LoadingRegime
{
    underloaded,  //!< pi < theta_i
    design,       //!< theta_i = pi
    overloaded,   //!< theta_i < pi
    buried        //!< theta_i <= phi + pi/2: covered flights do not discharge
};

std::string loadingRegimeName(LoadingRegime r);

//- Everything at one initial discharge angle (per metre of drum unless said)
struct TwoPhaseState
{
    double dischargeAngle = 0;          //!< theta_i, rad
    double interiorDischargeAngle = 0;  //!< psi_i, rad (pi: none / empty)
    bool interiorOverfilled = false;    //!< receipt exceeds a full interior flight (psi_i = 0)
    LoadingRegime regime = LoadingRegime::design;

    double airborneHoldup = 0;         //!< H_1, m3/m (bulk), Eqs 91, 127
    double dischargingHoldup = 0;      //!< H_2 in discharging flights, m3/m
    double nonDischargingHoldup = 0;   //!< H_2 in the others, m3/m
    double holdup = 0;                 //!< H = H_1 + H_2, m3/m

    double gasVelocity = 0;            //!< V_g in the free annulus, m/s
    double circulation = 0;            //!< solids discharged into the curtains per metre, kg/(s m): n rho_b/2 (N_ex int l_ex^2 + N_in int l_in^2) over the airborne limits of Eq 91 (Eq 40 summed)
    std::vector<double> airborneCapacity;  //!< n rho_b/2 (N_ex I_ex,i + N_in I_in,i), kg/s (Eq 51 / x_d,i)
    double slopedSurfaces = 0;         //!< N_ex,s
    double chord = 0;                  //!< c, m
    double dischargingCubes = 0;       //!< N_ex J_ex + N_in J_in, m3 rad

    // Filled by the flow solution (F0 from Eq 55 at gamma = 0, or given F0)
    bool valid = false;                //!< false: Eq 55 has no positive solution here
    std::string note;                  //!< why not valid
    double feedRate = 0;               //!< F_0, kg/s
    double airborneFlow = 0;           //!< F_1, kg/s
    double denseFlow = 0;              //!< F_2, kg/s
    std::vector<double> holdupFractions;   //!< x_d,i (Eq 53)
};

//- Holdup and flows along the drum (axial solve)
struct TwoPhaseProfilePoint
{
    double distanceFromDischarge = 0;  //!< m
    double dischargeAngle = 0;         //!< theta_i, rad
    double holdup = 0;                 //!< H, m3/m
    double airborneHoldup = 0;         //!< H_1, m3/m
    double airborneFlow = 0;           //!< F_1, kg/s
    double denseFlow = 0;              //!< F_2, kg/s
    double bedSlope = 0;               //!< gamma, rad (Eq 135, capped at phi)
    bool slopeCapped = false;          //!< Eq 135 asked for |gamma| > phi: Eq 79 at the cap cannot carry the F_2 of Eq 55
    double circulation = 0;            //!< kg/(s m) into the curtains (TwoPhaseState)
    std::vector<double> airborneCapacity;  //!< A_i = F_1,i/x_d,i, kg/s (Eq 51)
    std::vector<double> holdupFractions;   //!< x_d,i (Eq 53)
};

struct TwoPhaseResult
{
    double feedRate = 0;                  //!< F_0, kg/s
    double holdupMass = 0;                  //!< solids in the flighted length, kg
    double airborneFraction = 0;          //!< H_1/H (length averaged)
    double meanResidenceTime = 0;         //!< T, s (Eq 138)
    std::vector<double> sizeResidenceTimes;  //!< T_i, s (Eqs 139/140)
    std::vector<double> holdupFractions;  //!< x_d,i (length averaged by holdup)
    double airborneFlow = 0;              //!< F_1, kg/s (mean along the drum)
    double denseFlow = 0;                 //!< F_2, kg/s (mean along the drum)
    double dischargeAngle = 0;            //!< theta_i (DRUM1; feed end for axial)
    LoadingRegime regime = LoadingRegime::design;
    std::vector<TwoPhaseProfilePoint> profile;  //!< axial solve only
    //- Axial solve: drum length [m] over which the bed slope was held at
    //  the cap |gamma| = phi, i.e. where Eq 79 does not carry the dense flow
    //  that Eq 55 needs (the dense-phase balance is broken there)
    double cappedLength = 0;
};

struct AxialOptions
{
    //- theta_i at the solids discharge end; unset: 2 degrees below the
    //  flights' final discharge angle (no weir, Sherritt 1991 §3.7)
    std::optional<double> dischargeEndAngle;
};

//- The largest feed DRUM1 carries over a set of states and its theta_i
//  (0, 0 when none carries solids towards the discharge)
std::pair<double, double> largestCarriedFeed(const std::vector<TwoPhaseState>& states);

class TwoPhaseModel
{
public:
    //- Validates the case; throws drum::InputError naming the drumDict entry
    //  the value comes from (drumSolver reads it with the same range first),
    //  or the TwoPhaseOptions member for library-only options
    explicit TwoPhaseModel(TwoPhaseCase c);

    const TwoPhaseCase& input() const { return case_; }

    //- DRUM1 at one theta_i: holdups, gas velocity, airborne capacities,
    //  dense flow (gamma = 0 or imposed) and F0 from Eq 55
    TwoPhaseState atDischargeAngle(double thetaI) const;

    //- DRUM1 states over [from, to] in `points` steps
    std::vector<TwoPhaseState> sweep(double from, double to, int points) const;

    //- DRUM1 inverted: every theta_i with F0(theta_i) = feedRate, lowest
    //  holdup first. Throws drum::InputError if feedRate <= 0 or beyond the
    //  flow the drum carries over [minDischargeAngle, final angle].
    std::vector<TwoPhaseResult> solveConstantHoldup(double feedRate) const;

    //- DRUM3: holdup varying along the drum (horizontal or short drums).
    //  With an imposed dense flow the holdup is constant: returns the
    //  lowest-holdup constant solution with a flat profile. Throws
    //  drum::InputError (entry feedRate) when the bed slope is still at the
    //  cap phi at the feed end: no bed slope up to phi carries the feed
    //  there, so the drum has no steady state for it (the profile would
    //  stop rising where the chord vanishes, whatever the feed).
    TwoPhaseResult solveAxial(double feedRate, const AxialOptions& options = {}) const;

    //- The profile point of a DRUM1 state (constant holdup)
    TwoPhaseProfilePoint profilePoint(const TwoPhaseState& s, double distanceFromDischarge = 0) const;

    //- Total holdup H(theta_i) [m3/m] alone (no flows): cheap
    double holdupAt(double thetaI) const;

    //- Fall height [m] from an exterior tip at theta (Eqs 92-95 as coded)
    double exteriorFallHeight(double theta) const;

    //- Fall height [m] from an interior tip at psi (Eq 96)
    double interiorFallHeight(double psi) const;

    //- Largest theta_i where the exterior flights still hold material
    double finalDischargeAngle() const { return finalAngle_; }

    //- Upper edge of the overload range searched
    double minDischargeAngle() const { return case_.options.minDischargeAngle; }

private:
    struct Geometry
    {
        double thetaA, thetaB, thetaC, thetaE;
    };

    double interiorAngle(double thetaI, bool& overfilled) const;
    void holdups(double thetaI, double psiI, TwoPhaseState& s) const;
    double airborneMass(double thetaI, double psiI) const;
    void airborneCapacities(double thetaI, double psiI, double Vg, TwoPhaseState& s) const;
    void denseTerms(double thetaI, double psiI, TwoPhaseState& s) const;
    double denseFlow(const TwoPhaseState& s, double gamma) const;
    void solveFeed(TwoPhaseState& s) const;
    bool solveDenseFlow(const TwoPhaseState& s, double feed, double& F2) const;
    double gasVelocity(double holdup) const;
    double thetaOfHoldup(double H) const;
    TwoPhaseResult constantResult(const TwoPhaseState& s) const;
    //- DRUM1 states over [minDischargeAngle, final angle] in sweepStep
    //  steps (at least 8): the grid of the root search and of the capacity
    std::vector<TwoPhaseState> drum1Grid() const;

    TwoPhaseCase case_;
    SherrittFlightSurface ex_;
    std::optional<SherrittFlightSurface> in_;
    std::shared_ptr<const DriftModel> drift_;
    std::vector<double> xf_;      // normalised feed fractions
    std::vector<double> dp_;      // drag diameters
    double gasDensity_;
    double alphaGas_;             // incline in the gas frame (signed)
    double toSolids_;             // +1 cocurrent, -1 countercurrent
    Geometry g_;
    double finalAngle_;
    std::vector<double> Htheta_, Hvalue_;  // holdup table for inversion
};

} // namespace drum

#endif
