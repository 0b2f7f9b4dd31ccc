// Small tracer networks with closed-form responses, for the RTD tests
#ifndef DRUM_TESTS_RTDTESTNETWORKS_HPP
#define DRUM_TESTS_RTDTESTNETWORKS_HPP

#include "drum/rtd/tracerSystem.hpp"

#include <cmath>
#include <vector>

//- n equal CSTRs in series, each of mean time tau: E(t) = t^{n-1} e^{-t/tau}/((n-1)! tau^n)
inline drum::TracerSystem tanksInSeries(int n, double tau)
{
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
    {
        t.emplace_back(i, i, -1.0/tau);
        if (i + 1 < n) t.emplace_back(i + 1, i, 1.0/tau);
    }
    drum::TracerSystem s;
    s.K.resize(n, n);
    s.K.setFromTriplets(t.begin(), t.end());
    s.b = Eigen::VectorXd::Zero(n);
    s.b(0) = 1.0;
    s.c = Eigen::RowVectorXd::Zero(n);
    s.c(n - 1) = 1.0/tau;
    return s;
}

inline double gammaE(int n, double tau, double t)
{
    return std::exp((n - 1)*std::log(t) - t/tau - std::lgamma(double(n)) - n*std::log(tau));
}

#endif
