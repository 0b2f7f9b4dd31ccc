// Lee 2008 Ch. 5 single-flight rig (Tables 5.1-5.5), experiments 5-16 (with
// the abrasive tip): unloading end angle psi5 (Eq 4.13), the angle psi4 when
// only the tip triangle is left (Eq 4.12), the tip-triangle mass, and the
// total mass unloaded from the tip horizontal on, each with the spread that
// phi +- 2 sigma (Lee's "95.4 %" band, App. 11.2) gives. Targets: the numbers
// an independent hand calculation gives for experiments 6, 9 and 11; the thesis prints
// the rig masses only in figures.
#include "drum/flights/angleOfRepose.hpp"
#include "drum/flights/leeFlight.hpp"
#include "drum/io/csv.hpp"
#include "drum/io/projectPaths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace
{

struct RigFlight
{
    double s1, s2, a1, a2, backRadius;   // m, m, deg, deg, m (0: flat plate)
};

std::map<std::string, RigFlight> readFlights()
{
    io::CSVReader<9, io::trim_chars<' '>, io::double_quote_escape<',', '"'>>
        in((drum::dataDir()/"lee_flights.csv").string());
    in.read_header(io::ignore_no_column, "flight", "flight_as_printed", "s1_base_length_mm",
        "s2_tip_length_mm", "alpha1_base_angle_deg", "alpha2_tip_angle_deg",
        "section_length_m", "back_plate_radius_of_curvature_m", "radius_of_curvature_as_printed");
    std::map<std::string, RigFlight> out;
    std::string name, printed, radius, radiusPrinted;
    double s1, s2, a1, a2, length;
    while (in.read_row(name, printed, s1, s2, a1, a2, length, radius, radiusPrinted))
    {
        out[name] = RigFlight{s1/1000.0, s2/1000.0, a1, a2, radius.empty() ? 0.0 : std::stod(radius)};
    }
    return out;
}

std::map<std::string, double> readConsolidatedDensity()
{
    io::CSVReader<17, io::trim_chars<' '>, io::double_quote_escape<',', '"'>>
        in((drum::dataDir()/"lee_materials.csv").string());
    in.read_header(io::ignore_extra_column, "material", "material_as_printed",
        "particle_density_kg_m3", "particle_density_err_kg_m3",
        "bulk_density_unconsolidated_kg_m3", "bulk_density_unconsolidated_err_as_printed",
        "bulk_density_consolidated_kg_m3", "bulk_density_consolidated_err_as_printed",
        "static_angle_of_repose_deg", "static_angle_ci95_deg", "dynamic_angle_of_repose_deg",
        "dynamic_angle_ci95_deg", "pct_passing_2000um", "pct_passing_1180um",
        "pct_passing_600um", "pct_passing_425um", "pct_passing_300um");
    std::map<std::string, double> out;
    std::string name, printed, e1, e2;
    double rp, rpe, ru, rc, sa, sac, da, dac, p1, p2, p3, p4, p5;
    while (in.read_row(name, printed, rp, rpe, ru, e1, rc, e2, sa, sac, da, dac,
                       p1, p2, p3, p4, p5))
    {
        out[name] = rc;
    }
    return out;
}

// One rig flight as a LeeFlight: the back plate stands in for the drum wall
// (radius R); a flat plate is a wall of very large radius. The rig has no
// neighbours: nFlights only has to pass validation, and singleFlightArea
// ignores it.
drum::LeeFlight rigFlight(const RigFlight& r, double phi)
{
    const double R = r.backRadius > 0.0 ? r.backRadius : 500.0;
    return drum::LeeFlight(drum::FlightGeometry{R, r.s1, r.s2, r.a1, r.a2, 36}, phi);
}

struct RigPrediction
{
    double psi4, psi5, triangleKg, totalKg;
};

RigPrediction predict(const RigFlight& r, double phi, double rho)
{
    const drum::LeeFlight f = rigFlight(r, phi);
    return RigPrediction{f.transitionPoints()[3], f.transitionPoints()[4],
        rho*0.5*r.s1*r.s2*std::sin(r.a2*M_PI/180.0),
        rho*f.singleFlightArea(f.curtainStartDeg())};   // 1 m section
}

} // namespace


