// Plane polygons for flight holdup: area (shoelace) and clipping by the
// half-plane below a straight material surface. An independent route to the
// flight holdup that works for any flight outline or back plate, used as the
// cross-check of Lee's closed-form phase equations (Lee 2008 §4.2.3.2).
#ifndef DRUM_FLIGHTS_POLYGONCLIP_HPP
#define DRUM_FLIGHTS_POLYGONCLIP_HPP

#include <Eigen/Core>

#include <vector>

namespace drum
{

using Polygon = std::vector<Eigen::Vector2d>;

//- Area enclosed by a simple polygon (absolute value of the shoelace sum)
double polygonArea(const Polygon& polygon);

//- The part of the polygon on or below the line through `through` that
//  rises at `inclinationRad` to the +x axis: points p with
//  (p - through) x (cos a, sin a) >= 0, i.e. below the line when it is
//  traversed in +x. Sutherland-Hodgman against one half-plane: exact in area
//  for non-convex polygons too (it may leave zero-width slivers).
Polygon clipBelowLine
(
    const Polygon& polygon,
    const Eigen::Vector2d& through,
    double inclinationRad
);

//- Rotate every point by angleRad (counter-clockwise) about the origin
Polygon rotated(const Polygon& polygon, double angleRad);

} // namespace drum

#endif
