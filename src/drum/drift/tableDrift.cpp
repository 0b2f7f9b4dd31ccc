#include "drum/drift/tableDrift.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>

namespace drum
{

TableDrift::TableDrift(std::shared_ptr<const DriftTable> table, Reading reading)
:
    table_(std::move(table)),
    reading_(reading)
{
    if (!table_) throw InputError("", "drift.table", "the table drift model needs a table");
    if (reading_ == Reading::tunnel) table_->requireTunnelDrift();   // refused before any query
}


double TableDrift::displacement(const DriftQuery& q) const
{
    if (!(q.fallHeight >= 0) || !std::isfinite(q.fallHeight))
    {
        throw InputError("", "drift query fall height", "must be in [0, inf) m");
    }
    // Level table + free slide down the incline over the same fall time.
    // Without gas or without a fall there is no gas drift, exactly (a
    // curtain in still gas lands symmetrically: tests/foam/curtainNoGas):
    // no table query, so no clamped answer from the table's lowest V_g
    const double slide = q.fallHeight*std::sin(q.incline);
    if (q.gasVelocity == 0 || q.fallHeight == 0)
    {
        return slide;
    }
    return (reading_ == Reading::tunnel ? table_->tunnelDrift(q) : table_->drift(q)) + slide;
}


TableVcDrift::TableVcDrift(std::shared_ptr<const DriftTable> table, particleDrag::Gas gas, particleDrag::DragLaw law)
:
    IsolatedParticleDrift(gas, law),
    table_(std::move(table))
{
    if (!table_) throw InputError("", "drift.table", "the tableVc drift model needs a table");
}


double TableVcDrift::displacement(const DriftQuery& q) const
{
    if (q.gasVelocity == 0 || q.fallHeight == 0)
    {
        return IsolatedParticleDrift::displacement(q);   // no gas or no fall: V_c is irrelevant
    }
    DriftQuery inCurtain = q;
    inCurtain.gasVelocity = table_->vcOverVg(q)*q.gasVelocity;
    if (!(inCurtain.gasVelocity >= 0))
    {
        throw InputError(table_->file().string(), "vc_over_vg",
            "interpolated V_c/V_g is negative at this query: the table cannot serve the tableVc model here");
    }
    return IsolatedParticleDrift::displacement(inCurtain);
}

} // namespace drum
