// The drum-model interface drumSolver drives, with run-time selection by
// model.type (in the spirit of solids4foam's physicsModel::New):
//
//   DrumCase c = readDrumCase(dir, drumModelSections());
//   std::unique_ptr<DrumModel> m = DrumModel::New(c);   // reads and checks its own sections
//   m->run(outputFolder);                              // solves, writes its outputs
//
// A model reads its `model` section (and any top-level section only it uses)
// once in its constructor, refusing entries it does not use, and owns its
// outputs. Models are registered in drumModels.cpp, one line each.
#ifndef DRUM_MODELS_DRUMMODEL_HPP
#define DRUM_MODELS_DRUMMODEL_HPP

#include "drum/models/drumCase.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace drum
{

class DrumModel
{
public:
    virtual ~DrumModel() = default;

    //- Solve and write every output into `out` (a fresh folder that
    //  becomes the case's results/ once complete)
    virtual void run(const std::filesystem::path& out) const = 0;

    //- The model named by model.type; InputError listing the known names
    static std::unique_ptr<DrumModel> New(const DrumCase& c);
};

//- One registered model: its model.type name, the top-level sections it
//  reads beyond the shared ones, and its constructor
struct DrumModelEntry
{
    std::string name;
    std::vector<std::string> sections;
    std::unique_ptr<DrumModel> (*make)(const DrumCase&);
};

//- Every registered model (drumModels.cpp)
const std::vector<DrumModelEntry>& drumModelTable();

//- The top-level sections any registered model reads (for readDrumCase)
std::vector<std::string> drumModelSections();

} // namespace drum

#endif
