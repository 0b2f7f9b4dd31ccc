// The sections of a drumSolver case dictionary (DIR/drumDict, YAML) that
// every drum model reads: drum, flights, material, gas, rtd. Each is read
// and checked here once; the `model` section (and any section only one
// model uses) is read by the chosen model itself (drumModel.hpp).
// applications/utilities/drumSolver/README.md documents every entry.
#ifndef DRUM_MODELS_DRUMCASE_HPP
#define DRUM_MODELS_DRUMCASE_HPP

#include "drum/drift/driftDictionary.hpp"
#include "drum/flights/sherritt/sherrittFlightSpec.hpp"
#include "drum/io/dictReader.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "particleDrag/gasProperties.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace drum
{

struct CaseDrum
{
    double length = 0, diameter = 0, slopeDeg = 0, speedRpm = 0;
    double centrefillDiameter = 0;      //!< D_i, m (0: open drum)
};

//- Lee's two-section flight (Lee 2008 Table 4.1 parameters)
struct TwoSectionFlight
{
    int count = 0;
    double baseLength = 0, tipLength = 0, baseAngleDeg = 90, tipAngleDeg = 90;
};

struct CaseFlights
{
    double axialLength = 0;             //!< m (default: the drum length)
    double tableStepDeg = 1;            //!< tabulation step of flight shapes
    //- flat entries; unset when Sherritt's description (exterior) is given
    std::optional<TwoSectionFlight> twoSection;
    std::optional<SherrittFlightSpec> exterior, interior;
};

struct CaseMaterial
{
    double feedRate = 0, bulkDensity = 0, particleDensity = 0, sphericity = 1;
    std::optional<double> reposeDeg;                    //!< constant phi
    std::optional<std::pair<double, double>> moisture;  //!< inlet, outlet kg/kg (Lee Eq 7.2-7.3)
    std::vector<double> sizes;          //!< m
    std::vector<double> fractions;      //!< normalised to 1
};

struct CaseGas
{
    bool counterCurrent = true;
    double massRate = 0, temperatureC = 20;
    double pressureKPa = particleDrag::standardPressureKPa;   //!< a dryer above sea level: lower

    //- Dry air at the case's temperature and pressure (particleDrag::Gas::air)
    particleDrag::Gas air() const { return particleDrag::Gas::air(temperatureC, pressureKPa); }
};

struct TracerFile
{
    std::filesystem::path dict;     //!< the drumDict whose rtd.tracer names it
    std::filesystem::path file;
    std::string timeColumn;
    double timeScale = 1;       //!< to seconds
    std::string eColumn;
    double eScale = 1;          //!< to 1/s
    //- s: the end of the curve's body in the comparison with the model (0: the
    //  measured curve's t95, the time by which 95 % of it came out)
    double bodyEnd = 0;
};

struct DrumCase
{
    std::filesystem::path caseDir;
    std::filesystem::path path;         //!< caseDir/drumDict
    YAML::Node root;                    //!< the whole dictionary (the model reads its sections)
    CaseDrum drum;
    CaseFlights flights;
    CaseMaterial material;
    CaseGas gas;
    RtdOptions rtd;
    std::optional<TracerFile> tracer;
    //- Legal values that look like a unit mix-up (unitSlips.hpp), with the file
    std::vector<std::string> warnings;

    DictReader reader() const { return DictReader(path.string()); }
};

//- Reads DIR/drumDict's shared sections. `sections` are all the top-level
//  sections any model may read (a key outside them and the shared ones is a
//  typo). Throws InputError naming the file, the entry and the range.
DrumCase readDrumCase(const std::filesystem::path& caseDir, const std::vector<std::string>& sections);

//- model.denseDispersion, read the same way by every model: none,
//  sherritt2001 (Sherritt 2001 Eq 51) or a value in m2/s
struct DenseDispersionEntry
{
    std::string kind = "none";      //!< none | sherritt2001 | value
    double value = 0;               //!< m2/s when a value is given
};
DenseDispersionEntry readDenseDispersion(const DictReader& r, const YAML::Node& model);

//- model.drift and the drift section, with the curtain's surface-mean
//  diameter from the material (sieve sizes x sphericity)
DriftSettings readCaseDriftSettings(const DrumCase& c);

} // namespace drum

#endif
