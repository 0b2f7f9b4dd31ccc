#include "drum/drift/segmentDrift.hpp"

#include "drum/io/inputError.hpp"

namespace drum
{

SegmentVcDrift::SegmentVcDrift(std::shared_ptr<const SegmentTable> table, particleDrag::Gas gas, particleDrag::DragLaw law)
:
    IsolatedParticleDrift(gas, law),
    table_(std::move(table))
{
    if (!table_) throw InputError("", "drift.segmentTable", "the segmentVc drift model needs a drum-segment table");
}


double SegmentVcDrift::displacement(const DriftQuery& q) const
{
    if (q.gasVelocity == 0 || q.fallHeight == 0)
    {
        return IsolatedParticleDrift::displacement(q);   // no gas or no fall: V_c is irrelevant
    }
    DriftQuery inCurtain = q;
    inCurtain.gasVelocity = table_->vcOverVg(q.reposeAngleDeg, q.gasVelocity, q.releaseAngleDeg)*q.gasVelocity;
    if (!(inCurtain.gasVelocity >= 0))
    {
        throw InputError(table_->file().string(), "vc_over_vg",
            "interpolated V_c/V_g is negative at this release angle: the segmentVc model cannot serve it");
    }
    return IsolatedParticleDrift::displacement(inCurtain);
}

} // namespace drum
