#include "scoring/tunnelCollection.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

//- One class's parts of its own feed: on the suspended platform (and their
//  moment about the tunnel's start), on the fixed platform, lost
struct ClassShares
{
    double suspended = 0, suspendedMoment = 0, fixed = 0, lost = 0;
};

//- A bin's net crossing of a plane inside the fall can be negative: near the
//  release and above a floor the gas carries fines back up across the plane
//  (measured down to -1e-3 of the class's flux, 1.5 m above a floor). It counts
//  as it is, net. Neither a bin nor the class's caught parts together can carry
//  more than the class's feed down (1 % over, the steady state's wobble); a bin
//  cannot carry more than all of it back up, and the caught parts' net crossing
//  cannot be an upflow
constexpr double maxFeedShare = 1.01;
constexpr double maxNetUpflow = 1;
constexpr double maxCaughtUpflow = 1e-2;

ClassShares classShares
(
    const ClassLanding& landing,
    const TunnelFloor& floor,
    const std::string& source,
    std::size_t i
)
{
    ClassShares s;
    const double tol = 1e-9*std::max(1.0, floor.suspendedEnd);
    for (const auto& b : landing.bins)
    {
        if (!(b.fraction >= -maxNetUpflow && b.fraction <= maxFeedShare))
        {
            std::ostringstream os;
            os << "class " << i << ": fraction " << b.fraction << " in the bin " << b.xLow << "-"
               << b.xHigh << " m outside [" << -maxNetUpflow << ", " << maxFeedShare << "]";
            throw InputError(source, "fraction_of_inflow", os.str());
        }
        if (b.xLow < floor.suspendedEnd - tol && b.xHigh > floor.suspendedEnd + tol)
        {
            std::ostringstream os;
            os << "the bin " << b.xLow << "-" << b.xHigh << " m straddles the suspended platform's end at "
               << floor.suspendedEnd << " m: bins must have an edge there";
            throw InputError(source, "x_low_m", os.str());
        }
        if (b.fraction == 0) continue;
        if (b.xHigh <= floor.suspendedEnd + tol)
        {
            s.suspended += b.fraction;              // weighed by the load cells: exact centre
            s.suspendedMoment += b.fraction*b.xCentre;
        }
        else
        {
            s.fixed += b.fraction;                  // swept up: the platform's centre
        }
    }
    if (s.suspended + s.fixed < -maxCaughtUpflow)
    {
        std::ostringstream os;
        os << "class " << i << ": " << s.suspended + s.fixed
           << " of its feed caught (a net upflow through the whole plane)";
        throw InputError(source, "fraction_of_inflow", os.str());
    }
    if (s.suspended + s.fixed > maxFeedShare)
    {
        std::ostringstream os;
        os << "class " << i << ": " << s.suspended + s.fixed << " of its feed caught (more than all of it)";
        throw InputError(source, "fraction_of_inflow", os.str());
    }
    s.lost = std::max(0.0, 1 - s.suspended - s.fixed);   // the feed's mass balance
    return s;
}

double moment(const ClassShares& s, const TunnelFloor& floor)
{
    return s.suspendedMoment + s.fixed*floor.fixedCentre() + s.lost*floor.fixedEnd;
}

} // namespace


CollectedAdvance collectedAdvance
(
    const std::vector<ClassLanding>& classes,
    const std::vector<double>& massFractions,
    const TunnelFloor& floor,
    const std::string& source
)
{
    if (classes.size() != massFractions.size() || classes.empty())
    {
        throw InputError(source, "classes", "one mass fraction per landing class needed");
    }
    CollectedAdvance out;
    double m = 0, release = 0, total = 0;
    for (std::size_t i = 0; i < classes.size(); ++i)
    {
        const double w = massFractions[i];
        const ClassShares s = classShares(classes[i], floor, source, i);
        out.suspended += w*s.suspended;
        out.fixed += w*s.fixed;
        out.lost += w*s.lost;
        m += w*moment(s, floor);
        total += w*(s.suspended + s.fixed + s.lost);
        release += w*classes[i].releaseCentre;
    }
    out.advance = m/total - release;
    return out;
}


CollectedAdvance classCollectedAdvance
(
    const ClassLanding& landing,
    const TunnelFloor& floor,
    const std::string& source,
    std::size_t index
)
{
    const ClassShares s = classShares(landing, floor, source, index);
    CollectedAdvance out;
    out.suspended = s.suspended;
    out.fixed = s.fixed;
    out.lost = s.lost;
    out.advance = moment(s, floor)/(s.suspended + s.fixed + s.lost) - landing.releaseCentre;
    return out;
}

} // namespace drum
