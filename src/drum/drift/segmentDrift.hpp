// Drift with the drum segment's shielding (segmentTable.hpp):
//   segmentVc  V_c/V_g of the curtain released at the query's release angle,
//              from the segment runs (every flight's curtain at once in the
//              drum's own section), then the shared core's lone-particle fall
//              at V_c: Sherritt's route (1991 Eq 141/142) with the segment's
//              shielding in place of Eq 142, as tableVc takes the box's.
#ifndef DRUM_DRIFT_SEGMENTDRIFT_HPP
#define DRUM_DRIFT_SEGMENTDRIFT_HPP

#include "drum/drift/driftModel.hpp"
#include "drum/drift/segmentTable.hpp"

#include <memory>

namespace drum
{

class SegmentVcDrift : public IsolatedParticleDrift
{
public:
    SegmentVcDrift(std::shared_ptr<const SegmentTable> table, particleDrag::Gas gas, particleDrag::DragLaw law = {});
    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "segmentVc"; }
    const SegmentTable& table() const { return *table_; }

private:
    std::shared_ptr<const SegmentTable> table_;
};

} // namespace drum

#endif
