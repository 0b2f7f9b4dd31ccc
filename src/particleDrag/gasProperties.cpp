#include "particleDrag/gasProperties.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace particleDrag
{

namespace
{
double kelvin(double temperatureC)
{
    const double T = temperatureC + 273.15;
    if (!(T > 0.0))
    {
        std::ostringstream os;
        os << "gas temperature " << temperatureC << " degC is below absolute zero";
        throw std::invalid_argument(os.str());
    }
    return T;
}
} // namespace

double airDensity(double temperatureC, double pressureKPa)
{
    if (!(pressureKPa > 0.0))
    {
        std::ostringstream os;
        os << "gas pressure " << pressureKPa << " kPa is not positive";
        throw std::invalid_argument(os.str());
    }
    return 354.3/kelvin(temperatureC)*pressureKPa/standardPressureKPa;
}

double airViscosity(double temperatureC)
{
    const double T = kelvin(temperatureC);
    return 2.4e-5*((423.15 + 120.0)/(T + 120.0))*std::pow(T/423.15, 1.5);
}

Gas Gas::air(double temperatureC, double pressureKPa)
{
    return Gas{airDensity(temperatureC, pressureKPa), airViscosity(temperatureC)};
}

} // namespace particleDrag
