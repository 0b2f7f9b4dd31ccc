// How Sherritt's wind tunnel measured a test's bulk mean advance (Sherritt
// 1991, section 4.1 and 4.3.1), applied to a computed landing distribution:
// the suspended platform under the first 7.5 m of the tunnel weighs what it
// catches and gives its centre of gravity exactly (load cells); what lands on
// the fixed platform (the remaining 3.8 m) is put at that platform's centre;
// what is lost (the feed's mass balance: everything not caught) is put at the
// fixed platform's far end; the advance is the centre of gravity of all of it
// minus the hopper's. Coordinates along the flow from the tunnel's upstream
// end (the platforms start there).
#ifndef DRUM_WINDTUNNEL_TUNNELCOLLECTION_HPP
#define DRUM_WINDTUNNEL_TUNNELCOLLECTION_HPP

#include <string>
#include <vector>

namespace drum
{

struct TunnelFloor
{
    double suspendedEnd = 7.5;    //!< m, end of the suspended platform (section 4.1)
    double fixedEnd = 7.5 + 3.8;  //!< m, far end of the fixed platform: lost material (4.3.1)
    double fixedCentre() const { return 0.5*(suspendedEnd + fixedEnd); }   // 9.4 m
};

//- One size class's landing at the platform: bins along the flow with the
//  fraction of the class's feed landing in each and that part's mass centre,
//  and the mass centre of its release (the hopper)
struct ClassLanding
{
    struct Bin
    {
        double xLow = 0, xHigh = 0, fraction = 0, xCentre = 0;
    };
    std::vector<Bin> bins;
    double releaseCentre = 0;
};

//- What the tunnel would have recorded for the bulk: the parts of the feed on
//  each platform and lost, and the mean advance
struct CollectedAdvance
{
    double suspended = 0, fixed = 0, lost = 0;   //!< fractions of the feed
    double advance = 0;                           //!< m
};

//- The collection rule over classes weighted by their feed mass fractions
//  (summing to 1). A bin's fraction is its net crossing: at a plane inside
//  the fall it may be negative (fines carried back up), and counts as it is.
//  A bin straddling the suspended platform's end, a fraction outside
//  [-1, 1.01], caught parts above the feed (1.01) or below -0.01 are
//  InputErrors naming `source`.
CollectedAdvance collectedAdvance
(
    const std::vector<ClassLanding>& classes,
    const std::vector<double>& massFractions,
    const TunnelFloor& floor,
    const std::string& source
);

//- The rule for one class alone: what the tunnel would record had only this
//  class been fed (its shares of its own feed, and its advance). The bulk
//  advance of collectedAdvance is the feed-weighted sum of these within the
//  caught parts' overshoot of 1 (below 1e-2). `index` names the class in
//  errors.
CollectedAdvance classCollectedAdvance
(
    const ClassLanding& landing,
    const TunnelFloor& floor,
    const std::string& source,
    std::size_t index = 0
);

} // namespace drum

#endif
