// The drift entries of a case dictionary (YAML) and the drift-model factory
// that needs more than a name (table path, out-of-range policy, constants):
//
//   model:
//     drift: tableVc       # isolated | sherritt | table | tableVc | porousSheet | auto | segmentVc
//   drift:                 # optional
//     table: path          # CFD drift table, relative to the case folder or
//                          # starting with $DRYER_PROJECT or $DRYER_DATA;
//                          # default $DRYER_PROJECT/etc/defaults/driftTables/driftTable.csv
//     segmentTable: path   # drum-segment table (segmentTable.hpp), for segmentVc
//     outside: refuse      # refuse (default) | clamp, queries outside the table
//     scale: 1             # every drift multiplied by this factor, (0, 10]: an
//                          # error band (dryerStudy: exp(+-RMS ln) of a route's scores)
//     recordQueries: false # write results/driftQueries.csv: the least and largest
//                          # value of every table axis the run asked (a table's grid)
//     constants: path      # porousSheet constants; default
//                          # $DRYER_PROJECT/etc/defaults/driftModels/porousSheet.yaml
//     auto:                # with model.drift auto (autoDrift.hpp), optional
//       inside: tableVc    # table | tableVc: the model inside the table
//       diluteRatio: 0.95  # porousSheet V_c/V_g above which lone particles serve
//       fixedAxisTolerance: 0.2   # reach of an axis the sweep held fixed
#ifndef DRUM_DRIFT_DRIFTDICTIONARY_HPP
#define DRUM_DRIFT_DRIFTDICTIONARY_HPP

#include "drum/drift/autoDrift.hpp"
#include "drum/drift/driftModel.hpp"
#include "drum/drift/driftTable.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace YAML { class Node; }

namespace drum
{

struct DriftSettings
{
    std::string model = "sherritt";
    std::filesystem::path table;       //!< empty: defaultDriftTableFile()
    std::filesystem::path segmentTable; //!< segmentVc's table (required there)
    OutOfRangePolicy outside = OutOfRangePolicy::refuse;
    std::filesystem::path constants;   //!< empty: defaultPorousSheetConstantsFile()
    std::function<void(const std::string&)> warn;  //!< clamp warnings; null: std::cerr
    //- porousSheet: surface-mean diameter of the curtain's solids (set by
    //  the caller from the material, sauterDiameter()); 0: each class alone
    double curtainDiameter = 0;
    //- model auto: the table model inside the table, the model outside it
    //  (sherritt: Eq 142, which the wind-tunnel scores support there; or
    //  porousSheet), and the thresholds
    std::string autoInside = "tableVc";
    std::string autoOutside = "sherritt";
    AutoDriftOptions autoOptions;
    //- model table: answer the table's tunnel_drift_m (what Sherritt's wind
    //  tunnel would have recorded; windTunnelDrift's scoring) instead of drift_m
    bool tunnelReading = false;
    //- every drift multiplied by this factor (drift.scale)
    double scale = 1.0;
    //- record the extent of the queries (drift.recordQueries): makeDriftModel
    //  then returns a RecordingDrift
    bool recordQueries = false;
};

//- InputError naming the table when its sweep gas differs from `gas` by more
//  than 5 % in density or kinematic viscosity (nothing to check without one)
void requireTableGas(const DriftTable& table, const particleDrag::Gas& gas);
//- The same check on a `gas=air(rho=..,nu=..)` setting of any table file
void requireSweepGas(const std::optional<std::string>& gasSetting, const std::string& file, const particleDrag::Gas& gas);
//- Whether that setting lies within 5 % of `gas` (true without one): the test
//  the two checks above make
bool sweepGasMatches(const std::optional<std::string>& gasSetting, const particleDrag::Gas& gas);

//- Every drift-model name makeDriftModel knows
const std::vector<std::string>& driftModelNames();

//- drum::defaultsDir()/driftTables/driftTable.csv (etc/defaults of the checkout)
std::filesystem::path defaultDriftTableFile();

//- Read model.drift and the optional drift section of `root` (the YAML of
//  `file`); paths relative to caseDir. InputError names file and entry.
DriftSettings readDriftSettings
(
    const YAML::Node& root,
    const std::string& file,
    const std::filesystem::path& caseDir,
    const std::string& defaultModel = "sherritt"
);

//- Build the named model; InputError naming `entry` and the valid names
//  for an unknown name, or naming the table/constants file when unreadable,
//  or (table, tableVc, auto) when the table's sweep gas (its header's
//  `fixed: ... gas=air(rho=..,nu=..)`) differs from `gas` by more than 5 %
std::shared_ptr<const DriftModel> makeDriftModel
(
    const DriftSettings& settings,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law = {},
    const std::string& entry = "model.drift"
);

} // namespace drum

#endif
