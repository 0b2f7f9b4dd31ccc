#include "drum/transport/axialDispersion.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/drift/porousSheetDrift.hpp"
#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

namespace
{
constexpr double g = 9.81;
} // namespace


std::string bedRegimeName(BedRegime r)
{
    switch (r)
    {
        case BedRegime::slumping: return "slumping";
        case BedRegime::rollingCascading: return "rolling/cascading";
        case BedRegime::cataracting: return "cataracting";
        case BedRegime::centrifuging: return "centrifuging";
    }
    return "?";
}


DispersionConstants sherritt2001Constants(BedRegime regime)
{
    switch (regime)
    {
        case BedRegime::slumping: return {4.27e-6, -0.35, 0.85, 0.21, -0.50};
        case BedRegime::rollingCascading: return {5.82e-4, 0.44, 1.29, 0.35, -0.55};  // Eq 84
        case BedRegime::cataracting: return {4.30e-2, 0.90, 1.22, 0.87, -0.02};
        case BedRegime::centrifuging: break;
    }
    throw InputError("", "bed regime", "no dispersion correlation for a centrifuging bed (n >= n_c)");
}


DispersionConstants sherritt2001AllModes()
{
    return {1.10e-3, 0.39, 1.15, 0.46, -0.43};
}


double criticalSpeed(double drumDiameter)
{
    return std::sqrt(g/(0.5*drumDiameter))/(2*pi);  // Eq 1 in rev/s
}


BedRegime bedRegime(double r)
{
    return r < 0.03 ? BedRegime::slumping
         : r < 0.3 ? BedRegime::rollingCascading
         : r < 1.0 ? BedRegime::cataracting
         : BedRegime::centrifuging;
}


double segmentFillFraction(double beta)
{
    return (beta - std::sin(beta))/(2*pi);
}


AxialDispersionResult sherritt2001AxialDispersion(const AxialDispersionInput& in, const std::string& file)
{
    requirePositive(in.drumDiameter, "dispersion: drum diameter [m]", file);
    requirePositive(in.speed, "dispersion: speed [rev/s]", file);
    requirePositive(in.particleDiameter, "dispersion: particle diameter [m]", file);
    requireInRange(in.fill, 1e-12, 1.0, "dispersion: bed fill fraction X", file);
    AxialDispersionResult r;
    r.speedRatio = in.speed/criticalSpeed(in.drumDiameter);
    r.regime = bedRegime(r.speedRatio);
    if (r.regime == BedRegime::centrifuging)
    {
        std::ostringstream os;
        os << "n/n_c = " << r.speedRatio << " >= 1: the bed centrifuges, no axial-dispersion correlation";
        throw InputError(file, "dispersion: speed", os.str());
    }
    const DispersionConstants k = in.allModes ? sherritt2001AllModes() : sherritt2001Constants(r.regime);
    auto warn = [&](const std::string& w) { r.warnings.push_back(w); };
    std::ostringstream os;
    r.fillUsed = in.fill;
    if (in.fill < 0.03)
    {
        os.str("");
        os << "bed fill X = " << in.fill << " below 0.03: clamped to 0.03 (D_z ~ X^" << k.d << ")";
        warn(os.str());
        r.fillUsed = 0.03;
    }
    if (in.fill >= 0.5)
    {
        warn("bed fill X >= 0.5: outside the regression (X < 0.5)");
    }
    if (r.regime == BedRegime::rollingCascading || in.allModes)
    {
        // Eq 84's stated range (Sherritt 2001 5.2)
        if (in.drumDiameter < 0.05 || in.drumDiameter > 0.6)
        {
            os.str("");
            os << "drum diameter " << in.drumDiameter << " m outside the fitted 0.05-0.6 m";
            warn(os.str());
        }
        if (in.particleDiameter < 0.125e-3 || in.particleDiameter > 13e-3)
        {
            os.str("");
            os << "particle diameter " << in.particleDiameter*1e3 << " mm outside the fitted 0.125-13 mm";
            warn(os.str());
        }
    }
    else
    {
        os.str("");
        os << bedRegimeName(r.regime) << " bed (n/n_c = " << r.speedRatio
           << "): the regime's Table 3-3 set is less well supported than Eq 84";
        warn(os.str());
    }
    r.Dz = k.k*std::pow(r.speedRatio, k.a)*std::pow(in.drumDiameter, k.b)
          *std::pow(in.particleDiameter, k.c)*std::pow(r.fillUsed, k.d);  // Eq 51
    return r;
}


double dispersionParticleDiameter
(
    const std::vector<double>& sieveSizes,
    const std::vector<double>& fractions,
    const double sphericity
)
{
    std::vector<double> dp;
    for (double s : sieveSizes) dp.push_back(s*sphericity);
    return sauterDiameter(dp, fractions);
}


double bedFillFraction(const double bedVolumePerLength, const double drumDiameter)
{
    requirePositive(drumDiameter, "dispersion: drum diameter [m]");
    return bedVolumePerLength/(pi*drumDiameter*drumDiameter/4);
}


std::string describeAxialDispersion(const AxialDispersionResult& r, const AxialDispersionInput& in)
{
    std::ostringstream os;
    os << "Sherritt 2001 Eq 51 (" << bedRegimeName(r.regime) << ", n/n_c " << r.speedRatio
       << ", X " << r.fillUsed << ", d_p " << in.particleDiameter*1e6 << " um): D_z " << r.Dz << " m2/s";
    return os.str();
}

} // namespace drum
