// Drift models that read the CFD drift table (driftTable.hpp):
//   table    drift_m interpolated directly for the query's class diameter;
//            a drum incline adds the free slide y sin(alpha) (the incline
//            term of Sherritt 1991 Eq 12 over t^2 = 2y/g; the table is level).
//            Reading tunnel: tunnel_drift_m instead, the advance Sherritt's
//            wind tunnel would have recorded (for scoring against it)
//   tableVc  V_c/V_g from the table, then the shared core's lone-particle
//            fall at V_c (Sherritt's route, Eq 141/142, with the CFD's
//            shielding in place of the Eq 142 correlation)
#ifndef DRUM_DRIFT_TABLEDRIFT_HPP
#define DRUM_DRIFT_TABLEDRIFT_HPP

#include "drum/drift/driftModel.hpp"
#include "drum/drift/driftTable.hpp"

namespace drum
{

class TableDrift : public DriftModel
{
public:
    //- Which drift the table answers: what crossed the fall height (drift_m),
    //  or the wind tunnel's reading of it (tunnel_drift_m; the table must have it)
    enum class Reading { crossed, tunnel };

    explicit TableDrift(std::shared_ptr<const DriftTable> table, Reading reading = Reading::crossed);
    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "table"; }
    const DriftTable& table() const { return *table_; }

private:
    std::shared_ptr<const DriftTable> table_;
    Reading reading_;
};

class TableVcDrift : public IsolatedParticleDrift
{
public:
    TableVcDrift(std::shared_ptr<const DriftTable> table, particleDrag::Gas gas, particleDrag::DragLaw law = {});
    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "tableVc"; }
    const DriftTable& table() const { return *table_; }

private:
    std::shared_ptr<const DriftTable> table_;
};

} // namespace drum

#endif
