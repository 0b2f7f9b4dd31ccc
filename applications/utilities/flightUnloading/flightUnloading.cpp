// flightUnloading: Lee 2008 Ch. 4 geometric unloading of one flight design.
// Reads a YAML flight dictionary, writes the unloading profile with the
// release conditions per angle, the transition points, a summary, a PNG of the
// profile and a PNG of the drum cross-section. See README.md.
//
// Usage: flightUnloading -dict FILE [-out DIR]
#include "drum/flights/flightDictionary.hpp"
#include "drum/numerics/constants.hpp"
#include "drum/flights/unloadingModel.hpp"
#include "drum/io/csvWriter.hpp"
#include "drum/io/gnuplot.hpp"
#include "drum/io/resultsFolder.hpp"
#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>

namespace fs = std::filesystem;

namespace
{

void usage(std::ostream& os)
{
    os << "Usage: flightUnloading -dict FILE [-out DIR]\n"
          "  -dict FILE  flight dictionary (YAML; see the README beside the source)\n"
          "  -out DIR    output folder (default: flightUnloading)\n";
}

drum::Plot profilePlot(const drum::FlightCase& c, const drum::UnloadingModel& m,
                       const std::vector<drum::ReleaseConditions>& prof)
{
    drum::Plot p;
    p.title = "Flight unloading, Lee 2008 Ch. 4 (phi = " + std::to_string(c.phiDeg).substr(0, 5)
            + " deg)";
    p.xlabel = "root angle psi from the drum bottom [deg]";
    p.ylabel = "holdup [kg/m]";
    drum::PlotSeries h{"holdup H [kg/m]", {}, {}, "lines lw 2 lc rgb '#1f77b4'"};
    drum::PlotSeries d{"discharge -dH/dpsi [kg/(m rad)]", {}, {},
                       "lines lw 2 lc rgb '#d62728' axes x1y2"};
    for (const auto& r : prof)
    {
        h.x.push_back(r.psiDeg);
        h.y.push_back(r.holdup);
        d.x.push_back(r.psiDeg);
        d.y.push_back(r.discharge);
    }
    p.series = {h, d};
    p.extra.push_back("set y2label 'discharge -dH/dpsi [kg/(m rad)]'");
    p.extra.push_back("set y2tics");
    p.extra.push_back("set ytics nomirror");
    p.extra.push_back("set key center right inside opaque");
    const auto& psi = m.flight().transitionPoints();
    for (int k = 0; k < 5; ++k)
    {
        p.extra.push_back("set arrow from first " + std::to_string(psi[k])
            + ", graph 0 to first " + std::to_string(psi[k])
            + ", graph 1 nohead dt 2 lc rgb 'gray40'");
        p.extra.push_back("set label 'psi" + std::to_string(k + 1) + "' at first "
            + std::to_string(psi[k] + 1.0) + ", graph 0.96");
    }
    p.extra.push_back("set arrow from first " + std::to_string(m.flight().curtainStartDeg())
        + ", graph 0 to first " + std::to_string(m.flight().curtainStartDeg())
        + ", graph 1 nohead lc rgb 'dark-green'");
    p.extra.push_back("set label 'tip horizontal' at first "
        + std::to_string(m.flight().curtainStartDeg() + 1.0) + ", graph 0.05 tc rgb 'dark-green'");
    return p;
}

drum::Plot crossSectionPlot(const drum::FlightCase& c, const drum::UnloadingModel& m)
{
    const drum::LeeFlight& f = m.flight();
    const double R = c.geometry.drumRadius;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    drum::Plot p;
    p.title = "Drum cross-section, reference flight root at psi = "
            + std::to_string(c.snapshotAngleDeg).substr(0, 5) + " deg";
    p.xlabel = "x [m]";
    p.ylabel = "y [m]";
    p.width = 800;
    p.height = 800;
    p.extra = {"set size ratio -1", "set key top left inside opaque",
               "set xrange [" + std::to_string(-1.1*R) + ":" + std::to_string(1.1*R) + "]",
               "set yrange [" + std::to_string(-1.1*R) + ":" + std::to_string(1.1*R) + "]"};

    // Material in every flight: the clipped cell of each flight at its angle
    for (int k = 0; k < c.geometry.nFlights; ++k)
    {
        const double psi = std::fmod(c.snapshotAngleDeg + k*f.flightSpacingDeg(), 360.0);
        const drum::Polygon poly = f.materialPolygon(psi, 60);
        if (poly.size() < 3) continue;
        drum::PlotSeries s{k == 0 ? "flighted material" : "", {}, {},
                           "filledcurves closed fc rgb '#e0b050' fs solid 0.8"};
        for (const auto& q : poly) { s.x.push_back(q.x()); s.y.push_back(q.y()); }
        s.x.push_back(poly.front().x());
        s.y.push_back(poly.front().y());
        p.series.push_back(s);
    }
    drum::PlotSeries wall{"drum wall", {}, {}, "lines lw 2 lc rgb 'black'"};
    for (int i = 0; i <= 360; ++i)
    {
        wall.x.push_back(R*std::sin(i*drum::pi/180.0));
        wall.y.push_back(-R*std::cos(i*drum::pi/180.0));
    }
    p.series.push_back(wall);
    drum::PlotSeries flights{"flights", {}, {}, "lines lw 2 lc rgb '#404040'"};
    for (int k = 0; k < c.geometry.nFlights; ++k)
    {
        const double psi = c.snapshotAngleDeg + k*f.flightSpacingDeg();
        for (const auto& q : {f.rootPosition(psi), f.elbowPosition(psi), f.tipPosition(psi)})
        {
            flights.x.push_back(q.x());
            flights.y.push_back(q.y());
        }
        flights.x.push_back(nan);
        flights.y.push_back(nan);
    }
    p.series.push_back(flights);
    // Surface line of the reference flight and its vertical fall path
    const Eigen::Vector2d tip = f.tipPosition(c.snapshotAngleDeg);
    const double phi = c.phiDeg*drum::pi/180.0;
    drum::PlotSeries surf{"surface of the reference flight (phi)", {}, {},
                          "lines lw 1.5 lc rgb '#d62728'"};
    for (double t : {-0.6, 0.6})
    {
        surf.x.push_back(tip.x() + t*std::cos(phi));
        surf.y.push_back(tip.y() + t*std::sin(phi));
    }
    p.series.push_back(surf);
    const auto rc = m.at(c.snapshotAngleDeg);
    if (rc.toCurtain && rc.phase > 0 && rc.phase < 5)
    {
        drum::PlotSeries fall{"fall path from the tip", {tip.x(), tip.x()},
                              {tip.y(), rc.landingY}, "lines lw 1.5 dt 2 lc rgb '#1f77b4'"};
        p.series.push_back(fall);
    }
    return p;
}

} // namespace


