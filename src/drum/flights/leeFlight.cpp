#include "drum/flights/leeFlight.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <sstream>

namespace drum
{

namespace
{


std::string num(double v)
{
    std::ostringstream os;
    os.precision(6);
    os << v;
    return os.str();
}

void requireOpenRange
(
    double value, double lo, double hi,
    const std::string& entry, const std::string& file, const std::string& why = ""
)
{
    if (!(value > lo && value < hi))
    {
        throw InputError
        (
            file, entry,
            "value " + num(value) + " outside the allowed range (" + num(lo) + ", "
          + num(hi) + ")" + (why.empty() ? "" : ": " + why)
        );
    }
}

} // namespace


double serratedTipLength
(
    double s2, double width, double depth, double perMetre, const std::string& file
)
{
    requirePositive(s2, "flight.tipLength", file);
    requireInRange(width, 0.0, 1.0/std::max(perMetre, 1e-300), "flight.serration.width", file);
    requireInRange(depth, 0.0, s2, "flight.serration.depth", file);
    requireInRange(perMetre, 0.0, 1e6, "flight.serration.perMetre", file);
    // Lee 2008 Eq 4.18 (Eq 7.1): s2_bar = s2 - 1/2 s_w s_d s_N
    const double s2bar = s2 - 0.5*width*depth*perMetre;
    if (!(s2bar > 0.0))
    {
        throw InputError
        (
            file, "flight.serration",
            "serrations remove the whole tip (1/2 width*depth*perMetre = "
          + num(0.5*width*depth*perMetre) + " m >= tipLength " + num(s2) + " m)"
        );
    }
    return s2bar;
}


LeeFlight::LeeFlight(const FlightGeometry& g, double phiDeg, const std::string& file)
:
    geometry_(g),
    phi_(phiDeg*deg),
    phiDeg_(phiDeg)
{
    requireOpenRange(g.drumRadius, 0.0, 1e3, "drum.radius", file);
    requireOpenRange(g.baseLength, 0.0, g.drumRadius, "flight.baseLength", file,
        "the base must be positive and shorter than the drum radius");
    requireOpenRange(g.tipLength, 0.0, g.drumRadius, "flight.tipLength", file,
        "the tip must be positive and shorter than the drum radius");
    requireOpenRange(g.baseAngleDeg, 0.0, 180.0, "flight.baseAngle", file);
    if (!(g.tipAngleDeg >= 90.0 && g.tipAngleDeg < 180.0))
    {
        throw InputError(file, "flight.tipAngle",
            "value " + num(g.tipAngleDeg) + " outside the allowed range [90, 180): "
            "the tip must bend forward and inward (Lee 2008 §4.2)");
    }
    if (g.nFlights < 3 || g.nFlights > 1000)
    {
        throw InputError(file, "drum.nFlights",
            "value " + std::to_string(g.nFlights) + " outside the allowed range [3, 1000]");
    }
    requireOpenRange(phiDeg, 0.0, 90.0, "material.dynamicAngleOfRepose", file);

    const double R = g.drumRadius;
    const double s1 = g.baseLength;
    const double s2 = g.tipLength;
    const double a2 = g.tipAngleDeg*deg;

    a1p_ = pi/2 - g.baseAngleDeg*deg;                   // Lee 2008 Eq 4.1
    a2p_ = a2 - a1p_;                                   // Eq 4.2
    if (!(a2p_ > 0.0 && a2p_ < pi))
    {
        throw InputError(file, "flight.baseAngle",
            "baseAngle " + num(g.baseAngleDeg) + " with tipAngle " + num(g.tipAngleDeg)
          + " gives no equivalent perpendicular flight (need 0 < alpha2 - 90 + alpha1 < 180,"
            " i.e. allowed range of baseAngle (" + num(90.0 - g.tipAngleDeg) + ", "
          + num(270.0 - g.tipAngleDeg) + "))");
    }
    s1p_ = s1*std::sin(pi - a2)/std::sin(a2p_);         // Eq 4.3
    s2p_ = s1*std::sin(a1p_)/std::sin(a2p_) + s2;       // Eq 4.4
    if (!(s1p_ > 0.0 && s1p_ < R) || !(s2p_ > 0.0))
    {
        throw InputError(file, "flight.baseAngle",
            "the equivalent perpendicular flight (s1' = " + num(s1p_) + " m, s2' = "
          + num(s2p_) + " m) must have 0 < s1' < drum radius and s2' > 0 (the allowed range);"
            " bring baseAngle closer to 90");
    }

    psifl_ = 2.0*pi/g.nFlights;                         // Eq 4.5 (psi_fl, erratum §8.1)
    rf_ = std::sqrt((R - s1p_)*(R - s1p_) + s2p_*s2p_
        - 2.0*(R - s1p_)*s2p_*std::cos(pi - a2p_));     // Eq 4.6
    if (!(rf_ < R))
    {
        throw InputError(file, "flight.tipLength",
            "the flight tip lies outside the drum (tip radius " + num(rf_)
          + " m >= drum radius " + num(R) + " m); allowed range: tip radius in (0, drum radius)");
    }
    {
        // The real elbow must be inside the drum too
        const Eigen::Vector2d e = elbowPosition(0.0);
        if (!(e.norm() < R))
        {
            throw InputError(file, "flight.baseAngle",
                "the elbow lies outside the drum; the allowed range of baseAngle keeps it inside");
        }
    }
    psift_ = std::asin(s2p_*std::sin(pi - a2p_)/rf_);  // Eq 4.7
    if (!(psift_ < psifl_))
    {
        throw InputError(file, "drum.nFlights",
            "value " + std::to_string(g.nFlights) + ": the tip reaches past the next "
            "flight's root (psi_ft = " + num(psift_/deg) + " deg >= 360/nFlights); allowed "
            "range [3, " + std::to_string(int(std::floor(2.0*pi/psift_))) + "]");
    }

    // Lee's phases assume the surface through the tip never cuts the flight's
    // own tip section: at psi1 (Eq 4.9) the tip section, inclined at
    // psi + alpha2' - 90, must be at least as steep as phi. Below that the
    // closed forms overstate the holdup (checked against materialPolygon).
    {
        const double minA2p = pi/2 + psifl_/2.0 + psift_;
        if (a2p_ < minA2p)
        {
            throw InputError(file, "flight.tipAngle",
                "value " + num(g.tipAngleDeg) + ": the material surface cuts the flight's own "
                "tip section; Lee 2008 §4.2 needs the allowed range tipAngle - 90 + baseAngle >= "
              + num(minA2p/deg) + " deg (90 + 180/nFlights + psi_ft) for this drum");
        }
    }

    // Helpers of Lee 2008 §4.2.3.1 (docs/errata.md L1, L3)
    sft_ = 2.0*rf_*std::sin(psifl_/2.0);
    aft_ = a2p_ - pi/2 - psift_ + psifl_/2.0;           // explicit alpha_ft (§8.3)
    sa_ = std::sqrt(s2*s2 + sft_*sft_ - 2.0*s2*sft_*std::cos(aft_));
    aa_ = std::asin(s2*std::sin(aft_)/sa_);
    b_ = std::sqrt(s1*s1 + s2*s2 - 2.0*s1*s2*std::cos(a2));

    // Eq 4.8 (area per metre; H_full = rho_b L A_full)
    fullArea_ = 0.5*R*R*psifl_ - 0.5*rf_*rf_*std::sin(psifl_);

    const double c = std::sqrt(R*R + rf_*rf_ - 2.0*R*rf_*std::cos(psifl_ - psift_));
    psi_[0] = phi_ - psifl_/2.0 - psift_;                                   // Eq 4.9
    psi_[1] = phi_ - psift_ - psifl_/2.0 + aa_;                             // Eq 4.10
    psi_[2] = pi/2 + phi_ - psifl_ - std::asin(rf_*std::sin(psifl_ - psift_)/c); // Eq 4.11
    psi_[3] = pi/2 + phi_ + a1p_ + std::asin(s2*std::sin(a2)/b_);           // Eq 4.12
    psi_[4] = pi/2 + phi_ + (pi - a2p_);                                    // Eq 4.13
    for (double& p : psi_)
    {
        p /= deg;
    }
    for (int k = 0; k < 4; ++k)
    {
        if (!(psi_[k] < psi_[k + 1]))
        {
            throw InputError(file, "drum.nFlights",
                "the material surface misses the flight: transition points out of order (psi"
              + std::to_string(k + 1) + " = " + num(psi_[k]) + " deg >= psi"
              + std::to_string(k + 2) + " = " + num(psi_[k + 1]) + " deg); Lee's phases need "
                "psi1 < psi2 < psi3 < psi4 < psi5 (allowed range: more flights, or a different tipAngle)");
        }
    }
    // The phase denominators of Eqs 4.14, 4.15, 4.17 stay positive inside
    // their phases exactly when the order above holds; check at the ends
    for (int ph = 1; ph <= 4; ++ph)
    {
        const double a0 = areaT(psi_[ph - 1]*deg, ph);
        const double a1 = areaT(psi_[ph]*deg, ph);
        if (!std::isfinite(a0) || !std::isfinite(a1) || a0 < -1e-12 || a1 < -1e-12)
        {
            throw InputError(file, "material.dynamicAngleOfRepose",
                "value " + num(phiDeg) + ": the surface misses the flight in phase "
              + std::to_string(ph) + " (negative or undefined holdup); allowed range (0, 90) deg with this flight shape");
        }
    }
}


double LeeFlight::alpha1PrimeDeg() const { return a1p_/deg; }
double LeeFlight::alpha2PrimeDeg() const { return a2p_/deg; }
double LeeFlight::tipOffsetDeg() const { return psift_/deg; }
double LeeFlight::flightSpacingDeg() const { return psifl_/deg; }
double LeeFlight::alphaFtDeg() const { return aft_/deg; }
double LeeFlight::alphaADeg() const { return aa_/deg; }
double LeeFlight::curtainStartDeg() const { return 90.0 - psift_/deg; }


int LeeFlight::phase(double psiDeg) const
{
    if (psiDeg <= psi_[0]) return 0;
    for (int k = 1; k < 5; ++k)
    {
        if (psiDeg < psi_[k]) return k;
    }
    return 5;
}


template<class T>
T LeeFlight::areaT(const T& psi, int ph) const
{
    using std::sin;
    using std::asin;
    const double R = geometry_.drumRadius;
    const double s1 = geometry_.baseLength;
    const double s2 = geometry_.tipLength;
    const double a2 = geometry_.tipAngleDeg*deg;
    const double phi = phi_;

    switch (ph)
    {
        case 0:
            return T(fullArea_);                                         // Eq 4.8
        case 1:
        {
            // Eq 4.14: full minus the triangle between surface and tip chord
            const T delta = psi + psift_ + psifl_/2.0 - phi;
            return fullArea_
                - 0.5*sft_*sft_*sin(delta)/sin(pi - aft_ - delta)*std::sin(aft_);
        }
        case 2:
        {
            // Eq 4.15
            const T eps = psi + psift_ + psifl_/2.0 - aa_ - phi;
            const double zeta = pi + aft_ + aa_ - a2;
            return fullArea_
                - 0.5*(s2*sft_*std::sin(aft_)
                     + sa_*sa_*sin(eps)*std::sin(zeta)
                      /sin(phi + a2 - psi - psift_ - psifl_/2.0 - aft_));
        }
        case 3:
        {
            // Eq 4.16; the centre-elbow-tip triangle uses sin(alpha2') (equal to
            // the printed sin(alpha2) for perpendicular flights, erratum §8.4)
            // and the non-perpendicular correction is s1 s1' sin(alpha1')
            const T wallAngle = asin(rf_/R*sin(psift_ + psi + pi/2 - phi));
            const T sector = phi - psi + pi/2 - wallAngle;   // psi_ft + beta
            const T beta = sector - psift_;
            return 0.5*(R*R*sector - R*rf_*sin(beta)
                - (R - s1p_)*s2p_*std::sin(a2p_) - s1*s1p_*std::sin(a1p_));
        }
        case 4:
        {
            // Eq 4.17
            const double a2sup = pi - a2p_;
            return 0.5*s2*s2*std::sin(a2)*sin(a2sup - psi + phi + pi/2)
                /sin(pi/2 - a2 - a2sup + psi - phi);
        }
        default:
            return T(0.0);
    }
}


double LeeFlight::area(double psiDeg) const
{
    return areaT(psiDeg*deg, phase(psiDeg));
}


double LeeFlight::areaSlope(double psiDeg) const
{
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
    const int ph = phase(psiDeg);
    if (ph == 0 || ph == 5)
    {
        return 0.0;
    }
    const AD psi(psiDeg*deg, 1, 0);
    return areaT(psi, ph).derivatives()(0);
}


double LeeFlight::singleFlightArea(double psiDeg) const
{
    const int ph = psiDeg < psi_[3] ? 3 : (psiDeg < psi_[4] ? 4 : 5);
    return areaT(psiDeg*deg, ph);
}


double LeeFlight::singleFlightAreaSlope(double psiDeg) const
{
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
    const int ph = psiDeg < psi_[3] ? 3 : (psiDeg < psi_[4] ? 4 : 5);
    if (ph == 5) return 0.0;
    const AD psi(psiDeg*deg, 1, 0);
    return areaT(psi, ph).derivatives()(0);
}


Eigen::Vector2d LeeFlight::rootPosition(double psiDeg) const
{
    const double a = psiDeg*deg;
    return geometry_.drumRadius*Eigen::Vector2d(std::sin(a), -std::cos(a));
}


Eigen::Vector2d LeeFlight::elbowPosition(double psiDeg) const
{
    // Local frame (root at the bottom): fictitious elbow E' on the radius at
    // depth s1', tip line at alpha2' from the outward radius; the real elbow
    // lies s2' - s2 along it (Eqs 4.3-4.4)
    const double R = geometry_.drumRadius;
    const Eigen::Vector2d ep(0.0, -R + s1p_);
    const Eigen::Vector2d d(std::sin(a2p_), -std::cos(a2p_));
    const Polygon p{ep + (s2p_ - geometry_.tipLength)*d};
    return rotated(p, psiDeg*deg)[0];
}


Eigen::Vector2d LeeFlight::tipPosition(double psiDeg) const
{
    const double R = geometry_.drumRadius;
    const Eigen::Vector2d ep(0.0, -R + s1p_);
    const Eigen::Vector2d d(std::sin(a2p_), -std::cos(a2p_));
    const Polygon p{ep + s2p_*d};
    return rotated(p, psiDeg*deg)[0];
}


Polygon LeeFlight::cellPolygon(double psiDeg, int arcSegments) const
{
    const double next = psiDeg + psifl_/deg;
    Polygon cell{tipPosition(psiDeg), elbowPosition(psiDeg), rootPosition(psiDeg)};
    const int n = std::max(arcSegments, 1);
    for (int i = 1; i < n; ++i)
    {
        cell.push_back(rootPosition(psiDeg + (next - psiDeg)*i/n));
    }
    cell.push_back(rootPosition(next));
    cell.push_back(elbowPosition(next));
    cell.push_back(tipPosition(next));
    return cell;
}


Polygon LeeFlight::materialPolygon(double psiDeg, int arcSegments) const
{
    const int ph = phase(psiDeg);
    if (ph == 5)
    {
        return {};
    }
    const Polygon cell = cellPolygon(psiDeg, arcSegments);
    if (ph == 0)
    {
        return cell;
    }
    return clipBelowLine(cell, tipPosition(psiDeg), phi_);
}

} // namespace drum
