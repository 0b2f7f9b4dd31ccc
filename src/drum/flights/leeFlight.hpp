// Lee 2008 Chapter 4: geometric unloading of straight, unserrated two-section
// flights (base s1 at angle alpha1 to the wall, tip s2 at angle alpha2 to the
// base), material surface a straight line through the tip at the dynamic
// angle of repose phi (Lee 2008 Ch. 4; errata in docs/errata.md L1-L4).
//
// Frame used throughout: drum centre at the origin, x horizontal, y up, the
// drum turning counter-clockwise (the rising side is x > 0). psi is the angle
// of the flight root (wall attachment) from the drum bottom in the direction
// of rotation, so the root sits at R (sin psi, -cos psi) and the tip at
// R_F (sin(psi + psi_ft), -cos(psi + psi_ft)). A flight's material lies
// between its leading face and the back of the next flight (at psi + psi_fl),
// below the surface line (Lee 2008 §4.2; docs/errata.md L19).
//
// Every quantity is per metre of flight length; angles in the public API are
// in degrees, as in the thesis.
#ifndef DRUM_FLIGHTS_LEEFLIGHT_HPP
#define DRUM_FLIGHTS_LEEFLIGHT_HPP

#include "drum/flights/polygonClip.hpp"

#include <array>
#include <string>

namespace drum
{

struct FlightGeometry
{
    double drumRadius = 0.0;     //!< R [m]
    double baseLength = 0.0;     //!< s1 [m]
    double tipLength = 0.0;      //!< s2 [m] (use serratedTipLength for serrated tips)
    double baseAngleDeg = 90.0;  //!< alpha1 [deg], base to the forward wall tangent
    double tipAngleDeg = 90.0;   //!< alpha2 [deg], between base and tip at the elbow
    int nFlights = 0;            //!< N_F, flights round the drum
};

//- Lee 2008 Eq 4.18 / Eq 7.1: area-averaged tip length of a flight whose tip
//  carries triangular serrations of width sw [m] and depth sd [m], n of them
//  per metre of flight [1/m]. Throws InputError unless 0 < result <= s2.
double serratedTipLength
(
    double s2, double width, double depth, double perMetre,
    const std::string& file = ""
);

//- psi_1 ... psi_5 [deg] (Lee 2008 Eqs 4.9-4.13)
using TransitionPoints = std::array<double, 5>;

class LeeFlight
{
public:
    //- Validates the flight and phi; throws InputError (naming `file` and the
    //  dictionary entry: drum.radius, flight.baseLength, flight.tipLength,
    //  flight.baseAngle, flight.tipAngle, drum.nFlights,
    //  material.dynamicAngleOfRepose) for a flight that cannot exist or a
    //  surface that misses the flight.
    LeeFlight(const FlightGeometry& geometry, double phiDeg, const std::string& file = "");

    const FlightGeometry& geometry() const { return geometry_; }
    double phiDeg() const { return phiDeg_; }

    // Equivalent perpendicular flight (Eqs 4.1-4.4)
    double alpha1PrimeDeg() const;  //!< Eq 4.1
    double alpha2PrimeDeg() const;  //!< Eq 4.2
    double s1Prime() const { return s1p_; }  //!< Eq 4.3 [m]
    double s2Prime() const { return s2p_; }  //!< Eq 4.4 [m]

    double tipRadius() const { return rf_; }      //!< R_F, Eq 4.6 [m]
    double tipOffsetDeg() const;                  //!< psi_ft, Eq 4.7
    double flightSpacingDeg() const;              //!< psi_fl = 360/N_F (Eq 4.5, erratum §8.1)
    double tipChord() const { return sft_; }      //!< s_ft [m]
    double alphaFtDeg() const;                    //!< alpha_ft (explicit form, §8.3)
    double tipToNextElbow() const { return sa_; } //!< s_a [m]
    double alphaADeg() const;                     //!< alpha_a
    double tipToRoot() const { return b_; }       //!< b [m] (Eq 4.12)

    const TransitionPoints& transitionPoints() const { return psi_; }

    //- Root angle [deg] at which the tip crosses the horizontal on the
    //  rising side, psi + psi_ft = 90 deg: where unloading into the curtain starts
    double curtainStartDeg() const;

    //- Full-flight (maximum) cross-section area [m^2 per m], Eq 4.8 / (rho_b L)
    double fullArea() const { return fullArea_; }

    //- Phase of the unloading at psi: 0 full (psi <= psi1), 1..4 between
    //  psi_k and psi_k+1, 5 empty (psi >= psi5)
    int phase(double psiDeg) const;

    //- Material cross-section [m^2 per m] at psi, Eqs 4.8, 4.14-4.17
    double area(double psiDeg) const;

    //- dA/dpsi [m^2 per m per rad] (exact derivative of Eqs 4.14-4.17)
    double areaSlope(double psiDeg) const;

    //- One flight alone against a back plate of radius drumRadius (Lee's
    //  single-flight rig, App. 11.2): the quadrangle of Eq 4.16 until psi4,
    //  the triangle of Eq 4.17 until psi5, zero after; neighbours ignored.
    //  Valid while the surface meets the back plate (psi >= curtain start).
    double singleFlightArea(double psiDeg) const;
    double singleFlightAreaSlope(double psiDeg) const;  //!< [m^2 per m per rad]

    // Positions at root angle psi [m], in the frame above
    Eigen::Vector2d rootPosition(double psiDeg) const;
    Eigen::Vector2d elbowPosition(double psiDeg) const;
    Eigen::Vector2d tipPosition(double psiDeg) const;

    //- Space between this flight and the next one, closed by the chord
    //  between the tips, with the wall arc in arcSegments pieces
    Polygon cellPolygon(double psiDeg, int arcSegments = 400) const;

    //- The material at psi found by clipping the cell with the surface line
    //  (full cell for psi <= psi1, empty for psi >= psi5): the independent
    //  polygon-clipping route (polygonClip.hpp)
    Polygon materialPolygon(double psiDeg, int arcSegments = 400) const;

private:
    template<class T> T areaT(const T& psiRad, int phase) const;

    FlightGeometry geometry_;
    double phi_;      // rad
    double phiDeg_;
    double a1p_, a2p_, s1p_, s2p_;
    double rf_, psift_, psifl_, sft_, aft_, sa_, aa_, b_;
    double fullArea_;
    TransitionPoints psi_;  // deg
};

} // namespace drum

#endif
