// "auto": model no more than a scene needs (issue 7). For every query the
// cheapest drift model whose accuracy the speed-accuracy chart supports
// (README "Speed against accuracy"), and a record of what was chosen and why:
//
//   1. isolated   the curtain is dilute: the reduced curtain model calibrated
//                 on CFD (porousSheet) gives V_c/V_g >= diluteRatio (0.95),
//                 so shielding changes the drift by a few per cent at most
//                 and the lone particle of Sherritt 1991 Eqs 13/16/17 is
//                 enough (and exact in that limit: curtainLoneParticle test)
//   2. inside     the query lies inside the CFD table's swept range on every
//                 axis (an axis the sweep held fixed covers +-fixedAxisTolerance
//                 of its value; below the smallest fall height the table's
//                 exact anchor applies): the table model (tableVc by default)
//   3. outside    anywhere else: Sherritt's Eq 142 (the model the wind-tunnel
//                 scores support outside any table: docs/validation.md;
//                 drift.auto.outside: porousSheet selects the reduced model),
//                 and the report names the axis and the range, advising a
//                 fresh CFD run there (curtainCase, or buildDriftTable over a
//                 wider grid)
//
// The user overrides by naming any model instead of "auto".
#ifndef DRUM_DRIFT_AUTODRIFT_HPP
#define DRUM_DRIFT_AUTODRIFT_HPP

#include "drum/drift/driftModel.hpp"
#include "drum/drift/driftTable.hpp"
#include "drum/drift/porousSheetDrift.hpp"

#include <array>
#include <atomic>
#include <memory>
#include <string>

namespace drum
{

struct AutoDriftOptions
{
    double diluteRatio = 0.95;        //!< V_c/V_g (porousSheet) above which lone particles serve
    double fixedAxisTolerance = 0.2;  //!< relative reach of an axis the sweep held fixed
};

class AutoDrift : public DriftModel
{
public:
    enum Choice { dilute = 0, inside = 1, outside = 2 };

    //- table may be null (no table: inside never applies); insideModel
    //  reads that table (table or tableVc); reduced judges dilution;
    //  outsideModel answers outside the table (null: reduced)
    AutoDrift
    (
        std::shared_ptr<const DriftTable> table,
        std::shared_ptr<const DriftModel> insideModel,
        std::shared_ptr<const PorousSheetDrift> reduced,
        std::shared_ptr<const DriftModel> isolated,
        AutoDriftOptions options = {},
        std::shared_ptr<const DriftModel> outsideModel = nullptr
    );

    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "auto"; }

    //- The choice for a query, and why (axis and range when outside)
    Choice choose(const DriftQuery& q, std::string* why = nullptr, int* axis = nullptr) const;

    //- Name of the model a choice uses
    std::string modelName(Choice c) const;

    //- Queries so far per choice
    long count(Choice c) const { return counters_->n[c].load(); }

    //- One paragraph: counts per choice with the models and the reasons
    std::string summary() const override;

private:
    std::shared_ptr<const DriftTable> table_;
    std::shared_ptr<const DriftModel> inside_;
    std::shared_ptr<const PorousSheetDrift> reduced_;
    std::shared_ptr<const DriftModel> isolated_;
    std::shared_ptr<const DriftModel> outside_;
    AutoDriftOptions options_;

    struct Counters
    {
        std::array<std::atomic<long>, 3> n{};
        std::array<std::atomic<long>, driftAxisCount> outsideOn{};  //!< first axis out
        std::atomic<bool> outsideNoted{false};
        std::string firstOutside;   //!< written once, guarded by outsideNoted
    };
    std::shared_ptr<Counters> counters_;
};

} // namespace drum

#endif
