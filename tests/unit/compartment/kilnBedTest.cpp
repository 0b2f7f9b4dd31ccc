// Saeman's rolling bed (Sherritt 1991 Eqs 22-23, kilnBed.hpp): Eq 22 by hand,
// the segment geometry and its inverse, the flow-mass inverse pair, the
// half-fill limit; in the compartment network: the steady state with bed
// kilning is a fixed point of the dynamic balances and a dynamic run reaches it
#include "drum/transport/kilnBed.hpp"
#include "drum/transport/compartment/compartmentNetwork.hpp"
#include "drum/io/inputError.hpp"

#include "mixedSlices.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace drum;

namespace
{

const double pi = 3.14159265358979323846;

SaemanKiln invictaLike()
{
    SaemanKiln k;
    k.drumDiameter = 5.0;
    k.speed = 3.0/60;
    k.bulkDensity = 940;
    k.drumSlope = 2.8*pi/180;
    k.repose = 36*pi/180;
    return k;
}

} // namespace


TEST(KilnBed, Equation22ByHand)
{
    const SaemanKiln k = invictaLike();
    const double beta = 1.2;
    // F_2 = pi n D^3 rho_b/6 [(alpha + gamma cos phi)/sin phi] sin^3(beta/2), gamma = 0
    const double byHand = pi*0.05*125*940/6*(2.8*pi/180)/std::sin(36*pi/180)*std::pow(std::sin(0.6), 3);
    EXPECT_NEAR(saemanBedFlow(k, beta), byHand, 1e-12*byHand);
    // a bed slope adds gamma cos(phi) to the drum slope
    SaemanKiln g = k;
    g.bedSlope = 0.01;
    EXPECT_NEAR(saemanBedFlow(g, beta)/saemanBedFlow(k, beta),
                (2.8*pi/180 + 0.01*std::cos(36*pi/180))/(2.8*pi/180), 1e-12);
    // half fill carries the most; a level drum with a level bed none (refused)
    EXPECT_NEAR(saemanBedFlow(k, pi), saemanFlowScale(k), 1e-12*saemanFlowScale(k));
    SaemanKiln level = k;
    level.drumSlope = 0;
    EXPECT_THROW(saemanFlowScale(level), InputError);
}

TEST(KilnBed, SegmentAreaAndItsInverse)
{
    const double D = 5.0;
    EXPECT_NEAR(bedArea(D, pi), pi*D*D/8, 1e-12);          // half the section
    EXPECT_NEAR(bedArea(D, 2*pi), pi*D*D/4, 1e-12);        // the whole section
    for (double beta : {0.05, 0.4, 1.0, 2.0, 3.0, 4.5})
    {
        EXPECT_NEAR(fillAngle(D, bedArea(D, beta)), beta, 1e-9) << beta;
    }
}

TEST(KilnBed, KilnMassAndFlowAreInverse)
{
    const SaemanKiln k = invictaLike();
    const double dz = 12.0/33;
    for (double f : {0.1, 2.0, 10.0, 0.9*saemanFlowScale(k)})
    {
        const double m = saemanKilnMass(k, dz, f);
        EXPECT_GT(m, 0);
        EXPECT_NEAR(saemanKilnFlow(k, dz, m), f, 1e-9*f) << f;
    }
    EXPECT_EQ(saemanKilnMass(k, dz, 0.0), 0.0);
    EXPECT_THROW(saemanKilnMass(k, dz, 1.01*saemanFlowScale(k)), InputError);
    // a longer slice holds proportionally more bed for the same flow (t_kiln ~ dz)
    EXPECT_NEAR(saemanKilnMass(k, 2*dz, 5.0), 2*saemanKilnMass(k, dz, 5.0), 1e-9*saemanKilnMass(k, dz, 5.0));
}

class KilnBedNetwork : public testing::TestWithParam<bool> {};

