// What every drum model writes the same way: the progress line, the measured
// tracer (rtd.tracer), summary.csv with the measured moments appended, and
// rtd.csv with its linear and log-scale PNGs.
#ifndef DRUM_MODELS_RUNOUTPUTS_HPP
#define DRUM_MODELS_RUNOUTPUTS_HPP

#include "drum/io/gnuplot.hpp"
#include "drum/models/drumCase.hpp"
#include "drum/rtd/rtdMoments.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drum
{

//- "drumSolver: <s>" on standard output
void say(const std::string& s);

//- The PNG when gnuplot is on PATH, else a note
void plotIfPossible(const Plot& p, const std::filesystem::path& file);

struct MeasuredTracer
{
    std::vector<double> t, E;   //!< s, 1/s
};

//- The tracer file's two columns in s and 1/s; InputError naming the file
MeasuredTracer readTracer(const TracerFile& tf);

//- The comparison with the tracer's shape (rtd/rtdShape.hpp): t10, t50, t90,
//  the body's mean and SD and the tail's share, model and measured, each
//  against the goal (within tracerGoal of the measured); tracerComparison.csv
constexpr double tracerGoal = 0.05;
void writeTracerComparison
(
    const TracerFile& tf,
    const std::vector<double>& time,
    const std::vector<double>& E,
    const MeasuredTracer& measured,
    const std::filesystem::path& out
);

//- driftQueries.csv: the extent of the drift queries of a RecordingDrift
//  (drift.recordQueries), nothing for any other model
void writeDriftQueries(const DriftModel& drift, const std::filesystem::path& out);

//- The case's tracer, if it names one
std::optional<MeasuredTracer> readTracer(const DrumCase& c);

//- summary.csv: the model's columns, then the measured tracer's moments
//  (trapezoid on its sampling) when there is one; returns those moments
std::optional<RtdMoments> writeSummary
(
    std::vector<std::string> cols,
    std::vector<double> row,
    const std::optional<MeasuredTracer>& measured,
    const std::filesystem::path& out
);

//- " (measured mean / SD min)" for the progress line, empty without a tracer
std::string measuredNote(const std::optional<RtdMoments>& mm);

//- rtd.csv (time, E, cumulative F) and rtd.png / rtd_log.png against the
//  measured points
void writeRtdOutputs
(
    const DrumCase& c,
    const std::vector<double>& time,
    const std::vector<double>& E,
    const std::optional<MeasuredTracer>& measured,
    const std::string& modelLabel,
    const std::filesystem::path& out
);

} // namespace drum

#endif