TEST(LeeRig, EndAnglesAndMassesForExperiments5to16)
{
    const auto flights = readFlights();
    const auto rho = readConsolidatedDensity();
    const auto runs = drum::readLeeRigExperiments(drum::dataDir()/"lee_unloading_experiments.csv");
    ASSERT_EQ(flights.size(), 3u);
    ASSERT_EQ(runs.size(), 18u);

    std::printf("exp rep flight       material     phi+-sd      psi4 [deg]          psi5 [deg]"
                "          tip-triangle [kg]   unloaded from tip horizontal [kg]\n");
    int checked = 0;
    for (const auto& e : runs)
    {
        if (e.experiment < 5) continue;         // 1-4: smooth tip, not modelled by Lee
        ASSERT_TRUE(e.abrasiveTip);
        const RigFlight& fl = flights.at(e.flight);
        const double rhoB = rho.at(e.material);
        const RigPrediction mid = predict(fl, e.phiMeanDeg, rhoB);
        const RigPrediction lo = predict(fl, e.phiMeanDeg - 2.0*e.phiSdDeg, rhoB);
        const RigPrediction hi = predict(fl, e.phiMeanDeg + 2.0*e.phiSdDeg, rhoB);
        std::printf("%3d %3d %-12s %-12s %4.1f+-%4.1f  %6.1f [%5.1f,%5.1f]  %6.1f [%5.1f,%5.1f]"
                    "  %6.1f              %6.1f [%5.1f,%5.1f]\n",
                    e.experiment, e.repeat, e.flight.c_str(), e.material.c_str(), e.phiMeanDeg,
                    e.phiSdDeg, mid.psi4, lo.psi4, hi.psi4, mid.psi5, lo.psi5, hi.psi5,
                    mid.triangleKg, mid.totalKg, lo.totalKg, hi.totalKg);

        // Eq 4.13 and 4.12 shift one-for-one with phi
        EXPECT_NEAR(hi.psi5 - lo.psi5, 4.0*e.phiSdDeg, 1e-9);
        EXPECT_NEAR(hi.psi4 - lo.psi4, 4.0*e.phiSdDeg, 1e-9);
        // More material stays in a flight with a steeper surface
        EXPECT_GT(hi.totalKg, mid.totalKg);
        EXPECT_GT(mid.totalKg, lo.totalKg);
        EXPECT_GT(mid.totalKg, mid.triangleKg);

        // Mass conservation along the rig profile: unloaded = held at start
        const drum::LeeFlight f = rigFlight(fl, e.phiMeanDeg);
        double released = 0.0;
        const double a = f.curtainStartDeg();
        const double cuts[] = {a, f.transitionPoints()[3], f.transitionPoints()[4]};
        const int n = 4000;
        for (int k = 0; k < 2; ++k)   // midpoint rule on each smooth phase
        {
            const double h = (cuts[k + 1] - cuts[k])/n;
            for (int i = 0; i < n; ++i)
            {
                released -= f.singleFlightAreaSlope(cuts[k] + (i + 0.5)*h)*h*M_PI/180.0;
            }
        }
        EXPECT_NEAR(released/f.singleFlightArea(a), 1.0, 1e-7);

        // Independent hand calculation: psi4 / psi5 / tip-triangle mass (rho_b 1474)
        if (e.experiment == 11 && e.repeat == 0)
        {
            EXPECT_NEAR(mid.psi4, 175.9, 0.05);
            EXPECT_NEAR(mid.psi5, 205.7, 0.05);
            EXPECT_NEAR(mid.triangleKg, 28.9, 0.05);
            ++checked;
        }
        if (e.experiment == 9)
        {
            EXPECT_NEAR(mid.psi4, 169.7, 0.05);
            EXPECT_NEAR(mid.psi5, 199.5, 0.05);
            EXPECT_NEAR(mid.triangleKg, 7.2, 0.05);
            ++checked;
        }
        if (e.experiment == 6 && e.repeat == 0)
        {
            EXPECT_NEAR(mid.psi4, 174.0, 0.05);
            EXPECT_NEAR(mid.psi5, 209.6, 0.05);
            EXPECT_NEAR(mid.triangleKg, 19.6, 0.05);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 3);
}
