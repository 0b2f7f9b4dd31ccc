#include "drum/transport/compartment/compartmentFlightModel.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/flights/unloadingModel.hpp"
#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

std::vector<LeeSliceData> flightModelSliceData
(
    const LeeDryer& d,
    const int n,
    const FlightModelPartition& p
)
{
    if (!p.drift)
    {
        throw InputError("", "model.drift", "the flight-model partition needs a drift model");
    }
    if (n < 1)
    {
        throw InputError("", "slices", "number of slices must be >= 1");
    }
    if (p.sizes.empty() || p.sizes.size() != p.fractions.size())
    {
        throw InputError("", "material.sizes_um", "one mass fraction per size class needed");
    }
    const double dL = d.length/n;
    const double theta = d.slopeDeg*deg;
    const double omegaDeg = d.rpm*6.0;      // deg/s

    FlightGeometry g;
    g.drumRadius = d.geometry.drumRadius;
    g.baseLength = d.geometry.baseLength;
    g.tipLength = d.geometry.tipLength;
    g.baseAngleDeg = d.geometry.baseAngleDeg;
    g.tipAngleDeg = d.geometry.tipAngleDeg;
    g.nFlights = d.geometry.nFlights;

    UnloadingSettings us;
    us.bulkDensity = d.bulkDensity;
    us.speedRpm = d.rpm;
    us.flightLength = dL;
    us.drumSlopeDeg = d.slopeDeg;

    std::vector<LeeSliceData> out;
    out.reserve(n);
    for (int i = 1; i <= n; ++i)
    {
        LeeSliceData s{};
        s.phiDeg = leeSliceReposeDeg(d, i, n);
        const LeeFlight flight(g, s.phiDeg);
        const UnloadingModel um(flight, us);

        const double psiBar = um.meanReleaseAngleDeg();                 // Eq 3.3
        s.correlations.fallHeight = um.meanFallHeight();
        s.correlations.fallTime = um.meanFallTime();
        s.correlations.releaseAngle = psiBar*deg;
        s.correlations.passiveTime = (2.0*psiBar - 180.0)/omegaDeg;     // Eq 3.4
        s.correlations.flightTime = 60.0/d.rpm - s.correlations.passiveTime;
        s.correlations.designLoadPerLength = um.designLoad()/dL;        // Eq 4.21

        // Axial advance per release angle and size class, solids frame
        double wSum = 0, cf = 0, cb = 0;
        const double psi0 = flight.curtainStartDeg();
        const double psi5 = flight.transitionPoints()[4];
        for (double a = psi0; a < psi5; a += p.angleStepDeg)
        {
            const double b = std::min(a + p.angleStepDeg, psi5);
            const ReleaseConditions r = um.at(0.5*(a + b));
            const double w = std::max(um.holdup(a) - um.holdup(b), 0.0);   // mass released
            if (w <= 0 || r.fallHeight <= 0) continue;
            for (std::size_t k = 0; k < p.sizes.size(); ++k)
            {
                DriftQuery q;
                q.particleDiameter = p.sizes[k];
                q.particleDensity = p.particleDensity;
                q.gasVelocity = p.gasVelocity;
                q.fallHeight = r.fallHeight;
                q.spillRate = r.spillRate;
                q.flightLength = p.flightAxialLength;
                // Drift models work in the gas frame (+x along the gas)
                q.incline = p.counterCurrent ? -theta : theta;
                const double dx = p.drift->displacement(q);
                const double adv = p.counterCurrent ? -dx : dx;      // towards the discharge
                cf += w*p.fractions[k]*std::max(adv, 0.0);
                cb += w*p.fractions[k]*std::max(-adv, 0.0);
            }
            wSum += w;
        }
        if (wSum <= 0)
        {
            throw InputError("", "flights", "the flight releases nothing into the curtain");
        }
        s.slice.designLoad = d.designLoadMultiplier*um.designLoad();
        s.slice.passiveTime = s.correlations.passiveTime;
        s.slice.activeTime = s.correlations.fallTime;
        s.slice.forwardFraction = cf/wSum/dL;
        s.slice.backFraction = cb/wSum/dL;
        if (s.slice.forwardFraction + s.slice.backFraction > 1.0)
        {
            std::ostringstream os;
            os << "mean axial jump per fall " << (cf + cb)/wSum << " m exceeds the slice length "
               << dL << " m in slice " << i << " (Lee's nearest-neighbour rule, Fig. 3.4): use fewer slices";
            throw InputError("", "model.slices", os.str());
        }
        out.push_back(s);
    }
    return out;
}

CompartmentNetwork flightModelNetwork
(
    const LeeDryer& dryer,
    const int n,
    const FlightModelPartition& p,
    const double kilnTime
)
{
    std::vector<CompartmentSlice> slices;
    for (const LeeSliceData& s : flightModelSliceData(dryer, n, p))
    {
        slices.push_back(s.slice);
    }
    return CompartmentNetwork(std::move(slices), dryer.feedRate, kilnTime);
}

} // namespace drum
