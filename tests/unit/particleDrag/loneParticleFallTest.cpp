// The isolated-particle fall: closed forms (Sherritt 1991 Eqs 13, 16, 17)
// against RK4 integration of Eq 12, and limits worked by hand
#include "particleDrag/loneParticleFall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace particleDrag;

namespace
{
constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi/180.0;

// Relative agreement to 5 significant figures
void expectFiveFigures(double a, double b)
{
    EXPECT_NEAR(a, b, 5e-6*std::max(std::abs(a), std::abs(b))) << a << " vs " << b;
}
} // namespace

struct FallCase
{
    double diameter, density, Vg, alphaDeg, height;
};

class ClosedFormVsRK4 : public ::testing::TestWithParam<FallCase> {};

TEST_P(ClosedFormVsRK4, AgreeToFiveSignificantFigures)
{
    const FallCase c = GetParam();
    const DragLaw law = dragLawFromName("SchillerNaumann");
    const Particle p{c.diameter, c.density};
    const Gas air = Gas::air(20.0);

    const double closed = loneParticleAdvance(law, p, air, c.Vg, c.height, c.alphaDeg*deg);
    FallIntegration opts;
    opts.constantK = true;
    opts.steps = 4000;
    const FallResult rk4 = integrateFall(law, p, air, c.Vg, c.height, c.alphaDeg*deg, opts);
    expectFiveFigures(closed, rk4.advance);
    EXPECT_NEAR(rk4.time, fallTime(c.height), 1e-12);
}

std::string fallCaseName(const ::testing::TestParamInfo<FallCase>& info)
{
    const double a = info.param.alphaDeg;
    const char* eq = a == 0 ? "Eq17" : (a > 0 ? "Eq16" : "Eq13");
    return std::string(eq) + "_case" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P
(
    Sherritt1991,
    ClosedFormVsRK4,
    ::testing::Values
    (
        FallCase{0.5e-3, 2650, 4.0, 0.0, 10.3},     // Eq 17, wind-tunnel sand
        FallCase{0.1e-3, 1200, 2.0, 0.0, 3.5},      // Eq 17, fine shale
        FallCase{1.0e-3, 2650, 3.0, 3.0, 2.0},      // Eq 16, cocurrent slope
        FallCase{0.2e-3, 1500, 1.0, 5.0, 2.5},      // Eq 16 past t0 (overtakes gas)
        FallCase{1.0e-3, 2650, 3.0, -3.0, 2.0},     // Eq 13, countercurrent
        FallCase{3.0e-3, 1600, 0.5, -4.0, 1.5}      // Eq 13, gravity wins
    ),
    fallCaseName
);

TEST(LoneParticleFall, HandLimits)
{
    // No drag: free slide g sin(alpha) t^2/2 plus convection
    EXPECT_NEAR(axialAdvance(0.0, 2.0, 0.0, 1.5), 3.0, 1e-14);
    EXPECT_NEAR(axialAdvance(0.0, 0.0, 0.1, 2.0), 0.5*gravity*std::sin(0.1)*4.0, 1e-14);

    // Eq 17 small-time expansion: delta ~ K Vg^2 t^2/2
    const double K = 1e-4, Vg = 2.0, t = 0.1;
    EXPECT_NEAR(axialAdvance(K, Vg, 0.0, t), 0.5*K*Vg*Vg*t*t, 1e-3*0.5*K*Vg*Vg*t*t);

    // Eq 17 long-time: the particle reaches the gas velocity,
    // delta -> Vg t - ln(K Vg t)/K
    const double Kb = 5.0, tb = 100.0;
    EXPECT_NEAR(axialAdvance(Kb, Vg, 0.0, tb), Vg*tb - std::log(Kb*Vg*tb + 1.0)/Kb, 1e-9);

    // No gas: Sherritt's code returns y sin(alpha)
    const Particle p{1e-3, 2650};
    EXPECT_DOUBLE_EQ(loneParticleAdvance(dragLawFromName("SchillerNaumann"), p, Gas{}, 0.0, 2.0, 0.05),
                     2.0*std::sin(0.05));

    // Eq 19
    EXPECT_NEAR(fallTime(10.3), std::sqrt(2*10.3/9.81), 1e-15);
}

TEST(LoneParticleFall, VariableDragDiffersFromConstantK)
{
    // Sherritt holds K at its full-slip value. As the slip falls, Re falls,
    // Cd and so K rise: re-evaluating Cd gives more drift, by some 10% for a
    // wind-tunnel sand grain
    const DragLaw law = dragLawFromName("SchillerNaumann");
    const Particle p{0.5e-3, 2650};
    const Gas air = Gas::air(20.0);
    FallIntegration constant, variable;
    variable.constantK = false;
    const double a = integrateFall(law, p, air, 4.0, 10.3, 0.0, constant).advance;
    const double b = integrateFall(law, p, air, 4.0, 10.3, 0.0, variable).advance;
    EXPECT_GT(b, a);
    EXPECT_LT(b/a, 1.2);
}

TEST(LoneParticleFall, TerminalVelocityStokesAndVerticalDrag)
{
    const DragLaw law = dragLawFromName("SchillerNaumann");
    const Gas air = Gas::air(20.0);
    // Stokes regime (Re < 0.2): v = (rho_p - rho_g) g d^2/(18 mu)
    const Particle fine{20e-6, 2650};
    const double vStokes =
        (fine.density - air.density)*gravity*fine.diameter*fine.diameter/(18*air.viscosity);
    EXPECT_NEAR(terminalVelocity(law, fine, air), vStokes, 1e-9*vStokes);

    // A long fall with vertical drag ends at the terminal velocity
    const Particle p{0.2e-3, 2650};
    const double vt = terminalVelocity(law, p, air);
    FallIntegration opts;
    opts.verticalDrag = true;
    opts.constantK = false;
    const FallResult r = integrateFall(law, p, air, 0.0, 20.0, 0.0, opts);
    EXPECT_GT(r.time, fallTime(20.0));           // drag slows the fall
    EXPECT_NEAR(20.0/r.time, vt, 0.1*vt);        // mostly at terminal speed
    EXPECT_NEAR(r.advance, 0.0, 1e-12);          // no gas, no drift
}

TEST(LoneParticleFall, BadInputIsRefused)
{
    const DragLaw law = dragLawFromName("SchillerNaumann");
    const Gas air;
    EXPECT_THROW(dragParameter(law, Particle{-1e-3, 2650}, air, 1.0), std::invalid_argument);
    EXPECT_THROW(dragParameter(law, Particle{1e-3, 0.0}, air, 1.0), std::invalid_argument);
    EXPECT_THROW(fallTime(-1.0), std::invalid_argument);
    EXPECT_THROW(axialAdvance(-1.0, 1.0, 0.0, 1.0), std::invalid_argument);
    try
    {
        dragParameter(law, Particle{-1e-3, 2650}, air, 1.0);
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("diameter"), std::string::npos);
    }
}

