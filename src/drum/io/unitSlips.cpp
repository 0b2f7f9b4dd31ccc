#include "drum/io/unitSlips.hpp"

#include "particleDrag/gasProperties.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

const std::vector<UnitSlipRule>& drumDictUnitSlipRules()
{
    // each range lies below (or above) every value of its kind in the seeds'
    // dryers and materials, and maps to a usual value in the other unit
    static const std::vector<UnitSlipRule> rules{
        {"drum.speed_rpm", "rpm", 0, 0.5, "rev/s", 60, 0,
         "below 0.5 rpm, slower than rotary dryers turn (about 1-10 rpm)"},
        {"material.bulkDensity", "kg/m3", 0, 20, "g/cm3 (t/m3)", 1000, 0,
         "below 20 kg/m3, lighter than any bulk solid"},
        {"material.particleDensity", "kg/m3", 0, 30, "g/cm3", 1000, 0,
         "below 30 kg/m3, lighter than any particle that falls in a curtain"},
        {"material.sizes_um", "um", 0, 0.1, "m", 1e6, 0,
         "below 0.1 um, finer than any dryer's solids"},
        {"material.sizes_um", "um", 0.1, 10, "mm", 1e3, 0,
         "below 10 um, a dust rather than a dryer's feed"},
        {"gas.temperature_C", "degC", 273.0, particleDrag::maxTemperatureC, "K", 1, -273.15,
         "a whole number of degrees plus 273.15, the mark of a temperature in kelvin", true},
    };
    return rules;
}


std::optional<std::string> unitSlipWarning(const std::string& entry, const double value, const std::string& label)
{
    for (const auto& r : drumDictUnitSlipRules())
    {
        if (r.entry != entry || !(value > r.lo && value < r.hi)) continue;
        if (r.kelvinSignature && std::abs((value - 273.15) - std::round(value - 273.15)) > 1e-9) continue;
        std::ostringstream os;
        os.precision(6);
        os << "entry '" << (label.empty() ? entry : label) << "' = " << value << " " << r.unit << " is " << r.why << ": given in "
           << r.other << "? (" << value << " " << r.other << " = " << r.factor*value + r.offset << " " << r.unit
           << "); the value is used as given";
        return os.str();
    }
    return std::nullopt;
}

} // namespace drum
