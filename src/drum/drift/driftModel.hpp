// Drift per fall: the axial displacement of a particle falling from a flight
// through the gas, the delta_1 of Sherritt 1991 Eqs 45-51. The two-phase
// model asks a DriftModel for it at every discharge angle and size class,
// so the lone-particle law, Sherritt's sheet correction (Eq 142) or a CFD
// drift table plug in here.
//
// Sign convention (Sherritt 1991, docs/errata.md S12): +x is the direction of the gas flow,
// gasVelocity >= 0, incline > 0 when the drum slopes down along the gas.
#ifndef DRUM_DRIFT_DRIFTMODEL_HPP
#define DRUM_DRIFT_DRIFTMODEL_HPP

#include "particleDrag/dragLaw.hpp"
#include "particleDrag/gasProperties.hpp"
#include "particleDrag/sheetVelocity.hpp"

#include <array>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

namespace drum
{

//- What a drift model is asked
struct DriftQuery
{
    double particleDiameter = 0; //!< m (sieve size x sphericity)
    double particleDensity = 0;  //!< kg/m3
    double gasVelocity = 0;      //!< mean axial gas velocity V_g >= 0, m/s
    double fallHeight = 0;       //!< y >= 0, m
    double spillRate = 0;        //!< flight discharge rate per metre, kg/(s m) (Eq 40)
    double flightLength = 0;     //!< axial length of the flight, m
    double incline = 0;          //!< drum incline, rad, signed as above
    //- Where the flight releases (Lee 2008 Ch. 4 angles, deg): its root angle
    //  from the drum bottom along the rotation, and the dynamic angle of
    //  repose; NaN when the caller's model has no such angle (only the
    //  drum-segment table needs them)
    double releaseAngleDeg = std::numeric_limits<double>::quiet_NaN();
    double reposeAngleDeg = std::numeric_limits<double>::quiet_NaN();
};

class DriftModel
{
public:
    virtual ~DriftModel() = default;

    //- Axial displacement [m] along +x during the fall
    virtual double displacement(const DriftQuery& q) const = 0;

    //- Name used in dictionaries
    virtual std::string name() const = 0;

    //- What a run should tell the user about this model's use (choices
    //  made, ranges left); empty by default
    virtual std::string summary() const { return {}; }
};

//- The extent of the queries a run made: per axis of the drift table (gas
//  velocity, spill rate, fall height, flight length, particle density, particle
//  diameter, driftTable.hpp's order) the least and the largest value asked
struct DriftQueryRange
{
    std::array<double, 6> lo{}, hi{};
    long count = 0;
    //- The Lee angles (release, repose; deg) of the queries that carry them
    //  (finite): the drum-segment table's axes
    std::array<double, 2> angleLo{}, angleHi{};
    long angleCount = 0;
    void add(const DriftQuery& q);
};

//- Any model, each query's axes recorded in a DriftQueryRange (thread-safe):
//  what a drift table for this run must cover (drift.recordQueries)
class RecordingDrift : public DriftModel
{
public:
    explicit RecordingDrift(std::shared_ptr<const DriftModel> inner) : inner_(std::move(inner)) {}
    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return inner_->name(); }
    std::string summary() const override { return inner_->summary(); }
    //- The range so far
    DriftQueryRange range() const;
    //- range() as CSV: axis,min,max (the drift table's column names), then the
    //  query count; then release_angle_deg and repose_angle_deg (the segment
    //  table's names) when queries carried them
    std::string rangeCsv() const;

private:
    std::shared_ptr<const DriftModel> inner_;
    mutable std::mutex mutex_;
    mutable DriftQueryRange range_;
};

//- Any model's gas drift multiplied by a factor (drift.scale): the error band of
//  a drift model's measured error, e.g. exp(+-RMS ln) of the wind-tunnel scores.
//  The free slide along an inclined drum (the displacement in still gas) is
//  geometry, not drift, and is kept as it is.
class ScaledDrift : public DriftModel
{
public:
    ScaledDrift(std::shared_ptr<const DriftModel> inner, double factor) : inner_(std::move(inner)), factor_(factor) {}
    double displacement(const DriftQuery& q) const override
    {
        DriftQuery still = q;
        still.gasVelocity = 0;
        const double slide = inner_->displacement(still);
        return slide + factor_*(inner_->displacement(q) - slide);
    }
    std::string name() const override { return inner_->name(); }
    std::string summary() const override { return inner_->summary(); }

private:
    std::shared_ptr<const DriftModel> inner_;
    double factor_;
};

//- Lone particle in the mean gas velocity, V = V_g (Sherritt 1991 Eqs 13,
//  16, 17 with Eq 19; Kamke's and Kelly's model): particleDrag's
//  loneParticleAdvance
class IsolatedParticleDrift : public DriftModel
{
public:
    IsolatedParticleDrift(particleDrag::Gas gas, particleDrag::DragLaw law = {});
    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "isolated"; }

protected:
    particleDrag::Gas gas_;
    particleDrag::DragLaw law_;
};

//- Lone particle in the mean gas velocity with drag on the full slip vector:
//  Eq 12 with its vertical counterpart integrated from rest (RK4,
//  particleDrag::integrateFall), Cd re-evaluated from the instantaneous slip:
//  the fall speed joins the slip the horizontal drag acts on (K |w| w_x, not
//  K V_g^2), and drag makes the fall last longer than Eq 19's drag-free time.
//  Sherritt's Eq 17 (isolated) neglects both; this model says how much it matters.
class FullDragParticleDrift : public IsolatedParticleDrift
{
public:
    using IsolatedParticleDrift::IsolatedParticleDrift;
    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "isolatedFullDrag"; }
};

//- Lone particle in the sheet gas velocity V_c = C_V V_g, C_V from Eq 142
//  with the code's exponents and the cap at 1 (sheetgasvel())
class SherrittSheetDrift : public IsolatedParticleDrift
{
public:
    using IsolatedParticleDrift::IsolatedParticleDrift;

    //- With Eq 142's constants refitted (windTunnelDrift -sheetConstants)
    SherrittSheetDrift
    (
        particleDrag::Gas gas,
        particleDrag::DragLaw law,
        particleDrag::SheetVelocityConstants constants
    )
    :
        IsolatedParticleDrift(gas, law),
        constants_(constants)
    {}

    double displacement(const DriftQuery& q) const override;
    std::string name() const override { return "sherritt"; }

private:
    particleDrag::SheetVelocityConstants constants_;
};

//- By name with the default table, policy (refuse) and constants files:
//  isolated, sherritt, table, tableVc, porousSheet (driftDictionary.hpp has
//  the overload taking paths and the policy); throws drum::InputError naming
//  `entry` and the valid names otherwise
std::shared_ptr<const DriftModel> makeDriftModel
(
    const std::string& name,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law = {},
    const std::string& entry = "drift.model"
);

} // namespace drum

#endif
