#include "drum/rtd/metzlerExponential.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>

namespace drum
{

namespace
{

constexpr double pruneTol = 1e-22;

double bandMax(const BandedMatrix& A);

//- Zero entries below tol*max and recompute the band
void prune(BandedMatrix& A)
{
    const Eigen::Index n = A.a.rows();
    const double cut = pruneTol*bandMax(A);
    int lo = 0, up = 0;
    for (Eigen::Index j = 0; j < n; ++j)
    {
        const Eigen::Index i0 = std::max<Eigen::Index>(0, j - A.upper);
        const Eigen::Index i1 = std::min<Eigen::Index>(n - 1, j + A.lower);
        for (Eigen::Index i = i0; i <= i1; ++i)
        {
            double& v = A.a(i, j);
            if (v < cut)
            {
                v = 0;
            }
            else
            {
                lo = std::max(lo, int(i - j));
                up = std::max(up, int(j - i));
            }
        }
    }
    A.lower = lo;
    A.upper = up;
}

//- Zero A over its band (cheap reset of a reused buffer)
void clearBand(BandedMatrix& A)
{
    const Eigen::Index n = A.a.rows();
    for (Eigen::Index j = 0; j < n; ++j)
    {
        const Eigen::Index i0 = std::max<Eigen::Index>(0, j - A.upper);
        const Eigen::Index i1 = std::min<Eigen::Index>(n - 1, j + A.lower);
        A.a.col(j).segment(i0, i1 - i0 + 1).setZero();
    }
    A.lower = A.upper = 0;
}

//- C = scale A B over the bands, into a reused n x n buffer C
void productInto(const BandedMatrix& A, const BandedMatrix& B, double scale, BandedMatrix& C)
{
    const Eigen::Index n = A.a.rows();
    if (C.a.rows() != n)
    {
        C.a.setZero(n, n);
    }
    else
    {
        clearBand(C);
    }
    C.lower = std::min<int>(int(n - 1), A.lower + B.lower);
    C.upper = std::min<int>(int(n - 1), A.upper + B.upper);
    for (Eigen::Index j = 0; j < n; ++j)
    {
        const Eigen::Index k0 = std::max<Eigen::Index>(0, j - B.upper);
        const Eigen::Index k1 = std::min<Eigen::Index>(n - 1, j + B.lower);
        for (Eigen::Index k = k0; k <= k1; ++k)
        {
            const double b = B.a(k, j);
            if (b == 0) continue;
            const Eigen::Index i0 = std::max<Eigen::Index>(0, k - A.upper);
            const Eigen::Index i1 = std::min<Eigen::Index>(n - 1, k + A.lower);
            C.a.col(j).segment(i0, i1 - i0 + 1) += (scale*b)*A.a.col(k).segment(i0, i1 - i0 + 1);
        }
    }
    prune(C);
}

//- Largest entry within the band
double bandMax(const BandedMatrix& A)
{
    const Eigen::Index n = A.a.rows();
    double m = 0;
    for (Eigen::Index j = 0; j < n; ++j)
    {
        const Eigen::Index i0 = std::max<Eigen::Index>(0, j - A.upper);
        const Eigen::Index i1 = std::min<Eigen::Index>(n - 1, j + A.lower);
        m = std::max(m, A.a.col(j).segment(i0, i1 - i0 + 1).maxCoeff());
    }
    return m;
}

//- S += T over T's band (S's band widened to cover it)
void addBand(BandedMatrix& S, const BandedMatrix& T)
{
    const Eigen::Index n = S.a.rows();
    for (Eigen::Index j = 0; j < n; ++j)
    {
        const Eigen::Index i0 = std::max<Eigen::Index>(0, j - T.upper);
        const Eigen::Index i1 = std::min<Eigen::Index>(n - 1, j + T.lower);
        S.a.col(j).segment(i0, i1 - i0 + 1) += T.a.col(j).segment(i0, i1 - i0 + 1);
    }
    S.lower = std::max(S.lower, T.lower);
    S.upper = std::max(S.upper, T.upper);
}

} // namespace


Eigen::VectorXd BandedMatrix::operator*(const Eigen::VectorXd& x) const
{
    const Eigen::Index n = a.rows();
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
    for (Eigen::Index j = 0; j < n; ++j)
    {
        if (x(j) == 0) continue;
        const Eigen::Index i0 = std::max<Eigen::Index>(0, j - upper);
        const Eigen::Index i1 = std::min<Eigen::Index>(n - 1, j + lower);
        y.segment(i0, i1 - i0 + 1) += x(j)*a.col(j).segment(i0, i1 - i0 + 1);
    }
    return y;
}


BandedMatrix metzlerExponential(const Eigen::SparseMatrix<double>& M, const double h)
{
    const Eigen::Index n = M.rows();
    if (M.cols() != n)
    {
        throw InputError("", "rate matrix", "must be square");
    }
    BandedMatrix N;
    N.a.setZero(n, n);
    double L = 0;
    for (int k = 0; k < M.outerSize(); ++k)
    {
        for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it)
        {
            N.a(it.row(), it.col()) += it.value();
        }
    }
    for (Eigen::Index j = 0; j < n; ++j)
    {
        for (Eigen::Index i = 0; i < n; ++i)
        {
            const double v = N.a(i, j);
            if (i != j && v < 0)
            {
                throw InputError("", "rate matrix",
                    "negative off-diagonal entry: not a compartment (Metzler) matrix");
            }
            if (v != 0)
            {
                N.lower = std::max(N.lower, int(i - j));
                N.upper = std::max(N.upper, int(j - i));
            }
        }
        L = std::max(L, -N.a(j, j));
    }
    // Step d = h/2^s with L d <= 1/2
    int s = 0;
    while (L*h/std::ldexp(1.0, s) > 0.5) ++s;
    const double d = h/std::ldexp(1.0, s);
    for (Eigen::Index j = 0; j < n; ++j) N.a(j, j) += L;
    N.a *= d;

    // S = sum_k (N d)^k/k!, terms >= 0
    BandedMatrix S;
    S.a.setIdentity(n, n);
    BandedMatrix T = S, W;
    for (int k = 1; k < 200; ++k)
    {
        // powers of N commute; T N streams long columns of T
        productInto(T, N, 1.0/k, W);
        std::swap(T, W);
        const double tMax = bandMax(T);
        if (tMax == 0) break;
        addBand(S, T);
        if (tMax < 1e-18*bandMax(S)) break;
    }
    const double damp = std::exp(-L*d);
    for (int i = 0; i < s; ++i)
    {
        productInto(S, S, i == 0 ? damp*damp : 1.0, W);
        std::swap(S, W);
    }
    if (s == 0)
    {
        S.a *= damp;
    }
    return S;
}

} // namespace drum
