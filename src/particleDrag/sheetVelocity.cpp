#include "particleDrag/sheetVelocity.hpp"

#include <algorithm>
#include <cmath>

namespace particleDrag
{

double sherrittSheetVelocityRatio(double y, double spill, double L)
{
    // Sherritt 1991 Eq 142, code exponents and cap (sheetgasvel())
    if (y <= 0 || spill <= 0 || L <= 0)
    {
        return 1.0;
    }
    const double ratio =
        1.546*std::pow(y, 0.763)/std::pow(spill, 0.857)/std::pow(L, 0.437);
    return std::min(1.0, ratio);
}

} // namespace particleDrag
