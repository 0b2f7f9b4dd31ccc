// Sherritt 1991 wind-tunnel curtain tests (Appendix A): the test conditions
// (Table A.2) and the materials with their size distributions (Table A.1),
// read from CSV files with the columns of data/ (data/README.md). The reader of test
// conditions never reads the measured advance: predictions cannot see it.
#ifndef DRUM_WINDTUNNEL_WINDTUNNELDATA_HPP
#define DRUM_WINDTUNNEL_WINDTUNNELDATA_HPP

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace drum
{

//- One sieve class of a material
struct SieveClass
{
    double lowerUm = 0;      //!< lower sieve size, um (0: open bin)
    double upperUm = 0;      //!< upper sieve size, um (0: open bin)
    double diameter = 0;     //!< representative diameter for drag, m
    double massFraction = 0; //!< renormalised, sums to 1 over the classes
};

struct WindTunnelMaterial
{
    std::string name;
    double particleDensity = 0; //!< kg/m3
    double bulkDensity = 0;     //!< kg/m3
    double sphericity = 1;
    std::vector<SieveClass> classes;
};

//- The conditions of one test: what a model may use
struct WindTunnelTest
{
    int test = 0;
    std::string material;
    double airVelocity = 0;   //!< V_g, m/s
    double spillRate = 0;     //!< kg/(s m of flight)
    double flightLength = 0;  //!< m (as printed: 2.0 / 1.0)
    double fallHeight = 0;    //!< true fall height, m (10.3 / 6.6 / 3.5)
};

//- How the open sieve bins are closed and classes represented (the
//  reference predictions' choice, data/README.md)
struct SieveClosure
{
    double topUm = 4760;     //!< upper bound given to the open top bin
    double bottomUm = 37;    //!< lower bound given to the open bottom bin
};

//- Read Table A.1 (long format: one row per material and bin). Throws
//  InputError naming the file, row and column for a malformed file.
std::map<std::string, WindTunnelMaterial> readWindTunnelMaterials
(
    const std::filesystem::path& file,
    const SieveClosure& closure = SieveClosure()
);

//- Read test conditions (Table A.2 columns). Checks every material is in
//  `materials`, every value is in range and every test id is a whole number
//  given once; never reads mean_advance_m.
std::vector<WindTunnelTest> readWindTunnelTests
(
    const std::filesystem::path& file,
    const std::map<std::string, WindTunnelMaterial>& materials
);

//- One measured quantity per test, for scoring only: the column `column`
//  (mean_advance_m, or vc_m_s: Sherritt's apparent in-sheet gas velocity,
//  Eq 141) keyed by test. An empty cell is an error, or, with
//  emptyIsUnmeasured, a test that did not measure it, left out. A test id
//  that is not a whole number or appears twice is an error naming both lines;
//  `lines`, if given, receives each test's line in the file
std::map<int, double> readMeasured
(
    const std::filesystem::path& file,
    const std::string& column,
    bool emptyIsUnmeasured = false,
    std::map<int, int>* lines = nullptr
);

//- The measured mean advance per test, for scoring only
std::map<int, double> readMeasuredAdvance(const std::filesystem::path& file);

} // namespace drum

#endif
