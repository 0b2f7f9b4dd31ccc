// A drift model's prediction of a wind-tunnel test's bulk mean advance: the
// mass-weighted mean over the material's size classes (geometric-mean
// diameters, open bins closed as in data/README.md), the
// way the reference predictions and tests/unit/windTunnel score them.
#ifndef DRUM_WINDTUNNEL_WINDTUNNELPREDICTION_HPP
#define DRUM_WINDTUNNEL_WINDTUNNELPREDICTION_HPP

#include "drum/drift/driftModel.hpp"
#include "scoring/windTunnelData.hpp"

#include <vector>

namespace drum
{

//- The drift query of one size class of a test (level duct, incline 0)
DriftQuery windTunnelQuery(const WindTunnelTest& t, const WindTunnelMaterial& m, const SieveClass& c);

//- The model's advance delta_i of each class of m in test t, in the order of m.classes
std::vector<double> classAdvances(const DriftModel& model, const WindTunnelTest& t, const WindTunnelMaterial& m);

//- The bulk mean advance sum_i x_i delta_i (x_i renormalised mass fractions) of
//  classAdvance, in the order of m.classes
double meanAdvance(const WindTunnelMaterial& m, const std::vector<double>& classAdvance);

} // namespace drum

#endif