TEST_P(KilnBedNetwork, SteadyStateIsAFixedPointAndIsReached)
{
    std::vector<CompartmentSlice> slices = drumTest::mixedSlices();
    SaemanKiln k = invictaLike();
    k.drumDiameter = 2.0;     // a small drum: the 20 kg/s feed needs a deep bed (at most 65 kg/s)
    k.speed = 0.2;
    k.slopeFromProfile = GetParam();   // level bed, or gamma from the neighbouring beds
    for (auto& s : slices)
    {
        s.saemanKiln = k;
        s.length = 0.5;
    }
    const CompartmentNetwork net(slices, 20.0, std::numeric_limits<double>::infinity());
    const CompartmentSteadyState st = net.steadyState();
    EXPECT_GT(st.kilnMass(0), 0);
    Eigen::VectorXd m(2*net.nSlices());
    for (int i = 0; i < net.nSlices(); ++i)
    {
        m(2*i) = st.passiveMass(i);
        m(2*i + 1) = st.activeMass(i);
        // every boundary passes the feed: kilning + forward - the next slice's backmix
        const double back = i + 1 < net.nSlices() ? st.backFlow(i + 1) : 0.0;
        EXPECT_NEAR(st.kilnFlow(i) + st.forwardFlow(i) - back, 20.0, 1e-9) << i;
        if (!k.slopeFromProfile)
        {
            EXPECT_NEAR(st.kilnFlow(i), saemanKilnFlow(k, 0.5, st.kilnMass(i)), 1e-9) << i;
        }
    }
    EXPECT_LT(net.massRates(m).cwiseAbs().maxCoeff(), 1e-8);
    // a dynamic run from elsewhere settles there (the bed law is monotone)
    Eigen::VectorXd x = m*0.7;
    const double dt = 0.02;
    for (double t = 0; t < 3000; t += dt)
    {
        const Eigen::VectorXd k1 = net.massRates(x);
        const Eigen::VectorXd k2 = net.massRates(x + 0.5*dt*k1);
        const Eigen::VectorXd k3 = net.massRates(x + 0.5*dt*k2);
        const Eigen::VectorXd k4 = net.massRates(x + dt*k3);
        x += dt/6.0*(k1 + 2*k2 + 2*k3 + k4);
    }
    for (int i = 0; i < 2*net.nSlices(); ++i)
    {
        EXPECT_NEAR(x(i), m(i), 1e-5*std::max(1.0, m(i))) << i;
    }
}

INSTANTIATE_TEST_SUITE_P(LevelAndProfile, KilnBedNetwork, testing::Bool());

TEST(KilnBed, ProfileSlopeByHand)
{
    // gamma = (h - h_next)/dz enters Eq 22 as alpha + gamma cos(phi): a bed 0.3 m deep
    // before one 0.1 m deep over 0.5 m falls 0.4 rad
    const SaemanKiln k = invictaLike();
    const double D = k.drumDiameter, dz = 0.5;
    const double beta = 2*std::acos(1 - 2*0.3/D);            // depth 0.3 m
    EXPECT_NEAR(bedDepth(D, beta), 0.3, 1e-12);
    const double mass = k.bulkDensity*dz*bedArea(D, beta);
    SaemanKiln fixed = k;
    fixed.bedSlope = (0.3 - 0.1)/dz;
    EXPECT_NEAR(saemanKilnFlow(k, dz, mass, 0.1), saemanBedFlow(fixed, beta), 1e-9*saemanBedFlow(fixed, beta));
    EXPECT_NEAR(saemanKilnMass(k, dz, saemanKilnFlow(k, dz, mass, 0.1), 0.1), mass, 1e-6*mass);
}

TEST(KilnBed, NetworkRefusesABedSliceWithoutLength)
{
    std::vector<CompartmentSlice> slices = drumTest::mixedSlices();
    slices[0].saemanKiln = invictaLike();
    EXPECT_THROW(CompartmentNetwork(slices, 20.0, 8.0), InputError);
}
