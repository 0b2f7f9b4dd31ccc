// A Sherritt (1991) flight described by its type and dimensions, turned
// into the (angle, horizontal length) table of sherrittFlightProfile.hpp.
// One builder for every user (drumSolver's drumDict, the validation
// tests), so a case written down once gives the same table everywhere.
//
// Types (Sherritt 1991 §2.3; shapes in sherrittFlightShapes.hpp):
//   twoSided  base plate s1 at baseAngle to the shell, tip plate s2 at
//             tipAngle to the base (Fig 2.2a; Sheikh, Saeman, Kamke)
//   EAD       equal angular distribution arc of `radius` about the tip at
//             the design repose (Kelly, Fig 2.2b)
//   CBD       centrally biased arc (Kelly, Fig 2.2c; a stand-in shape)
//   table     the thesis' own description: angles and horizontal lengths
//             (the only type for interior/centrefill flights)
#ifndef DRUM_FLIGHTS_SHERRITTFLIGHTSPEC_HPP
#define DRUM_FLIGHTS_SHERRITTFLIGHTSPEC_HPP

#include "drum/flights/sherritt/sherrittFlightProfile.hpp"

#include <string>
#include <vector>

namespace drum
{

enum class SherrittFlightType { twoSided, ead, cbd, table };

//- "twoSided" | "EAD" | "CBD" | "table"; InputError naming entry/file otherwise
SherrittFlightType parseSherrittFlightType(const std::string& name, const std::string& entry, const std::string& file);

std::string toString(SherrittFlightType type);

struct SherrittFlightSpec
{
    SherrittFlightType type = SherrittFlightType::twoSided;
    int count = 0;                 //!< N_ex or N_in
    // twoSided
    double baseLength = 0;         //!< s1, m
    double tipLength = 0;          //!< s2, m
    double tipAngle = 1.5707963267948966;   //!< rad, tip plate to base
    double baseAngle = 1.5707963267948966;  //!< rad, base plate to the shell tangent
    // EAD / CBD
    double radius = 0;             //!< arc radius, m
    double bias = 0;               //!< CBD centre shift / radius, [0, 1)
    double designRepose = 0;       //!< rad, phi_d of the arc
    // EAD (0: D_o - 2 r), CBD, table: tip locus diameter, m
    double tipDiameter = 0;
    // table
    std::vector<double> angles;    //!< rad, ascending
    std::vector<double> lengths;   //!< m, >= 0
};

//- The flight table of a spec. Shapes are tabulated every `step` rad with
//  interference from the other flights (tabulateSherrittFlight); a table
//  is used as given. Interior flights must be tables. source names the
//  dictionary in errors.
SherrittFlightProfile buildSherrittFlight
(
    const SherrittFlightSpec& spec,
    FlightSide side,
    double shellDiameter,
    double axialLength,
    double step = 0.017453292519943295,
    const std::string& source = ""
);

} // namespace drum

#endif
