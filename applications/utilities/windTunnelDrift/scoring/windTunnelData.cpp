#include "scoring/windTunnelData.hpp"

#include "drum/io/csv.hpp"
#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

std::string rowEntry(int line, const std::string& column)
{
    return "line " + std::to_string(line) + ", column " + column;
}

double toDouble(const std::string& text, const std::string& file, int line, const std::string& column)
{
    try
    {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(v))
        {
            throw std::invalid_argument(text);
        }
        return v;
    }
    catch (const std::exception&)
    {
        throw InputError(file, rowEntry(line, column), "'" + text + "' is not a number");
    }
}

// A test id: a whole number, once per file (`seen`: id -> line of its first row)
int testId(const std::string& text, const std::string& file, int line, std::map<int, int>& seen)
{
    const double v = toDouble(text, file, line, "test");
    if (!(v == std::floor(v) && std::abs(v) < 1e9))
    {
        throw InputError(file, rowEntry(line, "test"), "'" + text + "' is not a whole test number");
    }
    const int id = static_cast<int>(v);
    const auto [it, added] = seen.emplace(id, line);
    if (!added)
    {
        throw InputError(file, "test " + std::to_string(id) + " (" + rowEntry(line, "test") + ")",
            "given twice: also on line " + std::to_string(it->second) + "; each test once");
    }
    return id;
}

// Run a reader body, turning the CSV library's errors into InputError
template<class Body>
auto guarded(const std::filesystem::path& file, Body body) -> decltype(body())
{
    requireReadableFile(file.string());
    try
    {
        return body();
    }
    catch (const io::error::base& e)
    {
        throw InputError(file.string(), "", std::string("malformed CSV: ") + e.what());
    }
}

} // namespace


std::map<std::string, WindTunnelMaterial> readWindTunnelMaterials
(
    const std::filesystem::path& file,
    const SieveClosure& closure
)
{
    const std::string fname = file.string();
    return guarded(file, [&]
    {
        io::CSVReader<7, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(fname);
        in.read_header(io::ignore_extra_column, "material", "particle_density_kg_m3",
                       "bulk_density_kg_m3", "sphericity", "psd_lower_um", "psd_upper_um",
                       "psd_wt_pct");
        std::map<std::string, WindTunnelMaterial> materials;
        std::string name, rho, rhoB, sph, lower, upper, pct;
        while (in.read_row(name, rho, rhoB, sph, lower, upper, pct))
        {
            const int line = static_cast<int>(in.get_file_line());
            if (name.empty())
            {
                throw InputError(fname, rowEntry(line, "material"), "empty material name");
            }
            WindTunnelMaterial& m = materials[name];
            m.name = name;
            m.particleDensity = toDouble(rho, fname, line, "particle_density_kg_m3");
            m.bulkDensity = toDouble(rhoB, fname, line, "bulk_density_kg_m3");
            m.sphericity = sph.empty() ? 1.0 : toDouble(sph, fname, line, "sphericity");
            requireInRange(m.particleDensity, 100, 20000, rowEntry(line, "particle_density_kg_m3"), fname);
            requireInRange(m.sphericity, 0.05, 1.0, rowEntry(line, "sphericity"), fname);

            SieveClass c;
            c.lowerUm = lower.empty() ? 0 : toDouble(lower, fname, line, "psd_lower_um");
            c.upperUm = upper.empty() ? 0 : toDouble(upper, fname, line, "psd_upper_um");
            if (lower.empty() && upper.empty())
            {
                throw InputError(fname, rowEntry(line, "psd_lower_um"), "a bin needs at least one bound");
            }
            const double lo = lower.empty() ? closure.bottomUm : c.lowerUm;
            const double hi = upper.empty() ? closure.topUm : c.upperUm;
            if (!(lo > 0 && hi > lo))
            {
                throw InputError(fname, rowEntry(line, "psd_lower_um"),
                    "sieve bounds must satisfy 0 < lower < upper");
            }
            // Geometric mean of the bounds x sphericity (Sherritt's D_p)
            c.diameter = std::sqrt(lo*hi)*1e-6*m.sphericity;
            c.massFraction = toDouble(pct, fname, line, "psd_wt_pct");
            requireInRange(c.massFraction, 0, 100, rowEntry(line, "psd_wt_pct"), fname);
            m.classes.push_back(c);
        }
        for (auto& kv : materials)
        {
            double sum = 0;
            for (const auto& c : kv.second.classes) sum += c.massFraction;
            if (!(sum > 0))
            {
                throw InputError(fname, "material " + kv.first, "size distribution sums to zero");
            }
            for (auto& c : kv.second.classes) c.massFraction /= sum;
        }
        if (materials.empty())
        {
            throw InputError(fname, "", "no material rows");
        }
        return materials;
    });
}


