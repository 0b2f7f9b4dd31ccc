// model.type twoPhase: Sherritt's (1991) airborne/dense model. The axial
// (DRUM3) solve gives the holdup profile, airborne fraction, mean residence
// time (Eq 138) and per size class (Eq 139); the constant-holdup (DRUM1)
// sweep and its roots are reported beside it; the RTD comes from the
// model's tracer network (twoPhaseTracer.hpp), with optional dense-phase
// dispersion. Writes summary.csv, profile.csv, classes.csv, sweep.csv,
// roots.csv, rtd.csv and PNGs.
#ifndef DRUM_MODELS_TWOPHASE_TWOPHASEDRUMMODEL_HPP
#define DRUM_MODELS_TWOPHASE_TWOPHASEDRUMMODEL_HPP

#include "drum/models/drumModel.hpp"
#include "drum/transport/twoPhase/twoPhaseCase.hpp"

#include <optional>

namespace drum
{

//- The two-phase model's own entries of the model section
struct TwoPhaseSettings
{
    std::optional<int> slices;                  //!< tracer network; unset: automatic
    std::optional<double> imposedDenseFlow;     //!< F_2, kg/s (Kamke, Fig 5.30)
    std::optional<double> dischargeEndAngleDeg; //!< theta_i at the solids discharge
    int axialSteps = 200;                       //!< RK4 steps of the axial solve
    DenseDispersionEntry dispersion;
    DriftSettings drift;
};

class TwoPhaseDrumModel : public DrumModel
{
public:
    explicit TwoPhaseDrumModel(const DrumCase& c);

    void run(const std::filesystem::path& out) const override;

    const TwoPhaseSettings& settings() const { return s_; }

private:
    DrumCase c_;
    TwoPhaseSettings s_;
};

std::unique_ptr<DrumModel> makeTwoPhaseDrumModel(const DrumCase& c);

} // namespace drum

#endif
