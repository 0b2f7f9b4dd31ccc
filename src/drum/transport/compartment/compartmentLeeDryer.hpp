// Lee's (2008) dryer model assembled from slice to network: slice
// parameters from the App. 10.2.3 correlations ("Lee correlations" option),
// the moisture/angle-of-repose profile of Eqs 7.2-7.3 (or a constant angle,
// as in the response studies of Tables 7.6-7.10), and the three fitted
// parameters t_kiln, C_B, C_F^G.
#ifndef DRUM_TRANSPORT_COMPARTMENTLEEDRYER_HPP
#define DRUM_TRANSPORT_COMPARTMENTLEEDRYER_HPP

#include "drum/transport/compartment/compartmentCorrelations.hpp"
#include "drum/transport/compartment/compartmentNetwork.hpp"

#include <optional>
#include <vector>

namespace drum
{

//- Operating data and geometry (defaults: Invicta Mill dryer No. 2 as in the
//  gPROMS process entity, Lee 2008 App. 10.1)
struct LeeDryer
{
    double length = 12.0;            //!< L, m
    double rpm = 3.0;                //!< drum speed, rev/min
    double slopeDeg = 2.8;           //!< theta, deg
    double feedRate = 98000.0/3600.0;  //!< kg/s
    double bulkDensity = 940.0;      //!< rho_b, kg/m3 (code value)
    LeeFlightGeometry geometry;
    double moistureInlet = 0.02;     //!< w at the feed end, kg/kg (code value)
    double moistureOutlet = 0.002;   //!< w at the discharge end, kg/kg
    std::optional<double> constantPhiDeg;  //!< when set, phi is this everywhere
    double fLoad = 1.0;              //!< flight loading factor (fixed at 1 by Lee)
    double designLoadMultiplier = 1.0;   //!< Table 7.10 study: M_des scaled
};

//- The fitted parameters of Lee 2008 Ch. 7 (Table 7.2)
struct LeeParameters
{
    double kilnTime;        //!< t_kiln, s
    double backFraction;    //!< C_B
    double dragFactor;      //!< C_F^G (Eq 3.8: C_F = C_F^0 C_F^G)
};

//- Per-slice values behind a Lee network, for reporting
struct LeeSliceData
{
    double phiDeg;
    LeeCorrelationValues correlations;
    CompartmentSlice slice;
    //- Diameter of the circle the kilning bed rolls in, m: the drum's, or
    //  the flight-tip circle 2 R_F where the pockets under the bed are
    //  counted as the flights' (flight model, flightHoldup bedFilled)
    double kilnBedDiameter = 0;
    //- Flight model: C_F and C_B of each size class alone (the slice's own
    //  are their feed-weighted sums)
    std::vector<double> classForward, classBack;
    //- Flight model: the unloading profile (Lee 2008 Ch. 4), one entry per
    //  release-angle step: root angle (deg), the flight's holdup there (kg per
    //  flight over the slice length), spill rate (kg/(m s)) and fall height (m)
    struct UnloadingPoint { double angleDeg, holdupKg, spillRate, fallHeight; };
    std::vector<UnloadingPoint> unloading;
};

//- Slice parameters for N slices (Eqs 4.24-4.27 code forms, Eq 3.7-3.8,
//  code line C_x = C_x_g maf_h sin(theta)/(L/N))
std::vector<LeeSliceData> leeSliceData(const LeeDryer& dryer, int nSlices, const LeeParameters& p);

//- Kinetic angle of repose of slice i of n (1-based), deg: the dryer's
//  constant phi, or Lee's sugar phi from the moisture profile (Eqs 7.2-7.3)
double leeSliceReposeDeg(const LeeDryer& dryer, int i, int nSlices);

//- The network of Lee's Dryer Model
CompartmentNetwork leeNetwork(const LeeDryer& dryer, int nSlices, const LeeParameters& p);

} // namespace drum

#endif