int main(int argc, char** argv)
{
    fs::path dict;
    fs::path out = "flightUnloading";
    bool haveDict = false, haveOut = false;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if ((a == "-dict" && haveDict) || (a == "-out" && haveOut))
        {
            std::cerr << "flightUnloading: option " << a << " given twice: give it once\n";
            return 2;
        }
        if ((a == "-dict" || a == "-out") && i + 1 < argc)
        {
            (a == "-dict" ? haveDict : haveOut) = true;
            (a == "-dict" ? dict : out) = argv[++i];
        }
        else if (a == "-help" || a == "--help" || a == "-h")
        {
            usage(std::cout);
            return 0;
        }
        else
        {
            std::cerr << "flightUnloading: unknown or incomplete option '" << a << "'\n";
            usage(std::cerr);
            return 2;
        }
    }
    if (dict.empty())
    {
        usage(std::cerr);
        return 2;
    }

    try
    {
        // Everything is computed before anything is written
        std::cout << "Reading " << dict.string() << '\n';
        const drum::FlightCase c = drum::readFlightDictionary(dict);
        const drum::LeeFlight flight(c.geometry, c.phiDeg, dict.string());
        const drum::UnloadingModel model(flight, c.settings, dict.string());
        const auto& psi = flight.transitionPoints();
        std::cout << "  phi = " << c.phiDeg << " deg (" << c.phiSource << "), R_F = "
                  << flight.tipRadius() << " m, psi_ft = " << flight.tipOffsetDeg()
                  << " deg, psi_fl = " << flight.flightSpacingDeg() << " deg\n"
                  << "  transition points psi1..psi5 [deg]: " << psi[0] << ", " << psi[1]
                  << ", " << psi[2] << ", " << psi[3] << ", " << psi[4] << '\n';

        const double end = c.angleEndDeg >= 0.0 ? c.angleEndDeg : psi[4] + 5.0;
        const auto prof = model.profile(c.angleStartDeg, end, c.angleStepDeg);

        drum::CsvTable profile({"angle_deg", "tip_angle_deg", "phase", "to_curtain",
            "holdup_kg_per_m", "discharge_kg_per_m_per_rad", "spill_rate_kg_per_m_per_s",
            "release_x_m", "release_y_m", "fall_height_m", "fall_time_s",
            "layer_thickness_m", "layer_velocity_m_per_s"});
        for (const auto& r : prof)
        {
            profile.addRow({r.psiDeg, r.tipAngleDeg, double(r.phase), r.toCurtain ? 1.0 : 0.0,
                r.holdup, r.discharge, r.spillRate, r.releaseX, r.releaseY, r.fallHeight,
                r.fallTime, r.layerThickness, r.layerVelocity});
        }
        drum::CsvTable transitions({"phi_deg", "psi1_deg", "psi2_deg", "psi3_deg",
                                    "psi4_deg", "psi5_deg"});
        transitions.addRow({c.phiDeg, psi[0], psi[1], psi[2], psi[3], psi[4]});

        drum::CsvTable summary({"phi_deg", "tip_radius_m", "psi_ft_deg", "psi_fl_deg",
            "curtain_start_deg", "max_holdup_kg_per_m", "design_flight_holdup_kg_per_m",
            "mean_release_angle_deg", "mean_fall_height_m", "mean_fall_time_s",
            "design_load_kg", "porter_design_load_kg", "flight_length_m",
            "curtain_flow_kg_s", "bed_filled_load_kg", "passive_time_eq34_s",
            "passive_time_eq421_s", "passive_time_bed_filled_s"});
        // passive times: Eq 3.4; Eq 4.21's load and the bed-filled load (flights
        // full from the drum bottom) over the flights' curtain flow (Little's law)
        const double flow = model.curtainFlow();
        const double bedFilled = model.bedFilledLoad(0.0);
        summary.addRow({c.phiDeg, flight.tipRadius(), flight.tipOffsetDeg(),
            flight.flightSpacingDeg(), flight.curtainStartDeg(), model.maxHoldup(),
            model.designFlightHoldup(), model.meanReleaseAngleDeg(), model.meanFallHeight(),
            model.meanFallTime(), model.designLoad(), model.porterDesignLoad(),
            c.settings.flightLength, flow, bedFilled,
            (2.0*model.meanReleaseAngleDeg() - 180.0)*drum::deg/model.omega(),
            model.designLoad()/flow, bedFilled/flow});

        drum::Plot pProfile, pSection;
        if (c.plots)
        {
            if (!drum::gnuplotAvailable())
            {
                throw std::runtime_error("gnuplot not found (install gnuplot-nox, "
                                         "or set output.plots: false)");
            }
            pProfile = profilePlot(c, model, prof);
            pSection = crossSectionPlot(c, model);
        }

        // a fresh folder that replaces the output folder only when complete
        drum::ResultsFolder results(drum::ownOutputFolder(out, "-out"));
        const fs::path finalOut = out;
        out = results.path();
        profile.write(out/"unloadingProfile.csv");
        std::cout << "Wrote " << (finalOut/"unloadingProfile.csv").string() << " (" << prof.size()
                  << " angles)\n";
        transitions.write(out/"transitionPoints.csv");
        std::cout << "Wrote " << (finalOut/"transitionPoints.csv").string() << '\n';
        summary.write(out/"flightSummary.csv");
        std::cout << "Wrote " << (finalOut/"flightSummary.csv").string() << '\n';
        if (c.plots)
        {
            drum::writePng(pProfile, out/"unloadingProfile.png");
            std::cout << "Wrote " << (finalOut/"unloadingProfile.png").string() << '\n';
            drum::writePng(pSection, out/"crossSection.png");
            std::cout << "Wrote " << (finalOut/"crossSection.png").string() << '\n';
        }
        for (const auto& f : results.commit())
        {
            std::cout << "Kept your file " << (finalOut/f).string() << '\n';
        }
        out = finalOut;
        std::cout << "  max holdup " << model.maxHoldup() << " kg/m, at tip horizontal "
                  << model.designFlightHoldup() << " kg/m, mean release angle "
                  << model.meanReleaseAngleDeg() << " deg, design load (Eq 4.21) "
                  << model.designLoad() << " kg, Porter (Eq 4.19) " << model.porterDesignLoad()
                  << " kg\n";
    }
    catch (const drum::InputError& e)
    {
        std::cerr << "flightUnloading: input error: " << e.what() << '\n';
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "flightUnloading: error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
