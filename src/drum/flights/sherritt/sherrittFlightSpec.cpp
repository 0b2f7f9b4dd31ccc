#include "drum/flights/sherritt/sherrittFlightSpec.hpp"

#include "drum/flights/sherritt/sherrittFlightShapes.hpp"
#include "drum/io/inputError.hpp"

namespace drum
{

SherrittFlightType parseSherrittFlightType(const std::string& name, const std::string& entry, const std::string& file)
{
    if (name == "twoSided") return SherrittFlightType::twoSided;
    if (name == "EAD") return SherrittFlightType::ead;
    if (name == "CBD") return SherrittFlightType::cbd;
    if (name == "table") return SherrittFlightType::table;
    throw InputError(file, entry, "unknown flight type '" + name + "'; allowed: twoSided, EAD, CBD, table");
}

std::string toString(SherrittFlightType type)
{
    switch (type)
    {
        case SherrittFlightType::twoSided: return "twoSided";
        case SherrittFlightType::ead: return "EAD";
        case SherrittFlightType::cbd: return "CBD";
        case SherrittFlightType::table: return "table";
    }
    return "?";
}

SherrittFlightProfile buildSherrittFlight
(
    const SherrittFlightSpec& s,
    FlightSide side,
    double shellDiameter,
    double axialLength,
    double step,
    const std::string& source
)
{
    if (s.type == SherrittFlightType::table)
    {
        return SherrittFlightProfile(s.angles, s.lengths, side, s.tipDiameter, s.count, axialLength, source);
    }
    if (side == FlightSide::interior)
    {
        throw InputError(source, "flights.interior.type",
            "interior (centrefill) flights are given as type table (angles_deg, lengths)");
    }
    try
    {
        SherrittFlightShape shape;
        switch (s.type)
        {
            case SherrittFlightType::twoSided:
                shape = twoSidedFlightShape(shellDiameter, s.baseLength, s.tipLength, s.tipAngle, s.baseAngle);
                break;
            case SherrittFlightType::ead:
                shape = eadFlightShape(shellDiameter, s.radius, s.designRepose, s.tipDiameter);
                break;
            default:
                shape = cbdFlightShape(shellDiameter, s.radius, s.bias, s.designRepose, s.tipDiameter);
                break;
        }
        return tabulateSherrittFlight(shape, s.count, axialLength, step);
    }
    catch (const InputError& e)
    {
        // the shape generators know the entry, not the dictionary
        if (!e.file().empty()) throw;
        throw InputError(source, "flights.exterior (" + toString(s.type) + ")", e.what());
    }
}

} // namespace drum
