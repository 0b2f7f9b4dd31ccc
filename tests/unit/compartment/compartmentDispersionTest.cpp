// Passive-phase axial dispersion in the compartment network
// (compartmentDispersion.hpp): tracer conservation, the bulk steady state
// untouched, the mean unchanged (holdup theorem), the variance against the
// exact backflow-cell formula and the continuum 2 D L/u^3, the numerical
// part u_b dz/2, Sherritt 2001 Eq 84 per slice by hand, bad input.
#include "drum/transport/compartment/compartmentDispersion.hpp"
#include "drum/io/inputError.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "drum/numerics/constants.hpp"

#include "mixedSlices.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>

using namespace drum;

namespace
{

using drum::pi;

using drumTest::mixedSlices;

// N equal slices carried by kilning only (C_F = C_B = 0): design load 1 kg,
// t_p 10 s, a fast fall (t_a 1e-4 s, 1e-5 kg airborne) and t_kiln 100 s, so
// at F = 1 kg/s every passive cell holds 101 kg of which 100 kg kiln: a chain
// of equal tanks with a uniform flow
CompartmentNetwork chain(int n)
{
    return CompartmentNetwork(std::vector<CompartmentSlice>(n, {1.0, 10.0, 1e-4, 0.0, 0.0}), 1.0, 100.0);
}

// masses in the tracer-state order (P_1, A_1, ...)
Eigen::VectorXd stateMasses(const CompartmentSteadyState& st)
{
    Eigen::VectorXd m(2*st.passiveMass.size());
    for (Eigen::Index i = 0; i < st.passiveMass.size(); ++i)
    {
        m(2*i) = st.passiveMass(i);
        m(2*i + 1) = st.activeMass(i);
    }
    return m;
}

double columnSumDefect(const TracerSystem& sys)
{
    const Eigen::RowVectorXd colSum = Eigen::RowVectorXd::Ones(sys.size())*Eigen::MatrixXd(sys.K) + sys.c;
    return colSum.cwiseAbs().maxCoeff();
}

} // namespace


