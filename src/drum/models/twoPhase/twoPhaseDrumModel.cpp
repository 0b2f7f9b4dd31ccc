#include "drum/models/twoPhase/twoPhaseDrumModel.hpp"

#include "drum/flights/sherritt/sherrittFlightShapes.hpp"
#include "drum/io/csvWriter.hpp"
#include "drum/io/inputError.hpp"
#include "drum/models/runOutputs.hpp"
#include "drum/numerics/constants.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdResolution.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/transport/axialDispersion.hpp"
#include "drum/transport/twoPhase/twoPhaseModel.hpp"
#include "drum/transport/twoPhase/twoPhaseTracer.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;

namespace drum
{

namespace
{

const double nan = std::numeric_limits<double>::quiet_NaN();

//- The two-phase model's entries of the model section
TwoPhaseSettings readSettings(const DrumCase& c)
{
    const DictReader r = c.reader();
    const YAML::Node mo = r.section(c.root, "model");
    r.only(mo, "model", {"type", "slices", "imposedDenseFlow", "dischargeEndAngle_deg", "axialSteps",
                         "denseDispersion", "drift"});
    if (!c.material.reposeDeg)
    {
        throw InputError(r.file(), "material.repose_deg",
            "model twoPhase needs a constant kinetic angle of repose (deg, (0, 90])");
    }
    r.refuse(r.section(c.root, "material"), "material", "moisture",
        "by model.type twoPhase (it takes the constant material.repose_deg)");
    TwoPhaseSettings s;
    if (mo["slices"])
    {
        s.slices = r.integer(mo, "model", "slices", 1, 1000);
    }
    if (mo["imposedDenseFlow"])
    {
        s.imposedDenseFlow = r.number(mo, "model", "imposedDenseFlow", -1e4, 1e4);
    }
    if (mo["dischargeEndAngle_deg"])
    {
        s.dischargeEndAngleDeg = r.number(mo, "model", "dischargeEndAngle_deg", 40, 360);
    }
    s.axialSteps = r.integer(mo, "model", "axialSteps", 10, 100000, 200);
    s.dispersion = readDenseDispersion(r, mo);
    s.drift = readCaseDriftSettings(c);
    return s;
}


//- The two-phase case of a dictionary (drum, flights, material, gas, model)
TwoPhaseCase twoPhaseCase(const DrumCase& c, const TwoPhaseSettings& s)
{
    TwoPhaseCase tc;
    tc.name = c.path.string();
    tc.drum.shellDiameter = c.drum.diameter;
    tc.drum.length = c.drum.length;
    tc.drum.slope = c.drum.slopeDeg*pi/180;
    tc.drum.speed = c.drum.speedRpm/60;
    tc.drum.centrefillDiameter = c.drum.centrefillDiameter;
    const double step = c.flights.tableStepDeg*pi/180;
    if (c.flights.exterior)
    {
        say("tabulating the " + toString(c.flights.exterior->type) + " exterior flight (Sherritt's horizontal-length table)");
        tc.exterior = buildSherrittFlight(*c.flights.exterior, FlightSide::exterior, c.drum.diameter,
            c.flights.axialLength, step, tc.name);
        if (c.flights.interior)
        {
            tc.interior = buildSherrittFlight(*c.flights.interior, FlightSide::interior, c.drum.diameter,
                c.flights.axialLength, step, tc.name);
        }
    }
    else
    {
        say("tabulating the two-section flight (Sherritt's horizontal-length table)");
        const TwoSectionFlight& t = *c.flights.twoSection;
        SherrittFlightSpec f;
        f.count = t.count;
        f.baseLength = t.baseLength;
        f.tipLength = t.tipLength;
        f.tipAngle = t.tipAngleDeg*pi/180;
        f.baseAngle = t.baseAngleDeg*pi/180;
        tc.exterior = buildSherrittFlight(f, FlightSide::exterior, c.drum.diameter, c.flights.axialLength,
            step, tc.name);
    }
    tc.material.particleDensity = c.material.particleDensity;
    tc.material.bulkDensity = c.material.bulkDensity;
    tc.material.repose = *c.material.reposeDeg*pi/180;
    tc.material.sphericity = c.material.sphericity;
    tc.material.sieveSizes = c.material.sizes;
    tc.material.massFractions = c.material.fractions;
    tc.gas.massRate = c.gas.massRate;
    tc.gas.temperatureC = c.gas.temperatureC;
    tc.gas.pressureKPa = c.gas.pressureKPa;
    tc.gas.direction = c.gas.counterCurrent ? GasFlow::countercurrent : GasFlow::cocurrent;
    if (s.drift.model == "segmentVc")
    {
        // Sherritt's flights are not Lee's: no release angle of the segment's
        throw InputError(c.path.string(), "model.drift", "segmentVc serves the compartment model's flightModel "
                         "partition (Lee's flight and release angles); the twoPhase model takes isolated, sherritt, "
                         "table, tableVc, porousSheet or auto");
    }
    tc.options.drift = makeDriftModel(s.drift, c.gas.air(), {}, "model.drift");
    tc.options.imposedDenseFlow = s.imposedDenseFlow;
    tc.options.axialSteps = s.axialSteps;
    return tc;
}

} // namespace


TwoPhaseDrumModel::TwoPhaseDrumModel(const DrumCase& c)
:
    c_(c),
    s_(readSettings(c))
{}


std::unique_ptr<DrumModel> makeTwoPhaseDrumModel(const DrumCase& c)
{
    return std::make_unique<TwoPhaseDrumModel>(c);
}


void TwoPhaseDrumModel::run(const fs::path& out) const
{
    const DrumCase& c = c_;
    const TwoPhaseSettings& s = s_;
    const TwoPhaseCase tc = twoPhaseCase(c, s);
    const std::optional<MeasuredTracer> measured = readTracer(c);
    say(std::string("two-phase model (Sherritt 1991), axial solve")
        + (s.imposedDenseFlow ? " with the dense flow imposed" : ""));
    const TwoPhaseModel model(tc);
    AxialOptions ax;
    if (s.dischargeEndAngleDeg)
    {
        ax.dischargeEndAngle = *s.dischargeEndAngleDeg*pi/180;
    }
    const TwoPhaseResult r = model.solveAxial(c.material.feedRate, ax);
    if (const std::string note = tc.options.drift->summary(); !note.empty())
    {
        say(note);
    }
    if (r.cappedLength > 0)
    {
        std::ostringstream os;
        os << "warning: the bed slope is held at the cap phi over " << r.cappedLength << " of " << c.drum.length
           << " m next to the discharge end (Eq 135 asks for more): there Eq 79 does not carry the dense flow of Eq 55";
        say(os.str());
    }

    // DRUM1 (constant holdup, Sherritt's driver for Sheikh, Kelly, O'Donnell
    // and Saeman): the theta_i sweep and every root F0(theta_i) = feed
    // (Sherritt 1991 §5.1: overloaded drums can have several)
    CsvTable sweepTable({"theta_i_deg", "regime", "valid", "feed_kg_s", "holdup_kg", "airborne_kg",
        "discharging_kg", "nondischarging_kg", "airborne_holdup_fraction", "airborne_flow_fraction"});
    const double kgPerM = c.material.bulkDensity*c.drum.length;
    for (double t = std::ceil(model.minDischargeAngle()*180/pi); t <= model.finalDischargeAngle()*180/pi + 1e-9; t += 1)
    {
        const TwoPhaseState st = model.atDischargeAngle(t*pi/180);
        sweepTable.addRow({t, double(static_cast<int>(st.regime)), st.valid ? 1.0 : 0.0,
            st.valid ? st.feedRate : nan, st.holdup*kgPerM, st.airborneHoldup*kgPerM,
            st.dischargingHoldup*kgPerM, st.nonDischargingHoldup*kgPerM, st.airborneHoldup/st.holdup,
            st.valid ? st.airborneFlow/st.feedRate : nan});
    }
    CsvTable rootTable({"theta_i_deg", "regime", "holdup_kg", "airborne_fraction", "mean_residence_time_s",
        "airborne_flow_kg_s", "dense_flow_kg_s"});
    try
    {
        const std::vector<TwoPhaseResult> roots = model.solveConstantHoldup(c.material.feedRate);
        std::ostringstream os;
        os << std::setprecision(4) << "DRUM1 (constant holdup) has " << roots.size() << " root"
           << (roots.size() > 1 ? "s" : "") << " for " << c.material.feedRate << " kg/s:";
        for (const auto& q : roots)
        {
            os << " theta_i " << q.dischargeAngle*180/pi << " deg (" << loadingRegimeName(q.regime)
               << ", " << q.holdupMass << " kg, airborne " << 100*q.airborneFraction << " %);";
            rootTable.addRow({q.dischargeAngle*180/pi, double(static_cast<int>(q.regime)), q.holdupMass,
                q.airborneFraction, q.meanResidenceTime, q.airborneFlow, q.denseFlow});
        }
        say(os.str());
    }
    catch (const InputError& e)
    {
        say(std::string("DRUM1 (constant holdup): no root: ") + e.what());
    }

    // Dense-phase axial dispersion (none, a value, or Sherritt 2001 Eq 51 by
    // regime with X the mean dense holdup over the drum cross-section)
    TwoPhaseTracerOptions to;
    if (s.slices)
    {
        to.slices = *s.slices;
    }
    std::string dispersionNote = "none";
    if (s.dispersion.kind == "value")
    {
        to.denseDispersion = s.dispersion.value;
        dispersionNote = "given";
    }
    else if (s.dispersion.kind == "sherritt2001")
    {
        double denseH = 0, sumZ = 0;
        for (std::size_t k = 1; k < r.profile.size(); ++k)
        {
            const auto& a = r.profile[k - 1];
            const auto& b = r.profile[k];
            const double dz = std::abs(b.distanceFromDischarge - a.distanceFromDischarge);
            denseH += 0.5*dz*((a.holdup - a.airborneHoldup) + (b.holdup - b.airborneHoldup));
            sumZ += dz;
        }
        AxialDispersionInput in;
        in.drumDiameter = c.drum.diameter;
        in.speed = c.drum.speedRpm/60;
        in.particleDiameter = dispersionParticleDiameter(c.material.sizes, c.material.fractions, c.material.sphericity);
        in.fill = bedFillFraction(sumZ > 0 ? denseH/sumZ : 0.0, c.drum.diameter);
        const AxialDispersionResult dz = sherritt2001AxialDispersion(in, c.path.string());
        to.denseDispersion = dz.Dz;
        dispersionNote = describeAxialDispersion(dz, in);
        say("dense dispersion " + dispersionNote);
        for (const std::string& w : dz.warnings)
        {
            say("warning: dense dispersion: " + w);
        }
    }
    const TwoPhaseTracerNetwork net = twoPhaseTracerNetwork(model, r, to);
    {
        std::ostringstream os;
        os << "tracer network: " << net.slices << " slices of " << net.sliceLength << " m"
           << (net.slicesClamped ? " (automatic slicing clamped to [20, 400])" : "")
           << ", " << toString(c.rtd.integrator) << " RTD with step " << c.rtd.timeStep << " s";
        say(os.str());
        if (to.denseDispersion > 0)
        {
            std::ostringstream w;
            w << "dense dispersion " << to.denseDispersion << " m2/s, upwind part u_2 dz/2 "
              << net.numericalDenseDispersion << " m2/s, added " << net.effectiveDenseDispersion << " m2/s";
            say(w.str());
            if (net.numericalDenseDispersion > to.denseDispersion)
            {
                say("warning: the slicing alone disperses more than D_z: refine model.slices to resolve it");
            }
        }
    }

    // Each size class is its own network; the overall E is the feed-weighted
    // sum, each class run until the recovery (its E is 0 after its end)
    const RtdMoments ex = exactMoments(net.system, c.rtd.pulseDuration);
    requireResolvingStep(ex, c.rtd.timeStep, c.path.string());
    std::vector<double> time, E;
    double recovered = 0;
    std::vector<RtdMoments> classMoments(net.classSystems.size());
    for (std::size_t k = 0; k < net.classSystems.size(); ++k)
    {
        const double x = net.feedFractions[k];
        if (!(x > 0))
        {
            continue;
        }
        const RtdResult rk = simulateRtd(net.classSystems[k], c.rtd);
        for (const std::string& w : rk.warnings)
        {
            say("warning: size class " + std::to_string(k) + ": " + w);
        }
        if (rk.time.size() > time.size())
        {
            time = rk.time;   // same step from 0: the longest grid holds the others
            E.resize(time.size(), 0.0);
        }
        for (std::size_t i = 0; i < rk.time.size(); ++i)
        {
            E[i] += x*rk.E[i];
        }
        recovered += x*rk.recovered;
        classMoments[k] = exactMoments(net.classSystems[k], c.rtd.pulseDuration);
    }
    const RtdMoments sm = sampledMoments(time, E);
    requireSampledMomentsMatch(sm, ex, c.rtd.timeStep, c.rtd.recovery, c.path.string());

    // the leading columns are those of the compartment model
    std::vector<std::string> cols = {"holdup_kg", "airborne_fraction", "mean_residence_time_s",
        "rtd_std_s", "rtd_skewness", "rtd_recovered", "exact_mean_s", "exact_std_s", "holdup_over_feed_s",
        "rtd_mean_s", "airborne_flow_kg_s", "dense_flow_kg_s", "discharge_angle_deg", "slices", "dense_dispersion_m2_s",
        "numerical_dispersion_m2_s", "capped_slope_length_m"};
    std::vector<double> row = {r.holdupMass, r.airborneFraction, r.meanResidenceTime,
        sm.sd(), sm.skewness, recovered, ex.mean, ex.sd(), r.holdupMass/c.material.feedRate, sm.mean,
        r.airborneFlow, r.denseFlow, r.dischargeAngle*180/pi, double(net.slices), to.denseDispersion,
        net.numericalDenseDispersion, r.cappedLength};
    const std::optional<RtdMoments> mm = writeSummary(cols, row, measured, out);

    CsvTable cls({"size_um", "feed_fraction", "holdup_fraction", "T_eq139_s", "network_mean_s", "network_std_s"});
    for (std::size_t k = 0; k < c.material.sizes.size(); ++k)
    {
        cls.addRow({c.material.sizes[k]*1e6, net.feedFractions[k], r.holdupFractions[k], r.sizeResidenceTimes[k],
            net.feedFractions[k] > 0 ? classMoments[k].mean : nan, net.feedFractions[k] > 0 ? classMoments[k].sd() : nan});
    }
    cls.write(out/"classes.csv");

    CsvTable prof({"x_m", "discharge_angle_deg", "holdup_kg_per_m", "airborne_kg_per_m",
        "airborne_flow_kg_s", "dense_flow_kg_s", "bed_slope_deg"});
    for (auto it = r.profile.rbegin(); it != r.profile.rend(); ++it)
    {
        prof.addRow({c.drum.length - it->distanceFromDischarge, it->dischargeAngle*180/pi,
            it->holdup*c.material.bulkDensity, it->airborneHoldup*c.material.bulkDensity,
            it->airborneFlow, it->denseFlow, it->bedSlope*180/pi});
    }
    prof.write(out/"profile.csv");
    sweepTable.write(out/"sweep.csv");
    rootTable.write(out/"roots.csv");
    writeRtdOutputs(c, time, E, measured, "two-phase network (" + std::to_string(net.slices) + " slices)", out);
    if (!r.profile.empty())
    {
        Plot ph;
        ph.title = "Two-phase holdup along the drum (feed end at 0)";
        ph.xlabel = "axial position (m)";
        ph.ylabel = "holdup (kg/m)";
        ph.series = {{"total", prof.column("x_m"), prof.column("holdup_kg_per_m")},
                     {"airborne", prof.column("x_m"), prof.column("airborne_kg_per_m")}};
        plotIfPossible(ph, out/"profile.png");
    }
    std::ostringstream os;
    os << std::setprecision(4) << "holdup " << r.holdupMass << " kg, airborne " << 100*r.airborneFraction
       << " %, mean residence time " << r.meanResidenceTime/60 << " min (Eq 138; network "
       << ex.mean/60 << "), RTD SD " << sm.sd()/60 << " min";
    os << measuredNote(mm);
    say(os.str());
    // every query of the run, the DRUM1 sweep's too
    writeDriftQueries(*tc.options.drift, out);
}

} // namespace drum
