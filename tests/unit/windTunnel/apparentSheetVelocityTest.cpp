// Sherritt's apparent in-sheet gas velocity (1991 Eq 141) fitted to class
// advances: the velocity that made lone-particle advances is found again,
// the two smallest classes do not count, the fit meets Eq 141's first-order
// condition, the lone-particle models give back their own gas velocity on
// every shared row, and what Eq 141 cannot answer is refused
#include "drum/drift/driftModel.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/projectPaths.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "particleDrag/sheetVelocity.hpp"
#include "scoring/apparentSheetVelocity.hpp"
#include "scoring/windTunnelPrediction.hpp"
#include "scoring/windTunnelData.hpp"
#include "expectInputError.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace drum;

namespace
{

const particleDrag::Gas air = particleDrag::Gas::air(20.0);

const std::map<std::string, WindTunnelMaterial>& materials()
{
    static const auto m = readWindTunnelMaterials(drum::dataDir()/"windtunnel_materials.csv");
    return m;
}

WindTunnelTest tunnelTest(double vg, double y)
{
    WindTunnelTest t;
    t.test = 901;
    t.material = "sand";
    t.airVelocity = vg;
    t.spillRate = 20;
    t.flightLength = 1;
    t.fallHeight = y;
    return t;
}

//- Eq 17 for each class of m at gas velocity v
std::vector<double> loneAdvances(const WindTunnelMaterial& m, double v, double y)
{
    std::vector<double> a;
    for (const auto& c : m.classes)
    {
        a.push_back(particleDrag::loneParticleAdvance({}, {c.diameter, m.particleDensity}, air, v, y));
    }
    return a;
}

//- the indices of the two smallest classes
std::pair<std::size_t, std::size_t> twoSmallest(const WindTunnelMaterial& m)
{
    std::vector<std::size_t> i(m.classes.size());
    for (std::size_t k = 0; k < i.size(); ++k) i[k] = k;
    std::sort(i.begin(), i.end(), [&](auto a, auto b) { return m.classes[a].diameter < m.classes[b].diameter; });
    return {i[0], i[1]};
}

} // namespace


TEST(ApparentSheetVelocity, FindsTheVelocityThatMadeTheAdvancesWithoutTheTwoSmallestClasses)
{
    for (const auto& name : {"sand", "raw_shale", "spent_shale"})
    {
        const auto& m = materials().at(name);
        const auto t = tunnelTest(5.0, 10.3);
        for (double v : {0.7, 2.3, 5.0})
        {
            auto a = loneAdvances(m, v, t.fallHeight);
            EXPECT_NEAR(apparentSheetVelocity(t, m, a, air), v, 1e-6*v) << name;
            // the two smallest classes are left out of Eq 141, whatever their advance
            const auto [s0, s1] = twoSmallest(m);
            a[s0] = 100;
            a[s1] = 0;
            EXPECT_NEAR(apparentSheetVelocity(t, m, a, air), v, 1e-6*v) << name;
        }
    }
}

TEST(ApparentSheetVelocity, MeetsTheFirstOrderConditionOfEq141)
{
    // classes that moved as if in different gases: the fit lies between, where
    // d/dV sum x_i (delta_i - delta_i(V))^2 = 0 over the classes it counts
    const auto& m = materials().at("spent_shale");
    const auto t = tunnelTest(4.0, 6.6);
    auto a = loneAdvances(m, 1.0, t.fallHeight);
    const auto fast = loneAdvances(m, 3.0, t.fallHeight);
    const auto [s0, s1] = twoSmallest(m);
    std::size_t k = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        if (i != s0 && i != s1 && (k++ % 2 == 0)) a[i] = fast[i];
    }
    const double v = apparentSheetVelocity(t, m, a, air);
    EXPECT_GT(v, 1.05);
    EXPECT_LT(v, 2.95);
    const auto objective = [&](double u)
    {
        const auto d = loneAdvances(m, u, t.fallHeight);
        double f = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            if (i != s0 && i != s1) f += m.classes[i].massFraction*(a[i] - d[i])*(a[i] - d[i]);
        }
        return f;
    };
    const double h = 1e-4*v;
    const double slope = (objective(v + h) - objective(v - h))/(2*h);
    const double scale = (objective(1.0) - objective(v))/std::abs(1.0 - v);   // a secant's slope
    EXPECT_LT(std::abs(slope), 1e-5*scale) << "slope " << slope << ", secant " << scale;
    EXPECT_LT(objective(v), objective(v*1.01));
    EXPECT_LT(objective(v), objective(v*0.99));
}

TEST(ApparentSheetVelocity, LoneParticleModelsGiveBackTheirGasOnEverySharedRow)
{
    const auto tests = readWindTunnelTests(drum::dataDir()/"windtunnel_tests.csv", materials());
    const IsolatedParticleDrift isolated(air);
    const SherrittSheetDrift sherritt(air);
    for (const auto& t : tests)
    {
        const auto& m = materials().at(t.material);
        EXPECT_NEAR(apparentSheetVelocity(t, m, classAdvances(isolated, t, m), air), t.airVelocity, 1e-6*t.airVelocity)
            << "test " << t.test;
        // Eq 142 with the code's exponents, capped at 1
        const double cv = particleDrag::sherrittSheetVelocityRatio(t.fallHeight, t.spillRate, t.flightLength);
        EXPECT_NEAR(apparentSheetVelocity(t, m, classAdvances(sherritt, t, m), air), cv*t.airVelocity, 1e-6*t.airVelocity)
            << "test " << t.test;
    }
}

TEST(ApparentSheetVelocity, RefusesWhatEq141CannotAnswer)
{
    const auto& sand = materials().at("sand");
    const auto t = tunnelTest(4.0, 10.3);
    auto a = loneAdvances(sand, 2.0, t.fallHeight);

    auto msg = expectInputError([&] { apparentSheetVelocity(t, sand, {1.0, 2.0}, air); });
    EXPECT_NE(msg.find("one advance per size class"), std::string::npos) << msg;
    EXPECT_NE(msg.find("test 901"), std::string::npos) << msg;

    WindTunnelMaterial two = sand;
    two.classes.resize(2);
    msg = expectInputError([&] { apparentSheetVelocity(t, two, {1.0, 2.0}, air); });
    EXPECT_NE(msg.find("at least 3"), std::string::npos) << msg;

    auto bad = a;
    bad[0] = std::numeric_limits<double>::quiet_NaN();   // the coarsest class (the file lists it first)
    msg = expectInputError([&] { apparentSheetVelocity(t, sand, bad, air); });
    EXPECT_NE(msg.find("not finite"), std::string::npos) << msg;

    // advances no gas within 4 V_g makes: the fit ends on the bound and is refused
    std::vector<double> far(a.size(), 1e3);
    msg = expectInputError([&] { apparentSheetVelocity(t, sand, far, air); });
    EXPECT_NE(msg.find("Eq 141"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[0.001, 4] V_g"), std::string::npos) << msg;
}