TEST(CompartmentDispersion, ConservesTracerAndLeavesTheSteadyStateUnchanged)
{
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    PassiveDispersion d;
    d.coefficient = {0.01};
    d.sliceLength = 0.5;
    d.bed = DispersionBed::passive;   // every face exchanges
    PassiveDispersionSummary s;
    const TracerSystem plain = net.tracerSystem(st);
    const TracerSystem sys = withPassiveDispersion(plain, st, d, &s);
    EXPECT_EQ(s.boundaries, 5);
    // the exchange really is there
    EXPECT_GT((Eigen::MatrixXd(sys.K) - Eigen::MatrixXd(plain.K)).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_LT(columnSumDefect(sys), 1e-14);
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
    // a feed labelled throughout at steady state is a steady tracer field
    // y = M: K M + F b = 0 holds with the exchange iff it moves no net mass
    const Eigen::VectorXd m = stateMasses(st);
    EXPECT_LT((K*m + 20.0*sys.b).cwiseAbs().maxCoeff(), 1e-12*20.0);

    // with stagnant zones appended (states 2N..3N-1) the same
    const StagnantExchange z{0.3, 500.0};
    const TracerSystem sz = withPassiveDispersion(net.tracerSystem(st, z), st, d);
    ASSERT_EQ(sz.size(), 3*net.nSlices());
    EXPECT_LT(columnSumDefect(sz), 1e-14);
    Eigen::VectorXd mz(3*net.nSlices());
    mz.head(2*net.nSlices()) = m;
    mz.tail(net.nSlices()) = z.massRatio*st.passiveMass;
    EXPECT_LT((Eigen::MatrixXd(sz.K)*mz + 20.0*sz.b).cwiseAbs().maxCoeff(), 1e-12*20.0);
}

TEST(CompartmentDispersion, MeanResidenceTimeIsHoldupOverFeedWithAndWithoutDispersion)
{
    // closed ends (no exchange across the feed end or into the product) and
    // a symmetric exchange: the holdup theorem keeps the mean exactly
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    const double T = st.totalHoldup()/20.0;
    PassiveDispersion d;
    d.coefficient = {0.05};
    d.sliceLength = 0.5;
    for (DispersionBed bed : {DispersionBed::kiln, DispersionBed::passive})
    {
        d.bed = bed;
        const RtdMoments plain = exactMoments(net.tracerSystem(st), 0.0);
        const RtdMoments with = exactMoments(withPassiveDispersion(net.tracerSystem(st), st, d), 0.0);
        EXPECT_NEAR(plain.mean, T, 1e-10*T);
        EXPECT_NEAR(with.mean, T, 1e-10*T) << toString(bed);
        EXPECT_GT(with.variance, plain.variance*(1 + 1e-6)) << toString(bed);
    }
}

TEST(CompartmentDispersion, ChainVarianceIsTheBackflowCellModel)
{
    // N equal tanks (mass M, flow F) with an exchange G = alpha F each way
    // between neighbours, closed ends: sigma^2/tau^2 = (1 + 2 alpha)/N
    //   - 2 alpha (1 + alpha)/N^2 (1 - (alpha/(1 + alpha))^N)
    // (backflow cell model; alpha = 0: tanks in series, 1/N)
    const int n = 10;
    const double L = 10.0, dz = L/n, F = 1.0;
    const CompartmentNetwork net = chain(n);
    const CompartmentSteadyState st = net.steadyState();
    ASSERT_NEAR(st.kilnMass(3), 100.0, 1e-9);
    const double Mcell = st.passiveMass(0) + st.activeMass(0);
    const double tau = n*Mcell/F;
    PassiveDispersion d;
    d.sliceLength = dz;
    d.coefficient = {0.008};   // G = D M_kiln/dz^2 = 0.8 kg/s
    const double alpha = 0.008*100.0/(dz*dz)/F;
    const RtdMoments plain = exactMoments(net.tracerSystem(st), 0.0);
    EXPECT_NEAR(plain.variance, tau*tau/n, 1e-6*tau*tau/n);
    const RtdMoments with = exactMoments(withPassiveDispersion(net.tracerSystem(st), st, d), 0.0);
    const double r = alpha/(1 + alpha);
    const double backflow = tau*tau*((1 + 2*alpha)/n - 2*alpha*(1 + alpha)/(n*n)*(1 - std::pow(r, n)));
    EXPECT_NEAR(with.mean, tau, 1e-9*tau);
    EXPECT_NEAR(with.variance, backflow, 1e-6*backflow);
}

TEST(CompartmentDispersion, SmallDispersionAddsTwoDLOverUCubed)
{
    // many slices, small D: the increase over the tanks in series is the
    // continuum closed-closed 2 D' L/u^3 with D' = D M_kiln/M_cell the
    // dispersion of the slice-average concentration and u = F dz/M_cell
    const int n = 200;
    const double L = 10.0, dz = L/n, F = 1.0, D = 1e-5;
    const CompartmentNetwork net = chain(n);
    const CompartmentSteadyState st = net.steadyState();
    const double Mcell = st.passiveMass(0) + st.activeMass(0);
    PassiveDispersion d;
    d.sliceLength = dz;
    d.coefficient = {D};
    const double v0 = exactMoments(net.tracerSystem(st), 0.0).variance;
    const double v1 = exactMoments(withPassiveDispersion(net.tracerSystem(st), st, d), 0.0).variance;
    const double u = F*dz/Mcell, Dcell = D*st.kilnMass(0)/Mcell;
    const double continuum = 2*Dcell*L/(u*u*u);
    std::printf("chain N = %d: added variance %.6g s2, 2 D' L/u^3 %.6g s2\n", n, v1 - v0, continuum);
    // the discrete correction is (1 + alpha)/N = 0.7 % here
    EXPECT_NEAR(v1 - v0, continuum, 0.015*continuum);
}

TEST(CompartmentDispersion, NumericalPartIsTheKilningUpwindStep)
{
    // kiln bed moving at u_b = F_k dz/M_kiln = dz/t_kiln: u_b dz/2 = dz^2/(2 t_kiln)
    const int n = 10;
    const double dz = 1.0;
    const CompartmentNetwork net = chain(n);
    const CompartmentSteadyState st = net.steadyState();
    PassiveDispersion d;
    d.sliceLength = dz;
    d.coefficient = {0.008};
    PassiveDispersionSummary s;
    withPassiveDispersion(net.tracerSystem(st), st, d, &s);
    EXPECT_EQ(s.boundaries, n - 1);
    EXPECT_NEAR(s.meanNumerical, dz*dz/(2*100.0), 1e-12);
    EXPECT_NEAR(s.meanAdded, 0.008, 1e-15);
    EXPECT_EQ(s.numericalExceeds, 0);
    // subtracted: D - u_b dz/2 = 0.003 is exchanged, i.e. alpha = 0.3
    d.subtractNumerical = true;
    const TracerSystem sub = withPassiveDispersion(net.tracerSystem(st), st, d, &s);
    EXPECT_NEAR(s.meanAdded, 0.003, 1e-12);
    d.subtractNumerical = false;
    d.coefficient = {0.003};
    const double v = exactMoments(withPassiveDispersion(net.tracerSystem(st), st, d), 0.0).variance;
    EXPECT_NEAR(exactMoments(sub, 0.0).variance, v, 1e-9*v);
    // below the numerical part nothing is added when subtracting
    d.subtractNumerical = true;
    d.coefficient = {0.001};
    const double v0 = exactMoments(net.tracerSystem(st), 0.0).variance;
    EXPECT_NEAR(exactMoments(withPassiveDispersion(net.tracerSystem(st), st, d, &s), 0.0).variance, v0, 1e-9*v0);
    EXPECT_EQ(s.numericalExceeds, n - 1);
    EXPECT_EQ(s.meanAdded, 0.0);
}

TEST(CompartmentDispersion, KilnBedExchangesOnlyWhereThereIsABed)
{
    // slices 4-6 are below their design load: no kiln bed, so the faces
    // 4|5 and 5|6 carry no exchange; face 3|4 has the bed of slice 3 only
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    ASSERT_GT(st.kilnMass(2), 0);
    ASSERT_EQ(st.kilnMass(3), 0);
    PassiveDispersion d;
    d.coefficient = {0.01};
    d.sliceLength = 0.5;
    PassiveDispersionSummary s;
    const TracerSystem plain = net.tracerSystem(st);
    const Eigen::MatrixXd dK = Eigen::MatrixXd(withPassiveDispersion(plain, st, d, &s).K) - Eigen::MatrixXd(plain.K);
    EXPECT_EQ(s.boundaries, 3);
    const int p3 = CompartmentNetwork::passiveIndex(2), p4 = CompartmentNetwork::passiveIndex(3),
              p5 = CompartmentNetwork::passiveIndex(4);
    const double G = 0.01*0.5*st.kilnMass(2)/(0.5*0.5);
    EXPECT_NEAR(dK(p4, p3), G/st.passiveMass(2), 1e-12);
    EXPECT_NEAR(dK(p3, p4), G/st.passiveMass(3), 1e-12);
    EXPECT_EQ(dK(p5, p4), 0.0);
    EXPECT_EQ(dK(p4, p5), 0.0);
}

TEST(CompartmentDispersion, Sherritt2001PerSliceFromTheKilnBed)
{
    // Eq 84 by hand in each kilning slice, X = M_kiln/(rho_b pi D^2/4 dz);
    // a 5 m drum is outside the fitted 0.05-0.6 m and says so
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    PassiveDispersionDrum drum;
    drum.drumDiameter = 5.0;
    drum.speed = 3.0/60;
    drum.particleDiameter = 850e-6;
    drum.bulkDensity = 940;
    drum.sliceLength = 0.05;
    const PassiveSherritt2001 r = sherritt2001PassiveDispersion(st, DispersionBed::kiln, drum);
    const double nc = std::sqrt(9.81/2.5)/(2*pi);
    EXPECT_NEAR(r.reference.speedRatio, 0.05/nc, 1e-12);
    EXPECT_EQ(r.reference.regime, BedRegime::rollingCascading);
    EXPECT_EQ(r.bedSlices, 3);
    for (int i = 0; i < 6; ++i)
    {
        const double X = st.kilnMass(i)/(940*pi*25/4*0.05);
        EXPECT_NEAR(r.fill[i], X, 1e-14);
        const double hand = X > 0
            ? 5.82e-4*std::pow(0.05/nc, 0.44)*std::pow(5.0, 1.29)*std::pow(850e-6, 0.35)*std::pow(std::max(X, 0.03), -0.55)
            : 0.0;
        EXPECT_NEAR(r.coefficient[i], hand, 1e-12*std::max(hand, 1e-12)) << "slice " << i;
    }
    bool diameterWarned = false;
    for (const std::string& w : r.warnings) diameterWarned |= w.find("drum diameter 5 m") != std::string::npos;
    EXPECT_TRUE(diameterWarned);
    // the whole passive cell as the bed: every slice has one
    const PassiveSherritt2001 rp = sherritt2001PassiveDispersion(st, DispersionBed::passive, drum);
    EXPECT_EQ(rp.bedSlices, 6);
    EXPECT_GT(rp.fill[0], r.fill[0]);
    EXPECT_LT(rp.coefficient[0], r.coefficient[0]);   // D_z ~ X^-0.55
}

TEST(CompartmentDispersion, BadInputNamesTheEntry)
{
    const CompartmentNetwork net(mixedSlices(), 20.0, 8.0);
    const CompartmentSteadyState st = net.steadyState();
    const TracerSystem sys = net.tracerSystem(st);
    auto expectEntry = [](auto&& f, const std::string& entry)
    {
        try
        {
            f();
            ADD_FAILURE() << "no InputError for " << entry;
        }
        catch (const InputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(entry), std::string::npos) << e.what();
        }
    };
    PassiveDispersion d;
    d.sliceLength = 0.5;
    d.coefficient = {-1e-4};
    expectEntry([&] { withPassiveDispersion(sys, st, d); }, "model.denseDispersion");
    d.coefficient = {2.0};
    expectEntry([&] { withPassiveDispersion(sys, st, d); }, "model.denseDispersion");
    d.coefficient = {1e-3, 1e-3};   // neither one nor one per slice
    expectEntry([&] { withPassiveDispersion(sys, st, d); }, "model.denseDispersion");
    d.coefficient = {1e-3};
    d.sliceLength = 0;
    expectEntry([&] { withPassiveDispersion(sys, st, d); }, "model.denseDispersion");
    expectEntry([] { parseDispersionBed("bottom", "model.dispersionBed"); }, "model.dispersionBed");

    PassiveDispersionDrum drum{5.0, 3.0/60, 850e-6, 940, 0.5};
    // every slice below its design load: no kiln bed anywhere
    const CompartmentNetwork under(std::vector<CompartmentSlice>(3, {800.0, 10.0, 0.8, 0.6, 0.1}), 20.0, 8.0);
    const CompartmentSteadyState su = under.steadyState();
    ASSERT_EQ(su.kilnMass.sum(), 0.0);
    expectEntry([&] { sherritt2001PassiveDispersion(su, DispersionBed::kiln, drum); }, "model.denseDispersion");
    // a centrifuging drum has no correlation
    drum.speed = 1.0;
    expectEntry([&] { sherritt2001PassiveDispersion(st, DispersionBed::kiln, drum); }, "speed");
}
