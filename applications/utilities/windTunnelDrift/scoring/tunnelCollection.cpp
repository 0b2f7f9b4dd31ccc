#include "scoring/tunnelCollection.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

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
    double moment = 0, release = 0, total = 0;
    const double tol = 1e-9*std::max(1.0, floor.suspendedEnd);
    for (std::size_t i = 0; i < classes.size(); ++i)
    {
        const double w = massFractions[i];
        double susp = 0, suspX = 0, fixed = 0;
        for (const auto& b : classes[i].bins)
        {
            if (!(b.fraction >= -1e-9 && b.fraction <= 1.01))
            {
                std::ostringstream os;
                os << "class " << i << ": fraction " << b.fraction << " in the bin " << b.xLow << "-"
                   << b.xHigh << " m outside [0, 1]";
                throw InputError(source, "fraction_of_inflow", os.str());
            }
            if (b.xLow < floor.suspendedEnd - tol && b.xHigh > floor.suspendedEnd + tol)
            {
                std::ostringstream os;
                os << "the bin " << b.xLow << "-" << b.xHigh << " m straddles the suspended platform's end at "
                   << floor.suspendedEnd << " m: bins must have an edge there";
                throw InputError(source, "x_low_m", os.str());
            }
            if (b.fraction <= 0) continue;
            if (b.xHigh <= floor.suspendedEnd + tol)
            {
                susp += b.fraction;              // weighed by the load cells: exact centre
                suspX += b.fraction*b.xCentre;
            }
            else
            {
                fixed += b.fraction;             // swept up: the platform's centre
            }
        }
        if (susp + fixed > 1.01)
        {
            std::ostringstream os;
            os << "class " << i << ": " << susp + fixed << " of its feed caught (more than all of it)";
            throw InputError(source, "fraction_of_inflow", os.str());
        }
        const double lost = std::max(0.0, 1 - susp - fixed);   // the feed's mass balance
        out.suspended += w*susp;
        out.fixed += w*fixed;
        out.lost += w*lost;
        moment += w*(suspX + fixed*floor.fixedCentre() + lost*floor.fixedEnd);
        total += w*(susp + fixed + lost);
        release += w*classes[i].releaseCentre;
    }
    out.advance = moment/total - release;
    return out;
}

} // namespace drum
