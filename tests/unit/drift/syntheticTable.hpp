// Writes drift tables in the issue-6 contract format from a function of the
// axes, for tests (never a hard-coded expected result: the expectation is
// the function itself).
#ifndef TESTS_DRIFT_SYNTHETICTABLE_HPP
#define TESTS_DRIFT_SYNTHETICTABLE_HPP

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace synthetic
{

using Point = std::array<double, 6>;   // V_g, S, y, L, rho_p, d
//- The values of a grid point; tunnel: the optional tunnel_drift_m column
//  (written when the first point has it)
struct Values { double vc, drift, captured; std::optional<double> tunnel = std::nullopt; };

const std::array<std::string, 6> names{{"gas_velocity_m_s", "spill_rate_kg_m_s", "fall_height_m",
    "flight_length_m", "particle_density_kg_m3", "particle_diameter_m"}};

//- The default grid: every axis varied
inline std::array<std::vector<double>, 6> defaultGrid()
{
    return {{{1.5, 3.0, 6.0}, {2.0, 8.0, 30.0}, {1.0, 4.0, 10.0}, {1.0, 2.0}, {1200.0, 2650.0}, {1e-4, 5e-4, 2e-3}}};
}

inline std::string header(const std::array<std::vector<double>, 6>& grid)
{
    std::ostringstream os;
    os.precision(17);
    os << "# dryerDriftTable 1\n"
       << "# generator: buildDriftTable test ; solver curtainFoam ; OpenFOAM v1912\n"
       << "# dictionary: tests/unit/drift\n# axes:";
    for (int a = 0; a < 6; ++a) if (grid[a].size() > 1) os << ' ' << names[a];
    os << "\n";
    for (int a = 0; a < 6; ++a)
    {
        if (grid[a].size() > 1) os << "# range " << names[a] << ": " << grid[a].front() << ' ' << grid[a].back() << "\n";
    }
    os << "# fixed: release_velocity_m_s=0 layer_thickness_m=0.05\n# mesh: coarse (1000 cells)\n"
       << "# elapsed_s: 1\n# cases: 1 (1 converged, 0 failed)\n";
    return os.str();
}

inline std::string columns(bool tunnel = false)
{
    return std::string("case,gas_velocity_m_s,spill_rate_kg_m_s,fall_height_m,flight_length_m,particle_density_kg_m3,"
           "particle_diameter_m,vc_over_vg,drift_m,captured_fraction") + (tunnel ? ",tunnel_drift_m\n" : "\n");
}

//- Rows of the full grid, in nested order (last axis fastest)
inline std::vector<std::string> rows(const std::array<std::vector<double>, 6>& grid,
                                     const std::function<Values(const Point&)>& f)
{
    std::vector<std::string> out;
    std::array<std::size_t, 6> i{};
    int n = 0;
    while (true)
    {
        Point p;
        for (int a = 0; a < 6; ++a) p[a] = grid[a][i[a]];
        const Values v = f(p);
        std::ostringstream os;
        os.precision(17);
        os << "c" << n++;
        for (double x : p) os << ',' << x;
        os << ',' << v.vc << ',' << v.drift << ',' << v.captured;
        if (v.tunnel) os << ',' << *v.tunnel;
        os << "\n";
        out.push_back(os.str());
        int a = 5;
        while (a >= 0 && ++i[a] == grid[a].size()) { i[a] = 0; --a; }
        if (a < 0) break;
    }
    return out;
}

inline std::string table(const std::array<std::vector<double>, 6>& grid, const std::function<Values(const Point&)>& f)
{
    Point first;
    for (int a = 0; a < 6; ++a) first[a] = grid[a].front();
    std::string s = header(grid) + columns(f(first).tunnel.has_value());
    for (const auto& r : rows(grid, f)) s += r;
    return s;
}

inline void write(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream(p, std::ios::binary) << text;
}

} // namespace synthetic

#endif
