#include "scoring/predictionScore.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace drum
{

PredictionScore scorePredictions
(
    const std::map<int, double>& predicted,
    const std::map<int, double>& measured
)
{
    PredictionScore s;
    double sum2 = 0, sum = 0;
    int hits = 0;
    for (const auto& kv : predicted)
    {
        const auto it = measured.find(kv.first);
        if (it == measured.end())
        {
            continue;
        }
        if (!(kv.second > 0 && it->second > 0))
        {
            throw std::invalid_argument
            (
                "scorePredictions: test " + std::to_string(kv.first)
              + " has a non-positive predicted or measured advance"
            );
        }
        const double e = std::log(kv.second/it->second);
        sum += e;
        sum2 += e*e;
        hits += std::abs(kv.second/it->second - 1.0) <= 0.25;
        ++s.count;
    }
    if (s.count > 0)
    {
        s.rmsLnError = std::sqrt(sum2/s.count);
        s.bias = sum/s.count;
        s.within25 = static_cast<double>(hits)/s.count;
    }
    return s;
}

} // namespace drum
