// PNG plots through gnuplot (Debian gnuplot-nox): line/point series on
// shared axes. The data travel inline in the script, so nothing but the PNG
// is left on disk.
#ifndef DRUM_IO_GNUPLOT_HPP
#define DRUM_IO_GNUPLOT_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace drum
{

struct PlotSeries
{
    std::string title;
    std::vector<double> x;
    std::vector<double> y;
    std::string style = "lines lw 2";  //!< gnuplot "with" clause
};

struct Plot
{
    std::string title;
    std::string xlabel;
    std::string ylabel;
    std::vector<PlotSeries> series;
    bool logx = false;
    bool logy = false;
    int width = 900;
    int height = 600;
    //- Extra gnuplot commands (set key, set arrow, ...), one per entry
    std::vector<std::string> extra;
};

//- True when a gnuplot executable is on PATH
bool gnuplotAvailable();

//- A PNG file that starts with its signature and ends with its IEND chunk
bool pngComplete(const std::filesystem::path& file);

//- Render the plot to a PNG at path. Throws std::runtime_error if gnuplot
//  fails or its PNG is incomplete; the PNG is written atomically.
void writePng(const Plot& plot, const std::filesystem::path& path);

} // namespace drum

#endif
