// Drag laws against values worked by hand from the printed formulas
#include "particleDrag/dragLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace particleDrag;

TEST(DragLaw, SchillerNaumannHandValues)
{
    // Sherritt 1991 Eq 9 below Re 0.2, Eq 10 above, no cut-off at 1000
    EXPECT_DOUBLE_EQ(schillerNaumannCd(0.1), 240.0);
    EXPECT_NEAR(schillerNaumannCd(1.0), 27.6, 1e-12);
    EXPECT_NEAR(schillerNaumannCd(100.0), 1.0917310910948732, 1e-12);
    EXPECT_NEAR(schillerNaumannCd(1000.0), 0.438288140019997, 1e-12);
    EXPECT_NEAR(schillerNaumannCd(5000.0), 24.0/5000*(1 + 0.15*std::pow(5000.0, 0.687)), 1e-14);
}

TEST(DragLaw, LeeSugarHandValues)
{
    // Lee 2008 Eq 6.6: Cd = 68/Re (1 + 0.004 Re^0.99)
    EXPECT_NEAR(leeSugarCd(1.0), 68.272, 1e-12);
    EXPECT_NEAR(leeSugarCd(100.0), 0.9397579833978307, 1e-12);
    // Lower than the sphere law in the dryer range (Lee: spheres overpredict)
    for (double Re : {100.0, 200.0, 300.0, 500.0})
    {
        EXPECT_LT(leeSugarCd(Re), schillerNaumannCd(Re)) << "Re " << Re;
    }
}

TEST(DragLaw, HaiderLevenspielHandValues)
{
    EXPECT_NEAR(haiderLevenspielCd(100.0, 1.0), 1.1498446432659095, 1e-12);
    EXPECT_NEAR(haiderLevenspielCd(100.0, 0.8), 1.3016970909409922, 1e-12);
    EXPECT_NEAR(haiderLevenspielCd(1000.0, 0.8), 1.2549243747048249, 1e-12);
    // A sphere (sphericity 1) stays within 12% of the sphere law
    for (double Re : {0.1, 1.0, 10.0, 100.0, 1000.0})
    {
        EXPECT_NEAR(haiderLevenspielCd(Re, 1.0)/schillerNaumannCd(Re), 1.0, 0.12) << "Re " << Re;
    }
    // Less spherical particles drag more
    EXPECT_GT(haiderLevenspielCd(100.0, 0.6), haiderLevenspielCd(100.0, 0.9));
}

TEST(DragLaw, SwarmLawsReduceToLoneParticle)
{
    const DragLaw wenYu = dragLawFromName("WenYu");
    const DragLaw gidaspow = dragLawFromName("Gidaspow");
    // (Wen-Yu keeps the 0.15 Re^0.687 term below Re 0.2, Sherritt's code not)
    for (double Re : {0.2, 1.0, 50.0, 900.0})
    {
        EXPECT_NEAR(wenYu.Cd(Re, 1.0), schillerNaumannCd(Re), 1e-12*schillerNaumannCd(Re));
        EXPECT_DOUBLE_EQ(gidaspow.Cd(Re, 0.95), wenYu.Cd(Re, 0.95));
    }
    // Wen-Yu: Cd = Cd_SN(alphaC Re) alphaC^-1.65
    const double a = 0.9, Re = 40.0;
    EXPECT_NEAR(wenYu.Cd(Re, a), schillerNaumannCd(a*Re)*std::pow(a, -1.65), 1e-12);
    // Ergun branch of Gidaspow: Cd Re = 200 alphaD/alphaC + 7/3 Re
    EXPECT_NEAR(gidaspow.CdRe(10.0, 0.5), 200.0 + 70.0/3.0, 1e-12);
}

TEST(DragLaw, CdReFiniteAtZeroSlip)
{
    for (const auto& name : dragLawNames())
    {
        const DragLaw law = dragLawFromName(name, 0.8);
        EXPECT_TRUE(std::isfinite(law.CdRe(0.0))) << name;
        EXPECT_GT(law.CdRe(0.0), 0.0) << name;
        EXPECT_TRUE(std::isinf(law.Cd(0.0))) << name;
    }
}

TEST(DragLaw, NamesRoundTrip)
{
    for (const auto& name : dragLawNames())
    {
        EXPECT_EQ(dragLawFromName(name).name(), name);
    }
}

TEST(DragLaw, BadInputIsRefused)
{
    try
    {
        dragLawFromName("StokesLaw");
        FAIL() << "unknown name accepted";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("StokesLaw"), std::string::npos);
        EXPECT_NE(msg.find("SchillerNaumann"), std::string::npos);  // lists valid names
    }
    EXPECT_THROW(dragLawFromName("HaiderLevenspiel", 0.0), std::invalid_argument);
    EXPECT_THROW(dragLawFromName("HaiderLevenspiel", 1.2), std::invalid_argument);
    EXPECT_THROW(schillerNaumannCd(-1.0), std::invalid_argument);
    EXPECT_THROW(schillerNaumannCd(std::nan("")), std::invalid_argument);
    EXPECT_THROW(dragLawFromName("WenYu").Cd(10.0, 0.0), std::invalid_argument);
    EXPECT_THROW(dragLawFromName("WenYu").Cd(10.0, 1.5), std::invalid_argument);
}
