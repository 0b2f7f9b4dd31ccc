#include "cfdPrediction.hpp"

#include "drum/io/csv.hpp"
#include "drum/io/inputError.hpp"
#include "drum/windTunnel/tunnelCollection.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <sys/wait.h>

namespace curtainDrift
{

namespace fs = std::filesystem;
using drum::InputError;

namespace
{
std::string join(const std::vector<double>& v)
{
    std::ostringstream os;
    os.precision(10);
    for (std::size_t i = 0; i < v.size(); ++i) os << (i ? "," : "") << v[i];
    return os.str();
}

std::string quote(const std::string& s)
{
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
} // namespace


double readCurtainResult
(
    const fs::path& file,
    double fallHeight,
    const std::vector<double>& diameters,
    const std::vector<double>& fractions
)
{
    const std::string f = file.string();
    if (!fs::exists(file)) throw InputError(f, "", "curtainCase wrote no result");
    std::vector<double> drift(diameters.size(), std::nan(""));
    try
    {
        io::CSVReader<6, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(f);
        in.read_header(io::ignore_extra_column, "class", "diameter_m", "fall_height_m", "drift_m",
                       "captured_fraction", "converged");
        std::string cls, ds, ys, dxs, caps, conv;
        while (in.read_row(cls, ds, ys, dxs, caps, conv))
        {
            if (cls == "bulk") continue;
            const std::string where = "line " + std::to_string(in.get_file_line());
            double d, y, dx;
            try
            {
                d = std::stod(ds);
                y = std::stod(ys);
                dx = dxs == "nan" || dxs == "NaN" ? std::nan("") : std::stod(dxs);
            }
            catch (const std::exception&)
            {
                throw InputError(f, where, "diameter_m, fall_height_m and drift_m must be numbers");
            }
            if (std::abs(y - fallHeight) > 1e-6*std::max(1.0, fallHeight)) continue;
            if (conv != "1" && conv != "true" && conv != "yes")
            {
                throw InputError(f, where, "case not converged");
            }
            for (std::size_t i = 0; i < diameters.size(); ++i)
            {
                if (std::abs(d - diameters[i]) > 1e-4*diameters[i]) continue;   // as printed by curtainCase
                if (!std::isfinite(dx))
                {
                    throw InputError(f, where, "class " + cls + " (diameter " + ds + " m) did not reach the fall "
                        "height inside the domain (drift_m " + dxs + "): no mean advance for this row");
                }
                drift[i] = dx;
            }
        }
    }
    catch (const io::error::base& e)
    {
        throw InputError(f, "", std::string("malformed curtainResult.csv: ") + e.what());
    }
    double sum = 0;
    for (std::size_t i = 0; i < diameters.size(); ++i)
    {
        if (std::isnan(drift[i]))
        {
            std::ostringstream os;
            os << "no row for diameter " << diameters[i] << " m at fall height " << fallHeight << " m";
            throw InputError(f, "class rows", os.str());
        }
        sum += fractions[i]*drift[i];
    }
    return sum;
}


double readLandingAdvance
(
    const fs::path& file,
    double fallHeight,
    const std::vector<double>& fractions
)
{
    const std::string f = file.string();
    if (!fs::exists(file)) throw InputError(f, "", "curtainCase wrote no landing distribution");
    std::vector<drum::ClassLanding> classes(fractions.size());
    std::vector<bool> released(fractions.size(), false);
    try
    {
        io::CSVReader<7, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(f);
        in.read_header(io::ignore_no_column, "fall_height_m", "class", "x_low_m", "x_high_m",
                       "mass_flow_kg_s", "fraction_of_inflow", "x_centre_m");
        std::string ys, cls, lo, hi, mass, frac, xc;
        while (in.read_row(ys, cls, lo, hi, mass, frac, xc))
        {
            const std::string where = "line " + std::to_string(in.get_file_line());
            double y;
            std::size_t i;
            try
            {
                y = std::stod(ys);
                if (cls.size() < 2 || cls[0] != 'c') throw std::invalid_argument(cls);
                i = std::stoul(cls.substr(1));
            }
            catch (const std::exception&)
            {
                throw InputError(f, where, "fall_height_m must be a number and class c<index>");
            }
            if (std::abs(y - fallHeight) > 1e-6*std::max(1.0, fallHeight)) continue;
            if (i >= fractions.size())
            {
                throw InputError(f, where, "class " + cls + " beyond the " + std::to_string(fractions.size())
                                 + " classes of the row");
            }
            if (lo == "lost") continue;        // the rule counts the loss by the feed's balance
            try
            {
                if (lo == "slot")
                {
                    classes[i].releaseCentre = std::stod(xc);
                    released[i] = true;
                    continue;
                }
                drum::ClassLanding::Bin b;
                b.xLow = std::stod(lo);
                b.xHigh = std::stod(hi);
                b.fraction = std::stod(frac);
                b.xCentre = xc == "nan" || xc == "NaN" ? 0.5*(b.xLow + b.xHigh) : std::stod(xc);
                classes[i].bins.push_back(b);
            }
            catch (const std::exception&)
            {
                throw InputError(f, where, "x_low_m, x_high_m, fraction_of_inflow and x_centre_m must be numbers");
            }
        }
    }
    catch (const io::error::base& e)
    {
        throw InputError(f, "", std::string("malformed curtainLanding.csv: ") + e.what());
    }
    for (std::size_t i = 0; i < fractions.size(); ++i)
    {
        if (!released[i] || classes[i].bins.empty())
        {
            std::ostringstream os;
            os << "no slot row or no bins of class c" << i << " at fall height " << fallHeight << " m";
            throw InputError(f, "class rows", os.str());
        }
    }
    return drum::collectedAdvance(classes, fractions, drum::TunnelFloor{}, f).advance;
}


std::map<int, double> cfdPredictions
(
    const std::vector<drum::WindTunnelTest>& tests,
    const std::map<std::string, drum::WindTunnelMaterial>& materials,
    const CfdOptions& o
)
{
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    std::map<int, double> out;
    fs::create_directories(o.work);
    int done = 0;
    for (const auto& t : tests)
    {
        const auto& m = materials.at(t.material);
        std::vector<double> d, w;
        for (const auto& c : m.classes)
        {
            d.push_back(c.diameter);
            w.push_back(c.massFraction);
        }
        const fs::path dir = o.work/("test" + std::to_string(t.test));
        fs::remove_all(dir);
        std::ostringstream cmd;
        cmd.precision(10);
        cmd << o.command << " -dir " << quote(dir.string()) << " -gasVelocity " << t.airVelocity
            << " -spillRate " << t.spillRate << " -fallHeight " << t.fallHeight
            << " -flightLength " << t.flightLength << " -density " << m.particleDensity
            << " -diameters " << join(d) << " -fractions " << join(w) << " -heights " << t.fallHeight
            << " -level " << o.level << " -np " << o.np;
        if (!o.drag.empty()) cmd << " -drag " << o.drag;
        if (!o.particleTurbulence.empty()) cmd << " -particleTurbulence " << o.particleTurbulence;
        if (!o.turbulentDispersion.empty()) cmd << " -turbulentDispersion " << o.turbulentDispersion;
        if (o.keep) cmd << " -keep";
        const fs::path log = o.work/("test" + std::to_string(t.test) + ".log");
        std::cout << "curtainDrift: cfd " << done + 1 << "/" << tests.size() << ": test " << t.test
                  << " (" << t.material << ", V_g " << t.airVelocity << " m/s, S " << t.spillRate
                  << " kg/(m s), y " << t.fallHeight << " m) ..." << std::flush;
        const auto t0 = clock::now();
        const int status = std::system((cmd.str() + " > " + quote(log.string()) + " 2>&1").c_str());
        const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        try
        {
            if (rc != 0)
            {
                throw InputError(log.string(), "test " + std::to_string(t.test),
                    "curtainCase failed (exit " + std::to_string(rc) + "); command: " + cmd.str());
            }
            out[t.test] = o.collection == "landed"
                ? readCurtainResult(dir/"curtainResult.csv", t.fallHeight, d, w)
                : readLandingAdvance(dir/"curtainLanding.csv", t.fallHeight, w);
        }
        catch (const InputError& e)
        {
            std::cout << " failed" << std::endl;
            if (!o.skipFailed) throw;
            std::cout << "curtainDrift: test " << t.test << " left out: " << e.what() << std::endl;
            ++done;
            continue;
        }
        ++done;
        const double el = std::chrono::duration<double>(clock::now() - start).count();
        const double row = std::chrono::duration<double>(clock::now() - t0).count();
        std::ostringstream msg;
        msg << std::fixed << std::setprecision(3) << out[t.test] << " m in " << std::setprecision(0) << row
            << " s; about " << el/done*(tests.size() - done) << " s left";
        std::cout << " " << msg.str() << std::endl;
        if (!o.keep)
        {
            fs::remove_all(dir);
            fs::remove(log);
        }
    }
    return out;
}

} // namespace curtainDrift
