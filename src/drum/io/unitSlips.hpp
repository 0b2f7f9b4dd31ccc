// Plausibility warnings for values that are legal but most likely given in
// another unit than the entry's (g/cm3 for kg/m3, m for um, K for degC, rev/s
// for rpm). A warning never refuses a value: it names the entry, the value,
// the likely mix-up and what the value would be in the entry's unit.
#ifndef DRUM_IO_UNITSLIPS_HPP
#define DRUM_IO_UNITSLIPS_HPP

#include <optional>
#include <string>
#include <vector>

namespace drum
{

//- One rule: a value of `entry` in [lo, hi] suggests the unit `other`
//  (factor: the entry's unit per `other`)
struct UnitSlipRule
{
    std::string entry;     //!< dictionary entry, e.g. material.bulkDensity
    std::string unit;      //!< the entry's unit, e.g. kg/m3
    double lo, hi;         //!< the suspect range
    std::string other;     //!< the unit the value was probably given in
    double factor;         //!< value in `unit` = factor*value + offset
    double offset;
    std::string why;       //!< what makes the range suspect
    bool kelvinSignature = false;   //!< suspect only if value - 273.15 is whole (353.15)
};

//- The rules of drumDict's entries (the one list: tests/badInput counts them)
const std::vector<UnitSlipRule>& drumDictUnitSlipRules();

//- The warning for `value` of `entry` (without the file), if a rule of that
//  entry finds it suspect; `label` names the entry in the message (default:
//  `entry`; another dictionary's name for the same quantity)
std::optional<std::string> unitSlipWarning(const std::string& entry, double value, const std::string& label = "");

} // namespace drum

#endif
