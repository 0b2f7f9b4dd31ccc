// The classical fourth-order Runge-Kutta step, the ODE stepper of the drum
// models (the two-phase model's axial DRUM3 solve, Sherritt 1991 §5.2).
#ifndef DRUM_NUMERICS_RUNGEKUTTA4_HPP
#define DRUM_NUMERICS_RUNGEKUTTA4_HPP

#include <cstddef>
#include <vector>

namespace drum
{

//- Advance y from s to s + h for dy/ds = rhs(s, y), given k1 = rhs(s, y)
//  (the caller often needs what the first evaluation saw)
template<class Rhs>
void rungeKutta4Step(const Rhs& rhs, double s, double h, const std::vector<double>& k1, std::vector<double>& y)
{
    const std::size_t n = y.size();
    auto add = [&](const std::vector<double>& k, double f)
    {
        std::vector<double> out(y);
        for (std::size_t j = 0; j < n; ++j)
        {
            out[j] += f*k[j];
        }
        return out;
    };
    const std::vector<double> k2 = rhs(s + 0.5*h, add(k1, 0.5*h));
    const std::vector<double> k3 = rhs(s + 0.5*h, add(k2, 0.5*h));
    const std::vector<double> k4 = rhs(s + h, add(k3, h));
    for (std::size_t j = 0; j < n; ++j)
    {
        y[j] += h/6*(k1[j] + 2*k2[j] + 2*k3[j] + k4[j]);
    }
}

} // namespace drum

#endif
