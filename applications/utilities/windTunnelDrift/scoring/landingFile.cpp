#include "scoring/landingFile.hpp"

#include "drum/io/csv.hpp"
#include "drum/io/inputError.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <sstream>

namespace drum
{

namespace
{
//- The number a whole field spells; an underflow (a denormal flux, 1e-320,
//  as OpenFOAM prints it) reads as the tiny value strtod gives, not an error
double fieldNumber(const std::string& text)
{
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') throw std::invalid_argument(text);
    return v;
}
} // namespace


std::map<double, std::vector<ClassLanding>> readLandingFile(const std::filesystem::path& file)
{
    const std::string f = file.string();
    if (!std::filesystem::exists(file)) throw InputError(f, "", "curtainCase wrote no landing distribution");
    requireReadableFile(f);
    // per height and class index: the landing, and whether its slot row was read
    std::map<double, std::map<std::size_t, std::pair<ClassLanding, bool>>> byHeight;
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
            auto& [c, released] = byHeight[y][i];
            if (lo == "lost") continue;        // the rule counts the loss by the feed's balance
            try
            {
                if (lo == "slot")
                {
                    c.releaseCentre = fieldNumber(xc);
                    released = true;
                    continue;
                }
                ClassLanding::Bin b;
                b.xLow = fieldNumber(lo);
                b.xHigh = fieldNumber(hi);
                b.fraction = fieldNumber(frac);
                b.xCentre = xc == "nan" || xc == "NaN" ? 0.5*(b.xLow + b.xHigh) : fieldNumber(xc);
                if (!std::isfinite(b.xLow) || !std::isfinite(b.xHigh) || !std::isfinite(b.fraction)
                 || !std::isfinite(b.xCentre))
                {
                    throw std::invalid_argument(xc);
                }
                c.bins.push_back(b);
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
    std::map<double, std::vector<ClassLanding>> out;
    for (auto& [y, classes] : byHeight)
    {
        std::vector<ClassLanding> v;
        for (auto& [i, entry] : classes)
        {
            auto& [c, released] = entry;
            if (i != v.size() || !released || c.bins.empty())
            {
                std::ostringstream os;
                os << "no slot row or no bins of class c" << v.size() << " at fall height " << y << " m";
                throw InputError(f, "class rows", os.str());
            }
            v.push_back(std::move(c));
        }
        out[y] = std::move(v);
    }
    return out;
}


std::vector<ClassLanding> landingAt
(
    const std::map<double, std::vector<ClassLanding>>& landings,
    double fallHeight,
    std::size_t classes,
    const std::filesystem::path& file
)
{
    for (const auto& [y, v] : landings)
    {
        if (std::abs(y - fallHeight) > 1e-6*std::max(1.0, fallHeight)) continue;
        if (v.size() != classes)
        {
            std::ostringstream os;
            os << v.size() << " classes at fall height " << fallHeight << " m, the row has " << classes;
            throw InputError(file.string(), "class rows", os.str());
        }
        return v;
    }
    std::ostringstream os;
    os << "no slot row or no bins of class c0 at fall height " << fallHeight << " m";
    throw InputError(file.string(), "class rows", os.str());
}

} // namespace drum
