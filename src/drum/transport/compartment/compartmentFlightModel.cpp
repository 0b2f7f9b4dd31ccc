#include "drum/transport/compartment/compartmentFlightModel.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/flights/unloadingModel.hpp"
#include "drum/io/inputError.hpp"
#include "drum/transport/kilnBed.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

FlightGeometry flightGeometry(const LeeDryer& d)
{
    FlightGeometry g;
    g.drumRadius = d.geometry.drumRadius;
    g.baseLength = d.geometry.baseLength;
    g.tipLength = d.geometry.tipLength;
    g.baseAngleDeg = d.geometry.baseAngleDeg;
    g.tipAngleDeg = d.geometry.tipAngleDeg;
    g.nFlights = d.geometry.nFlights;
    return g;
}

} // namespace


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
    if (!p.bedSpanDeg.empty() && int(p.bedSpanDeg.size()) != n)
    {
        throw InputError("", "model.flightPickup_deg", "one bed span per slice needed");
    }
    if (p.sizes.empty() || p.sizes.size() != p.fractions.size())
    {
        throw InputError("", "material.sizes_um", "one mass fraction per size class needed");
    }
    const double dL = d.length/n;
    const double theta = d.slopeDeg*deg;
    const double omegaDeg = d.rpm*6.0;      // deg/s

    const FlightGeometry g = flightGeometry(d);

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
        s.kilnBedDiameter = 2.0*d.geometry.drumRadius;
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
        std::vector<double> cfk(p.sizes.size(), 0.0), cbk(p.sizes.size(), 0.0);
        const double psi0 = flight.curtainStartDeg();
        const double psi5 = flight.transitionPoints()[4];
        for (double a = psi0; a < psi5; a += p.angleStepDeg)
        {
            const double b = std::min(a + p.angleStepDeg, psi5);
            const ReleaseConditions r = um.at(0.5*(a + b));
            const double w = std::max(um.holdup(a) - um.holdup(b), 0.0);   // mass released
            s.unloading.push_back({a, um.holdup(a), r.spillRate, r.fallHeight});
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
                q.releaseAngleDeg = 0.5*(a + b);
                q.reposeAngleDeg = s.phiDeg;
                // Drift models work in the gas frame (+x along the gas)
                q.incline = p.counterCurrent ? -theta : theta;
                const double dx = p.drift->displacement(q);
                const double adv = p.counterCurrent ? -dx : dx;      // towards the discharge
                cf += w*p.fractions[k]*std::max(adv, 0.0);
                cb += w*p.fractions[k]*std::max(-adv, 0.0);
                cfk[k] += w*std::max(adv, 0.0);
                cbk[k] += w*std::max(-adv, 0.0);
            }
            wSum += w;
        }
        if (wSum <= 0)
        {
            throw InputError("", "flights", "the flight releases nothing into the curtain");
        }
        double load = um.designLoad();                                  // Eq 4.21
        if (p.holdup == FlightHoldup::bedFilled)
        {
            // Little's law: the flights' load over the flow they release
            load = p.bedSpanDeg.empty() ? um.bedFilledLoad(p.pickupDeg)
                 : um.bedFilledLoad(p.bedSpanDeg.at(i - 1).first, p.bedSpanDeg.at(i - 1).second);
            s.correlations.passiveTime = load/um.curtainFlow();
            s.correlations.flightTime = 60.0/d.rpm - s.correlations.passiveTime;
            s.correlations.designLoadPerLength = load/dL;
            // the bed rolls over the full pockets, in the flight-tip circle
            s.kilnBedDiameter = 2.0*flight.tipRadius();
        }
        s.slice.designLoad = d.designLoadMultiplier*load;
        s.slice.passiveTime = s.correlations.passiveTime;
        s.slice.activeTime = s.correlations.fallTime;
        s.slice.forwardFraction = cf/wSum/dL;
        s.slice.backFraction = cb/wSum/dL;
        for (std::size_t k = 0; k < p.sizes.size(); ++k)
        {
            s.classForward.push_back(cfk[k]/wSum/dL);
            s.classBack.push_back(cbk[k]/wSum/dL);
        }
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

std::vector<std::pair<double, double>> kilnBedSpansDeg
(
    const LeeDryer& d,
    const std::vector<LeeSliceData>& slices,
    const std::vector<double>& kilnMass,
    const double sliceLength
)
{
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 0; i < slices.size(); ++i)
    {
        const LeeFlight flight(flightGeometry(d), slices[i].phiDeg);
        const double D = slices[i].kilnBedDiameter;
        const double half = 0.5*fillAngle(D, kilnMass.at(i)/(d.bulkDensity*sliceLength))/deg;
        const double to = std::min(slices[i].phiDeg + half, flight.curtainStartDeg());
        out.emplace_back(std::min(slices[i].phiDeg - half, to), to);
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
