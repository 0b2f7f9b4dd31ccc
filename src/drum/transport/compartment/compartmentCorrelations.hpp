// Lee's (2008) polynomial correlations that stand in for the geometric
// flight-unloading model in the compartment network: mass-averaged fall
// height, fall time and release angle, and the dryer design load. They were
// regressed for one geometry only (Invicta Mill dryer No. 2: R = 2.5 m,
// s1 = 0.195 m, s2 = 0.183 m, alpha2 = 117 deg, 28 flights); any other drum
// needs them regenerated from the geometric model.
//
// The printed Eqs 4.24-4.28 carry coefficient errors (docs/errata.md L5
// item 5), so the full-precision Appendix 10.2.3 gPROMS code forms are used.
#ifndef DRUM_TRANSPORT_COMPARTMENTCORRELATIONS_HPP
#define DRUM_TRANSPORT_COMPARTMENTCORRELATIONS_HPP

namespace drum
{

//- Two-section flight and drum geometry as Lee's Geometry sub-model reads it
struct LeeFlightGeometry
{
    double drumRadius = 2.5;        //!< R, m
    double baseLength = 0.195;      //!< s1, m
    double tipLength = 0.183;       //!< s2, m
    double baseAngleDeg = 90.0;     //!< alpha1, deg
    double tipAngleDeg = 117.0;     //!< alpha2, deg
    int nFlights = 28;              //!< N_f

    //- Radius of the flight-tip circle R_F (Lee 2008 Eqs 4.1-4.4, 4.6,
    //  App. 10.2.3 code form), m
    double tipRadius() const;
};

//- Values of Lee's correlations at one dynamic angle of repose
struct LeeCorrelationValues
{
    double fallHeight;      //!< maf_h, mass-averaged fall height, m (Eq 4.24 code form)
    double fallTime;        //!< maft, mass-averaged fall time = active time, s (Eq 4.25 code form)
    double releaseAngle;    //!< mafa = asin(maf_h/2R_F) + pi/2, rad (Eq 4.26)
    double flightTime;      //!< t_flight = 2(mafa - pi/2)/omega, s (code line)
    double passiveTime;     //!< t_p = 60/rpm - t_flight, s (docs/errata.md L6)
    double designLoadPerLength; //!< m_des/(L/N), kg/m (Eq 4.27 code form)
};

//- Lee 2008 App. 10.2.3 correlations. phiDeg: dynamic angle of repose in
//  degrees (the correlations take degrees); fLoad: flight loading factor
//  (Lee fixed it at 1 for the overloaded Invicta dryer); rpm: drum speed;
//  bulkDensity in kg/m3. Throws InputError outside 0 < f_load <= 1,
//  20 <= phi <= 70 deg (range of the regression grid and a little beyond).
LeeCorrelationValues leeCorrelations
(
    const LeeFlightGeometry& geometry,
    double phiDeg,
    double fLoad,
    double rpm,
    double bulkDensity
);

//- Eq 7.2 (Britton et al. 2006): dynamic angle of repose of raw sugar, deg,
//  from moisture w in kg/kg
double leeSugarAngleOfRepose(double moisture);

//- Eq 7.3: moisture in slice i (1-based) of n, exponential profile
double leeMoistureProfile(double wInlet, double wOutlet, int i, int n);

} // namespace drum

#endif
