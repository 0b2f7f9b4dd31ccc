// drumSolver's case dictionary DIR/drumDict (YAML), read and checked in full
// before anything runs. Every entry and its unit is documented in README.md.
#ifndef DRUMSOLVER_DRUMDICT_HPP
#define DRUMSOLVER_DRUMDICT_HPP

#include "drum/drift/driftDictionary.hpp"
#include "drum/flights/sherrittFlightSpec.hpp"
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
    double centrefillDiameter;      //!< D_i, m (0: open drum; twoPhase)
    // flights (two-section flight, Lee Table 4.1 parameters)
    int flightCount;
    double baseLength, tipLength, baseAngleDeg, tipAngleDeg, flightAxialLength;
    //- Sherritt flight description (flights.exterior / flights.interior,
    //  twoPhase); unset exterior: the two-section flight above
    std::optional<drum::SherrittFlightSpec> exteriorFlight, interiorFlight;
    double flightTableStepDeg;      //!< tabulation step of flight shapes
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
    bool slicesGiven;           //!< model.slices in the dictionary (twoPhase: else automatic)
    // twoPhase
    std::optional<double> imposedDenseFlow;      //!< F_2, kg/s (Kamke, Fig 5.30)
    std::optional<double> dischargeEndAngleDeg;  //!< theta_i at the solids discharge
    int axialSteps;                              //!< RK4 steps of the axial solve
    std::string denseDispersion;                 //!< none | sherritt2001 | value (twoPhase and compartment)
    double denseDispersionValue;                 //!< m2/s when a value is given
    std::string dispersionBed;                   //!< compartment: kiln | passive
    bool subtractNumericalDispersion;            //!< compartment: take u_b dz/2 off D_z
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
