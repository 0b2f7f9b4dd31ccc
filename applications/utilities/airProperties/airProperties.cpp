// airProperties -temperature T [-pressure P]: density, dynamic and kinematic
// viscosity of dry air at T degC and P kPa (default 1 atm), from the project's
// one gas model (particleDrag/gasProperties.hpp), one "name value" line each
// at 6 significant digits. curtainCase -gasTemperature/-gasPressure writes
// these into a curtain case's constant/transportProperties, so the curtain
// tables and the drum model use the same air. Exit 2 on bad input, with the
// allowed range. A temperature that looks like one in kelvin (353.15) is
// warned on stderr (drum/io/unitSlips.hpp), and used as given.
#include "drum/io/unitSlips.hpp"
#include "particleDrag/gasProperties.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace
{

//- The number of option `name` = text in [lo, hi]; false (message printed) otherwise
bool readNumber(const char* name, const char* text, double lo, double hi, const char* units, double& v)
{
    char* end = nullptr;
    v = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(v >= lo && v <= hi))
    {
        std::fprintf(stderr, "airProperties: %s '%s': not a %s in [%g, %g] %s\n", name, text,
                     name + 1, lo, hi, units);
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char* argv[])
{
    const char* usage = "Usage: airProperties -temperature T [-pressure P] [-entry NAME]   "
                        "(T degC in [-50, 1500]; P kPa in [10, 1000], default 101.325;\n"
                        "  NAME: the caller's entry, named in a warning)\n";
    if (argc == 2 && (!std::strcmp(argv[1], "-help") || !std::strcmp(argv[1], "-h")))
    {
        std::fputs(usage, stdout);
        return 0;
    }
    double t = 0, p = particleDrag::standardPressureKPa;
    bool haveT = false;
    std::string entry = "-temperature";
    for (int i = 1; i < argc; i += 2)
    {
        const bool isT = !std::strcmp(argv[i], "-temperature"), isP = !std::strcmp(argv[i], "-pressure");
        if (!std::strcmp(argv[i], "-entry") && i + 1 < argc)
        {
            entry = argv[i + 1];
            continue;
        }
        if ((!isT && !isP) || i + 1 >= argc)
        {
            std::fputs(usage, stderr);
            return 2;
        }
        if (isT ? !readNumber("-temperature", argv[i + 1], particleDrag::minTemperatureC,
                              particleDrag::maxTemperatureC, "degC", t)
                : !readNumber("-pressure", argv[i + 1], particleDrag::minPressureKPa,
                              particleDrag::maxPressureKPa, "kPa", p))
        {
            return 2;
        }
        haveT = haveT || isT;
    }
    if (!haveT)
    {
        std::fputs(usage, stderr);
        return 2;
    }
    // a temperature that looks like kelvin: warned on stderr, used as given
    if (const auto w = drum::unitSlipWarning("gas.temperature_C", t, entry))
    {
        std::fprintf(stderr, "airProperties: warning: %s\n", w->c_str());
    }
    const particleDrag::Gas air = particleDrag::Gas::air(t, p);
    std::printf("rho %.6g\nmu %.6g\nnu %.6g\n", air.density, air.viscosity, air.viscosity/air.density);
    return 0;
}