TEST(LoneParticleFall, StiffDragRefinesTheStepInsteadOfDiverging)
{
    // A 10 um sand grain relaxes to the gas in ~1e-3 s; in Stokes drag with
    // K held constant is not the regime, so use the variable-Cd route: the
    // requested 50 steps over a 1.45 s fall (h = 0.029 s, h lambda ~ 30)
    // would make RK4 diverge. The step is refined automatically and the
    // answer matches the Stokes closed form: with relaxation time tau the
    // axial velocity is V_g (1 - exp(-t/tau)), so
    //     x = V_g (t - tau (1 - exp(-t/tau))).
    const DragLaw law = dragLawFromName("SchillerNaumann");
    const Gas air = Gas::air(20.0);
    const Particle p{10e-6, 2650};
    FallIntegration opts;
    opts.constantK = false;
    opts.steps = 50;
    const double Vg = 0.05;   // slip Re = 0.03: Stokes within 0.5 %
    const FallResult r = integrateFall(law, p, air, Vg, 10.3, 0.0, opts);
    EXPECT_GT(r.steps, 50) << "the step count must have been refined";
    const double tau = p.density*p.diameter*p.diameter/(18*air.viscosity);
    const double t = fallTime(10.3);
    const double stokes = Vg*(t - tau*(1 - std::exp(-t/tau)));
    ASSERT_TRUE(std::isfinite(r.advance));
    EXPECT_NEAR(r.advance, stokes, 0.01*stokes);

    // Finer still, the refinement would need more than maxStiffSteps: the
    // call refuses with a message saying why, never a diverged number
    FallIntegration capped = opts;
    capped.maxStiffSteps = 1000;
    try
    {
        integrateFall(law, p, air, Vg, 10.3, 0.0, capped);
        FAIL() << "stiff fall beyond maxStiffSteps must throw";
    }
    catch (const std::runtime_error& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("stiff drag"), std::string::npos) << msg;
        EXPECT_NE(msg.find("follows the gas"), std::string::npos) << msg;
    }
}
