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


std::vector<double> classAdvances(const DriftModel& model, const WindTunnelTest& t, const WindTunnelMaterial& m)
{
    std::vector<double> advance;
    for (const auto& c : m.classes) advance.push_back(model.displacement(windTunnelQuery(t, m, c)));
    return advance;
}


double meanAdvance(const WindTunnelMaterial& m, const std::vector<double>& classAdvance)
{
    double sum = 0;
    for (std::size_t i = 0; i < m.classes.size(); ++i) sum += m.classes[i].massFraction*classAdvance.at(i);
    return sum;
}

} // namespace drum
