#include "driftScores.hpp"

#include "drum/io/atomicFile.hpp"
#include "drum/io/csv.hpp"
#include "drum/io/gnuplot.hpp"
#include "drum/io/inputError.hpp"
#include "scoring/predictionScore.hpp"
#include "scoring/windTunnelData.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

namespace windTunnelDrift
{

namespace fs = std::filesystem;

ScoredQuantity scoredQuantity(const std::string& name)
{
    if (name == "advance") return ScoredQuantity();
    if (name == "apparentVc") return {"vc_m_s", "apparent in-sheet gas velocity V_c (Eq 141) [m/s]", true};
    throw drum::InputError("", "-quantity", "'" + name + "': valid names are advance, apparentVc");
}


void writeScores
(
    const fs::path& testsFile,
    const std::vector<NamedPredictions>& predictions,
    const fs::path& csv,
    const fs::path& png,
    const fs::path& byMaterial,
    const std::vector<std::string>& drawn,
    const ScoredQuantity& quantity,
    const bool allowMissing
)
{
    for (const auto& name : drawn)
    {
        bool known = false;
        for (const auto& p : predictions) known = known || p.model == name;
        if (!known) throw drum::InputError("", "-pngModels", "'" + name + "' is not one of the -predictions names");
    }
    const auto measured = drum::readMeasured(testsFile, quantity.column, quantity.emptyIsUnmeasured);
    // fall height and material per test: the scoring side may read the whole file
    std::map<int, double> height;
    std::map<int, std::string> material;
    {
        // read test,fall_height_m,material without the material check
        io::CSVReader<3, io::trim_chars<' '>, io::double_quote_escape<',', '"'>> in(testsFile.string());
        in.read_header(io::ignore_extra_column, "test", "fall_height_m", "material");
        int t;
        double y;
        std::string m;
        while (in.read_row(t, y, m))
        {
            height[t] = y;
            material[t] = m;
        }
    }
    std::set<double> heights;
    for (const auto& kv : height) heights.insert(kv.second);
    std::set<std::string> materials;
    for (const auto& kv : material) materials.insert(kv.second);
    std::ostringstream om;
    om << "model,material,count,rms_ln,bias_ln,within25\n" << std::setprecision(4);

    std::ostringstream os;
    os << "model,fall_height_m,count,rms_ln,bias_ln,within25\n" << std::setprecision(4);
    drum::Plot plot;
    plot.title = (quantity.column == "vc_m_s" ? "Apparent in-sheet gas velocity" : "Mean advance")
        + std::string(", predicted against measured (Sherritt 1991 wind tunnel)");
    plot.xlabel = "measured " + quantity.label;
    plot.ylabel = "predicted " + quantity.label;
    plot.logx = plot.logy = true;
    plot.extra.push_back("set key top left");
    plot.extra.push_back("set termoption noenhanced");   // model names as written (underscores)
    plot.extra.push_back("set clip two");   // draw the +-25 % lines whose ends lie on the frame
    const std::vector<std::string> points{"7", "5", "9", "11", "13", "3", "1"};
    double lo = 1e9, hi = 0;
    std::cout << std::left << std::setw(14) << "model" << std::setw(8) << "y [m]" << std::setw(6) << "n"
              << std::setw(9) << "RMS ln" << std::setw(9) << "bias" << "within 25 %\n";
    for (std::size_t k = 0; k < predictions.size(); ++k)
    {
        const auto& p = predictions[k];
        std::map<int, int> lines;
        const auto pred = drum::readMeasured(p.file, quantity.column, false, &lines);   // test,<the quantity's column>
        if (pred.empty()) throw drum::InputError(p.file.string(), "", "no predictions");
        for (const auto& kv : pred)
        {
            if (!height.count(kv.first))
            {
                throw drum::InputError(p.file.string(), "test " + std::to_string(kv.first) + " (line "
                    + std::to_string(lines.at(kv.first)) + ")", "not a test of " + testsFile.string());
            }
        }
        std::vector<int> missing;
        for (const auto& kv : measured)
        {
            if (!pred.count(kv.first)) missing.push_back(kv.first);
        }
        if (!missing.empty() && !allowMissing)
        {
            std::string list;
            for (std::size_t i = 0; i < missing.size() && i < 10; ++i) list += (i ? ", " : "") + std::to_string(missing[i]);
            if (missing.size() > 10) list += ", ...";
            throw drum::InputError(p.file.string(), "test " + std::to_string(missing.front()),
                "no prediction for " + std::to_string(missing.size()) + " measured test(s) of " + testsFile.string()
              + " (" + list + "); each measured test needs one, or -allowMissing scores the model on the tests "
                "it predicts");
        }
        if (!missing.empty())
        {
            std::cout << "windTunnelDrift: " << p.model << " predicts " << measured.size() - missing.size() << " of "
                      << measured.size() << " measured tests (-allowMissing): scored on those\n";
        }
        // one CSV row of scores
        const auto row = [&](std::ostringstream& out, const std::string& label, const drum::PredictionScore& s)
        {
            out << p.model << ',' << label << ',' << s.count << ',' << s.rmsLnError << ',' << s.bias << ','
                << s.within25 << '\n';
        };
        // the predictions of the tests whose key (fall height, material) is v
        const auto subset = [&](const auto& key, const auto& v)
        {
            std::map<int, double> sub;
            for (const auto& kv : pred)
            {
                const auto it = key.find(kv.first);
                if (it != key.end() && it->second == v) sub.insert(kv);
            }
            return sub;
        };
        auto line = [&](const std::string& label, const std::map<int, double>& sub)
        {
            const drum::PredictionScore s = drum::scorePredictions(sub, measured);
            row(os, label, s);
            std::cout << std::setw(14) << p.model << std::setw(8) << label << std::setw(6) << s.count
                      << std::fixed << std::setprecision(3) << std::setw(9) << s.rmsLnError << std::setw(9)
                      << s.bias << s.within25 << std::defaultfloat << std::setprecision(6) << "\n";
        };
        for (double y : heights)
        {
            const auto sub = subset(height, y);
            std::ostringstream yl;
            yl << y;
            if (!sub.empty()) line(yl.str(), sub);
        }
        line("all", pred);
        for (const auto& m : materials)
        {
            const auto sub = subset(material, m);
            if (!sub.empty()) row(om, m, drum::scorePredictions(sub, measured));
        }
        if (!drawn.empty() && std::find(drawn.begin(), drawn.end(), p.model) == drawn.end()) continue;
        const std::size_t style = plot.series.size();
        drum::PlotSeries s{p.model, {}, {}, "points pt " + points[style % points.size()] + " ps 1.3"};
        for (const auto& kv : pred)
        {
            if (!measured.count(kv.first)) continue;
            s.x.push_back(measured.at(kv.first));
            s.y.push_back(kv.second);
            lo = std::min({lo, s.x.back(), s.y.back()});
            hi = std::max({hi, s.x.back(), s.y.back()});
        }
        plot.series.push_back(s);
    }
    drum::writeFileAtomically(csv, os.str());
    if (!byMaterial.empty()) drum::writeFileAtomically(byMaterial, om.str());
    if (!png.empty())
    {
        lo = std::max(lo*0.8, 1e-3);
        hi *= 1.25;
        plot.series.push_back({"1:1", {lo, hi}, {lo, hi}, "lines lc 'black' lw 1"});
        plot.series.push_back({"+25 %", {lo, hi}, {1.25*lo, 1.25*hi}, "lines lc 'gray40' dt 2 lw 1.5"});
        plot.series.push_back({"-25 %", {lo, hi}, {0.75*lo, 0.75*hi}, "lines lc 'gray40' dt 4 lw 1.5"});
        std::ostringstream r;
        r << "set xrange [" << lo << ":" << hi << "]; set yrange [" << lo << ":" << hi << "]";
        plot.extra.push_back(r.str());
        if (drum::gnuplotAvailable()) drum::writePng(plot, png);
        else std::cout << "gnuplot not on PATH: " << png << " not drawn\n";
    }
}

} // namespace windTunnelDrift
