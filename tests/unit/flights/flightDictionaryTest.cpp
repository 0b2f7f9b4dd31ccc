// The flightUnloading dictionary: a good one parses, bad ones are refused
// naming the entry
#include "drum/flights/flightDictionary.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>

namespace
{
const char* good = R"(
drum: {radius: 2.5, nFlights: 28, speed: 3}
flight: {baseLength: 0.195, tipLength: 0.183, tipAngle: 117,
         serration: {width: 0.03, depth: 0.02, perMetre: 20}}
material: {bulkDensity: 936.06, moisture: 0.002}
)";

std::string refused(const std::string& text)
{
    try
    {
        const auto c = drum::parseFlightDictionary(text, "case.yaml");
        drum::LeeFlight f(c.geometry, c.phiDeg, "case.yaml");
    }
    catch (const drum::InputError& e)
    {
        return e.entry();
    }
    return "<accepted>";
}

std::string replaced(std::string s, const std::string& from, const std::string& to)
{
    s.replace(s.find(from), from.size(), to);
    return s;
}
} // namespace


TEST(FlightDictionary, ParsesGoodDictionary)
{
    const auto c = drum::parseFlightDictionary(good, "case.yaml");
    EXPECT_NEAR(c.geometry.tipLength, 0.177, 1e-12);        // Eq 4.18
    EXPECT_NEAR(c.phiDeg, 1222.2*0.002 + 34.5, 1e-12);      // Eq 7.2
    EXPECT_DOUBLE_EQ(c.geometry.baseAngleDeg, 90.0);
    EXPECT_EQ(c.geometry.nFlights, 28);
}


TEST(FlightDictionary, RefusesBadEntries)
{
    EXPECT_EQ(refused(replaced(good, "radius: 2.5", "radius: -2.5")), "drum.radius");
    EXPECT_EQ(refused(replaced(good, "nFlights: 28", "nFlights: 2.5")), "drum.nFlights");
    EXPECT_EQ(refused(replaced(good, "tipLength: 0.183", "tipLength: 3.0")), "flight.tipLength");
    EXPECT_EQ(refused(replaced(good, "baseLength: 0.195", "baseLength: -0.1")), "flight.baseLength");
    EXPECT_EQ(refused(replaced(good, "moisture: 0.002", "dynamicAngleOfRepose: 95")),
              "material.dynamicAngleOfRepose");
    EXPECT_EQ(refused(replaced(good, "moisture: 0.002", "moisture: 0.1")), "material.moisture");
    EXPECT_EQ(refused(replaced(good, "moisture: 0.002", "moisture: 0.002, dynamicAngleOfRepose: 40")),
              "material.dynamicAngleOfRepose");
    EXPECT_EQ(refused(replaced(good, "speed: 3", "speed: 3, sped: 4")), "drum.sped");
    EXPECT_EQ(refused(replaced(good, "radius: 2.5, ", "")), "drum.radius");
    EXPECT_EQ(refused(replaced(good, "tipAngle: 117", "tipAngle: abc")), "flight.tipAngle");
    EXPECT_EQ(refused(replaced(good, "depth: 0.02", "depth: 0.5")), "flight.serration.depth");
    // a key given twice is refused (yaml-cpp alone would keep the first)
    EXPECT_EQ(refused(replaced(good, "speed: 3", "speed: 3, speed: 4")), "drum.speed");
}


TEST(FlightDictionary, ErrorsNameTheLineAndTheNearestKey)
{
    try
    {
        drum::parseFlightDictionary(replaced(good, "speed: 3", "sped: 3"), "case.yaml");
        FAIL() << "accepted a misspelt key";
    }
    catch (const drum::InputError& e)
    {
        EXPECT_EQ(e.file(), "case.yaml:2");
        EXPECT_EQ(e.entry(), "drum.sped");
        EXPECT_NE(std::string(e.what()).find("did you mean 'drum.speed'?"), std::string::npos) << e.what();
    }
}
