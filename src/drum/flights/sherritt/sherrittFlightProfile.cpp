#include "drum/flights/sherritt/sherrittFlightProfile.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

std::string indexed(const char* what, std::size_t i)
{
    std::ostringstream os;
    os << what << "[" << i << "]";
    return os.str();
}
} // namespace


SherrittFlightProfile::SherrittFlightProfile
(
    std::vector<double> angles,
    std::vector<double> lengths,
    FlightSide side,
    double tipDiameter,
    int count,
    double axialLength,
    std::string source
)
:
    angles_(std::move(angles)),
    lengths_(std::move(lengths)),
    side_(side),
    tipDiameter_(tipDiameter),
    count_(count),
    axialLength_(axialLength),
    source_(std::move(source))
{
    if (angles_.size() != lengths_.size())
    {
        std::ostringstream os;
        os << angles_.size() << " angles but " << lengths_.size()
           << " lengths: the table needs one length per angle";
        throw InputError(source_, "flight table", os.str());
    }
    if (angles_.size() < 2)
    {
        throw InputError(source_, "flight table",
            "needs at least 2 (angle, length) rows");
    }
    for (std::size_t i = 0; i < angles_.size(); ++i)
    {
        if (!std::isfinite(angles_[i]) || std::abs(angles_[i]) > 4*pi)
        {
            std::ostringstream os;
            os << "angle " << angles_[i] << " rad outside [-4 pi, 4 pi]";
            throw InputError(source_, indexed("flight table angle", i), os.str());
        }
        if (i > 0 && !(angles_[i] > angles_[i - 1]))
        {
            std::ostringstream os;
            os << "angle " << angles_[i] << " rad not above the previous "
               << angles_[i - 1] << ": angles must be strictly ascending";
            throw InputError(source_, indexed("flight table angle", i), os.str());
        }
        if (!(lengths_[i] >= 0.0) || !std::isfinite(lengths_[i]))
        {
            std::ostringstream os;
            os << "length " << lengths_[i] << " m outside [0, inf)";
            throw InputError(source_, indexed("flight table length", i), os.str());
        }
    }
    requirePositive(tipDiameter_, "flight tip diameter", source_);
    if (count_ < 1 || count_ > 1000)
    {
        std::ostringstream os;
        os << "number of flights " << count_ << " outside [1, 1000]";
        throw InputError(source_, "flight count", os.str());
    }
    requirePositive(axialLength_, "flight axial length", source_);
}


double SherrittFlightProfile::emptyAngle() const
{
    return side_ == FlightSide::exterior ? 2*pi : pi;
}


double SherrittFlightProfile::horizontalLength(double angle) const
{
    const auto& x = angles_;
    const auto& y = lengths_;
    std::size_t k;
    if (angle <= x.front())
    {
        k = 0;
    }
    else if (angle >= x.back())
    {
        k = x.size() - 2;
    }
    else
    {
        k = static_cast<std::size_t>
        (
            std::upper_bound(x.begin(), x.end(), angle) - x.begin()
        ) - 1;
    }
    const double s = (y[k + 1] - y[k])/(x[k + 1] - x[k]);
    return y[k] + s*(angle - x[k]);
}


void SherrittFlightProfile::checkTipsAgainst(double wallDiameter, const std::string& entry) const
{
    std::ostringstream os;
    if (side_ == FlightSide::exterior && !(tipDiameter_ < wallDiameter))
    {
        os << "exterior flight tip diameter " << tipDiameter_
           << " m must lie inside the shell: range (0, " << wallDiameter << ") m";
        throw InputError(source_, entry, os.str());
    }
    if (side_ == FlightSide::interior && !(tipDiameter_ > wallDiameter))
    {
        os << "interior flight tip diameter " << tipDiameter_
           << " m must lie outside the centrefill wall: range ("
           << wallDiameter << ", shell diameter) m";
        throw InputError(source_, entry, os.str());
    }
}

} // namespace drum
