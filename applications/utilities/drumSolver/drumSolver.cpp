// drumSolver -case DIR: solids transport through a flighted rotary drum from
// the case dictionary DIR/drumDict (README.md beside this file documents
// every entry). Models:
//   compartment  Lee/Sheehan slice network (Lee 2008 Ch. 3, App. 10.2) with
//                Lee's App. 10.2.3 correlations; steady holdup profile and
//                the tracer RTD (exact / implicit / explicit integration);
//                optional least-squares estimation from a measured curve,
//                optional passive-phase dispersion (compartmentDispersion.hpp)
//   twoPhase     Sherritt (1991) airborne/dense model, axial (DRUM3) solve:
//                holdup, airborne fraction, mean residence time (Eq 138),
//                per size class (Eq 139), and the RTD of its tracer network
//                (twoPhaseTracer.hpp), optional dense-phase dispersion
// Writes DIR/results/{summary,rtd,profile}.csv (+ estimation.csv, classes.csv) and PNGs,
// each file whole or not at all.
#include "drumDict.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/drift/driftModel.hpp"
#include "drum/flights/sherrittFlightShapes.hpp"
#include "drum/io/atomicFile.hpp"
#include "drum/io/csv.hpp"
#include "drum/io/csvWriter.hpp"
#include "drum/io/gnuplot.hpp"
#include "drum/io/resultsFolder.hpp"
#include "drum/io/inputError.hpp"
#include "drum/transport/compartmentLeeEstimation.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/rtd/rtdSimulation.hpp"
#include "drum/transport/compartmentDispersion.hpp"
#include "drum/transport/compartmentFlightModel.hpp"
#include "drum/transport/compartmentLeeDryer.hpp"
#include "drum/transport/axialDispersion.hpp"
#include "drum/transport/twoPhaseModel.hpp"
#include "drum/transport/twoPhaseTracer.hpp"
#include "drum/drift/porousSheetDrift.hpp"
#include "drum/flights/sherrittFlightSpec.hpp"

#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <limits>

namespace fs = std::filesystem;
using namespace drumSolver;

