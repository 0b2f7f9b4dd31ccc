#include "cfdPrediction.hpp"

#include "drum/io/csv.hpp"
#include "drum/io/inputError.hpp"
#include "scoring/landingFile.hpp"

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <sys/wait.h>

namespace windTunnelDrift
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


CfdRow readCurtainResult
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
    CfdRow row;
    for (std::size_t i = 0; i < diameters.size(); ++i)
    {
        if (std::isnan(drift[i]))
        {
            std::ostringstream os;
            os << "no row for diameter " << diameters[i] << " m at fall height " << fallHeight << " m";
            throw InputError(f, "class rows", os.str());
        }
        row.advance += fractions[i]*drift[i];
    }
    row.classAdvance = drift;
    return row;
}


CfdRow readLandingAdvance
(
    const fs::path& file,
    double fallHeight,
    const std::vector<double>& fractions
)
{
    const auto classes = drum::landingAt(drum::readLandingFile(file), fallHeight, fractions.size(), file);
    CfdRow row;
    row.advance = drum::collectedAdvance(classes, fractions, drum::TunnelFloor{}, file.string()).advance;
    for (std::size_t i = 0; i < classes.size(); ++i)
    {
        row.classAdvance.push_back(
            drum::classCollectedAdvance(classes[i], drum::TunnelFloor{}, file.string(), i).advance);
    }
    return row;
}


std::map<int, CfdRow> cfdPredictions
(
    const std::vector<drum::WindTunnelTest>& tests,
    const std::map<std::string, drum::WindTunnelMaterial>& materials,
    const CfdOptions& o
)
{
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    fs::create_directories(o.work);

    // one curtainCase per row; o.jobs rows at a time (each its own process)
    struct Row
    {
        std::string cmd;
        fs::path dir, log;
        std::vector<double> d, w;
        bool ok = false;
        CfdRow result;
        std::string error;
    };
    std::vector<Row> rows(tests.size());
    for (std::size_t k = 0; k < tests.size(); ++k)
    {
        const auto& t = tests[k];
        const auto& m = materials.at(t.material);
        Row& r = rows[k];
        for (const auto& c : m.classes)
        {
            r.d.push_back(c.diameter);
            r.w.push_back(c.massFraction);
        }
        r.dir = o.work/("test" + std::to_string(t.test));
        r.log = o.work/("test" + std::to_string(t.test) + ".log");
        std::ostringstream cmd;
        cmd.precision(10);
        cmd << o.command << " -dir " << quote(r.dir.string()) << " -gasVelocity " << t.airVelocity
            << " -spillRate " << t.spillRate << " -fallHeight " << t.fallHeight
            << " -flightLength " << t.flightLength << " -density " << m.particleDensity
            << " -diameters " << join(r.d) << " -fractions " << join(r.w) << " -heights " << t.fallHeight
            << " -level " << o.level << " -np " << o.np;
        if (!o.drag.empty()) cmd << " -drag " << o.drag;
        if (!o.sphericity.empty()) cmd << " -sphericity " << quote(o.sphericity);
        if (!o.particleTurbulence.empty()) cmd << " -particleTurbulence " << o.particleTurbulence;
        if (!o.turbulentDispersion.empty()) cmd << " -turbulentDispersion " << o.turbulentDispersion;
        if (!o.particleParticleDrag.empty()) cmd << " -particleParticleDrag " << o.particleParticleDrag;
        if (!o.turbulence.empty()) cmd << " -turbulence " << o.turbulence;
        if (!o.wakeShare.empty()) cmd << " -wakeShare " << quote(o.wakeShare);
        if (!o.releaseVelocity.empty()) cmd << " -releaseVelocity " << quote(o.releaseVelocity);
        if (o.layerThickness == "packed")
        {
            // curtainCase sizes the layer from the spill, the bulk density and the release speed
            cmd << " -layerThickness packed -bulkDensity " << m.bulkDensity;
        }
        else if (!o.layerThickness.empty())
        {
            cmd << " -layerThickness " << quote(o.layerThickness);
        }
        if (o.gasPressure) cmd << " -gasPressure " << *o.gasPressure;
        if (o.keep) cmd << " -keep";
        r.cmd = cmd.str();
    }

    std::mutex mutex;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::size_t done = 0;
    const auto work = [&]()
    {
        for (std::size_t k; !stop && (k = next++) < rows.size();)
        {
            const auto& t = tests[k];
            Row& r = rows[k];
            {
                std::lock_guard<std::mutex> lock(mutex);
                std::cout << "windTunnelDrift: cfd test " << t.test << " (" << t.material << ", V_g "
                          << t.airVelocity << " m/s, S " << t.spillRate << " kg/(m s), y " << t.fallHeight
                          << " m) started" << std::endl;
                fs::remove_all(r.dir);
            }
            const auto t0 = clock::now();
            const int status = std::system((r.cmd + " > " + quote(r.log.string()) + " 2>&1").c_str());
            const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            try
            {
                if (rc != 0)
                {
                    throw InputError(r.log.string(), "test " + std::to_string(t.test),
                        "curtainCase failed (exit " + std::to_string(rc) + "); command: " + r.cmd);
                }
                r.result = o.collection == "landed"
                    ? readCurtainResult(r.dir/"curtainResult.csv", t.fallHeight, r.d, r.w)
                    : readLandingAdvance(r.dir/"curtainLanding.csv", t.fallHeight, r.w);
                r.ok = true;
            }
            catch (const InputError& e)
            {
                r.error = e.what();
                if (!o.skipFailed) stop = true;
            }
            std::lock_guard<std::mutex> lock(mutex);
            ++done;
            const double el = std::chrono::duration<double>(clock::now() - start).count();
            const double row = std::chrono::duration<double>(clock::now() - t0).count();
            std::ostringstream msg;
            msg << "windTunnelDrift: cfd " << done << "/" << rows.size() << ": test " << t.test << " ";
            if (r.ok)
            {
                msg << std::fixed << std::setprecision(3) << r.result.advance << " m in " << std::setprecision(0)
                    << row << " s; about " << el/done*(rows.size() - done) << " s left";
            }
            else
            {
                msg << "failed" << (o.skipFailed ? " (left out): " : ": ") << r.error;
            }
            std::cout << msg.str() << std::endl;
            if (r.ok && !o.keep)
            {
                fs::remove_all(r.dir);
                fs::remove(r.log);
            }
        }
    };
    std::vector<std::thread> pool;
    for (int j = 0; j < std::max(1, o.jobs); ++j) pool.emplace_back(work);
    for (auto& th : pool) th.join();

    std::map<int, CfdRow> out;
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        if (rows[k].ok)
        {
            out[tests[k].test] = rows[k].result;
        }
        else if (!o.skipFailed && !rows[k].error.empty())
        {
            throw InputError(rows[k].log.string(), "test " + std::to_string(tests[k].test), rows[k].error);
        }
    }
    return out;
}

} // namespace windTunnelDrift
