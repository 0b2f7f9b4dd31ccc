// Size classes in the compartment network: identical classes are the bulk
// network; every class passes its own feed across every slice face; the
// mixture's tracer mean is the holdup over the feed; a class held back by
// the gas stays longer.
#include "drum/transport/compartment/compartmentSizeClasses.hpp"
#include "drum/io/inputError.hpp"
#include "drum/numerics/constants.hpp"
#include "drum/rtd/rtdMoments.hpp"
#include "mixedSlices.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace drum;

namespace
{

//- Six slices with a rolling bed whose slope follows the bed depths
CompartmentNetwork rollingBedNetwork()
{
    std::vector<CompartmentSlice> s = drumTest::mixedSlices();
    for (CompartmentSlice& c : s)
    {
        SaemanKiln k;
        k.drumDiameter = 2.0;
        k.speed = 3.0/60;
        k.bulkDensity = 940;
        k.drumSlope = 2.8*pi/180;
        k.repose = 40*pi/180;
        k.slopeFromProfile = true;
        c.saemanKiln = k;
        c.length = 1.0;
    }
    return CompartmentNetwork(s, 5.0, std::numeric_limits<double>::infinity());
}

std::vector<SizeClassSplits> copiesOf(const CompartmentNetwork& net, const std::vector<double>& shares)
{
    std::vector<SizeClassSplits> out;
    for (double w : shares)
    {
        SizeClassSplits c;
        c.feedShare = w;
        for (const CompartmentSlice& s : net.slices())
        {
            c.forward.push_back(s.forwardFraction);
            c.back.push_back(s.backFraction);
        }
        out.push_back(c);
    }
    return out;
}

void expectSame(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const char* what)
{
    ASSERT_EQ(a.size(), b.size()) << what;
    for (Eigen::Index i = 0; i < a.size(); ++i)
    {
        EXPECT_NEAR(a(i), b(i), 1e-9*std::max(1.0, std::abs(b(i)))) << what << " slice " << i + 1;
    }
}

} // namespace


TEST(CompartmentSizeClasses, IdenticalClassesAreTheBulkNetwork)
{
    for (const CompartmentNetwork& net : {CompartmentNetwork(drumTest::mixedSlices(), 5.0, 20.0), rollingBedNetwork()})
    {
        const CompartmentSteadyState one = net.steadyState();
        const auto classes = copiesOf(net, {0.2, 0.3, 0.5});
        const SizeClassSteadyState st = sizeClassSteadyState(net, classes);
        expectSame(st.total.passiveMass, one.passiveMass, "passive mass");
        expectSame(st.total.activeMass, one.activeMass, "active mass");
        expectSame(st.total.kilnMass, one.kilnMass, "kiln mass");
        expectSame(st.total.kilnFlow, one.kilnFlow, "kiln flow");
        expectSame(st.total.forwardFlow, one.forwardFlow, "forward flow");
        expectSame(st.total.backFlow, one.backFlow, "back flow");
        // each class is its share of everything
        for (std::size_t k = 0; k < classes.size(); ++k)
        {
            expectSame(st.classes[k].passiveMass, classes[k].feedShare*one.passiveMass, "class passive mass");
        }
        const RtdMoments a = exactMoments(net.tracerSystem(one), 0.0);
        const RtdMoments b = exactMoments(sizeClassTracerSystem(net, st, classes), 0.0);
        EXPECT_NEAR(b.mean, a.mean, 1e-9*a.mean);
        EXPECT_NEAR(b.sd(), a.sd(), 1e-8*a.sd());
    }
}


TEST(CompartmentSizeClasses, EachClassPassesItsFeedAndTheMixtureMeanIsHoldupOverFeed)
{
    const CompartmentNetwork net = rollingBedNetwork();
    auto classes = copiesOf(net, {0.25, 0.5, 0.25});
    // a fine class blown back, a coarse one thrown forward
    for (std::size_t i = 0; i < classes[0].forward.size(); ++i)
    {
        classes[0].forward[i] = 0.02;
        classes[0].back[i] = 0.3;
        classes[2].forward[i] = std::min(0.9, 1.5*classes[2].forward[i]);
        classes[2].back[i] = 0.0;
    }
    const SizeClassSteadyState st = sizeClassSteadyState(net, classes);
    const int n = net.nSlices();
    for (std::size_t k = 0; k < classes.size(); ++k)
    {
        const CompartmentSteadyState& c = st.classes[k];
        for (int i = 0; i < n; ++i)
        {
            const double back = i + 1 < n ? c.backFlow(i + 1) : 0.0;
            EXPECT_NEAR(c.kilnFlow(i) + c.forwardFlow(i) - back, classes[k].feedShare*5.0, 1e-9)
                << "class " << k + 1 << " face " << i + 1;
        }
    }
    // the slices' shares add up, and every class leaves at the slice's rates per mass
    for (int i = 0; i < n; ++i)
    {
        double share = 0;
        for (const auto& c : st.classes) share += c.passiveMass(i)/st.total.passiveMass(i);
        EXPECT_NEAR(share, 1.0, 1e-12);
        for (const auto& c : st.classes)
        {
            EXPECT_NEAR(c.releaseFlow(i)/c.passiveMass(i), st.total.releaseFlow(i)/st.total.passiveMass(i), 1e-12);
        }
    }
    // holdup theorem for the mixture, and the fine class stays longest
    const TracerSystem sys = sizeClassTracerSystem(net, st, classes);
    EXPECT_NEAR(exactMoments(sys, 0.0).mean, st.total.totalHoldup()/5.0, 1e-9*st.total.totalHoldup()/5.0);
    const double fine = st.classes[0].totalHoldup()/(0.25*5.0);
    const double mid = st.classes[1].totalHoldup()/(0.5*5.0);
    const double coarse = st.classes[2].totalHoldup()/(0.25*5.0);
    EXPECT_GT(fine, 1.2*mid);
    EXPECT_LT(coarse, mid);
    EXPECT_NEAR(exactMoments(net.tracerSystem(st.classes[0]), 0.0).mean, fine, 1e-9*fine);
}


TEST(CompartmentSizeClasses, RefusesBadClasses)
{
    const CompartmentNetwork net = rollingBedNetwork();
    auto c = copiesOf(net, {0.5, 0.4});
    EXPECT_THROW(sizeClassSteadyState(net, c), InputError);           // shares sum to 0.9
    c = copiesOf(net, {0.5, 0.5});
    c[1].forward.pop_back();
    EXPECT_THROW(sizeClassSteadyState(net, c), InputError);           // one split short
    c = copiesOf(net, {0.5, 0.5});
    c[0].forward[2] = 0.8;
    c[0].back[2] = 0.3;
    try
    {
        sizeClassSteadyState(net, c);
        ADD_FAILURE() << "C_F + C_B = 1.1 accepted";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("model.slices"), std::string::npos) << e.what();
    }
    // no kilning and a class that never moves forward: no steady state
    const CompartmentNetwork still(drumTest::mixedSlices(), 5.0, std::numeric_limits<double>::infinity());
    c = copiesOf(still, {0.5, 0.5});
    for (double& f : c[0].forward) f = 0.0;
    EXPECT_THROW(sizeClassSteadyState(still, c), InputError);
}
