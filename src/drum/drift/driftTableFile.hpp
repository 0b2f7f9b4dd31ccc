// The drift-table file, format "dryerDriftTable 1": its one reader and its
// one writer (buildDriftTable hands its sweep to writeDriftTable, which
// calls writeDriftTableFile; DriftTable::read calls readDriftTableFile).
//
// The format, line by line:
//   # dryerDriftTable 1                       magic and version
//   # generator: <tool, version, solver>      then "# key: value" lines, in this order:
//   # dictionary: <sweep dictionary>            generator, dictionary, [material,] axes,
//   # axes: <varied axes, contract order>       one "range <axis>: <min> <max>" per
//   # range <axis>: <min> <max>                 listed axis, fixed, mesh, [elapsed_s,]
//   # fixed: <k=v ...>                          cases; after them any notes
//   # mesh: <level> (<cells> cells)             (vc_over_vg, drift_m, iterations, ...)
//   # cases: <n> (<c> converged, <f> failed)    and one "# missing: ..." line per case
//   ...                                         a sweep did not finish (only then may
//                                               grid points be missing)
//   case,gas_velocity_m_s,spill_rate_kg_m_s,fall_height_m,flight_length_m,
//        particle_density_kg_m3,particle_diameter_m,vc_over_vg,drift_m,captured_fraction
//        [,tunnel_drift_m]
//   <one row per grid point: the curtain case's name, the six axis values,
//    the three values [and the tunnel's reading]>   every line ends with a newline
// tunnel_drift_m, optional (all rows or none): the class's advance as
// Sherritt's wind tunnel would have recorded it (its collection rule on the
// case's landing distribution, Sherritt 1991 section 4.3.1); written for
// sweeps in the wind tunnel's own domain.
// Numbers: the first five axes with 6 significant digits, the diameter and
// the values with 8 (printf %.6g / %.8g). The axes are the
// DriftAxis order of driftTable.hpp; an axis not on the axes line is the
// value the sweep held fixed. Key names and what each value means:
// etc/defaults/driftTables/README.md.
#ifndef DRUM_DRIFT_DRIFTTABLEFILE_HPP
#define DRUM_DRIFT_DRIFTTABLEFILE_HPP

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace drum
{

//- Text helpers the reader and DriftTable share
namespace driftTableParse
{
std::vector<std::string> words(const std::string& s);      //!< whitespace-separated words
std::string line(int n);                                    //!< "line n"
//- A whole finite number; InputError naming file and entry otherwise
double number(const std::string& text, const std::string& file, const std::string& entry);
//- The value of `key=value` on a table's '# fixed:' header line (the drift
//  table's and the segment table's), nullopt without the line or the key
std::optional<std::string> fixedSetting(const std::map<std::string, std::string>& header,
                                        const std::string& key);
}

//- The data columns, in order (without the optional last one)
const std::vector<std::string>& driftTableColumns();
//- The optional last column's name, "tunnel_drift_m"
const std::string& tunnelDriftColumn();

struct DriftTableRecord
{
    std::string caseName;
    std::array<double, 6> x{};      //!< gas velocity, spill, fall height, flight length, density, diameter
    std::array<double, 3> v{};      //!< vc_over_vg, drift_m, captured_fraction
    std::optional<double> tunnelDrift;  //!< tunnel_drift_m, when the table has the column
    int line = 0;                   //!< line in the file read (0: not read from a file)
};

struct DriftTableFile
{
    //- "# key: value" lines after the magic line, in file order
    std::vector<std::pair<std::string, std::string>> header;
    std::vector<DriftTableRecord> rows;
};

//- Read the file's lines: magic and version, header lines, column row, data
//  rows with numeric fields, final newline. InputError naming the file and
//  the line for every defect. The grid itself is checked by DriftTable.
DriftTableFile readDriftTableFile(const std::filesystem::path& file);

//- The text of the file, exactly as writeDriftTableFile writes it
std::string driftTableText(const DriftTableFile& table);

//- Check the table as DriftTable::read would (header order, ranges, a
//  complete grid unless '# missing:' says why) and write it atomically;
//  InputError naming `file` and the defect, nothing written then
void writeDriftTableFile(const DriftTableFile& table, const std::filesystem::path& file);

} // namespace drum

#endif
