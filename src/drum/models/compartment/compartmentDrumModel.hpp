// model.type compartment: Lee/Sheehan slice network (Lee 2008 Ch. 3,
// App. 10.2). Partitions: leeCorrelations (Lee's App. 10.2.3 correlations)
// or flightModel (Lee's geometric unloading + a drift model). Steady holdup
// profile and the tracer RTD; optional least-squares estimation from the
// measured curve (section `estimation`, leeCorrelations only), optional
// passive-phase dispersion, optional stagnant zone.
// Writes summary.csv, profile.csv, rtd.csv (+ estimation.csv) and PNGs.
#ifndef DRUM_MODELS_COMPARTMENT_COMPARTMENTDRUMMODEL_HPP
#define DRUM_MODELS_COMPARTMENT_COMPARTMENTDRUMMODEL_HPP

#include "drum/models/drumModel.hpp"
#include "drum/models/runOutputs.hpp"
#include "drum/transport/compartment/compartmentFlightModel.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"
#include "drum/transport/compartment/compartmentNetwork.hpp"
#include "drum/transport/compartment/compartmentSizeClasses.hpp"

#include <optional>
#include <string>
#include <vector>

namespace drum
{

//- The compartment model's own entries (model and estimation sections)
struct CompartmentSettings
{
    int slices = 30;
    std::string partition = "leeCorrelations";     //!< leeCorrelations | flightModel
    LeeParameters lee{9.28, 0.0, 1.0};              //!< kilnTime, backFraction, forwardDragFactor
    double designLoadMultiplier = 1;
    //- model.kilnTime saeman: each slice's kilning from its rolling bed
    //  (Sherritt 1991 Eq 22) instead of one t_kiln; kilnBedSlope_deg its gamma
    bool saemanKiln = false;
    double kilnBedSlopeDeg = 0;
    bool kilnBedSlopeFromProfile = false;   //!< kilnBedSlope_deg profile: gamma from the bed depths
    StagnantExchange stagnant{0.0, 600.0};          //!< stagnantRatio, exchangeTime
    DenseDispersionEntry dispersion;
    std::string dispersionBed = "kiln";             //!< kiln | passive
    bool subtractNumericalDispersion = false;
    std::optional<DriftSettings> drift;             //!< flightModel only
    FlightHoldup flightHoldup = FlightHoldup::eq421;   //!< flightModel only
    double flightPickupDeg = 0;                     //!< flightHoldup bedFilled only
    bool flightPickupFromBed = true;                //!< flightPickup_deg bed (the default)
    //- sizeClasses resolved: each class its own curtains in the shared slices
    //  (compartmentSizeClasses.hpp); mixed: one feed-weighted C_F, C_B
    bool resolveSizeClasses = false;
    // estimation
    std::vector<std::string> estimate;
    int starts = 1;
    bool logObjective = false;
    double logOffset = 0.01;                        //!< 1/h
};

class CompartmentDrumModel : public DrumModel
{
public:
    explicit CompartmentDrumModel(const DrumCase& c);

    void run(const std::filesystem::path& out) const override;

    const CompartmentSettings& settings() const { return s_; }

private:
    //- The steady state of `net`: size-resolved with `splits` when asked (classes filled then)
    CompartmentSteadyState solve(const CompartmentNetwork& net, const std::vector<SizeClassSplits>& splits,
                                 std::vector<CompartmentSteadyState>* classes = nullptr) const;
    std::vector<SizeClassSplits> sizeClassSplits(const std::vector<LeeSliceData>& data) const;
    CompartmentNetwork makeNetwork(const LeeDryer& dryer, const std::vector<LeeSliceData>& data,
                                   const LeeParameters& p) const;
    void runWith(const LeeDryer& dryer, const LeeParameters& p, const StagnantExchange& stagnant,
                 const std::optional<MeasuredTracer>& measured, const std::filesystem::path& out) const;

    DrumCase c_;
    CompartmentSettings s_;
    LeeDryer dryer_;
};

std::unique_ptr<DrumModel> makeCompartmentDrumModel(const DrumCase& c);

} // namespace drum

#endif
