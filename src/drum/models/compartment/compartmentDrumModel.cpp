#include "drum/models/compartment/compartmentDrumModel.hpp"

#include "drum/io/atomicFile.hpp"
#include "drum/io/csvWriter.hpp"
#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdResolution.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/transport/compartment/compartmentDispersion.hpp"
#include "drum/transport/compartment/compartmentFlightModel.hpp"
#include "drum/transport/compartment/compartmentLeeEstimation.hpp"
#include "drum/transport/kilnBed.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;

namespace drum
{

namespace
{

const double nan = std::numeric_limits<double>::quiet_NaN();

//- The compartment model's entries of the model and estimation sections
CompartmentSettings readSettings(const DrumCase& c)
{
    const DictReader r = c.reader();
    const std::string& file = r.file();
    const YAML::Node mo = r.section(c.root, "model");
    r.only(mo, "model", {"type", "slices", "partition", "kilnTime", "backFraction", "forwardDragFactor",
                         "designLoadMultiplier", "stagnantRatio", "exchangeTime", "denseDispersion",
                         "dispersionBed", "subtractNumericalDispersion", "drift", "kilnBedSlope_deg",
                         "flightHoldup", "flightPickup_deg", "sizeClasses"});
    if (!c.flights.twoSection)
    {
        throw InputError(file, "flights.exterior", "model compartment needs the two-section flight entries "
            "(flights.count, baseLength, tipLength, baseAngle_deg, tipAngle_deg)");
    }
    CompartmentSettings s;
    s.slices = r.integer(mo, "model", "slices", 1, 1000, 30);
    s.partition = r.word(mo, "model", "partition", {"leeCorrelations", "flightModel"}, std::string("leeCorrelations"));
    const bool lee = s.partition == "leeCorrelations";
    // entries the other partition reads are refused, not ignored
    if (lee)
    {
        r.refuse(mo, "model", "drift", "by partition leeCorrelations (Lee's correlations carry no drift model)");
        r.refuse(c.root, "", "drift", "by partition leeCorrelations (Lee's correlations carry no drift model)");
    }
    else
    {
        for (const char* k : {"backFraction", "forwardDragFactor"})
        {
            r.refuse(mo, "model", k, "by partition flightModel (the flight model gives the forward and back shares)");
        }
    }
    if (lee)
    {
        for (const char* k : {"flightHoldup", "flightPickup_deg", "sizeClasses"})
        {
            r.refuse(mo, "model", k, "by partition leeCorrelations (its design load is Lee's Eq 4.27)");
        }
    }
    else
    {
        // eq421: Lee's mirror rule; bedFilled: flights leave the bed full at flightPickup_deg
        s.flightHoldup = r.word(mo, "model", "flightHoldup", {"eq421", "bedFilled"}, std::string("eq421"))
            == "bedFilled" ? FlightHoldup::bedFilled : FlightHoldup::eq421;
        if (s.flightHoldup == FlightHoldup::bedFilled)
        {
            // bed: the pockets under the slice's kilning bed are full (iterated with the bed)
            s.flightPickupFromBed = !mo["flightPickup_deg"]
                || r.numberOrWord(mo, "model", "flightPickup_deg", -90, 80, {"bed"},
                       "a root angle in deg, range [-90, 80], or bed (the span of the slice's kilning bed)",
                       s.flightPickupDeg) == "bed";
        }
        else
        {
            r.refuse(mo, "model", "flightPickup_deg", "without model.flightHoldup bedFilled");
        }
        s.resolveSizeClasses = r.word(mo, "model", "sizeClasses", {"mixed", "resolved"}, std::string("mixed"))
            == "resolved";
    }
    // kilnTime: Lee's t_kiln, or saeman: the kilning bed from physics (no kiln time to give or fit)
    // (at most 1e5 s, a day per slice: a kiln that slow holds the tracer for longer than
    // any tracer run can follow, and the run could not reach its recovery)
    s.saemanKiln = r.numberOrWord(mo, "model", "kilnTime", 0, 1e5, {"saeman"},
        "a time in s, range (0, 1e5], or saeman (the rolling bed of Sherritt 1991 Eq 22)",
        s.lee.kilnTime, 9.28, true) == "saeman";
    if (s.saemanKiln)
    {
        s.lee.kilnTime = std::numeric_limits<double>::infinity();
        s.kilnBedSlopeFromProfile = r.numberOrWord(mo, "model", "kilnBedSlope_deg", -10, 10, {"profile"},
            "a slope in deg, range [-10, 10], or profile (from the bed depths)", s.kilnBedSlopeDeg, 0.0) == "profile";
    }
    else
    {
        r.refuse(mo, "model", "kilnBedSlope_deg", "without model.kilnTime saeman");
    }
    s.lee.backFraction = r.number(mo, "model", "backFraction", 0, 1, 0.0);
    s.lee.dragFactor = r.number(mo, "model", "forwardDragFactor", 0, 100, 1.0);
    s.designLoadMultiplier = r.number(mo, "model", "designLoadMultiplier", 0, 100, 1.0, true);
    s.stagnant.massRatio = r.number(mo, "model", "stagnantRatio", 0, 10, 0.0);
    s.stagnant.exchangeTime = r.number(mo, "model", "exchangeTime", 1, 1e6, 600.0);
    s.dispersion = readDenseDispersion(r, mo);
    // which passive mass disperses, and the slicing's own part
    s.dispersionBed = r.word(mo, "model", "dispersionBed", {"kiln", "passive"}, std::string("kiln"));
    s.subtractNumericalDispersion =
        r.word(mo, "model", "subtractNumericalDispersion", {"true", "false"}, std::string("false")) == "true";
    for (const char* k : {"dispersionBed", "subtractNumericalDispersion"})
    {
        if (mo[k] && s.dispersion.kind == "none")
        {
            throw InputError(file, std::string("model.") + k, "needs model.denseDispersion (sherritt2001 or a value)");
        }
    }
    if (!lee)
    {
        s.drift = readCaseDriftSettings(c);
    }
    if (s.resolveSizeClasses)
    {
        if (s.dispersion.kind != "none")
        {
            throw InputError(file, "model.denseDispersion", "not with model.sizeClasses resolved (the "
                "dispersion exchange acts on one network); use mixed or leave it out");
        }
        if (s.stagnant.massRatio > 0)
        {
            throw InputError(file, "model.stagnantRatio", "not with model.sizeClasses resolved; use mixed");
        }
    }

    if (const YAML::Node e = c.root["estimation"])
    {
        r.only(e, "estimation", {"parameters", "starts", "objective", "logOffset"});
        if (!c.tracer)
        {
            throw InputError(file, "estimation", "needs a measured curve: rtd.tracer");
        }
        if (!lee)
        {
            throw InputError(file, "estimation", "only for model.type compartment with partition leeCorrelations");
        }
        if (s.saemanKiln)
        {
            throw InputError(file, "estimation", "not with model.kilnTime saeman (the fit is Lee's network "
                "with one t_kiln); give kilnTime a value to estimate");
        }
        if (s.dispersion.kind != "none")
        {
            throw InputError(file, "model.denseDispersion", "not with estimation (the fitted network has no "
                "passive dispersion); use none, or run the fitted parameters without an estimation section");
        }
        const YAML::Node ps = e["parameters"];
        if (!ps || !ps.IsSequence() || ps.size() == 0)
        {
            std::string allowed;
            for (const auto& p : leeEstimationParameters()) allowed += (allowed.empty() ? "" : ", ") + p.entry;
            throw InputError(file, "estimation.parameters", "a list from: " + allowed);
        }
        for (const auto& q : ps)
        {
            s.estimate.push_back(leeEstimationParameter(q.as<std::string>(), "estimation.parameters", file).name);
        }
        s.starts = r.integer(e, "estimation", "starts", 1, 100, 4);
        s.logObjective = r.word(e, "estimation", "objective", {"linear", "log"}, std::string("linear")) == "log";
        s.logOffset = r.number(e, "estimation", "logOffset", 0, 100, 0.01, true);
    }
    return s;
}


//- Lee's dryer description from the case and the model's entries
LeeDryer leeDryer(const DrumCase& c, const CompartmentSettings& s)
{
    const TwoSectionFlight& f = *c.flights.twoSection;
    LeeDryer l;
    l.length = c.drum.length;
    l.rpm = c.drum.speedRpm;
    l.slopeDeg = c.drum.slopeDeg;
    l.feedRate = c.material.feedRate;
    l.bulkDensity = c.material.bulkDensity;
    l.geometry.drumRadius = c.drum.diameter/2;
    l.geometry.baseLength = f.baseLength;
    l.geometry.tipLength = f.tipLength;
    l.geometry.baseAngleDeg = f.baseAngleDeg;
    l.geometry.tipAngleDeg = f.tipAngleDeg;
    l.geometry.nFlights = f.count;
    if (c.material.reposeDeg)
    {
        l.constantPhiDeg = *c.material.reposeDeg;
    }
    else
    {
        l.moistureInlet = c.material.moisture->first;
        l.moistureOutlet = c.material.moisture->second;
    }
    l.designLoadMultiplier = s.designLoadMultiplier;
    return l;
}

} // namespace


CompartmentDrumModel::CompartmentDrumModel(const DrumCase& c)
:
    c_(c),
    s_(readSettings(c)),
    dryer_(leeDryer(c_, s_))
{}


std::unique_ptr<DrumModel> makeCompartmentDrumModel(const DrumCase& c)
{
    return std::make_unique<CompartmentDrumModel>(c);
}


CompartmentSteadyState CompartmentDrumModel::solve
(
    const CompartmentNetwork& net,
    const std::vector<SizeClassSplits>& splits,
    std::vector<CompartmentSteadyState>* classes
) const
{
    if (!s_.resolveSizeClasses)
    {
        return net.steadyState();
    }
    const SizeClassSteadyState st = sizeClassSteadyState(net, splits);
    if (classes) *classes = st.classes;
    return st.total;
}


std::vector<SizeClassSplits> CompartmentDrumModel::sizeClassSplits(const std::vector<LeeSliceData>& data) const
{
    std::vector<SizeClassSplits> out(c_.material.fractions.size());
    for (std::size_t k = 0; k < out.size(); ++k)
    {
        out[k].feedShare = c_.material.fractions[k];
        for (const LeeSliceData& s : data)
        {
            out[k].forward.push_back(s.classForward.at(k));
            out[k].back.push_back(s.classBack.at(k));
        }
    }
    return out;
}


CompartmentNetwork CompartmentDrumModel::makeNetwork
(
    const LeeDryer& dryer,
    const std::vector<LeeSliceData>& data,
    const LeeParameters& p
) const
{
    std::vector<CompartmentSlice> slices;
    for (const auto& s : data) slices.push_back(s.slice);
    if (s_.saemanKiln)
    {
        // each slice's kiln mass rolls as Saeman's bed (Sherritt 1991 Eq 22) at its own phi
        for (std::size_t i = 0; i < slices.size(); ++i)
        {
            SaemanKiln k;
            k.drumDiameter = data[i].kilnBedDiameter > 0 ? data[i].kilnBedDiameter : c_.drum.diameter;
            k.speed = c_.drum.speedRpm/60;
            k.bulkDensity = dryer.bulkDensity;
            k.drumSlope = c_.drum.slopeDeg*deg;
            k.bedSlope = s_.kilnBedSlopeDeg*deg;
            k.slopeFromProfile = s_.kilnBedSlopeFromProfile;
            k.repose = data[i].phiDeg*deg;
            slices[i].saemanKiln = k;
            slices[i].length = c_.drum.length/s_.slices;
        }
    }
    return CompartmentNetwork(std::move(slices), dryer.feedRate, p.kilnTime);
}


void CompartmentDrumModel::runWith
(
    const LeeDryer& dryer,
    const LeeParameters& p,
    const StagnantExchange& stagnant,
    const std::optional<MeasuredTracer>& measured,
    const fs::path& out
) const
{
    std::vector<LeeSliceData> data;
    if (s_.partition == "flightModel")
    {
        const particleDrag::Gas air = c_.gas.air();
        FlightModelPartition fp;
        fp.drift = makeDriftModel(*s_.drift, air, {}, "model.drift");
        // Mean gas velocity over the free cross-section (holdup neglected)
        fp.gasVelocity = c_.gas.massRate/(air.density*pi*c_.drum.diameter*c_.drum.diameter/4);
        fp.counterCurrent = c_.gas.counterCurrent;
        for (double s : c_.material.sizes) fp.sizes.push_back(s*c_.material.sphericity);
        fp.fractions = c_.material.fractions;
        fp.particleDensity = c_.material.particleDensity;
        fp.flightAxialLength = c_.flights.axialLength;
        fp.holdup = s_.flightHoldup;
        fp.pickupDeg = s_.flightPickupDeg;
        say("slice parameters from Lee's flight model and the " + s_.drift->model + " drift model (V_g "
          + std::to_string(fp.gasVelocity) + " m/s)");
        if (s_.flightHoldup == FlightHoldup::bedFilled && s_.flightPickupFromBed)
        {
            // start from an empty bed: every slice's span is its phi
            for (int i = 1; i <= s_.slices; ++i)
            {
                const double phi = leeSliceReposeDeg(dryer, i, s_.slices);
                fp.bedSpanDeg.emplace_back(phi, phi);
            }
        }
        data = flightModelSliceData(dryer, s_.slices, fp);
        if (const std::string note = fp.drift->summary(); !note.empty())
        {
            say(note);
        }
        if (!fp.bedSpanDeg.empty())
        {
            // the flights' load depends on the bed, the bed on the load: fixed point
            say("flights' holdup with the pockets under each slice's kilning bed full (model.flightPickup_deg bed)");
            for (int it = 0;; ++it)
            {
                const CompartmentSteadyState st = solve(makeNetwork(dryer, data, p),
                    s_.resolveSizeClasses ? sizeClassSplits(data) : std::vector<SizeClassSplits>{});
                const auto spans = kilnBedSpansDeg(dryer, data,
                    std::vector<double>(st.kilnMass.data(), st.kilnMass.data() + st.kilnMass.size()),
                    c_.drum.length/s_.slices);
                double change = 0;
                for (int i = 0; i < s_.slices; ++i)
                {
                    change = std::max({change, std::abs(spans[i].first - fp.bedSpanDeg[i].first),
                                       std::abs(spans[i].second - fp.bedSpanDeg[i].second)});
                }
                fp.bedSpanDeg = spans;
                data = flightModelSliceData(dryer, s_.slices, fp);
                if (change < 1e-9) break;
                if (it == 200)
                {
                    throw InputError(c_.path.string(), "model.flightPickup_deg",
                        "the flights' load and the kilning bed did not settle in 200 passes (last change "
                      + std::to_string(change) + " deg); give a pickup angle instead of bed");
                }
            }
            const auto& a = fp.bedSpanDeg.front();
            const auto& b = fp.bedSpanDeg.back();
            say("kilning bed from root angle " + std::to_string(a.first) + "-" + std::to_string(a.second)
              + " deg (feed end) to " + std::to_string(b.first) + "-" + std::to_string(b.second)
              + " deg (discharge end)");
        }
        writeDriftQueries(*fp.drift, out);
    }
    else
    {
        data = leeSliceData(dryer, s_.slices, p);
    }
    if (s_.saemanKiln)
    {
        say("kilning from the rolling-bed equation (Sherritt 1991 Eq 22), no kiln time");
    }
    const CompartmentNetwork net = makeNetwork(dryer, data, p);
    say("steady state of " + std::to_string(s_.slices) + " slices"
      + (s_.resolveSizeClasses ? ", " + std::to_string(c_.material.sizes.size()) + " size classes resolved" : ""));
    // each size class's curtain shares (resolved classes only: the flight model's)
    const std::vector<SizeClassSplits> splits =
        s_.resolveSizeClasses ? sizeClassSplits(data) : std::vector<SizeClassSplits>{};
    std::vector<CompartmentSteadyState> classStates;
    const CompartmentSteadyState st = solve(net, splits, &classStates);
    // Passive-phase axial dispersion (none, a value, or Sherritt 2001 Eq 51
    // per slice with X from the slice's bed mass): a symmetric exchange
    // between neighbouring passive cells (compartmentDispersion.hpp)
    PassiveDispersion disp;
    disp.sliceLength = c_.drum.length/s_.slices;
    disp.subtractNumerical = s_.subtractNumericalDispersion;
    if (s_.dispersion.kind != "none")
    {
        disp.bed = parseDispersionBed(s_.dispersionBed, "model.dispersionBed", c_.path.string());
    }
    std::vector<double> dispersionFill;
    if (s_.dispersion.kind == "value")
    {
        disp.coefficient = {s_.dispersion.value};
    }
    else if (s_.dispersion.kind == "sherritt2001")
    {
        PassiveDispersionDrum pd;
        pd.drumDiameter = c_.drum.diameter;
        pd.speed = c_.drum.speedRpm/60;
        pd.particleDiameter = dispersionParticleDiameter(c_.material.sizes, c_.material.fractions, c_.material.sphericity);
        pd.bulkDensity = dryer.bulkDensity;
        pd.sliceLength = disp.sliceLength;
        const PassiveSherritt2001 sz = sherritt2001PassiveDispersion(st, disp.bed, pd, c_.path.string());
        say("passive dispersion " + sz.note);
        for (const std::string& w : sz.warnings)
        {
            say("warning: passive dispersion: " + w);
        }
        disp.coefficient = sz.coefficient;
        dispersionFill = sz.fill;
    }
    PassiveDispersionSummary ds;
    const TracerSystem sys = s_.resolveSizeClasses
        ? sizeClassTracerSystem(net, SizeClassSteadyState{st, classStates}, splits)
        : withPassiveDispersion(net.tracerSystem(st, stagnant), st, disp, &ds, c_.path.string());
    if (!disp.coefficient.empty())
    {
        std::ostringstream w;
        w << "passive dispersion (" << toString(disp.bed) << " bed) at " << ds.boundaries
          << " slice faces: D_z " << ds.meanCoefficient << " m2/s, kilning's upwind part u_b dz/2 "
          << ds.meanNumerical << " m2/s, added " << ds.meanAdded << " m2/s"
          << (disp.subtractNumerical ? " (upwind part subtracted)" : " (on top of the network's own mixing)");
        say(w.str());
        if (ds.numericalExceeds > 0)
        {
            say("warning: at " + std::to_string(ds.numericalExceeds) + " of " + std::to_string(ds.boundaries)
              + " faces the slicing's kilning step alone disperses the bed more than D_z");
        }
    }
    // with the rolling bed, the kiln time its flows imply (kiln mass over kilning flow)
    const double kilnTime = s_.saemanKiln
        ? (st.kilnFlow.sum() > 0 ? st.kilnMass.sum()/st.kilnFlow.sum() : nan) : p.kilnTime;
    const double stagnantKg = stagnant.massRatio*st.passiveMass.sum();
    const double holdup = st.totalHoldup() + stagnantKg;

    {
        std::ostringstream os;
        os << "tracer RTD (" << toString(c_.rtd.integrator) << ", step " << c_.rtd.timeStep << " s)";
        say(os.str());
    }
    RtdOptions opt = c_.rtd;
    int lastPct = -10;
    opt.progress = [&](double f)
    {
        const int pct = int(100*std::min(f, 1.0));
        if (pct >= lastPct + 10)
        {
            lastPct = pct;
            std::cout << "drumSolver:   RTD " << pct << " % done" << std::endl;
        }
    };
    const RtdMoments ex = exactMoments(sys, c_.rtd.pulseDuration);
    requireResolvingStep(ex, c_.rtd.timeStep, c_.path.string());
    const RtdResult rtd = simulateRtd(sys, opt);
    for (const std::string& w : rtd.warnings)
    {
        say("warning: " + w);
    }
    const RtdMoments sm = sampledMoments(rtd.time, rtd.E);
    requireSampledMomentsMatch(sm, ex, c_.rtd.timeStep, c_.rtd.recovery, c_.path.string());

    // summary.csv
    std::vector<std::string> cols = {"holdup_kg", "airborne_fraction", "mean_residence_time_s", "rtd_std_s",
        "rtd_skewness", "rtd_recovered", "exact_mean_s", "exact_std_s", "holdup_over_feed_s",
        "design_load_kg", "kiln_mass_kg", "kiln_time_s", "back_fraction", "forward_drag_factor", "slices",
        "stagnant_kg", "exchange_time_s", "dense_dispersion_m2_s", "numerical_dispersion_m2_s",
        "added_dispersion_m2_s"};
    double design = 0;
    for (const auto& s : data) design += s.slice.designLoad;
    std::vector<double> row = {holdup, st.activeMass.sum()/holdup, sm.mean, sm.sd(), sm.skewness,
        rtd.recovered, ex.mean, ex.sd(), holdup/c_.material.feedRate, design, st.kilnMass.sum(),
        kilnTime,
        s_.partition == "flightModel" ? data[0].slice.backFraction : p.backFraction,
        s_.partition == "flightModel" ? nan : p.dragFactor, double(s_.slices),
        stagnantKg, stagnant.massRatio > 0 ? stagnant.exchangeTime : nan,
        disp.coefficient.empty() ? 0.0 : ds.meanCoefficient, disp.coefficient.empty() ? nan : ds.meanNumerical,
        disp.coefficient.empty() ? 0.0 : ds.meanAdded};
    const std::optional<RtdMoments> mm = writeSummary(cols, row, measured, out);

    if (s_.resolveSizeClasses)
    {
        // each class alone: its holdup, and its tracer's moments (exact, on the class's network)
        CsvTable cls({"class", "diameter_um", "feed_share", "holdup_kg", "airborne_fraction",
                      "exact_mean_s", "exact_std_s", "holdup_over_class_feed_s"});
        for (std::size_t k = 0; k < classStates.size(); ++k)
        {
            const CompartmentSteadyState& ck = classStates[k];
            const double hk = ck.totalHoldup();
            const RtdMoments mk = exactMoments(net.tracerSystem(ck), c_.rtd.pulseDuration);
            cls.addRow({double(k + 1), c_.material.sizes[k]*1e6, splits[k].feedShare, hk,
                        hk > 0 ? ck.activeMass.sum()/hk : nan, mk.mean, mk.sd(),
                        hk/(splits[k].feedShare*c_.material.feedRate)});
            std::ostringstream os;
            os << std::setprecision(4) << "size class " << k + 1 << " (" << c_.material.sizes[k]*1e6 << " um, "
               << 100*splits[k].feedShare << " % of the feed): holdup " << hk << " kg, mean " << mk.mean/60
               << " min, SD " << mk.sd()/60 << " min";
            say(os.str());
        }
        cls.write(out/"classes.csv");
    }

    CsvTable prof({"slice", "x_m", "phi_deg", "design_load_kg", "passive_kg", "active_kg", "kiln_kg",
        "holdup_kg_per_m", "release_kg_s", "kiln_flow_kg_s", "forward_kg_s", "back_kg_s", "return_kg_s",
        "passive_time_s", "fall_time_s", "fall_height_m", "C_F", "C_B", "dispersion_fill", "dense_dispersion_m2_s",
        "kiln_depth_m"});
    const double dL = c_.drum.length/s_.slices;
    for (int i = 0; i < s_.slices; ++i)
    {
        const auto& s = data[i];
        // the kilning bed's surface over the drum bottom: a segment of the circle
        // it rolls in (the flight-tip circle when the flights leave the bed full,
        // their pockets below it), of the slice's kiln mass at the bulk density
        const double Dk = s.kilnBedDiameter > 0 ? s.kilnBedDiameter : c_.drum.diameter;
        const double kilnDepth = 0.5*(c_.drum.diameter - Dk)
            + (st.kilnMass(i) > 0 ? bedDepth(Dk, fillAngle(Dk, st.kilnMass(i)/(dryer.bulkDensity*dL))) : 0.0);
        prof.addRow({double(i + 1), (i + 0.5)*dL, s.phiDeg, s.slice.designLoad, st.passiveMass(i),
            st.activeMass(i), st.kilnMass(i), (st.passiveMass(i) + st.activeMass(i))/dL,
            st.releaseFlow(i), st.kilnFlow(i), st.forwardFlow(i), st.backFlow(i), st.returnFlow(i),
            s.slice.passiveTime, s.slice.activeTime, s.correlations.fallHeight,
            s.slice.forwardFraction, s.slice.backFraction,
            dispersionFill.empty() ? nan : dispersionFill[i],
            disp.coefficient.empty() ? 0.0 : disp.coefficient.size() == 1 ? disp.coefficient[0] : disp.coefficient[i],
            kilnDepth});
    }
    prof.write(out/"profile.csv");
    if (s_.partition == "flightModel")
    {
        // the flights' unloading (Lee 2008 Ch. 4) in every slice: what the drift model was asked
        CsvTable unl({"slice", "phi_deg", "root_angle_deg", "flight_holdup_kg", "spill_rate_kg_m_s",
                      "fall_height_m"});
        for (int i = 0; i < s_.slices; ++i)
        {
            for (const auto& u : data[i].unloading)
            {
                unl.addRow({double(i + 1), data[i].phiDeg, u.angleDeg, u.holdupKg, u.spillRate, u.fallHeight});
            }
        }
        unl.write(out/"unloading.csv");
    }

    writeRtdOutputs(c_, rtd.time, rtd.E, measured,
        "compartment model (" + std::to_string(s_.slices) + " slices)", out);

    Plot ph;
    ph.title = "Holdup along the drum (feed end at 0)";
    ph.xlabel = "axial position (m)";
    ph.ylabel = "mass per slice (kg)";
    PlotSeries ps{"passive", prof.column("x_m"), prof.column("passive_kg")};
    PlotSeries pa{"active (airborne)", prof.column("x_m"), prof.column("active_kg")};
    PlotSeries pd{"design load", prof.column("x_m"), prof.column("design_load_kg"), "lines lw 2 dt 2"};
    ph.series = {ps, pa, pd};
    plotIfPossible(ph, out/"profile.png");

    std::ostringstream os;
    os << std::setprecision(4) << "holdup " << holdup << " kg, airborne " << 100*st.activeMass.sum()/holdup
       << " %, mean residence time " << sm.mean/60 << " min, SD " << sm.sd()/60 << " min";
    os << measuredNote(mm);
    say(os.str());
}


void CompartmentDrumModel::run(const fs::path& out) const
{
    const LeeDryer& dryer = dryer_;
    const LeeFlightGeometry invicta;
    if (s_.partition == "leeCorrelations"
     && (std::abs(dryer.geometry.tipRadius() - invicta.tipRadius()) > 1e-3 || c_.flights.twoSection->count != invicta.nFlights))
    {
        say("warning: Lee's correlations were regressed for the Invicta flights "
            "(D 5 m, 28 flights, s1 0.195, s2 0.183, alpha2 117 deg); this geometry differs");
    }
    LeeParameters p = s_.lee;

    const std::optional<MeasuredTracer> measured = readTracer(c_);

    if (!s_.estimate.empty())
    {
        say("estimating " + std::to_string(s_.estimate.size()) + " parameters from "
          + c_.tracer->file.filename().string() + " (" + std::to_string(s_.starts) + " starts)");
        std::vector<double> t, E;
        for (std::size_t i = 0; i < measured->t.size(); ++i)
        {
            if (measured->t[i] >= 0) { t.push_back(measured->t[i]); E.push_back(measured->E[i]*3600.0); }
        }
        std::vector<FitParameter> fp;
        for (const std::string& n : s_.estimate)
        {
            const LeeEstimationParameter& q = leeEstimationParameter(n, "estimation.parameters");
            const double initial = n == "kilnTime" ? s_.lee.kilnTime : n == "backFraction" ? s_.lee.backFraction
                : n == "dragFactor" ? s_.lee.dragFactor : n == "forwardShare" ? 0.5
                : n == "stagnantRatio" ? s_.stagnant.massRatio : n == "exchangeTime" ? s_.stagnant.exchangeTime
                : s_.designLoadMultiplier;
            fp.push_back({n, initial, q.lower, q.upper});
        }
        const RtdObjective objective{s_.logObjective, s_.logOffset};
        const StagnantExchange stagnant0{s_.stagnant.massRatio, s_.stagnant.exchangeTime};
        const PredictionModel model = leeRtdModel(dryer, s_.slices, p, s_.estimate,
            c_.rtd.pulseDuration, t, stagnant0, objective);
        const std::vector<FitResult> runs = multiStartFit(model,
            transformForObjective(E, objective), fp, s_.starts);
        if (runs.empty())
        {
            throw InputError(c_.path.string(), "estimation", "no start gave a feasible fit");
        }
        const FitResult& best = runs.front();
        LeeDryer mod = dryer;
        p = leeParametersFrom(dryer, s_.slices, p, s_.estimate, best.values, &mod);
        const StagnantExchange zFit = stagnantFrom(stagnant0, s_.estimate, best.values);
        AtomicFile f(out/"estimation.csv");
        f.stream() << "run,parameter,initial,value,std_error,ci95_low,ci95_high,at_bound,sse\n" << std::setprecision(10);
        for (std::size_t r = 0; r < runs.size(); ++r)
        {
            for (std::size_t k = 0; k < runs[r].names.size(); ++k)
            {
                f.stream() << r << ',' << runs[r].names[k] << ',' << runs[r].initial[k] << ',' << runs[r].values[k]
                           << ',' << runs[r].standardErrors[k] << ',' << runs[r].ciLow[k] << ',' << runs[r].ciHigh[k]
                           << ',' << (runs[r].atBound[k] ? 1 : 0) << ',' << runs[r].sse << '\n';
            }
        }
        f.commit();
        std::ostringstream os;
        os << std::setprecision(4) << "best fit (SSE " << best.sse << (s_.logObjective ? " in ln E" : " h^-2") << "): t_kiln " << p.kilnTime
           << " s, C_B " << p.backFraction << ", C_F^G " << p.dragFactor
           << ", design-load multiplier " << mod.designLoadMultiplier
           << ", stagnant M_s/M_p " << zFit.massRatio << " exchanging in " << zFit.exchangeTime << " s"
           << "; worst start SSE " << runs.back().sse;
        say(os.str());
        return runWith(mod, p, zFit, measured, out);
    }
    runWith(dryer, p, {s_.stagnant.massRatio, s_.stagnant.exchangeTime}, measured, out);
}

} // namespace drum
