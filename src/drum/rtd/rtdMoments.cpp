#include "drum/rtd/rtdMoments.hpp"

#include "drum/io/inputError.hpp"

#include <Eigen/SparseLU>
#include <cmath>

namespace drum
{

double RtdMoments::sd() const
{
    return std::sqrt(std::max(variance, 0.0));
}

RtdMoments sampledMoments(const std::vector<double>& t, const std::vector<double>& E)
{
    if (t.size() != E.size() || t.size() < 2)
    {
        throw InputError("", "RTD curve", "times and E(t) must have the same length >= 2");
    }
    double m0 = 0, m1 = 0;
    for (std::size_t i = 1; i < t.size(); ++i)
    {
        if (t[i] < t[i - 1])
        {
            throw InputError("", "RTD curve", "times must be ascending");
        }
        if (t[i - 1] < 0)
        {
            continue;
        }
        const double h = t[i] - t[i - 1];
        m0 += 0.5*h*(E[i] + E[i - 1]);
        m1 += 0.5*h*(t[i]*E[i] + t[i - 1]*E[i - 1]);
    }
    RtdMoments m;
    m.area = m0;
    if (m0 <= 0)
    {
        return m;
    }
    m.mean = m1/m0;
    double m2 = 0, m3 = 0;
    for (std::size_t i = 1; i < t.size(); ++i)
    {
        if (t[i - 1] < 0)
        {
            continue;
        }
        const double h = t[i] - t[i - 1];
        const double a = t[i - 1] - m.mean, b = t[i] - m.mean;
        m2 += 0.5*h*(a*a*E[i - 1] + b*b*E[i]);
        m3 += 0.5*h*(a*a*a*E[i - 1] + b*b*b*E[i]);
    }
    m.variance = m2/m0;
    m.skewness = m.variance > 0 ? m3/m0/std::pow(m.variance, 1.5) : 0.0;
    return m;
}

RtdMoments exactMoments(const TracerSystem& sys, const double T)
{
    Eigen::SparseMatrix<double> A = -sys.K;
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success)
    {
        throw InputError("", "tracer network",
            "rate matrix is singular: some tracer can never leave the drum");
    }
    const Eigen::VectorXd z1 = lu.solve(sys.b);
    const Eigen::VectorXd z2 = lu.solve(z1);
    const Eigen::VectorXd z3 = lu.solve(z2);
    const Eigen::VectorXd z4 = lu.solve(z3);
    const double M0 = sys.c.dot(z1);
    const double M1 = sys.c.dot(z2)/M0;          // raw moments of the impulse response
    const double M2 = 2.0*sys.c.dot(z3)/M0;
    const double M3 = 6.0*sys.c.dot(z4)/M0;

    RtdMoments m;
    m.area = M0;
    const double var = M2 - M1*M1;
    const double mu3 = M3 - 3.0*M1*M2 + 2.0*M1*M1*M1;
    // Rectangular pulse: add an independent U(0, T) delay
    m.mean = M1 + 0.5*T;
    m.variance = var + T*T/12.0;
    m.skewness = mu3/std::pow(m.variance, 1.5);
    return m;
}

} // namespace drum
