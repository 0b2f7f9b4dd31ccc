// Banded Metzler exponential against Eigen's dense Pade exponential
// (unsupported/Eigen/MatrixFunctions), an independent method
#include "drum/rtd/metzlerExponential.hpp"
#include "drum/transport/compartment/compartmentLeeDryer.hpp"
#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

using namespace drum;

TEST(MetzlerExponential, MatchesDensePadeOnALeeNetwork)
{
    const CompartmentNetwork net = leeNetwork(LeeDryer{}, 20, {9.0, 0.5, 0.3});
    const TracerSystem sys = net.tracerSystem(net.steadyState());
    for (double h : {0.05, 5.0, 600.0})
    {
        const BandedMatrix B = metzlerExponential(sys.K, h);
        const Eigen::MatrixXd D = (Eigen::MatrixXd(sys.K)*h).exp();
        EXPECT_LT((B.a - D).cwiseAbs().maxCoeff(), 1e-13) << "h = " << h;
        // Banded matrix-vector product equals the dense one
        const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(sys.size(), 0.0, 1.0);
        EXPECT_LT((B*x - D*x).cwiseAbs().maxCoeff(), 1e-13);
        // Non-negative, as exp of a Metzler matrix must be
        EXPECT_GE(B.a.minCoeff(), 0.0);
    }
}

TEST(MetzlerExponential, StiffTwoTankChainClosedForm)
{
    // Two-tank chain, fast then slow: exp(K t)(1,0) = k1/(k1-k2)(e^{-k2 t} - e^{-k1 t})
    Eigen::MatrixXd K(2, 2);
    K << -5.0, 0.0, 5.0, -0.001;
    const double t = 20.0;
    const BandedMatrix B = metzlerExponential(K.sparseView(), t);
    // Entries below 1e-22 of the largest are dropped (e^{-100} ~ 4e-44)
    EXPECT_NEAR(B.a(0, 0), std::exp(-100.0), 1e-22);
    const double exact = 5.0/4.999*(std::exp(-0.02) - std::exp(-100.0));
    EXPECT_NEAR(B.a(1, 0)/exact, 1.0, 1e-13);
    EXPECT_NEAR(B.a(1, 1)/std::exp(-0.02), 1.0, 1e-13);
}

TEST(MetzlerExponential, RejectsNegativeOffDiagonals)
{
    Eigen::MatrixXd K(2, 2);
    K << -1.0, -0.5, 1.0, -1.0;
    EXPECT_THROW(metzlerExponential(K.sparseView(), 1.0), InputError);
}
