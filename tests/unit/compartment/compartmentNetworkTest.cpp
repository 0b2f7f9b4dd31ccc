// Compartment network: steady state against an independent dynamic
// integration of the mass balances, hand values, flow conservation, input
// checks.
#include "drum/transport/compartment/compartmentNetwork.hpp"
#include "drum/io/inputError.hpp"

#include "mixedSlices.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace drum;

namespace
{

// Classical RK4 on the network's mass rates (independent of steadyState())
Eigen::VectorXd integrateMasses(const CompartmentNetwork& net, Eigen::VectorXd m, double tEnd, double dt)
{
    for (double t = 0; t < tEnd; t += dt)
    {
        const Eigen::VectorXd k1 = net.massRates(m);
        const Eigen::VectorXd k2 = net.massRates(m + 0.5*dt*k1);
        const Eigen::VectorXd k3 = net.massRates(m + 0.5*dt*k2);
        const Eigen::VectorXd k4 = net.massRates(m + dt*k3);
        m += dt/6.0*(k1 + 2*k2 + 2*k3 + k4);
    }
    return m;
}

using drumTest::mixedSlices;

} // namespace


TEST(CompartmentNetwork, SteadyStateIsAFixedPointOfTheDynamicBalances)
{
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    Eigen::VectorXd m(2*net.nSlices());
    for (int i = 0; i < net.nSlices(); ++i)
    {
        m(2*i) = st.passiveMass(i);
        m(2*i + 1) = st.activeMass(i);
    }
    const Eigen::VectorXd r = net.massRates(m);
    EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-10);
    // Both regimes are present
    EXPECT_GT(st.kilnMass(0), 0);
    EXPECT_EQ(st.kilnMass(5), 0);
}

TEST(CompartmentNetwork, DynamicRunFromLeesInitialStateReachesTheSteadyState)
{
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    // gPROMS-like start: uniform guesses, not the steady state
    Eigen::VectorXd m0 = Eigen::VectorXd::Constant(2*net.nSlices(), 40.0);
    for (int i = 0; i < net.nSlices(); ++i) m0(2*i) = 400.0;
    const Eigen::VectorXd m = integrateMasses(net, m0, 6000.0, 0.05);
    const CompartmentSteadyState st = net.steadyState();
    for (int i = 0; i < net.nSlices(); ++i)
    {
        EXPECT_NEAR(m(2*i), st.passiveMass(i), 1e-6*st.passiveMass(i)) << "slice " << i;
        EXPECT_NEAR(m(2*i + 1), st.activeMass(i), 1e-6*st.activeMass(i)) << "slice " << i;
    }
}

TEST(CompartmentNetwork, SingleSliceHandValues)
{
    // Underloaded single slice: all product leaves by the forward step,
    // F = C_F M_p/t_p, so M_p = F t_p/C_F and M_a = F t_a/C_F
    const CompartmentNetwork under({{1000.0, 10.0, 1.0, 0.5, 0.2}}, 2.0, 5.0);
    const CompartmentSteadyState a = under.steadyState();
    EXPECT_DOUBLE_EQ(a.passiveMass(0), 2.0*10.0/0.5);
    EXPECT_DOUBLE_EQ(a.activeMass(0), 2.0*1.0/0.5);
    EXPECT_DOUBLE_EQ(a.kilnFlow(0), 0.0);
    // Overloaded: release capped at 100/10 = 10 kg/s, forward 0.1*10 = 1,
    // kilning carries the other 1 kg/s: M_k = 1*5 s
    const CompartmentNetwork over({{100.0, 10.0, 1.0, 0.1, 0.2}}, 2.0, 5.0);
    const CompartmentSteadyState b = over.steadyState();
    EXPECT_DOUBLE_EQ(b.releaseFlow(0), 10.0);
    EXPECT_DOUBLE_EQ(b.kilnFlow(0), 1.0);
    EXPECT_DOUBLE_EQ(b.passiveMass(0), 105.0);
    EXPECT_DOUBLE_EQ(b.activeMass(0), 10.0);
    EXPECT_DOUBLE_EQ(b.returnFlow(0), 7.0);
}

