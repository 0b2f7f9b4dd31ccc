// Generators of Sherritt flight tables from flight cross-sections (Sherritt
// 1991 §2.3, §3.2): the thesis measured (angle, horizontal tip-to-surface
// length) off drawings; here the drawing is a polyline and the length is
// found by casting the horizontal line from the tip.
//
// A shape is a polyline from the wall attachment P0 to the tip, in a
// reference frame where the drum axis is the origin, the tip lies on the +x
// axis (theta = 0) and z is up; at theta = 0 the tip moves down, so the
// direction of rotation there is -z ("forward").
//
// Tabulation rule at rotation theta (tip at (R cos theta, -R sin theta)):
//  * the horizontal line runs from the tip towards -x, i.e. back against the
//    rotation over the upper half where flights discharge (Sherritt 1991 §3.2);
//  * the material below it is held only if the flight edge at the tip runs
//    downwards from the tip (otherwise material would slide off the tip):
//    the length is then 0, unless the tip is below the drum axis: there
//    the shell below carries the material, the overload bed of an
//    overloaded drum (Sherritt 1991 Fig 3.1b/c), and the line is the bed
//    surface through the tip of the first discharging flight, running to
//    the shell (or a flight) across the drum bottom;
//  * otherwise the length is the distance to the first wall or flight the
//    line meets: the shell, this flight, or (interference) the other N-1
//    flights.
#ifndef DRUM_FLIGHTS_SHERRITTFLIGHTSHAPES_HPP
#define DRUM_FLIGHTS_SHERRITTFLIGHTSHAPES_HPP

#include "drum/flights/sherritt/sherrittFlightProfile.hpp"

#include <Eigen/Core>

#include <vector>

namespace drum
{

//- A flight cross-section: polyline P0 (on the shell) ... tip, reference
//  frame as above, and the shell diameter it is fixed to
struct SherrittFlightShape
{
    std::vector<Eigen::Vector2d> points;
    double shellDiameter = 0;

    //- Tip locus diameter 2|tip|
    double tipDiameter() const;
};

//- Two-sided (angled) flight: a base plate of length s1 leaving the shell at
//  baseAngle to the tangent (pi/2: radial), then a tip plate of length s2 at
//  tipAngle to the base, turned forward (pi/2: rectangular flight of
//  Fig 2.2a; Sheikh's 135 deg flights: 3 pi/4)
SherrittFlightShape twoSidedFlightShape
(
    double shellDiameter,
    double baseLength,
    double tipLength,
    double tipAngle,
    double baseAngle = 1.5707963267948966
);

//- Straight radial plate of the given length
SherrittFlightShape straightRadialFlightShape(double shellDiameter, double length);

//- Semi-circular flight (Fig 2.2d): a half circle of the given radius whose
//  diameter is radial from the shell, bulging backwards so it opens forward
SherrittFlightShape semiCircularFlightShape
(
    double shellDiameter,
    double radius,
    int segments = 60
);

//- Equal angular distribution flight (Kelly, Fig 2.2b): the flight wall is
//  an arc of the given radius centred on the tip, spanning the directions
//  the surface takes from theta = pi to 2 pi at the design angle of repose
//  (-phi_d .. pi - phi_d from the outward radial), joined to the shell by a
//  radial plate. Every surface from the tip then ends on the arc, so l = r
//  and the discharge rate is constant over the discharging arc. The tips sit
//  at D_ex = D_o - 2 r (the arc touches the shell) unless tipDiameter > 0 is
//  given (then D_ex/2 + r <= D_o/2 is required).
SherrittFlightShape eadFlightShape
(
    double shellDiameter,
    double radius,
    double designRepose,
    double tipDiameter = 0,
    int segments = 90
);

//- Centrally biased distribution flight (Kelly, Fig 2.2c): as EAD, but the
//  arc's centre is moved from the tip by bias*radius (0 <= bias < 1) along
//  the surface direction met at theta = 3 pi/2, so the surface, and so the
//  discharge, is longest with the flight at the top of the drum. Kelly's
//  exact drawing is not in the thesis text: this is a stand-in with the
//  defining property (bias 0 is the EAD flight).
SherrittFlightShape cbdFlightShape
(
    double shellDiameter,
    double radius,
    double bias,
    double designRepose,
    double tipDiameter,
    int segments = 90
);

//- Tabulate (angle, horizontal length) at `step` [rad] over [0, 2 pi] for an
//  exterior flight (rules in the file header). interference: also stop the
//  line at the other count-1 flights. Throws drum::InputError for a shape
//  with its tip outside the drum or points outside the shell.
SherrittFlightProfile tabulateSherrittFlight
(
    const SherrittFlightShape& shape,
    int count,
    double axialLength,
    double step = 0.017453292519943295,
    bool interference = true
);

} // namespace drum

#endif
