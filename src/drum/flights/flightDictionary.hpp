// The flightUnloading dictionary (YAML via yaml-cpp): drum, flight, material
// and output entries; see applications/utilities/flightUnloading/README.md
#ifndef DRUM_FLIGHTS_FLIGHTDICTIONARY_HPP
#define DRUM_FLIGHTS_FLIGHTDICTIONARY_HPP

#include "drum/flights/unloadingModel.hpp"

#include <filesystem>
#include <string>

namespace drum
{

struct FlightCase
{
    FlightGeometry geometry;        //!< tipLength already reduced by serrations (Eq 4.18)
    double phiDeg = 0.0;            //!< given, or from moisture by Eq 7.2
    std::string phiSource;          //!< "dynamicAngleOfRepose" or "moisture (Lee 2008 Eq 7.2)"
    UnloadingSettings settings;
    double angleStartDeg = 0.0;
    double angleEndDeg = -1.0;      //!< < 0: psi5 + 5 deg
    double angleStepDeg = 0.5;
    double snapshotAngleDeg = 120.0;
    bool plots = true;
};

//- Parse a YAML text (file names the source in errors); InputError on any
//  missing, unknown or out-of-range entry
FlightCase parseFlightDictionary(const std::string& yamlText, const std::string& file);

//- Read and parse a dictionary file
FlightCase readFlightDictionary(const std::filesystem::path& path);

} // namespace drum

#endif
