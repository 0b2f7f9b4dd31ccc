#include "drum/io/gnuplot.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace drum
{

namespace
{
std::string quoted(const std::string& s)
{
    std::string out = "\"";
    for (char c : s)
    {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}
} // namespace

bool pngComplete(const std::filesystem::path& file)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char end[8] = {'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    std::ifstream in(file, std::ios::binary);
    if (!in) return false;
    unsigned char head[8] = {}, tail[8] = {};
    in.read(reinterpret_cast<char*>(head), 8);
    in.seekg(-8, std::ios::end);
    in.read(reinterpret_cast<char*>(tail), 8);
    return in && std::equal(head, head + 8, signature) && std::equal(tail, tail + 8, end);
}

bool gnuplotAvailable()
{
    return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

void writePng(const Plot& plot, const std::filesystem::path& path)
{
    if (!path.parent_path().empty())
    {
        std::filesystem::create_directories(path.parent_path());
    }
    const std::filesystem::path temp = path.parent_path()
        / ("." + path.filename().string() + ".tmp" + std::to_string(::getpid()) + ".png");

    std::ostringstream gp;
    gp << "set terminal pngcairo size " << plot.width << "," << plot.height
       << " enhanced font 'Sans,11'\n"
       << "set output " << quoted(temp.string()) << "\n"
       << "set title " << quoted(plot.title) << "\n"
       << "set xlabel " << quoted(plot.xlabel) << "\n"
       << "set ylabel " << quoted(plot.ylabel) << "\n"
       << "set grid\nset key outside right top\n";
    if (plot.logx) gp << "set logscale x\n";
    if (plot.logy) gp << "set logscale y\n";
    for (const auto& e : plot.extra) gp << e << "\n";
    gp << "plot ";
    for (std::size_t i = 0; i < plot.series.size(); ++i)
    {
        gp << (i ? ", " : "") << "'-' using 1:2 with " << plot.series[i].style
           << " title " << quoted(plot.series[i].title);
    }
    gp << "\n";
    gp.precision(10);
    for (const auto& s : plot.series)
    {
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k)
        {
            gp << s.x[k] << ' ' << s.y[k] << '\n';
        }
        gp << "e\n";
    }

    FILE* pipe = ::popen("gnuplot 2>&1", "w");
    if (!pipe)
    {
        throw std::runtime_error("cannot start gnuplot (install gnuplot-nox)");
    }
    const std::string script = gp.str();
    std::fwrite(script.data(), 1, script.size(), pipe);
    const int status = ::pclose(pipe);
    // gnuplot exits 0 even when its PNG could not be written whole
    if (status != 0 || !pngComplete(temp))
    {
        std::error_code ec;
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + path.string() + " (gnuplot's PNG is missing or "
                                 "incomplete: disk full or not writable?)");
    }
    std::filesystem::rename(temp, path);
}

} // namespace drum
