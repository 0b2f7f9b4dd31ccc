// Template part of unloadingModel.hpp
#ifndef DRUM_FLIGHTS_UNLOADINGMODELI_HPP
#define DRUM_FLIGHTS_UNLOADINGMODELI_HPP

#include "drum/numerics/constants.hpp"
#include "drum/numerics/gaussLegendre.hpp"

#include <vector>

namespace drum
{

template<class F>
double UnloadingModel::integrate(F&& f, double aDeg, double bDeg) const
{
    // 10 points on 64 panels between transition points; f in degrees
    const auto& tp = flight_.transitionPoints();
    return compositeGaussLegendre<10>(f, aDeg, bDeg, std::vector<double>(tp.begin(), tp.end()), PanelSplit{64, 0.0}, deg);
}

} // namespace drum

#endif
