// exp(M h) for a Metzler matrix M (off-diagonal entries >= 0), the rate
// matrix of every compartment network. With L = max(-M_jj) and N = M + L I
// (all entries >= 0), exp(M d) = e^{-L d} sum_k (N d)^k/k!: every term is
// non-negative, so the series has no cancellation (the matrix form of
// uniformization, Grassmann 1977). It is summed for a step d = h/2^s with
// L d <= 1/2 and squared s times. Products run over the band only and drop
// entries below 1e-22 of the largest, so a banded M (nearest-neighbour
// slices) costs O(n b^2) instead of O(n^3).
#ifndef DRUM_RTD_METZLEREXPONENTIAL_HPP
#define DRUM_RTD_METZLEREXPONENTIAL_HPP

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace drum
{

//- A dense square matrix with its band: entries outside [j - lower, j + upper]
//  in column j are zero
struct BandedMatrix
{
    Eigen::MatrixXd a;
    int lower = 0;
    int upper = 0;

    //- y = A x over the band
    Eigen::VectorXd operator*(const Eigen::VectorXd& x) const;
};

//- exp(M h); throws InputError if M has a negative off-diagonal entry
BandedMatrix metzlerExponential(const Eigen::SparseMatrix<double>& M, double h);

} // namespace drum

#endif
