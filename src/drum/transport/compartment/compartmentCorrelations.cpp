#include "drum/transport/compartment/compartmentCorrelations.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>

namespace drum
{

namespace
{
}

double LeeFlightGeometry::tipRadius() const
{
    // Lee 2008 Eqs 4.1-4.4 (equivalent perpendicular flight) and Eq 4.6,
    // exactly as the Geometry sub-model computes them (App. 10.2.3)
    const double a1 = baseAngleDeg*pi/180.0;
    const double a2 = tipAngleDeg*pi/180.0;
    const double a1p = pi/2.0 - a1;                               // Eq 4.1
    const double a2p = a2 - a1p;                                  // Eq 4.2
    const double s1p = baseLength*std::sin(pi - a2)/std::sin(a2p);  // Eq 4.3
    const double s2p = baseLength*std::sin(a1p)/std::sin(a2p) + tipLength; // Eq 4.4
    const double r = drumRadius - s1p;
    return std::sqrt(r*r + s2p*s2p - 2.0*r*s2p*std::cos(pi - a2p));   // Eq 4.6
}

LeeCorrelationValues leeCorrelations
(
    const LeeFlightGeometry& geometry,
    const double phi,
    const double f,
    const double rpm,
    const double bulkDensity
)
{
    requireInRange(phi, 20.0, 70.0, "dynamic angle of repose phi (deg), Lee correlations");
    requireInRange(f, 1e-12, 1.0, "flight loading factor f_load, Lee correlations");
    requirePositive(rpm, "rotational speed (rpm)");
    requirePositive(bulkDensity, "bulk density (kg/m3)");

    const double phi2 = phi*phi;
    const double phi3 = phi2*phi;
    const double f2 = f*f;
    const double f3 = f2*f;

    LeeCorrelationValues v{};

    // Eq 4.24, App. 10.2.3 code form (maf_h)
    v.fallHeight =
        1.80225658814015 + 0.0517970853538827*phi - 0.000629336469614827*phi2
      + 6.32035529121722E-08*phi3 + 1.22476072594873*f + 2.16717025928665*f2
      - 1.21939160376451*f3 + 0.010656063519491*phi*f
      - 0.0301050931666396*phi*f2 + 0.000647364680432361*phi2*f
      - 0.00059240889866885*phi2*f2;

    const double tipRadius = geometry.tipRadius();
    const double s = v.fallHeight/(2.0*tipRadius);
    if (s >= 1.0)
    {
        throw InputError("", "flight geometry",
            "fall height from Lee's correlation exceeds the tip-circle diameter 2 R_F = "
          + std::to_string(2.0*tipRadius) + " m: the correlations belong to the Invicta geometry");
    }
    // Eq 4.26 (mafa)
    v.releaseAngle = std::asin(s) + pi/2.0;

    // Eq 4.25, App. 10.2.3 code form (maft; note the minus sign on phi*f_load)
    v.fallTime =
        0.649949441894023 + 0.00467465968739589*phi - 8.34170550900737E-05*phi2
      + 1.10469313271619E-07*phi3 + 0.401111371313164*f - 0.105617246423208*f2
      - 0.012464783688614*f3 - 0.00275163282481117*phi*f
      - 0.00121958102772624*phi*f2 + 0.000113383344526596*phi2*f
      - 9.32689258128505E-05*phi2*f2;

    // App. 10.2.3: t_flight = 2(mafa - pi/2)/(omega 2 pi/60)
    const double omega = rpm*2.0*pi/60.0;
    v.flightTime = 2.0*(v.releaseAngle - pi/2.0)/omega;
    // Passive time actually used for Ch. 7 (docs/errata.md L6):
    // t_p = 60/rpm - t_flight, i.e. Eq 3.4 with the descending-side release
    // point 360 deg - mafa
    v.passiveTime = 60.0/rpm - v.flightTime;

    // Eq 4.27, App. 10.2.3 code form, per metre of drum (times L/N = slice length)
    v.designLoadPerLength = bulkDensity*
    (
        -2.31115676858565 + 0.339781159235542*phi - 0.0184202242225151*phi2
      + 0.000536975704927556*phi3 - 8.65128896429708E-06*phi2*phi2
      + 7.328805813683E-08*phi2*phi3 - 2.54709110347933E-10*phi3*phi3
    );

    if (v.designLoadPerLength <= 0 || v.fallTime <= 0 || v.passiveTime <= 0)
    {
        throw InputError("", "dynamic angle of repose phi (deg), Lee correlations",
            "correlations give a non-positive design load or time at phi = "
          + std::to_string(phi) + " deg");
    }
    return v;
}

double leeSugarAngleOfRepose(const double w)
{
    return 1222.2*w + 34.5;     // Lee 2008 Eq 7.2
}

double leeMoistureProfile(const double wIn, const double wOut, const int i, const int n)
{
    if (n < 2)
    {
        return wIn;
    }
    // Lee 2008 Eq 7.3
    return wIn*std::exp(std::log(wOut/wIn)*double(i - 1)/double(n - 1));
}

} // namespace drum
