#include "drum/flights/unloadingModel.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"
#include "particleDrag/releaseLayer.hpp"

#include <cmath>

namespace drum
{

namespace
{
} // namespace


UnloadingModel::UnloadingModel
(
    const LeeFlight& flight, const UnloadingSettings& s, const std::string& file
)
:
    flight_(flight),
    settings_(s)
{
    requireInRange(s.bulkDensity, 1.0, 2.0e4, "material.bulkDensity", file);
    requireInRange(s.speedRpm, 1e-6, 1e3, "drum.speed", file);
    requirePositive(s.flightLength, "flight.length", file);
    requireInRange(s.drumSlopeDeg, 0.0, 45.0, "drum.slope", file);
    requireInRange(s.bedDepth, 0.0, flight.geometry().drumRadius, "drum.bedDepth", file);
    requirePositive(s.layerVelocity, "material.layerVelocity", file);
    if (s.layerBulkDensity != 0.0)
    {
        requireInRange(s.layerBulkDensity, 1.0, s.bulkDensity, "material.layerBulkDensity", file);
    }
    requirePositive(s.gravity, "gravity", file);
    if (settings_.layerBulkDensity == 0.0)
    {
        settings_.layerBulkDensity = settings_.bulkDensity;
    }
}


double UnloadingModel::omega() const
{
    return settings_.speedRpm*2.0*pi/60.0;
}


double UnloadingModel::holdup(double psiDeg) const
{
    return settings_.bulkDensity*flight_.area(psiDeg);    // H = rho_b A (per metre)
}


double UnloadingModel::discharge(double psiDeg) const
{
    return 0.0 - settings_.bulkDensity*flight_.areaSlope(psiDeg);  // F/omega = -dH/dpsi (§4.2.4)
}


double UnloadingModel::fallHeight(double x, double y) const
{
    const double R = flight_.geometry().drumRadius;
    const double wallY = -std::sqrt(std::max(R*R - x*x, 0.0));
    const double bedY = -R + settings_.bedDepth;
    const double landing = std::max(wallY, bedY);
    // Lee 2008 Eq 3.5: the cross-section drop over cos(theta)
    return std::max(y - landing, 0.0)/std::cos(settings_.drumSlopeDeg*deg);
}


ReleaseConditions UnloadingModel::at(double psiDeg) const
{
    ReleaseConditions r;
    r.psiDeg = psiDeg;
    r.tipAngleDeg = psiDeg + flight_.tipOffsetDeg();
    r.phase = flight_.phase(psiDeg);
    r.toCurtain = r.tipAngleDeg >= 90.0;
    r.holdup = holdup(psiDeg);
    r.discharge = discharge(psiDeg);
    r.spillRate = omega()*r.discharge;                     // F = omega dH/dpsi
    const Eigen::Vector2d tip = flight_.tipPosition(psiDeg);
    r.releaseX = tip.x();
    r.releaseY = tip.y();
    const double R = flight_.geometry().drumRadius;
    r.landingY = std::max(-std::sqrt(std::max(R*R - tip.x()*tip.x(), 0.0)),
                          -R + settings_.bedDepth);
    r.fallHeight = fallHeight(tip.x(), tip.y());
    r.fallTime = std::sqrt(2.0*r.fallHeight/settings_.gravity);   // Eq 3.6
    r.layerVelocity = settings_.layerVelocity;
    // Lee 2008 Eq 5.4 per metre of flight: dM/dt = rho_bl h v
    r.layerThickness = particleDrag::releaseLayerThickness(r.spillRate, settings_.layerBulkDensity,
                                                           settings_.layerVelocity);
    return r;
}


std::vector<ReleaseConditions> UnloadingModel::profile
(
    double psiStartDeg, double psiEndDeg, double stepDeg
) const
{
    requirePositive(stepDeg, "output.angleStep");
    std::vector<double> angles;
    const int n = int(std::floor((psiEndDeg - psiStartDeg)/stepDeg + 1e-9));
    for (int i = 0; i <= n; ++i)
    {
        angles.push_back(psiStartDeg + i*stepDeg);
    }
    for (double p : flight_.transitionPoints())
    {
        if (p > psiStartDeg && p < psiEndDeg) angles.push_back(p);
    }
    std::sort(angles.begin(), angles.end());
    std::vector<ReleaseConditions> out;
    for (double a : angles)
    {
        if (out.empty() || a - out.back().psiDeg > 1e-9)
        {
            out.push_back(at(a));
        }
    }
    return out;
}


double UnloadingModel::maxHoldup() const
{
    return settings_.bulkDensity*flight_.fullArea();      // Eq 4.8 per metre
}


double UnloadingModel::designFlightHoldup() const
{
    return holdup(flight_.curtainStartDeg());             // H_0,des (§4.4)
}


double UnloadingModel::meanReleaseAngleDeg() const
{
    // Lee 2008 Eq 3.3: psi_bar = int psi dH / H_0 from the tip horizontal
    const double h0 = designFlightHoldup();
    if (!(h0 > 0.0)) return flight_.curtainStartDeg();
    return integrate([&](double p) { return p*discharge(p); },
                     flight_.curtainStartDeg(), flight_.transitionPoints()[4])/h0;
}


double UnloadingModel::meanFallHeight() const
{
    const double h0 = designFlightHoldup();
    if (!(h0 > 0.0)) return 0.0;
    return integrate([&](double p)
        {
            const Eigen::Vector2d t = flight_.tipPosition(p);
            return fallHeight(t.x(), t.y())*discharge(p);
        },
        flight_.curtainStartDeg(), flight_.transitionPoints()[4])/h0;
}


double UnloadingModel::meanFallTime() const
{
    const double h0 = designFlightHoldup();
    if (!(h0 > 0.0)) return 0.0;
    return integrate([&](double p) { return at(p).fallTime*discharge(p); },
        flight_.curtainStartDeg(), flight_.transitionPoints()[4])/h0;
}


double UnloadingModel::designLoad() const
{
    // Lee 2008 Eq 4.20/4.21: M_p,des = H_0 + 2 sum_{i=1}^{N_F/2-1} H_i with
    // H_i the holdup of the i-th flight past the tip horizontal
    const int nf = flight_.geometry().nFlights;
    const double psi0 = flight_.curtainStartDeg();
    double m = designFlightHoldup();
    for (int i = 1; i <= nf/2 - 1; ++i)
    {
        m += 2.0*holdup(psi0 + i*flight_.flightSpacingDeg());
    }
    return m*settings_.flightLength;
}


double UnloadingModel::porterDesignLoad() const
{
    // Porter's rule, Lee 2008 Eq 4.19: M_des = N_F H_0,des / 2
    return flight_.geometry().nFlights*designFlightHoldup()*settings_.flightLength/2.0;
}


double UnloadingModel::curtainFlow() const
{
    return flight_.geometry().nFlights*designFlightHoldup()*settings_.speedRpm/60.0*settings_.flightLength;
}


double UnloadingModel::bedFilledLoad(double pickupDeg) const
{
    requireInRange(pickupDeg, -90.0, flight_.curtainStartDeg(), "model.flightPickup_deg");
    return bedFilledLoad(pickupDeg, pickupDeg);     // a bed of no width: H(psi) from the pickup on
}


double UnloadingModel::bedFilledLoad(double bedFromDeg, double bedToDeg) const
{
    const double psi5 = flight_.transitionPoints()[4];
    requireInRange(bedToDeg, -90.0, flight_.curtainStartDeg(), "bed span end (root angle, deg)");
    requireInRange(bedFromDeg, -90.0, bedToDeg, "bed span start (root angle, deg)");
    const int nf = flight_.geometry().nFlights;
    const double pockets = (bedToDeg - bedFromDeg)*deg*maxHoldup();
    // flights per radian N_F/(2 pi) times the pockets' and the carried holdup
    return nf/(2.0*pi)*(pockets + integrate([&](double p) { return holdup(p); }, bedToDeg, psi5))
         *settings_.flightLength;
}


double UnloadingModel::loadingFactor(double dLoad) const
{
    requireInRange(dLoad, 0.0, 1e6, "d_load");
    if (dLoad >= 1.0) return 1.0;
    // Lee 2008 Eq 4.22: d_load M_p,des = f H_0 + 2 sum H_i, where a flight
    // loaded to f H_0 holds min(f H_0, H(psi_i)) (it starts unloading later)
    const int nf = flight_.geometry().nFlights;
    const double psi0 = flight_.curtainStartDeg();
    const double h0 = designFlightHoldup();
    const double target = dLoad*designLoad()/settings_.flightLength;
    const auto load = [&](double f)
    {
        double m = f*h0;
        for (int i = 1; i <= nf/2 - 1; ++i)
        {
            m += 2.0*std::min(f*h0, holdup(psi0 + i*flight_.flightSpacingDeg()));
        }
        return m;
    };
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200 && hi - lo > 1e-14; ++it)
    {
        const double mid = 0.5*(lo + hi);
        (load(mid) < target ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}

} // namespace drum
