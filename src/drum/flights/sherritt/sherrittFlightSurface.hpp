// A Sherritt flight at a given kinetic angle of repose phi: the discharging
// surface length l(theta) = max(0, table(theta - phi)) (Sherritt 1991 §3.2), the
// discharge rate dm/dt = pi n rho_b l^2 (Sherritt 1991 Eqs 40/41) and the
// flight holdup as the integral of the discharge (Eqs 97/98), with the
// initial discharge angle as its inverse.
//
// l is piecewise linear between the (shifted) table nodes and the points
// where the interpolant crosses zero, so every integral of l^2 and l^3, and
// the iterated integrals the holdup needs (Eqs 117-125), are exact here.
#ifndef DRUM_FLIGHTS_SHERRITTFLIGHTSURFACE_HPP
#define DRUM_FLIGHTS_SHERRITTFLIGHTSURFACE_HPP

#include "drum/flights/sherritt/sherrittFlightProfile.hpp"

#include <vector>

namespace drum
{

class SherrittFlightSurface
{
public:
    //- repose: kinetic angle of repose phi [rad], in (0, pi/2); throws
    //  drum::InputError otherwise. Defined on [emptyAngle - 2 pi, emptyAngle].
    SherrittFlightSurface(const SherrittFlightProfile& profile, double repose);

    const SherrittFlightProfile& profile() const { return profile_; }
    double repose() const { return repose_; }
    double lowerAngle() const { return nodes_.front(); }
    double emptyAngle() const { return nodes_.back(); }

    //- Surface length l(theta) [m] (clamped to the domain ends)
    double length(double theta) const;

    //- Discharge rate per metre of flight [kg/(s m)], Eq 40/41:
    //  pi n rho_b l^2 on the discharging arc, 0 past the empty angle
    double dischargeRate(double theta, double rps, double bulkDensity) const;

    //- Exact integrals over [a, b] (a > b gives the negative):
    double integralL2(double a, double b) const;  //!< int l^2 dtheta [m2 rad]
    double integralL3(double a, double b) const;  //!< int l^3 dtheta (Eqs 81/82)

    //- C(theta) = int_{lower}^{theta} l^2 and its integral int_a^b C(theta)
    double cumulativeL2(double theta) const;
    double integralOfCumulativeL2(double a, double b) const;

    //- Iterated integral int_a^b int_theta^{empty} l^2 dtheta' dtheta: the
    //  discharging-flight term of Eqs 117-125 (times 1/4 pi per flight)
    double iteratedDischarge(double a, double b) const;

    //- Bulk volume left in a discharging flight at theta [m3 per m of
    //  flight], Eq 97/98: h = 1/2 int_theta^{empty} l^2
    double holdupVolume(double theta) const;

    //- Holdup mass per metre of flight [kg/m]: rho_b h, which equals the
    //  time integral of Eq 40 from theta to the empty angle
    double holdupMass(double theta, double bulkDensity) const;

    //- The angle at which a flight holding `volume` [m3/m] starts to
    //  discharge: the theta_i with holdupVolume(theta_i) = volume (the
    //  greatest such angle where h is flat). Throws drum::InputError when the
    //  volume is negative or above what the flight holds at lowerAngle().
    double initialDischargeAngle(double volume) const;

    //- Breakpoints of l (sorted, spanning the domain): useful as quadrature
    //  panel edges for integrands built from l
    const std::vector<double>& nodes() const { return nodes_; }

private:
    struct Piece
    {
        double l0, l1, x0, x1;
    };

    // Index k of the node interval containing x (clamped)
    std::size_t interval(double x) const;

    // Integral of C over [x0 of interval k, x] (C cubic there)
    double partialIntC(std::size_t k, double x) const;

    SherrittFlightProfile profile_;  // a copy: the surface outlives temporaries
    double repose_;
    std::vector<double> nodes_;   // breakpoints
    std::vector<double> values_;  // l at the breakpoints (>= 0)
    std::vector<double> cumL2_;   // int l^2 from lower to node
    std::vector<double> cumL3_;   // int l^3 from lower to node
    std::vector<double> cumC_;    // int C from lower to node
};

} // namespace drum

#endif
