#include "drum/models/runOutputs.hpp"

#include "drum/io/csv.hpp"
#include "drum/io/atomicFile.hpp"
#include "drum/io/csvWriter.hpp"
#include "drum/io/inputError.hpp"
#include "drum/rtd/rtdShape.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>
#include <vector>

namespace fs = std::filesystem;

namespace drum
{

void say(const std::string& s)
{
    std::cout << "drumSolver: " << s << std::endl;
}


MeasuredTracer readTracer(const TracerFile& tf)
{
    MeasuredTracer m;
    requireReadableFile(tf.file.string(), "rtd.tracer.file");
    {
        // the columns drumDict names must be in the CSV's header: say which entry to fix
        std::ifstream in(tf.file);
        std::string header, cell;
        std::getline(in, header);
        std::vector<std::string> names;
        std::istringstream cells(header);
        while (std::getline(cells, cell, ','))
        {
            const auto a = cell.find_first_not_of(" \t\r\""), b = cell.find_last_not_of(" \t\r\"");
            names.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
        }
        for (const auto& [entry, column] : {std::pair<std::string, std::string>{"rtd.tracer.timeColumn", tf.timeColumn},
                                            {"rtd.tracer.EColumn", tf.eColumn}})
        {
            if (std::find(names.begin(), names.end(), column) == names.end())
            {
                std::string list;
                for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
                throw InputError(tf.dict.string(), entry, "column '" + column + "' is not in the header of "
                    + tf.file.string() + " (its columns: " + list + ")");
            }
        }
    }
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
        throw InputError(tf.file.string(), "rtd.tracer", e.what());
    }
    if (m.t.size() < 3)
    {
        throw InputError(tf.file.string(), "rtd.tracer", "needs at least 3 rows");
    }
    return m;
}


std::optional<MeasuredTracer> readTracer(const DrumCase& c)
{
    if (!c.tracer) return std::nullopt;
    return readTracer(*c.tracer);
}


void plotIfPossible(const Plot& p, const fs::path& file)
{
    if (!gnuplotAvailable())
    {
        say("gnuplot not on PATH: " + file.filename().string() + " not drawn");
        return;
    }
    writePng(p, file);
}


std::optional<RtdMoments> writeSummary
(
    std::vector<std::string> cols,
    std::vector<double> row,
    const std::optional<MeasuredTracer>& measured,
    const fs::path& out
)
{
    std::optional<RtdMoments> mm;
    if (measured)
    {
        mm = sampledMoments(measured->t, measured->E);
        cols.insert(cols.end(), {"measured_mean_s", "measured_std_s", "measured_skewness"});
        row.insert(row.end(), {mm->mean, mm->sd(), mm->skewness});
    }
    CsvTable summary(cols);
    summary.addRow(row);
    summary.write(out/"summary.csv");
    return mm;
}


std::string measuredNote(const std::optional<RtdMoments>& mm)
{
    if (!mm) return {};
    std::ostringstream os;
    os << std::setprecision(4) << " (measured " << mm->mean/60 << " / " << mm->sd()/60 << " min)";
    return os.str();
}


void writeRtdOutputs
(
    const DrumCase& c,
    const std::vector<double>& time,
    const std::vector<double>& E,
    const std::optional<MeasuredTracer>& measured,
    const std::string& modelLabel,
    const fs::path& out
)
{
    CsvTable r({"time_s", "E_per_s", "F_cumulative"});
    double F = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
    {
        if (i > 0) F += 0.5*(time[i] - time[i - 1])*(E[i] + E[i - 1]);
        r.addRow({time[i], E[i], F});
    }
    r.write(out/"rtd.csv");

    Plot pr;
    pr.title = "Residence-time distribution";
    pr.xlabel = "time after pulse start (min)";
    pr.ylabel = "E(t) (1/min)";
    PlotSeries model{modelLabel, {}, {}};
    for (std::size_t i = 0; i < time.size(); ++i)
    {
        model.x.push_back(time[i]/60);
        model.y.push_back(E[i]*60);
    }
    pr.series.push_back(model);
    if (measured)
    {
        std::string name = c.tracer->file.filename().string();
        for (char& ch : name) if (ch == '_') ch = ' ';   // gnuplot enhanced text
        PlotSeries meas{"measured (" + name + ")", {}, {}, "points pt 7 ps 1.2"};
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
    Plot lg = pr;
    lg.logy = true;
    lg.title = "Residence-time distribution (log scale: the tail)";
    for (PlotSeries& se : lg.series)
    {
        PlotSeries keep{se.title, {}, {}, se.style};
        for (std::size_t i = 0; i < se.x.size(); ++i)
        {
            if (se.y[i] > 1e-7) { keep.x.push_back(se.x[i]); keep.y.push_back(se.y[i]); }
        }
        se = keep;
    }
    plotIfPossible(lg, out/"rtd_log.png");
    if (measured)
    {
        writeTracerComparison(*c.tracer, time, E, *measured, out);
    }
}


void writeTracerComparison
(
    const TracerFile& tf,
    const std::vector<double>& time,
    const std::vector<double>& E,
    const MeasuredTracer& measured,
    const fs::path& out
)
{
    // the body ends where the drumDict says, else where 95 % of the measured tracer is out
    const double cut = tf.bodyEnd > 0 ? tf.bodyEnd : rtdQuantile(measured.t, measured.E, 0.95);
    const RtdShape m = rtdShape(time, E, cut), x = rtdShape(measured.t, measured.E, cut);
    std::ostringstream csv;
    csv << std::setprecision(10) << "quantity,model,measured,model_over_measured,within_goal\n";
    std::ostringstream line;
    line << std::setprecision(3) << "against the tracer (body to " << cut/60 << " min; goal within "
         << 100*tracerGoal << " %):";
    const std::vector<std::tuple<std::string, double, double>> rows{
        {"t10_s", m.t10, x.t10}, {"t50_s", m.t50, x.t50}, {"t90_s", m.t90, x.t90},
        {"body_mean_s", m.bodyMean, x.bodyMean}, {"body_std_s", m.bodySd, x.bodySd},
        {"tail_share", m.tailShare, x.tailShare}};
    for (const auto& [name, a, b] : rows)
    {
        const double r = a/b;
        const bool ok = std::abs(r - 1) <= tracerGoal;
        csv << name << ',' << a << ',' << b << ',' << r << ',' << (ok ? "yes" : "no") << '\n';
        const bool share = name == "tail_share";
        line << ' ' << name.substr(0, name.rfind('_')) << ' ' << (share ? a : a/60) << '/' << (share ? b : b/60)
             << (ok ? "" : " (off)");
    }
    writeFileAtomically(out/"tracerComparison.csv", csv.str());
    say(line.str() + " (times in min; tracerComparison.csv)");
}


void writeDriftQueries(const DriftModel& drift, const fs::path& out)
{
    if (const auto* r = dynamic_cast<const RecordingDrift*>(&drift))
    {
        writeFileAtomically(out/"driftQueries.csv", r->rangeCsv());
        say("the drift queries' extent per table axis: driftQueries.csv");
    }
}

} // namespace drum
