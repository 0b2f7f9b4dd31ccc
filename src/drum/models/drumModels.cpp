// The drum models drumSolver can select by model.type. Adding one: a folder
// beside compartment/ and twoPhase/ with a DrumModel subclass and its make
// function, and one line here (CONTRIBUTING.md, "Adding a drum model").
#include "drum/models/drumModel.hpp"

#include "drum/models/compartment/compartmentDrumModel.hpp"
#include "drum/models/twoPhase/twoPhaseDrumModel.hpp"

namespace drum
{

const std::vector<DrumModelEntry>& drumModelTable()
{
    // name, top-level sections beyond drum/flights/material/gas/model/rtd, constructor
    static const std::vector<DrumModelEntry> table = {
        {"compartment", {"drift", "estimation"}, &makeCompartmentDrumModel},
        {"twoPhase", {"drift"}, &makeTwoPhaseDrumModel},
    };
    return table;
}

} // namespace drum
