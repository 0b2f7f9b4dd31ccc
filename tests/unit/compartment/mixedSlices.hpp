// A six-slice compartment network for the unit tests: slices 1-3
// overloaded (kilning bed), 4-6 underloaded (no bed, a large forward step)
#ifndef TESTS_UNIT_COMPARTMENT_MIXEDSLICES_HPP
#define TESTS_UNIT_COMPARTMENT_MIXEDSLICES_HPP

#include "drum/transport/compartment/compartmentNetwork.hpp"

#include <vector>

namespace drumTest
{

inline std::vector<drum::CompartmentSlice> mixedSlices()
{
    std::vector<drum::CompartmentSlice> s;
    for (int i = 0; i < 6; ++i)
    {
        const bool under = i >= 3;
        s.push_back({under ? 800.0 : 150.0, 10.0 + i, 0.8 + 0.02*i, under ? 0.6 : 0.1, under ? 0.1 : 0.4});
    }
    return s;
}

} // namespace drumTest

#endif
