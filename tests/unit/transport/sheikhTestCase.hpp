// Sheikh's (1987) drum as Sherritt (1991) Table 5.1 gives it, with the
// flights assumed in cases/sherrittDrums (12 two-sided 90 deg flights,
// s1 = s2 = 0.04 m): the shared fixture of the two-phase unit tests
#ifndef TESTS_UNIT_TRANSPORT_SHEIKHTESTCASE_HPP
#define TESTS_UNIT_TRANSPORT_SHEIKHTESTCASE_HPP

#include "drum/flights/sherritt/sherrittFlightShapes.hpp"
#include "drum/transport/twoPhase/twoPhaseModel.hpp"

#include <string>

namespace drumTest
{

inline drum::TwoPhaseCase sheikhCase(double slope, const std::string& name)
{
    constexpr double deg = 3.14159265358979323846/180;
    drum::TwoPhaseCase c;
    c.name = name;
    c.drum = {0.385, 2.10, slope, 5.7/60, 0.0};
    c.exterior = drum::tabulateSherrittFlight(drum::twoSidedFlightShape(0.385, 0.04, 0.04, 90*deg), 12, 2.10, 1*deg);
    c.material.particleDensity = 2650;
    c.material.bulkDensity = 1517;
    c.material.repose = 35.69*deg;
    c.material.sieveSizes = {600e-6, 427e-6, 327e-6, 256e-6, 168e-6, 88e-6};
    c.material.massFractions = {11.6, 21.6, 12.0, 29.6, 22.1, 3.2};
    return c;
}

} // namespace drumTest

#endif
