// airProperties -temperature T: density, dynamic and kinematic viscosity of
// dry air at 1 atm and T degC, from the project's one gas model
// (particleDrag/gasProperties.hpp), one "name value" line each at 6
// significant digits. curtainCase -gasTemperature writes these into a
// curtain case's constant/transportProperties, so the curtain tables and the
// drum model use the same air. Exit 2 on bad input, with the allowed range.
#include "particleDrag/gasProperties.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char* argv[])
{
    const char* usage = "Usage: airProperties -temperature T   (degC, in [-50, 1500])\n";
    if (argc == 2 && (!std::strcmp(argv[1], "-help") || !std::strcmp(argv[1], "-h")))
    {
        std::fputs(usage, stdout);
        return 0;
    }
    if (argc != 3 || std::strcmp(argv[1], "-temperature") != 0)
    {
        std::fputs(usage, stderr);
        return 2;
    }
    char* end = nullptr;
    const double t = std::strtod(argv[2], &end);
    if (end == argv[2] || *end != '\0' || !(t >= -50.0 && t <= 1500.0))
    {
        std::fprintf(stderr, "airProperties: -temperature '%s': not a temperature in [-50, 1500] degC\n", argv[2]);
        return 2;
    }
    const particleDrag::Gas air = particleDrag::Gas::air(t);
    std::printf("rho %.6g\nmu %.6g\nnu %.6g\n", air.density, air.viscosity, air.viscosity/air.density);
    return 0;
}
