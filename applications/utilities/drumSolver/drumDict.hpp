// drumSolver's case dictionary DIR/drumDict (YAML), read and checked in full
// before anything runs. Every entry and its unit is documented in README.md.
#ifndef DRUMSOLVER_DRUMDICT_HPP
#define DRUMSOLVER_DRUMDICT_HPP

#include "drum/drift/driftDictionary.hpp"
#include "drum/rtd/rtdSimulation.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drumSolver
{

struct TracerFile
{
    std::filesystem::path file;
    std::string timeColumn;
    double timeScale;       //!< to seconds
    std::string eColumn;
    double eScale;          //!< to 1/s
};

struct DrumDict
{
    std::filesystem::path path;     //!< the dictionary read

    // drum
    double length, diameter, slopeDeg, speedRpm;
    // flights (two-section flight, Lee Table 4.1 parameters)
    int flightCount;
    double baseLength, tipLength, baseAngleDeg, tipAngleDeg, flightAxialLength;
    // material
    double feedRate, bulkDensity, particleDensity, sphericity;
    std::optional<double> reposeDeg;                 //!< constant phi
    std::optional<std::pair<double, double>> moisture;  //!< inlet, outlet kg/kg (Lee Eq 7.2-7.3)
    std::vector<double> sizes;                       //!< m
    std::vector<double> fractions;                   //!< normalised
    // gas
    bool counterCurrent;
    double gasMassRate, gasTemperatureC;
    // model
    std::string model;          //!< compartment | twoPhase
    int slices;
    std::string partition;      //!< leeCorrelations | flightModel
    double kilnTime, backFraction, dragFactor, designLoadMultiplier;
    double stagnantRatio, exchangeTime;   //!< stagnant-zone extension
    std::string drift;          //!< isolated | sherritt | table | tableVc | porousSheet
    drum::DriftSettings driftSettings;   //!< model.drift + drift section (table, outside, constants)
    // rtd
    drum::RtdOptions rtd;
    std::optional<TracerFile> tracer;
    // estimation
    std::vector<std::string> estimate;
    int starts;
    bool logObjective;
    double logOffset;           //!< 1/h
};

//- Reads DIR/drumDict; throws drum::InputError naming the file, entry and range
DrumDict readDrumDict(const std::filesystem::path& caseDir);

} // namespace drumSolver

#endif