namespace
{

const double nan = std::numeric_limits<double>::quiet_NaN();

void say(const std::string& s)
{
    std::cout << "drumSolver: " << s << std::endl;
}

struct Measured
{
    std::vector<double> t, E;   // s, 1/s
};

Measured readTracer(const TracerFile& tf)
{
    Measured m;
    try
    {
        io::CSVReader<2, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(tf.file.string());
        in.read_header(io::ignore_extra_column, tf.timeColumn, tf.eColumn);
        double t, e;
        while (in.read_row(t, e))
        {
            m.t.push_back(t*tf.timeScale);
            m.E.push_back(e*tf.eScale);
        }
    }
    catch (const io::error::base& e)
    {
        throw drum::InputError(tf.file.string(), "rtd.tracer", e.what());
    }
    if (m.t.size() < 3)
    {
        throw drum::InputError(tf.file.string(), "rtd.tracer", "needs at least 3 rows");
    }
    return m;
}

drum::LeeDryer leeDryer(const DrumDict& d)
{
    drum::LeeDryer l;
    l.length = d.length;
    l.rpm = d.speedRpm;
    l.slopeDeg = d.slopeDeg;
    l.feedRate = d.feedRate;
    l.bulkDensity = d.bulkDensity;
    l.geometry.drumRadius = d.diameter/2;
    l.geometry.baseLength = d.baseLength;
    l.geometry.tipLength = d.tipLength;
    l.geometry.baseAngleDeg = d.baseAngleDeg;
    l.geometry.tipAngleDeg = d.tipAngleDeg;
    l.geometry.nFlights = d.flightCount;
    if (d.reposeDeg)
    {
        l.constantPhiDeg = *d.reposeDeg;
    }
    else
    {
        l.moistureInlet = d.moisture->first;
        l.moistureOutlet = d.moisture->second;
    }
    l.designLoadMultiplier = d.designLoadMultiplier;
    return l;
}

void plotIfPossible(const drum::Plot& p, const fs::path& file)
{
    if (!drum::gnuplotAvailable())
    {
        say("gnuplot not on PATH: " + file.filename().string() + " not drawn");
        return;
    }
    drum::writePng(p, file);
}

// summary.csv: the model's columns, then the measured tracer's moments
// (trapezoid on its sampling) when the case names a tracer file; returns them
std::optional<drum::RtdMoments> writeSummary
(
    std::vector<std::string> cols,
    std::vector<double> row,
    const std::optional<Measured>& measured,
    const fs::path& out
)
{
    std::optional<drum::RtdMoments> mm;
    if (measured)
    {
        mm = drum::sampledMoments(measured->t, measured->E);
        cols.insert(cols.end(), {"measured_mean_s", "measured_std_s", "measured_skewness"});
        row.insert(row.end(), {mm->mean, mm->sd(), mm->skewness});
    }
    drum::CsvTable summary(cols);
    summary.addRow(row);
    summary.write(out/"summary.csv");
    return mm;
}

// " (measured mean / SD min)" for the progress line, empty without a tracer
std::string measuredNote(const std::optional<drum::RtdMoments>& mm)
{
    if (!mm) return {};
    std::ostringstream os;
    os << std::setprecision(4) << " (measured " << mm->mean/60 << " / " << mm->sd()/60 << " min)";
    return os.str();
}

// rtd.csv and the linear and log RTD plots against the measured points
void writeRtdOutputs
(
    const DrumDict& d,
    const std::vector<double>& time,
    const std::vector<double>& E,
    const std::optional<Measured>& measured,
    const std::string& modelLabel,
    const fs::path& out
)
{
    drum::CsvTable r({"time_s", "E_per_s", "F_cumulative"});
    double F = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
    {
        if (i > 0) F += 0.5*(time[i] - time[i - 1])*(E[i] + E[i - 1]);
        r.addRow({time[i], E[i], F});
    }
    r.write(out/"rtd.csv");

    drum::Plot pr;
    pr.title = "Residence-time distribution";
    pr.xlabel = "time after pulse start (min)";
    pr.ylabel = "E(t) (1/min)";
    drum::PlotSeries model{modelLabel, {}, {}};
    for (std::size_t i = 0; i < time.size(); ++i)
    {
        model.x.push_back(time[i]/60);
        model.y.push_back(E[i]*60);
    }
    pr.series.push_back(model);
    if (measured)
    {
        std::string name = d.tracer->file.filename().string();
        for (char& ch : name) if (ch == '_') ch = ' ';   // gnuplot enhanced text
        drum::PlotSeries meas{"measured (" + name + ")", {}, {}, "points pt 7 ps 1.2"};
        for (std::size_t i = 0; i < measured->t.size(); ++i)
        {
            if (measured->t[i] < 0) continue;
            meas.x.push_back(measured->t[i]/60);
            meas.y.push_back(measured->E[i]*60);
        }
        pr.series.push_back(meas);
    }
    plotIfPossible(pr, out/"rtd.png");
    // The tail on a log scale (positive values only)
    drum::Plot lg = pr;
    lg.logy = true;
    lg.title = "Residence-time distribution (log scale: the tail)";
    for (drum::PlotSeries& se : lg.series)
    {
        drum::PlotSeries keep{se.title, {}, {}, se.style};
        for (std::size_t i = 0; i < se.x.size(); ++i)
        {
            if (se.y[i] > 1e-7) { keep.x.push_back(se.x[i]); keep.y.push_back(se.y[i]); }
        }
        se = keep;
    }
    plotIfPossible(lg, out/"rtd_log.png");
}

void runCompartmentWith
(
    const DrumDict& d,
    const drum::LeeDryer& dryer,
    const drum::LeeParameters& p,
    const drum::StagnantExchange& stagnant,
    const std::optional<Measured>& measured,
    const fs::path& out
)
{
    std::vector<drum::LeeSliceData> data;
    if (d.partition == "flightModel")
    {
        const particleDrag::Gas air = particleDrag::Gas::air(d.gasTemperatureC);
        drum::FlightModelPartition fp;
        fp.drift = drum::makeDriftModel(d.driftSettings, air, {}, "model.drift");
        // Mean gas velocity over the free cross-section (holdup neglected)
        fp.gasVelocity = d.gasMassRate/(air.density*drum::pi*d.diameter*d.diameter/4);
        fp.counterCurrent = d.counterCurrent;
        for (double s : d.sizes) fp.sizes.push_back(s*d.sphericity);
        fp.fractions = d.fractions;
        fp.particleDensity = d.particleDensity;
        fp.flightAxialLength = d.flightAxialLength;
        say("slice parameters from Lee's flight model and the " + d.drift + " drift model (V_g "
          + std::to_string(fp.gasVelocity) + " m/s)");
        data = drum::flightModelSliceData(dryer, d.slices, fp);
        if (const std::string note = fp.drift->summary(); !note.empty())
        {
            say(note);
        }
    }
    else
    {
        data = drum::leeSliceData(dryer, d.slices, p);
    }
    std::vector<drum::CompartmentSlice> slices;
    for (const auto& s : data) slices.push_back(s.slice);
    const drum::CompartmentNetwork net(slices, dryer.feedRate, p.kilnTime);
    say("steady state of " + std::to_string(d.slices) + " slices");
    const drum::CompartmentSteadyState st = net.steadyState();
    // Passive-phase axial dispersion (none, a value, or Sherritt 2001 Eq 51
    // per slice with X from the slice's bed mass): a symmetric exchange
    // between neighbouring passive cells (compartmentDispersion.hpp)
    drum::PassiveDispersion disp;
    disp.sliceLength = d.length/d.slices;
    disp.subtractNumerical = d.subtractNumericalDispersion;
    if (d.denseDispersion != "none")
    {
        disp.bed = drum::parseDispersionBed(d.dispersionBed, "model.dispersionBed", d.path.string());
    }
    std::vector<double> dispersionFill;
    if (d.denseDispersion == "value")
    {
        disp.coefficient = {d.denseDispersionValue};
    }
    else if (d.denseDispersion == "sherritt2001")
    {
        drum::PassiveDispersionDrum pd;
        pd.drumDiameter = d.diameter;
        pd.speed = d.speedRpm/60;
        pd.particleDiameter = drum::dispersionParticleDiameter(d.sizes, d.fractions, d.sphericity);
        pd.bulkDensity = dryer.bulkDensity;
        pd.sliceLength = disp.sliceLength;
        const drum::PassiveSherritt2001 sz = drum::sherritt2001PassiveDispersion(st, disp.bed, pd, d.path.string());
        say("passive dispersion " + sz.note);
        for (const std::string& w : sz.warnings)
        {
            say("warning: passive dispersion: " + w);
        }
        disp.coefficient = sz.coefficient;
        dispersionFill = sz.fill;
    }
    drum::PassiveDispersionSummary ds;
    const drum::TracerSystem sys = drum::withPassiveDispersion(net.tracerSystem(st, stagnant), st, disp, &ds,
        d.path.string());
    if (!disp.coefficient.empty())
    {
        std::ostringstream w;
        w << "passive dispersion (" << drum::toString(disp.bed) << " bed) at " << ds.boundaries
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
    const double stagnantKg = stagnant.massRatio*st.passiveMass.sum();
    const double holdup = st.totalHoldup() + stagnantKg;

    {
        std::ostringstream os;
        os << "tracer RTD (" << drum::toString(d.rtd.integrator) << ", step " << d.rtd.timeStep << " s)";
        say(os.str());
    }
    drum::RtdOptions opt = d.rtd;
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
    const drum::RtdResult rtd = drum::simulateRtd(sys, opt);
    for (const std::string& w : rtd.warnings)
    {
        say("warning: " + w);
    }
    const drum::RtdMoments sm = drum::sampledMoments(rtd.time, rtd.E);
    const drum::RtdMoments ex = drum::exactMoments(sys, d.rtd.pulseDuration);

    // summary.csv
    std::vector<std::string> cols = {"holdup_kg", "airborne_fraction", "mean_residence_time_s", "rtd_std_s",
        "rtd_skewness", "rtd_recovered", "exact_mean_s", "exact_std_s", "holdup_over_feed_s",
        "design_load_kg", "kiln_mass_kg", "kiln_time_s", "back_fraction", "forward_drag_factor", "slices",
        "stagnant_kg", "exchange_time_s", "dense_dispersion_m2_s", "numerical_dispersion_m2_s",
        "added_dispersion_m2_s"};
    double design = 0;
    for (const auto& s : data) design += s.slice.designLoad;
    std::vector<double> row = {holdup, st.activeMass.sum()/holdup, sm.mean, sm.sd(), sm.skewness,
        rtd.recovered, ex.mean, ex.sd(), holdup/d.feedRate, design, st.kilnMass.sum(),
        p.kilnTime,
        d.partition == "flightModel" ? data[0].slice.backFraction : p.backFraction,
        d.partition == "flightModel" ? nan : p.dragFactor, double(d.slices),
        stagnantKg, stagnant.massRatio > 0 ? stagnant.exchangeTime : nan,
        disp.coefficient.empty() ? 0.0 : ds.meanCoefficient, disp.coefficient.empty() ? nan : ds.meanNumerical,
        disp.coefficient.empty() ? 0.0 : ds.meanAdded};
    const std::optional<drum::RtdMoments> mm = writeSummary(cols, row, measured, out);

    drum::CsvTable prof({"slice", "x_m", "phi_deg", "design_load_kg", "passive_kg", "active_kg", "kiln_kg",
        "holdup_kg_per_m", "release_kg_s", "kiln_flow_kg_s", "forward_kg_s", "back_kg_s", "return_kg_s",
        "passive_time_s", "fall_time_s", "fall_height_m", "C_F", "C_B", "dispersion_fill", "dense_dispersion_m2_s"});
    const double dL = d.length/d.slices;
    for (int i = 0; i < d.slices; ++i)
    {
        const auto& s = data[i];
        prof.addRow({double(i + 1), (i + 0.5)*dL, s.phiDeg, s.slice.designLoad, st.passiveMass(i),
            st.activeMass(i), st.kilnMass(i), (st.passiveMass(i) + st.activeMass(i))/dL,
            st.releaseFlow(i), st.kilnFlow(i), st.forwardFlow(i), st.backFlow(i), st.returnFlow(i),
            s.slice.passiveTime, s.slice.activeTime, s.correlations.fallHeight,
            s.slice.forwardFraction, s.slice.backFraction,
            dispersionFill.empty() ? nan : dispersionFill[i],
            disp.coefficient.empty() ? 0.0 : disp.coefficient.size() == 1 ? disp.coefficient[0] : disp.coefficient[i]});
    }
    prof.write(out/"profile.csv");

    writeRtdOutputs(d, rtd.time, rtd.E, measured,
        "compartment model (" + std::to_string(d.slices) + " slices)", out);

    drum::Plot ph;
    ph.title = "Holdup along the drum (feed end at 0)";
    ph.xlabel = "axial position (m)";
    ph.ylabel = "mass per slice (kg)";
    drum::PlotSeries ps{"passive", prof.column("x_m"), prof.column("passive_kg")};
    drum::PlotSeries pa{"active (airborne)", prof.column("x_m"), prof.column("active_kg")};
    drum::PlotSeries pd{"design load", prof.column("x_m"), prof.column("design_load_kg"), "lines lw 2 dt 2"};
    ph.series = {ps, pa, pd};
    plotIfPossible(ph, out/"profile.png");

    std::ostringstream os;
    os << std::setprecision(4) << "holdup " << holdup << " kg, airborne " << 100*st.activeMass.sum()/holdup
       << " %, mean residence time " << sm.mean/60 << " min, SD " << sm.sd()/60 << " min";
    os << measuredNote(mm);
    say(os.str());
}

void runCompartment(const DrumDict& d, const fs::path& out)
{
    const drum::LeeDryer dryer = leeDryer(d);
    const drum::LeeFlightGeometry invicta;
    if (d.partition == "leeCorrelations"
     && (std::abs(dryer.geometry.tipRadius() - invicta.tipRadius()) > 1e-3 || d.flightCount != invicta.nFlights))
    {
        say("warning: Lee's correlations were regressed for the Invicta flights "
            "(D 5 m, 28 flights, s1 0.195, s2 0.183, alpha2 117 deg); this geometry differs");
    }
    drum::LeeParameters p{d.kilnTime, d.backFraction, d.dragFactor};

    std::optional<Measured> measured;
    if (d.tracer)
    {
        measured = readTracer(*d.tracer);
    }

    if (!d.estimate.empty())
    {
        say("estimating " + std::to_string(d.estimate.size()) + " parameters from "
          + d.tracer->file.filename().string() + " (" + std::to_string(d.starts) + " starts)");
        std::vector<double> t, E;
        for (std::size_t i = 0; i < measured->t.size(); ++i)
        {
            if (measured->t[i] >= 0) { t.push_back(measured->t[i]); E.push_back(measured->E[i]*3600.0); }
        }
        std::vector<drum::FitParameter> fp;
        for (const std::string& n : d.estimate)
        {
            if (n == "kilnTime") fp.push_back({n, d.kilnTime, 0.01, 1e30});
            else if (n == "backFraction") fp.push_back({n, d.backFraction, 0.0, 1.0});
            else if (n == "dragFactor") fp.push_back({n, d.dragFactor, 0.0, 100.0});
            else if (n == "forwardShare") fp.push_back({n, 0.5, 0.0, 1.0});
            else if (n == "stagnantRatio") fp.push_back({n, d.stagnantRatio, 0.0, 10.0});
            else if (n == "exchangeTime") fp.push_back({n, d.exchangeTime, 1.0, 1e6});
            else fp.push_back({n, d.designLoadMultiplier, 0.05, 20.0});
        }
        const drum::RtdObjective objective{d.logObjective, d.logOffset};
        const drum::StagnantExchange stagnant0{d.stagnantRatio, d.exchangeTime};
        const drum::PredictionModel model = drum::leeRtdModel(dryer, d.slices, p, d.estimate,
            d.rtd.pulseDuration, t, stagnant0, objective);
        const std::vector<drum::FitResult> runs = drum::multiStartFit(model,
            drum::transformForObjective(E, objective), fp, d.starts);
        if (runs.empty())
        {
            throw drum::InputError(d.path.string(), "estimation", "no start gave a feasible fit");
        }
        const drum::FitResult& best = runs.front();
        drum::LeeDryer mod = dryer;
        p = drum::leeParametersFrom(dryer, d.slices, p, d.estimate, best.values, &mod);
        const drum::StagnantExchange zFit = drum::stagnantFrom(stagnant0, d.estimate, best.values);
        drum::AtomicFile f(out/"estimation.csv");
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
        os << std::setprecision(4) << "best fit (SSE " << best.sse << (d.logObjective ? " in ln E" : " h^-2") << "): t_kiln " << p.kilnTime
           << " s, C_B " << p.backFraction << ", C_F^G " << p.dragFactor
           << ", design-load multiplier " << mod.designLoadMultiplier
           << ", stagnant M_s/M_p " << zFit.massRatio << " exchanging in " << zFit.exchangeTime << " s"
           << "; worst start SSE " << runs.back().sse;
        say(os.str());
        return runCompartmentWith(d, mod, p, zFit, measured, out);
    }
    runCompartmentWith(d, dryer, p, {d.stagnantRatio, d.exchangeTime}, measured, out);
}

} // namespace

namespace
{

// The two-phase case of a dictionary (drum, flights, material, gas, model)
drum::TwoPhaseCase twoPhaseCase(const DrumDict& d)
{
    if (!d.reposeDeg)
    {
        throw drum::InputError(d.path.string(), "material.repose_deg",
            "model twoPhase needs a constant kinetic angle of repose (deg, (0, 90])");
    }
    drum::TwoPhaseCase c;
    c.name = d.path.string();
    c.drum.shellDiameter = d.diameter;
    c.drum.length = d.length;
    c.drum.slope = d.slopeDeg*drum::pi/180;
    c.drum.speed = d.speedRpm/60;
    c.drum.centrefillDiameter = d.centrefillDiameter;
    const double step = d.flightTableStepDeg*drum::pi/180;
    if (d.exteriorFlight)
    {
        say("tabulating the " + drum::toString(d.exteriorFlight->type) + " exterior flight (Sherritt's horizontal-length table)");
        c.exterior = drum::buildSherrittFlight(*d.exteriorFlight, drum::FlightSide::exterior, d.diameter,
            d.flightAxialLength, step, d.path.string());
        if (d.interiorFlight)
        {
            c.interior = drum::buildSherrittFlight(*d.interiorFlight, drum::FlightSide::interior, d.diameter,
                d.flightAxialLength, step, d.path.string());
        }
    }
    else
    {
        say("tabulating the two-section flight (Sherritt's horizontal-length table)");
        drum::SherrittFlightSpec f;
        f.count = d.flightCount;
        f.baseLength = d.baseLength;
        f.tipLength = d.tipLength;
        f.tipAngle = d.tipAngleDeg*drum::pi/180;
        f.baseAngle = d.baseAngleDeg*drum::pi/180;
        c.exterior = drum::buildSherrittFlight(f, drum::FlightSide::exterior, d.diameter, d.flightAxialLength,
            step, d.path.string());
    }
    c.material.particleDensity = d.particleDensity;
    c.material.bulkDensity = d.bulkDensity;
    c.material.repose = *d.reposeDeg*drum::pi/180;
    c.material.sphericity = d.sphericity;
    c.material.sieveSizes = d.sizes;
    c.material.massFractions = d.fractions;
    c.gas.massRate = d.gasMassRate;
    c.gas.temperatureC = d.gasTemperatureC;
    c.gas.direction = d.counterCurrent ? drum::GasFlow::countercurrent : drum::GasFlow::cocurrent;
    c.options.drift = drum::makeDriftModel(d.driftSettings, particleDrag::Gas::air(d.gasTemperatureC), {}, "model.drift");
    c.options.imposedDenseFlow = d.imposedDenseFlow;
    c.options.axialSteps = d.axialSteps;
    return c;
}

void runTwoPhase(const DrumDict& d, const fs::path& out)
{
    const drum::TwoPhaseCase c = twoPhaseCase(d);
    std::optional<Measured> measured;
    if (d.tracer)
    {
        measured = readTracer(*d.tracer);
    }
    say(std::string("two-phase model (Sherritt 1991), axial solve")
        + (d.imposedDenseFlow ? " with the dense flow imposed" : ""));
    const drum::TwoPhaseModel model(c);
    drum::AxialOptions ax;
    if (d.dischargeEndAngleDeg)
    {
        ax.dischargeEndAngle = *d.dischargeEndAngleDeg*drum::pi/180;
    }
    const drum::TwoPhaseResult r = model.solveAxial(d.feedRate, ax);
    if (const std::string note = c.options.drift->summary(); !note.empty())
    {
        say(note);
    }
    if (r.cappedLength > 0)
    {
        std::ostringstream os;
        os << "warning: the bed slope is held at the cap phi over " << r.cappedLength << " of " << d.length
           << " m next to the discharge end (Eq 135 asks for more): there Eq 79 does not carry the dense flow of Eq 55";
        say(os.str());
    }

    // DRUM1 (constant holdup, Sherritt's driver for Sheikh, Kelly, O'Donnell
    // and Saeman): the theta_i sweep and every root F0(theta_i) = feed
    // (Sherritt 1991 §5.1: overloaded drums can have several)
    drum::CsvTable sweepTable({"theta_i_deg", "regime", "valid", "feed_kg_s", "holdup_kg", "airborne_kg",
        "discharging_kg", "nondischarging_kg", "airborne_holdup_fraction", "airborne_flow_fraction"});
    const double kgPerM = d.bulkDensity*d.length;
    for (double t = std::ceil(model.minDischargeAngle()*180/drum::pi); t <= model.finalDischargeAngle()*180/drum::pi + 1e-9; t += 1)
    {
        const drum::TwoPhaseState st = model.atDischargeAngle(t*drum::pi/180);
        sweepTable.addRow({t, double(static_cast<int>(st.regime)), st.valid ? 1.0 : 0.0,
            st.valid ? st.feedRate : nan, st.holdup*kgPerM, st.airborneHoldup*kgPerM,
            st.dischargingHoldup*kgPerM, st.nonDischargingHoldup*kgPerM, st.airborneHoldup/st.holdup,
            st.valid ? st.airborneFlow/st.feedRate : nan});
    }
    drum::CsvTable rootTable({"theta_i_deg", "regime", "holdup_kg", "airborne_fraction", "mean_residence_time_s",
        "airborne_flow_kg_s", "dense_flow_kg_s"});
    try
    {
        const std::vector<drum::TwoPhaseResult> roots = model.solveConstantHoldup(d.feedRate);
        std::ostringstream os;
        os << std::setprecision(4) << "DRUM1 (constant holdup) has " << roots.size() << " root"
           << (roots.size() > 1 ? "s" : "") << " for " << d.feedRate << " kg/s:";
        for (const auto& q : roots)
        {
            os << " theta_i " << q.dischargeAngle*180/drum::pi << " deg (" << drum::loadingRegimeName(q.regime)
               << ", " << q.holdup_kg << " kg, airborne " << 100*q.airborne_fraction << " %);";
            rootTable.addRow({q.dischargeAngle*180/drum::pi, double(static_cast<int>(q.regime)), q.holdup_kg,
                q.airborne_fraction, q.meanResidenceTime, q.airborneFlow, q.denseFlow});
        }
        say(os.str());
    }
    catch (const drum::InputError& e)
    {
        say(std::string("DRUM1 (constant holdup): no root: ") + e.what());
    }

    // Dense-phase axial dispersion (none, a value, or Sherritt 2001 Eq 51 by
    // regime with X the mean dense holdup over the drum cross-section)
    drum::TwoPhaseTracerOptions to;
    if (d.slicesGiven)
    {
        to.slices = d.slices;
    }
    std::string dispersionNote = "none";
    if (d.denseDispersion == "value")
    {
        to.denseDispersion = d.denseDispersionValue;
        dispersionNote = "given";
    }
    else if (d.denseDispersion == "sherritt2001")
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
        drum::AxialDispersionInput in;
        in.drumDiameter = d.diameter;
        in.speed = d.speedRpm/60;
        in.particleDiameter = drum::dispersionParticleDiameter(d.sizes, d.fractions, d.sphericity);
        in.fill = drum::bedFillFraction(sumZ > 0 ? denseH/sumZ : 0.0, d.diameter);
        const drum::AxialDispersionResult dz = drum::sherritt2001AxialDispersion(in, d.path.string());
        to.denseDispersion = dz.Dz;
        dispersionNote = drum::describeAxialDispersion(dz, in);
        say("dense dispersion " + dispersionNote);
        for (const std::string& w : dz.warnings)
        {
            say("warning: dense dispersion: " + w);
        }
    }
    const drum::TwoPhaseTracerNetwork net = drum::twoPhaseTracerNetwork(model, r, to);
    {
        std::ostringstream os;
        os << "tracer network: " << net.slices << " slices of " << net.sliceLength << " m"
           << (net.slicesClamped ? " (automatic slicing clamped to [20, 400])" : "")
           << ", " << drum::toString(d.rtd.integrator) << " RTD with step " << d.rtd.timeStep << " s";
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
    std::vector<double> time, E;
    double recovered = 0;
    std::vector<drum::RtdMoments> classMoments(net.classSystems.size());
    for (std::size_t k = 0; k < net.classSystems.size(); ++k)
    {
        const double x = net.feedFractions[k];
        if (!(x > 0))
        {
            continue;
        }
        const drum::RtdResult rk = drum::simulateRtd(net.classSystems[k], d.rtd);
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
        classMoments[k] = drum::exactMoments(net.classSystems[k], d.rtd.pulseDuration);
    }
    const drum::RtdMoments sm = drum::sampledMoments(time, E);
    const drum::RtdMoments ex = drum::exactMoments(net.system, d.rtd.pulseDuration);

    // the leading columns are those of the compartment model
    std::vector<std::string> cols = {"holdup_kg", "airborne_fraction", "mean_residence_time_s",
        "rtd_std_s", "rtd_skewness", "rtd_recovered", "exact_mean_s", "exact_std_s", "holdup_over_feed_s",
        "rtd_mean_s", "airborne_flow_kg_s", "dense_flow_kg_s", "discharge_angle_deg", "slices", "dense_dispersion_m2_s",
        "numerical_dispersion_m2_s", "capped_slope_length_m"};
    std::vector<double> row = {r.holdup_kg, r.airborne_fraction, r.meanResidenceTime,
        sm.sd(), sm.skewness, recovered, ex.mean, ex.sd(), r.holdup_kg/d.feedRate, sm.mean,
        r.airborneFlow, r.denseFlow, r.dischargeAngle*180/drum::pi, double(net.slices), to.denseDispersion,
        net.numericalDenseDispersion, r.cappedLength};
    const std::optional<drum::RtdMoments> mm = writeSummary(cols, row, measured, out);

    drum::CsvTable cls({"size_um", "feed_fraction", "holdup_fraction", "T_eq139_s", "network_mean_s", "network_std_s"});
    for (std::size_t k = 0; k < d.sizes.size(); ++k)
    {
        cls.addRow({d.sizes[k]*1e6, net.feedFractions[k], r.holdupFractions[k], r.sizeResidenceTimes[k],
            net.feedFractions[k] > 0 ? classMoments[k].mean : nan, net.feedFractions[k] > 0 ? classMoments[k].sd() : nan});
    }
    cls.write(out/"classes.csv");

    drum::CsvTable prof({"x_m", "discharge_angle_deg", "holdup_kg_per_m", "airborne_kg_per_m",
        "airborne_flow_kg_s", "dense_flow_kg_s", "bed_slope_deg"});
    for (auto it = r.profile.rbegin(); it != r.profile.rend(); ++it)
    {
        prof.addRow({d.length - it->distanceFromDischarge, it->dischargeAngle*180/drum::pi,
            it->holdup*d.bulkDensity, it->airborneHoldup*d.bulkDensity,
            it->airborneFlow, it->denseFlow, it->bedSlope*180/drum::pi});
    }
    prof.write(out/"profile.csv");
    sweepTable.write(out/"sweep.csv");
    rootTable.write(out/"roots.csv");
    writeRtdOutputs(d, time, E, measured, "two-phase network (" + std::to_string(net.slices) + " slices)", out);
    if (!r.profile.empty())
    {
        drum::Plot ph;
        ph.title = "Two-phase holdup along the drum (feed end at 0)";
        ph.xlabel = "axial position (m)";
        ph.ylabel = "holdup (kg/m)";
        ph.series = {{"total", prof.column("x_m"), prof.column("holdup_kg_per_m")},
                     {"airborne", prof.column("x_m"), prof.column("airborne_kg_per_m")}};
        plotIfPossible(ph, out/"profile.png");
    }
    std::ostringstream os;
    os << std::setprecision(4) << "holdup " << r.holdup_kg << " kg, airborne " << 100*r.airborne_fraction
       << " %, mean residence time " << r.meanResidenceTime/60 << " min (Eq 138; network "
       << ex.mean/60 << "), RTD SD " << sm.sd()/60 << " min";
    os << measuredNote(mm);
    say(os.str());
}

} // namespace


int main(int argc, char* argv[])
{
    fs::path caseDir;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "-case") == 0 && i + 1 < argc)
        {
            caseDir = argv[++i];
        }
        else if (std::strcmp(argv[i], "-help") == 0 || std::strcmp(argv[i], "--help") == 0)
        {
            std::cout << "Usage: drumSolver -case DIR\n"
                         "  reads DIR/drumDict (YAML), writes DIR/results/\n";
            return 0;
        }
        else
        {
            std::cerr << "drumSolver: unknown argument '" << argv[i] << "'\nUsage: drumSolver -case DIR\n";
            return 2;
        }
    }
    if (caseDir.empty())
    {
        caseDir = ".";
    }
    DrumDict d;
    // errors name the results folder, not the hidden one a run writes into
    std::string partial, target;
    const auto named = [&](std::string msg)
    {
        for (std::size_t at; !partial.empty() && (at = msg.find(partial)) != std::string::npos;)
        {
            msg.replace(at, partial.size(), target);
        }
        return msg;
    };
    try
    {
        say("reading " + (caseDir/"drumDict").string());
        d = readDrumDict(caseDir);
        // outputs go to a fresh folder that replaces results/ only when complete
        drum::ResultsFolder results(caseDir/"results");
        const fs::path& out = results.path();
        partial = out.string();
        target = results.target().string();
        if (d.model == "compartment")
        {
            runCompartment(d, out);
        }
        else
        {
            runTwoPhase(d, out);
        }
        const auto kept = results.commit();
        for (const auto& f : kept)
        {
            say("kept your file " + (results.target()/f).string());
        }
        say("results in " + results.target().string());
    }
    catch (const drum::InputError& e)
    {
        // Model-level errors carry no file: this dictionary is where to fix them
        std::cerr << "drumSolver: input error: "
                  << (e.file().empty() ? (caseDir/"drumDict").string() + ": " : std::string())
                  << named(e.what()) << std::endl;
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "drumSolver: error: " << named(e.what()) << " (results/ left as it was)" << std::endl;
        return 1;
    }
    return 0;
}
