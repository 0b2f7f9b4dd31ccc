// Lee 2008 Table 4.2: transition points of the Invicta flight (Table 4.1) at
// phi = 30 and 60 deg, every row of lee_transition_points.csv to 0.1 deg.
#include "drum/flights/leeFlight.hpp"
#include "drum/io/csv.hpp"
#include "drum/io/projectPaths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

TEST(LeeTable42, TransitionPointsReproduced)
{
    io::CSVReader<15> in((drum::dataDir()/"lee_transition_points.csv").string());
    in.read_header(io::ignore_no_column, "D_m", "R_m", "s1_m", "s2_m", "alpha1_deg",
        "alpha2_deg", "N_flights", "phi_deg", "transition_point", "psi_reported_deg",
        "psi_recomputed_deg", "equation", "R_F_m", "psi_ft_deg", "psi_fl_deg");
    double D, R, s1, s2, a1, a2, nf, phi, reported, recomputed, rf, psift, psifl;
    std::string which, equation;
    int rows = 0;
    while (in.read_row(D, R, s1, s2, a1, a2, nf, phi, which, reported, recomputed,
                       equation, rf, psift, psifl))
    {
        const drum::LeeFlight f(drum::FlightGeometry{R, s1, s2, a1, a2, int(nf)}, phi);
        ASSERT_EQ(which.substr(0, 3), "psi");
        const int k = std::stoi(which.substr(3)) - 1;
        ASSERT_GE(k, 0);
        ASSERT_LT(k, 5);
        const double psi = f.transitionPoints()[k];
        std::cout << "phi " << phi << " " << which << " (" << equation << "): "
                  << psi << " deg, Table 4.2 " << reported << '\n';
        EXPECT_NEAR(psi, reported, 0.1) << which << " phi " << phi;
        EXPECT_NEAR(std::round(psi*10.0)/10.0, reported, 1e-9) << which << " phi " << phi;
        EXPECT_NEAR(psi, recomputed, 1e-3);
        EXPECT_NEAR(f.tipRadius(), rf, 1e-5);
        EXPECT_NEAR(f.tipOffsetDeg(), psift, 1e-4);
        EXPECT_NEAR(f.flightSpacingDeg(), psifl, 1e-4);
        ++rows;
    }
    EXPECT_EQ(rows, 10);
}
