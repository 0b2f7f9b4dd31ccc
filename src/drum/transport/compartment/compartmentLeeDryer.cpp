#include "drum/transport/compartment/compartmentLeeDryer.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>

namespace drum
{

double leeSliceReposeDeg(const LeeDryer& d, int i, int n)
{
    // Dryer Model: phi_i = 1222.2 w_i + 34.5 (Eqs 7.2-7.3)
    return d.constantPhiDeg
        ? *d.constantPhiDeg
        : leeSugarAngleOfRepose(leeMoistureProfile(d.moistureInlet, d.moistureOutlet, i, n));
}


std::vector<LeeSliceData> leeSliceData
(
    const LeeDryer& d,
    const int n,
    const LeeParameters& p
)
{
    if (n < 1)
    {
        throw InputError("", "slices", "number of slices must be >= 1");
    }
    requirePositive(d.length, "drum length (m)");
    requireInRange(d.slopeDeg, 0.0, 20.0, "drum slope (deg)");
    requirePositive(d.designLoadMultiplier, "design load multiplier");

    const double dL = d.length/n;
    const double sinTheta = std::sin(d.slopeDeg*pi/180.0);
    std::vector<LeeSliceData> out;
    out.reserve(n);
    for (int i = 1; i <= n; ++i)
    {
        LeeSliceData s{};
        s.phiDeg = leeSliceReposeDeg(d, i, n);
        s.correlations = leeCorrelations(d.geometry, s.phiDeg, d.fLoad, d.rpm, d.bulkDensity);
        s.slice.designLoad = d.designLoadMultiplier*s.correlations.designLoadPerLength*dL;
        s.slice.passiveTime = s.correlations.passiveTime;
        s.slice.activeTime = s.correlations.fallTime;
        // Eqs 3.7-3.8, code form: C_x = C_x_g maf_h sin(theta)/(L/N)
        s.slice.forwardFraction = p.dragFactor*s.correlations.fallHeight*sinTheta/dL;
        s.slice.backFraction = p.backFraction;
        out.push_back(s);
    }
    return out;
}

CompartmentNetwork leeNetwork(const LeeDryer& d, const int n, const LeeParameters& p)
{
    std::vector<CompartmentSlice> slices;
    for (const LeeSliceData& s : leeSliceData(d, n, p))
    {
        slices.push_back(s.slice);
    }
    return CompartmentNetwork(std::move(slices), d.feedRate, p.kilnTime);
}

} // namespace drum
