#include "scoring/windTunnelPrediction.hpp"

namespace drum
{

DriftQuery windTunnelQuery(const WindTunnelTest& t, const WindTunnelMaterial& m, const SieveClass& c)
{
    DriftQuery q;
    q.particleDiameter = c.diameter;
    q.particleDensity = m.particleDensity;
    q.gasVelocity = t.airVelocity;
    q.fallHeight = t.fallHeight;
    q.spillRate = t.spillRate;
    q.flightLength = t.flightLength;
    q.incline = 0;
    return q;
}


double predictMeanAdvance(const DriftModel& model, const WindTunnelTest& t, const WindTunnelMaterial& m)
{
    double sum = 0;
    for (const auto& c : m.classes)
    {
        sum += c.massFraction*model.displacement(windTunnelQuery(t, m, c));
    }
    return sum;
}

} // namespace drum
