// Template part of unloadingModel.hpp
#ifndef DRUM_FLIGHTS_UNLOADINGMODELI_HPP
#define DRUM_FLIGHTS_UNLOADINGMODELI_HPP

#include <algorithm>
#include <array>
#include "drum/numerics/constants.hpp"

namespace drum
{

template<class F>
double UnloadingModel::integrate(F&& f, double aDeg, double bDeg) const
{
    // 10-point Gauss-Legendre nodes and weights on [-1, 1]
    static constexpr std::array<double, 5> x{0.1488743389816312, 0.4333953941292472,
        0.6794095682990244, 0.8650633666889845, 0.9739065285171717};
    static constexpr std::array<double, 5> w{0.2955242247147529, 0.2692667193099963,
        0.2190863625159820, 0.1494513491505806, 0.0666713443086881};
    if (!(bDeg > aDeg))
    {
        return 0.0;
    }
    std::vector<double> cuts{aDeg};
    for (double p : flight_.transitionPoints())
    {
        if (p > aDeg && p < bDeg) cuts.push_back(p);
    }
    cuts.push_back(bDeg);
    double sum = 0.0;
    constexpr int pieces = 64;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    {
        const double h = (cuts[k + 1] - cuts[k])/pieces;
        for (int i = 0; i < pieces; ++i)
        {
            const double mid = cuts[k] + (i + 0.5)*h;
            for (std::size_t j = 0; j < x.size(); ++j)
            {
                sum += w[j]*(f(mid - 0.5*h*x[j]) + f(mid + 0.5*h*x[j]))*0.5*h*deg;
            }
        }
    }
    return sum;
}

} // namespace drum

#endif