TEST(CompartmentNetwork, NetAxialFlowEqualsFeedAtEveryBoundary)
{
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    for (int i = 0; i + 1 < net.nSlices(); ++i)
    {
        EXPECT_NEAR(st.kilnFlow(i) + st.forwardFlow(i) - st.backFlow(i + 1), 20.0, 1e-10);
    }
    const int n = net.nSlices() - 1;
    EXPECT_NEAR(st.kilnFlow(n) + st.forwardFlow(n), 20.0, 1e-10);
}

TEST(CompartmentNetwork, TracerSystemConservesTracer)
{
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const TracerSystem sys = net.tracerSystem(net.steadyState());
    // Column sums of K plus the outflow to the product vanish
    const Eigen::RowVectorXd colSum = Eigen::RowVectorXd::Ones(sys.size())*Eigen::MatrixXd(sys.K) + sys.c;
    EXPECT_LT(colSum.cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_DOUBLE_EQ(sys.b.sum(), 1.0);
    // Off-diagonal entries are non-negative (Metzler matrix)
    const Eigen::MatrixXd K(sys.K);
    for (int i = 0; i < K.rows(); ++i)
    {
        for (int j = 0; j < K.cols(); ++j)
        {
            if (i != j)
            {
                EXPECT_GE(K(i, j), 0.0);
            }
        }
    }
}

TEST(CompartmentNetwork, BadInputNamesTheEntry)
{
    EXPECT_THROW(CompartmentNetwork({{100, 10, 1, 0.7, 0.4}}, 1.0, 5.0), InputError);
    EXPECT_THROW(CompartmentNetwork({{100, 10, 1, 0.1, 0.1}}, -1.0, 5.0), InputError);
    EXPECT_THROW(CompartmentNetwork({{100, 0, 1, 0.1, 0.1}}, 1.0, 5.0), InputError);
    EXPECT_THROW(CompartmentNetwork({}, 1.0, 5.0), InputError);
    try
    {
        CompartmentNetwork({{100, 10, 1, 0.7, 0.4}}, 1.0, 5.0);
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("C_F + C_B"), std::string::npos);
    }
    // No kilning and a slice that cannot pass the feed: no steady state
    const CompartmentNetwork blocked({{100, 10, 1, 0.1, 0.1}}, 5.0, std::numeric_limits<double>::infinity());
    EXPECT_THROW(blocked.steadyState(), InputError);
}

TEST(CompartmentNetwork, StagnantZonesAddTheirMassToTheMeanResidenceTime)
{
    // Holdup theorem: mean residence time = tracer-accessible mass / feed
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    const StagnantExchange z{0.3, 500.0};
    const TracerSystem sys = net.tracerSystem(st, z);
    ASSERT_EQ(sys.size(), 3*net.nSlices());
    const Eigen::RowVectorXd colSum = Eigen::RowVectorXd::Ones(sys.size())*Eigen::MatrixXd(sys.K) + sys.c;
    EXPECT_LT(colSum.cwiseAbs().maxCoeff(), 1e-14);
    // -K^-1 b summed = mean time (impulse): solve densely, independent of rtdMoments
    const Eigen::VectorXd z1 = Eigen::MatrixXd(-sys.K).partialPivLu().solve(sys.b);
    const double holdup = st.totalHoldup() + z.massRatio*st.passiveMass.sum();
    EXPECT_NEAR(z1.sum(), holdup/20.0, 1e-9*holdup);
    // No stagnant mass: the plain network
    const TracerSystem plain = net.tracerSystem(st, StagnantExchange{});
    EXPECT_EQ(plain.size(), 2*net.nSlices());
}