std::vector<WindTunnelTest> readWindTunnelTests
(
    const std::filesystem::path& file,
    const std::map<std::string, WindTunnelMaterial>& materials
)
{
    const std::string fname = file.string();
    return guarded(file, [&]
    {
        io::CSVReader<6, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(fname);
        in.read_header(io::ignore_extra_column, "test", "material", "air_velocity_m_s",
                       "spill_rate_kg_m_s", "flight_length_m", "fall_height_m");
        std::vector<WindTunnelTest> tests;
        std::map<int, int> seen;
        std::string id, material, vg, spill, L, y;
        while (in.read_row(id, material, vg, spill, L, y))
        {
            const int line = static_cast<int>(in.get_file_line());
            WindTunnelTest t;
            t.test = testId(id, fname, line, seen);
            t.material = material;
            if (!materials.count(material))
            {
                std::ostringstream os;
                os << "unknown material '" << material << "'; known:";
                for (const auto& kv : materials) os << ' ' << kv.first;
                throw InputError(fname, "test " + id + " (" + rowEntry(line, "material") + ")", os.str());
            }
            const std::string where = "test " + id + " (line " + std::to_string(line) + ")";
            t.airVelocity = toDouble(vg, fname, line, "air_velocity_m_s");
            t.spillRate = toDouble(spill, fname, line, "spill_rate_kg_m_s");
            t.flightLength = toDouble(L, fname, line, "flight_length_m");
            t.fallHeight = toDouble(y, fname, line, "fall_height_m");
            requireInRange(t.airVelocity, 0, 30, where + " air_velocity_m_s", fname);
            requireInRange(t.spillRate, 1e-6, 500, where + " spill_rate_kg_m_s", fname);
            requireInRange(t.flightLength, 1e-3, 100, where + " flight_length_m", fname);
            requireInRange(t.fallHeight, 1e-3, 100, where + " fall_height_m", fname);
            tests.push_back(t);
        }
        if (tests.empty())
        {
            throw InputError(fname, "", "no test rows");
        }
        return tests;
    });
}


std::map<int, double> readMeasured
(
    const std::filesystem::path& file,
    const std::string& column,
    bool emptyIsUnmeasured,
    std::map<int, int>* lines
)
{
    const std::string fname = file.string();
    return guarded(file, [&]
    {
        io::CSVReader<2, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(fname);
        in.read_header(io::ignore_extra_column, "test", column);
        std::map<int, double> measured;
        std::map<int, int> seen;
        std::string id, value;
        while (in.read_row(id, value))
        {
            const int line = static_cast<int>(in.get_file_line());
            const int t = testId(id, fname, line, seen);
            if (value.empty() && emptyIsUnmeasured) continue;   // not measured in this test
            measured[t] = toDouble(value, fname, line, column);
        }
        if (lines) *lines = seen;
        return measured;
    });
}


std::map<int, double> readMeasuredAdvance(const std::filesystem::path& file)
{
    return readMeasured(file, "mean_advance_m");
}

} // namespace drum
