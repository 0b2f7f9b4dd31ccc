#include "drum/flights/sherritt/sherrittFlightShapes.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace drum
{

namespace
{

using Vec = Eigen::Vector2d;

void requireAngle(double value, double lo, double hi, const char* entry)
{
    if (!(value > lo && value < hi))
    {
        std::ostringstream os;
        os << "angle " << value*180/pi << " deg outside the open range ("
           << lo*180/pi << ", " << hi*180/pi << ") deg";
        throw InputError("", entry, os.str());
    }
}

// Rotate a reference-frame point to the tip angle theta (Sherritt 1991 nomenclature:
// tip at (R cos theta, -R sin theta))
Vec toWorld(const Vec& p, double theta)
{
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    return Vec(p.x()*c + p.y()*s, -p.x()*s + p.y()*c);
}

// Rotate the shape about the axis so its tip lies on the +x axis
SherrittFlightShape alignTip(std::vector<Vec> pts, double shellDiameter)
{
    const Vec tip = pts.back();
    const double beta = std::atan2(tip.y(), tip.x());
    const double c = std::cos(beta);
    const double s = std::sin(beta);
    for (auto& p : pts)
    {
        p = Vec(p.x()*c + p.y()*s, -p.x()*s + p.y()*c);
    }
    SherrittFlightShape shape;
    shape.points = std::move(pts);
    shape.shellDiameter = shellDiameter;
    return shape;
}

// Arc wall centred at c with radius r, seen from the tip t along directions
// a0..a1: the points where rays from t meet the circle
std::vector<Vec> arcFromTip(const Vec& t, const Vec& c, double r, double a0, double a1, int segments)
{
    std::vector<Vec> pts;
    for (int i = 0; i <= segments; ++i)
    {
        const double a = a0 + (a1 - a0)*i/segments;
        const Vec d(std::cos(a), std::sin(a));
        const Vec m = t - c;
        // |m + s d| = r, s > 0
        const double b = m.dot(d);
        const double disc = b*b - (m.squaredNorm() - r*r);
        const double s = -b + std::sqrt(std::max(0.0, disc));
        pts.push_back(t + s*d);
    }
    return pts;
}

SherrittFlightShape arcFlight
(
    double shellDiameter, double radius, double bias, double designRepose,
    double tipDiameter, int segments, const char* what
)
{
    requirePositive(shellDiameter, std::string(what) + " shell diameter");
    requirePositive(radius, std::string(what) + " radius");
    requireAngle(designRepose, 0, 0.5*pi, "design angle of repose");
    requireInRange(bias, 0, 0.95, std::string(what) + " bias");
    if (segments < 4)
    {
        throw InputError("", std::string(what) + " segments", "need at least 4 arc segments");
    }
    const double Ro = 0.5*shellDiameter;
    const double Rex = tipDiameter > 0 ? 0.5*tipDiameter : Ro - radius*(1 + bias);
    if (!(Rex > 0))
    {
        std::ostringstream os;
        os << "radius " << radius << " m leaves no room for the tip inside a "
           << shellDiameter << " m drum: range (0, " << Ro << ") m";
        throw InputError("", std::string(what) + " radius", os.str());
    }
    const Vec tip(Rex, 0);
    const double ac = 0.5*pi - designRepose;  // surface direction at theta = 3 pi/2
    const Vec centre = tip + bias*radius*Vec(std::cos(ac), std::sin(ac));
    std::vector<Vec> arc = arcFromTip(tip, centre, radius, -designRepose, pi - designRepose, segments);

    std::vector<Vec> pts;
    const Vec a0 = arc.front();
    if (a0.norm() < Ro*(1 - 1e-9))
    {
        pts.push_back(a0.normalized()*Ro);  // radial plate to the shell
    }
    pts.insert(pts.end(), arc.begin(), arc.end());
    pts.push_back(tip);
    for (const auto& p : pts)
    {
        if (p.norm() > Ro*(1 + 1e-9))
        {
            std::ostringstream os;
            os << "the flight wall reaches radius " << p.norm()
               << " m, outside the shell radius " << Ro
               << " m: reduce the radius or the tip diameter";
            throw InputError("", std::string(what) + " tip diameter", os.str());
        }
    }
    SherrittFlightShape shape;
    shape.points = std::move(pts);
    shape.shellDiameter = shellDiameter;
    return shape;
}

} // namespace


double SherrittFlightShape::tipDiameter() const
{
    return points.empty() ? 0.0 : 2*points.back().norm();
}


SherrittFlightShape twoSidedFlightShape
(
    double shellDiameter,
    double baseLength,
    double tipLength,
    double tipAngle,
    double baseAngle
)
{
    requirePositive(shellDiameter, "shell diameter");
    requirePositive(baseLength, "base length s1");
    if (!(tipLength >= 0) || !std::isfinite(tipLength))
    {
        throw InputError("", "tip length s2", "must be in [0, inf) m");
    }
    requireAngle(tipAngle, 0, pi, "tip angle");
    requireAngle(baseAngle, 0, pi, "base angle");
    const double Ro = 0.5*shellDiameter;
    const Vec p0(Ro, 0);
    // base leaves the shell at baseAngle to the tangent (forward = -z)
    const Vec base(-std::sin(baseAngle), -std::cos(baseAngle));
    const Vec p1 = p0 + baseLength*base;
    // tip plate at tipAngle to the base, turned forward: rotate the
    // direction back along the base (p1 -> p0) by tipAngle clockwise
    const Vec back = -base;
    const Vec dir
    (
        back.x()*std::cos(tipAngle) + back.y()*std::sin(tipAngle),
        -back.x()*std::sin(tipAngle) + back.y()*std::cos(tipAngle)
    );
    std::vector<Vec> pts{p0, p1};
    if (tipLength > 0)
    {
        pts.push_back(p1 + tipLength*dir);
    }
    return alignTip(std::move(pts), shellDiameter);
}


SherrittFlightShape straightRadialFlightShape(double shellDiameter, double length)
{
    requirePositive(shellDiameter, "shell diameter");
    requirePositive(length, "radial flight length");
    const double Ro = 0.5*shellDiameter;
    return alignTip({Vec(Ro, 0), Vec(Ro - length, 0)}, shellDiameter);
}


SherrittFlightShape semiCircularFlightShape(double shellDiameter, double radius, int segments)
{
    requirePositive(shellDiameter, "shell diameter");
    requirePositive(radius, "semi-circular flight radius");
    if (segments < 4)
    {
        throw InputError("", "semi-circular flight segments", "need at least 4");
    }
    const double Ro = 0.5*shellDiameter;
    std::vector<Vec> pts;
    const Vec c(Ro - radius, 0);
    for (int i = 0; i <= segments; ++i)
    {
        const double t = pi*i/segments;
        pts.push_back(c + radius*Vec(std::cos(t), std::sin(t)));  // bulges backwards (+z)
    }
    return alignTip(std::move(pts), shellDiameter);
}


SherrittFlightShape eadFlightShape
(
    double shellDiameter, double radius, double designRepose, double tipDiameter, int segments
)
{
    return arcFlight(shellDiameter, radius, 0.0, designRepose, tipDiameter, segments, "EAD flight");
}


SherrittFlightShape cbdFlightShape
(
    double shellDiameter, double radius, double bias, double designRepose,
    double tipDiameter, int segments
)
{
    return arcFlight(shellDiameter, radius, bias, designRepose, tipDiameter, segments, "CBD flight");
}


SherrittFlightProfile tabulateSherrittFlight
(
    const SherrittFlightShape& shape,
    int count,
    double axialLength,
    double step,
    bool interference
)
{
    requirePositive(shape.shellDiameter, "shell diameter");
    if (shape.points.size() < 2)
    {
        throw InputError("", "flight shape", "needs at least 2 points");
    }
    const double Ro = 0.5*shape.shellDiameter;
    const double Rtip = shape.points.back().norm();
    if (!(Rtip < Ro) || !(Rtip > 0))
    {
        std::ostringstream os;
        os << "tip radius " << Rtip << " m outside the drum: range (0, " << Ro << ") m";
        throw InputError("", "flight tip", os.str());
    }
    for (std::size_t i = 0; i < shape.points.size(); ++i)
    {
        if (shape.points[i].norm() > Ro*(1 + 1e-9))
        {
            std::ostringstream os;
            os << "point at radius " << shape.points[i].norm()
               << " m lies outside the shell radius " << Ro << " m";
            throw InputError("", "flight shape point[" + std::to_string(i) + "]", os.str());
        }
    }
    if (count < 1)
    {
        throw InputError("", "flight count", "must be in [1, 1000]");
    }
    requireInRange(step, 1e-4, 0.2, "tabulation step [rad]");

    const std::size_t np = shape.points.size();
    const int nAngles = static_cast<int>(std::ceil(2*pi/step - 1e-9));
    std::vector<double> angles;
    std::vector<double> lengths;
    std::vector<Vec> world(np);
    for (int j = 0; j <= nAngles; ++j)
    {
        const double theta = std::min(2*pi, j*step);
        for (std::size_t i = 0; i < np; ++i)
        {
            world[i] = toWorld(shape.points[i], theta);
        }
        const Vec tip = world.back();
        const Vec u = world[np - 2] - tip;
        double length = 0;
        // Held if the flight edge at the tip runs down from the tip (a
        // pocket), or if the tip is below the drum axis: then the material
        // under the line is carried by the shell below, the overload bed in
        // the drum bottom whose surface passes the first discharging tip
        // (Sherritt 1991 Fig 3.1b/c, the surface of Eqs 77/84/85)
        const bool belowAxis = tip.y() < 0;
        if (!(u.y() > 1e-12*u.norm()) || belowAxis)
        {
            // horizontal line from the tip towards -x: nearest obstacle
            const double x0 = tip.x();
            const double z0 = tip.y();
            double best = x0 + std::sqrt(std::max(0.0, Ro*Ro - z0*z0));  // the shell
            auto hitPolyline = [&](const std::vector<Vec>& pts, std::size_t nSeg)
            {
                for (std::size_t i = 0; i < nSeg; ++i)
                {
                    const Vec& p = pts[i];
                    const Vec& q = pts[i + 1];
                    const double dp = p.y() - z0;
                    const double dq = q.y() - z0;
                    if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0))
                    {
                        continue;
                    }
                    double x;
                    if (dp == dq)
                    {
                        x = std::max(p.x() < x0 ? p.x() : -1e300, q.x() < x0 ? q.x() : -1e300);
                    }
                    else
                    {
                        x = p.x() + (q.x() - p.x())*dp/(dp - dq);
                    }
                    const double d = x0 - x;
                    if (d > 1e-12*Ro && d < best)
                    {
                        best = d;
                    }
                }
            };
            // this flight, without the tip segment itself
            hitPolyline(world, np - 2);
            if (interference)
            {
                std::vector<Vec> other(np);
                for (int k = 1; k < count; ++k)
                {
                    const double thetaK = theta + 2*pi*k/count;
                    for (std::size_t i = 0; i < np; ++i)
                    {
                        other[i] = toWorld(shape.points[i], thetaK);
                    }
                    hitPolyline(other, np - 1);
                }
            }
            length = best;
        }
        if (!angles.empty() && theta <= angles.back())
        {
            break;
        }
        angles.push_back(theta);
        lengths.push_back(length);
    }
    return SherrittFlightProfile
    (
        angles, lengths, FlightSide::exterior, 2*Rtip, count, axialLength, "generated flight"
    );
}

} // namespace drum
