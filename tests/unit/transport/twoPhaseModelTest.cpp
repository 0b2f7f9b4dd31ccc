// Sherritt 1991 two-phase model: analytic EAD results, mass balances,
// closed forms of Sherritt 1991 §3.6-3.7, DRUM1 inversion, axial solve, bad input.
#include "drum/drift/driftModel.hpp"
#include "drum/flights/sherritt/sherrittFlightShapes.hpp"
#include "drum/flights/sherritt/sherrittFlightSurface.hpp"
#include "drum/io/inputError.hpp"
#include "drum/transport/twoPhase/twoPhaseModel.hpp"
#include "sheikhTestCase.hpp"
#include "drum/numerics/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numeric>

using namespace drum;

namespace
{
using drum::pi;
using drum::deg;

// A flight with l = r on the whole discharging arc at phi: the table is
// constant r from pi - phi to 2 pi - phi and 0 elsewhere (unit-radius EAD
// hand checks of §5.2, at radius r)
SherrittFlightProfile eadTable(double r, double phi, double Dex, int N, double L)
{
    const double e = 1e-9;
    return SherrittFlightProfile({0, pi - phi - e, pi - phi, 2*pi - phi, 2*pi - phi + e, 2*pi},
        {0, 0, r, r, 0, 0}, FlightSide::exterior, Dex, N, L);
}

TwoPhaseCase eadCase(double slope = 2*deg)
{
    TwoPhaseCase c;
    c.name = "ead test";
    c.drum = {0.305, 1.69, slope, 8.0/60, 0.0};
    c.exterior = eadTable(0.05, 45.6*deg, 0.205, 8, 1.69);
    c.material.particleDensity = 1147;
    c.material.bulkDensity = 591;
    c.material.repose = 45.6*deg;
    c.material.sieveSizes = {1750e-6};
    c.material.massFractions = {1.0};
    return c;
}

TwoPhaseCase sheikhCase(double slope = 1*deg)
{
    return drumTest::sheikhCase(slope, "sheikh test");
}
} // namespace

TEST(TwoPhaseModel, EadDesignLoadedHoldupAndDenseFlowByHand)
{
    const auto c = eadCase();
    const TwoPhaseModel m(c);
    const auto s = m.atDischargeAngle(pi);
    const double r = 0.05;
    const int N = 8;
    // Eq 122 at theta_i = pi with l = r: each double integral is r^2 pi^2/2
    EXPECT_NEAR(s.dischargingHoldup, N*r*r*pi/8, 1e-6*N*r*r);
    EXPECT_NEAR(s.nonDischargingHoldup, N*r*r*pi/8, 1e-6*N*r*r);
    // Eq 86: N_ex,s = 1, c = r, J = pi r^3
    const double n = 8.0/60;
    const double a = 2*deg;
    const double phi = 45.6*deg;
    const double F2 = n*591*a/(6*std::sin(phi))*(pi*r*r*r + 2*N*pi*r*r*r);
    EXPECT_NEAR(s.denseFlow, F2, 1e-6*F2);
    // no gas: delta = y sin(alpha), Eq 48 by Simpson with Eq 92
    const double Do = 0.305;
    const double Dex = 0.205;
    auto y = [&](double t) { return 0.5*Do*(std::sin(std::acos(Dex/Do*std::cos(t))) - Dex/Do*std::sin(t)); };
    double I = 0;
    double M = 0;
    const int K = 20000;
    for (int k = 0; k <= K; ++k)
    {
        const double t = pi + pi*k/K;
        const double w = (k == 0 || k == K) ? 1 : (k % 2 ? 4 : 2);
        I += w*r*r*y(t)*std::sin(a);
        M += w*r*r*std::sqrt(2*y(t)/9.81);
    }
    I *= pi/K/3;
    M *= pi/K/3;
    EXPECT_NEAR(s.airborneCapacity[0], 0.5*n*591*N*I, 1e-5*0.5*n*591*N*I);
    EXPECT_NEAR(s.airborneHoldup, 0.5*n*N*M, 1e-5*0.5*n*N*M);       // Eq 91 / rho_b
    EXPECT_NEAR(s.feedRate, s.airborneCapacity[0] + F2, 1e-9);      // Eq 55, one size
}

TEST(TwoPhaseModel, OpenDrumHoldupMatchesClosedForms)
{
    // Sherritt 1991 §3.6 open-drum forms, from the flight-surface integrals
    const auto c = sheikhCase();
    const TwoPhaseModel m(c);
    const SherrittFlightSurface s(*c.exterior, c.material.repose);
    const double N = 12;
    for (double ti : {70*deg, 120*deg, 180*deg, 230*deg, 290*deg})
    {
        const auto st = m.atDischargeAngle(ti);
        double expect;
        if (ti <= pi)  // Eq 122
        {
            expect = (ti*s.integralL2(0, 2*pi) - s.integralOfCumulativeL2(2*pi - ti, 2*pi)
                      + s.iteratedDischarge(ti, 2*pi))/(4*pi);
            // the first term: int_0^ti int_{2pi - t}^{2pi} l^2 = ti C(2pi) - int_{2pi-ti}^{2pi} C
            expect = (ti*s.cumulativeL2(2*pi) - s.integralOfCumulativeL2(2*pi - ti, 2*pi)
                      + s.iteratedDischarge(ti, 2*pi))/(4*pi);
        }
        else
        {
            const double tf = 2*pi - ti;
            expect = (tf*s.cumulativeL2(2*pi) - s.integralOfCumulativeL2(2*pi - tf, 2*pi)
                      + (ti - tf)*s.integralL2(ti, 2*pi) + s.iteratedDischarge(ti, 2*pi))/(4*pi);
        }
        EXPECT_NEAR(st.dischargingHoldup + st.nonDischargingHoldup, N*expect, 1e-5*N*expect) << ti/deg;
    }
}

TEST(TwoPhaseModel, DesignLoadingIsAnInflectionOfTheDenseHoldup)
{
    // closed forms (Sherritt 1991 §3.7): dH2/dtheta_i vanishes at pi from both sides
    const TwoPhaseModel m(sheikhCase());
    auto H2 = [&](double t) { const auto s = m.atDischargeAngle(t); return s.dischargingHoldup + s.nonDischargingHoldup; };
    const double h = 2*deg;
    const double slopeAtPi = (H2(pi + h) - H2(pi - h))/(2*h);
    const double slopeBelow = (H2(pi - 20*deg + h) - H2(pi - 20*deg - h))/(2*h);
    const double slopeAbove = (H2(pi + 20*deg + h) - H2(pi + 20*deg - h))/(2*h);
    EXPECT_LT(slopeBelow, 0);
    EXPECT_LT(slopeAbove, 0);
    EXPECT_LT(std::abs(slopeAtPi), 0.1*std::min(std::abs(slopeBelow), std::abs(slopeAbove)));
}

TEST(TwoPhaseModel, SizeFractionsCloseAndInversionReproducesFeed)
{
    auto c = sheikhCase();
    c.gas.massRate = 0.05;  // cocurrent air: sizes separate
    const TwoPhaseModel m(c);
    const auto s = m.atDischargeAngle(250*deg);
    ASSERT_TRUE(s.valid) << s.note;
    EXPECT_NEAR(std::accumulate(s.holdupFractions.begin(), s.holdupFractions.end(), 0.0), 1.0, 1e-12);  // Eq 54
    // cocurrent gas carries fines faster: they are depleted in the drum
    EXPECT_LT(s.holdupFractions.back()/0.032, s.holdupFractions.front()/0.116);
    const auto roots = m.solveConstantHoldup(s.feedRate);
    ASSERT_FALSE(roots.empty());
    bool found = false;
    for (const auto& r : roots)
    {
        EXPECT_NEAR(m.atDischargeAngle(r.dischargeAngle).feedRate, s.feedRate, 1e-6*s.feedRate);
        found = found || std::abs(r.dischargeAngle - 250*deg) < 1e-4;
        // Eq 138 and per-size Eq 140 average back to T
        double Tbar = 0;
        for (std::size_t i = 0; i < r.sizeResidenceTimes.size(); ++i)
        {
            Tbar += c.material.massFractions[i]/100.1*r.sizeResidenceTimes[i];
        }
        EXPECT_NEAR(Tbar, r.meanResidenceTime, 1e-6*r.meanResidenceTime);
    }
    EXPECT_TRUE(found);
}

TEST(TwoPhaseModel, AxialSolveRelaxesToConstantHoldupInALongInclinedDrum)
{
    auto c = sheikhCase(3*deg);
    c.drum.length = 30.0;  // long: the bed slope relaxes to the drum slope
    c.options.axialSteps = 300;  // explicit RK4: 120 steps is unstable here (stiff relaxation)
    const TwoPhaseModel m(c);
    const double F0 = 0.015;
    const auto drum1 = m.solveConstantHoldup(F0).front();
    const auto drum3 = m.solveAxial(F0);
    EXPECT_NEAR(drum3.profile.back().holdup*c.material.bulkDensity*c.drum.length, drum1.holdupMass, 0.01*drum1.holdupMass);
    EXPECT_NEAR(drum3.profile.back().bedSlope, 0.0, 1e-3);
}

TEST(TwoPhaseModel, HorizontalDrumIntegratesThroughDesignLoading)
{
    // Horizontal, cocurrent air: airborne flow alone carries 0.0635 kg/s at
    // design loading and 0.0658 kg/s at 140 deg (DRUM1), so a feed of
    // 0.064 kg/s settles overloaded, through theta_i = pi from the light
    // discharge end (no weir)
    auto c = sheikhCase(0.0);
    c.gas.massRate = 0.1;
    c.gas.direction = GasFlow::cocurrent;
    c.options.axialSteps = 60;
    const TwoPhaseModel m(c);
    const double F0 = 0.064;
    ASSERT_LT(m.atDischargeAngle(pi).feedRate, F0);
    const auto r = m.solveAxial(F0);
    // the holdup rises from the discharge end and passes theta_i = pi
    EXPECT_GT(r.profile.front().dischargeAngle, pi);
    EXPECT_LT(r.profile.back().dischargeAngle, pi);
    EXPECT_FALSE(r.profile.back().slopeCapped);
    EXPECT_LT(r.cappedLength, 0.1*c.drum.length);
    for (std::size_t k = 1; k < r.profile.size(); ++k)
    {
        EXPECT_NEAR(r.profile[k].airborneFlow + r.profile[k].denseFlow, F0, 1e-9);
    }
    // upstream it relaxes (gamma -> 0) onto a DRUM1 root of the same feed
    double nearest = 1e9;
    for (const auto& q : m.solveConstantHoldup(F0))
    {
        nearest = std::min(nearest, std::abs(q.dischargeAngle - r.profile.back().dischargeAngle));
    }
    EXPECT_LT(nearest, 1*deg);
    // step doubling: the gamma cap next to the discharge end makes the
    // right-hand side non-smooth, so RK4 converges at low order there
    c.options.axialSteps = 120;
    const auto r2 = TwoPhaseModel(c).solveAxial(F0);
    EXPECT_NEAR(r.meanResidenceTime, r2.meanResidenceTime, 0.03*r2.meanResidenceTime);
    // without gas only the bed slope carries solids (Eq 79, alpha = 0):
    // DRUM1 has no flow. Near design loading (N_ex,s -> 1) even gamma = phi
    // carries less than 0.01 kg/s; the holdup then rises along the drum into
    // overload, where the bed surface (chord across the drum bottom) is long
    // enough for a bed slope below phi to carry the feed: all of it dense
    auto still = sheikhCase(0.0);
    still.options.axialSteps = 60;
    const TwoPhaseModel ms(still);
    EXPECT_THROW(ms.solveConstantHoldup(0.01), InputError);
    const auto rs = ms.solveAxial(0.01);
    const auto& feedEnd = rs.profile.back();
    EXPECT_LT(feedEnd.dischargeAngle, pi);
    EXPECT_FALSE(feedEnd.slopeCapped);
    EXPECT_GT(feedEnd.bedSlope, 0.0);
    EXPECT_LT(feedEnd.bedSlope, 35.69*deg);
    for (const auto& q : rs.profile)
    {
        EXPECT_NEAR(q.denseFlow, 0.01, 1e-9);
        EXPECT_NEAR(q.airborneFlow, 0.0, 1e-9);
    }
}

TEST(TwoPhaseModel, UnderloadedHoldupsFromDischargeMomentsByHand)
{
    // Independent of the model's integrators: for an open underloaded drum
    // the dense holdup of Eqs 97, 101/102, 116, 126 reduces to
    // H_2 = N V (u - pi)/pi, with V = 1/2 int l^2 the load discharged per
    // flight and revolution and u its discharge-weighted mean angle (the
    // receiving arc mirrors the discharging one); Eq 91 gives
    // H_1 = n N V t, t the discharge-weighted fall time sqrt(2 y/g) of
    // Eq 92. So H_1/H_2 = n t pi/(u - pi): proportional to the speed.
    // Sums by Simpson on l(theta) and Eq 92 written out here.
    const auto c = sheikhCase();
    const SherrittFlightSurface fl(*c.exterior, c.material.repose);
    const double Do = 0.385;
    const double Dex = c.exterior->tipDiameter();
    auto y = [&](double t) { return 0.5*Do*(std::sin(std::acos(Dex/Do*std::cos(t))) - Dex/Do*std::sin(t)); };
    const double N = 12;
    for (double ti : {200*deg, 230*deg, 260*deg})
    {
        double m0 = 0, m1 = 0, mt = 0;
        const int K = 40000;
        for (int k = 0; k <= K; ++k)
        {
            const double t = ti + (2*pi - ti)*k/K;
            const double w = (k == 0 || k == K) ? 1 : (k % 2 ? 4 : 2);
            const double l2 = std::pow(fl.length(t), 2);
            m0 += w*l2;
            m1 += w*l2*t;
            mt += w*l2*std::sqrt(2*y(t)/9.81);
        }
        const double V = 0.5*m0*(2*pi - ti)/K/3;
        const double u = m1/m0;
        const double tbar = mt/m0;
        for (double rpm : {5.7, 12.0})
        {
            auto cc = c;
            cc.drum.speed = rpm/60;
            const auto s = TwoPhaseModel(cc).atDischargeAngle(ti);
            const double H2 = N*V*(u - pi)/pi;
            const double H1 = rpm/60*N*V*tbar;
            EXPECT_NEAR(s.dischargingHoldup + s.nonDischargingHoldup, H2, 1e-4*H2) << ti/deg;
            EXPECT_NEAR(s.airborneHoldup, H1, 1e-4*H1) << ti/deg << " " << rpm;
        }
    }
}

TEST(TwoPhaseModel, AxialSolveCarriesOverloadAndRefusesBeyondCapacity)
{
    // Sheikh drum at 1 deg. Before the overload bed was tabulated the flight
    // table ended at ~137 deg, DRUM1 carried at most ~0.025 kg/s and 0.04-0.1
    // kg/s were refused. With the bed chord the dense flow rises steeply into
    // overload (Sherritt 1991 Fig 5.4): those feeds have a steady state, in
    // an overloaded or buried drum, heavier than any underloaded holdup.
    const TwoPhaseModel m(sheikhCase());
    const double full = 0.25*pi*0.385*0.385*2.10*1517;  // drum filled, kg
    const auto design = m.atDischargeAngle(pi);
    for (double F : {0.04, 0.1})
    {
        const auto roots = m.solveConstantHoldup(F);
        ASSERT_FALSE(roots.empty()) << F;
        EXPECT_LT(roots.front().dischargeAngle, pi) << F;
        const auto r = m.solveAxial(F);
        EXPECT_LT(r.dischargeAngle, pi) << F;
        EXPECT_GT(r.holdupMass, design.holdup*2.10*1517) << F;
        EXPECT_LT(r.holdupMass, full) << F;
        EXPECT_FALSE(r.profile.back().slopeCapped) << F;
    }
    // far beyond what even the buried drum carries over the sweep: refused
    auto msg = [&](double F) {
        try { m.solveAxial(F); } catch (const InputError& e) { return std::string(e.what()); }
        return std::string("no error");
    };
    double most = 0;
    for (const auto& s : m.sweep(m.minDischargeAngle(), m.finalDischargeAngle(), 200))
    {
        if (s.valid) most = std::max(most, s.feedRate);
    }
    EXPECT_THROW(m.solveConstantHoldup(2*most), InputError);
    EXPECT_NE(msg(2*most).find("cannot carry"), std::string::npos) << msg(2*most);
    // within capacity: the holdup rises with the feed, the cap (if any)
    // only next to the discharge end, and the feed end relaxes to DRUM1
    const auto a = m.solveAxial(0.01);
    const auto b = m.solveAxial(0.02);
    EXPECT_GT(b.holdupMass, 1.2*a.holdupMass);
    for (const auto* r : {&a, &b})
    {
        EXPECT_LT(r->cappedLength, 0.1*2.10);
        EXPECT_FALSE(r->profile.back().slopeCapped);
        EXPECT_NEAR(r->dischargeAngle, m.solveConstantHoldup(r->feedRate).front().dischargeAngle, 0.5*deg);
    }
}

TEST(TwoPhaseModel, BuriedFlightsSurfaceIsTheBedChordAndDenseFlowRisesSteeply)
{
    // Sheikh's flights without interference, so the bed surface through the
    // first discharging tip runs to the shell: l(theta_i) = R cos a +
    // sqrt(Ro^2 - R^2 sin^2 a), a = theta_i - phi (surface at phi, §3.2)
    auto c = sheikhCase();
    c.exterior = tabulateSherrittFlight(twoSidedFlightShape(0.385, 0.04, 0.04, 90*deg), 12, 2.10, 1*deg, false);
    const TwoPhaseModel m(c);
    const double phi = 35.69*deg;
    const double Ro = 0.1925;
    const double R = 0.5*c.exterior->tipDiameter();
    const double n = 5.7/60;
    const double alpha = 1*deg;
    for (double thetaI : {50*deg, 80*deg, 110*deg, 130*deg})
    {
        const auto s = m.atDischargeAngle(thetaI);
        const double a = thetaI - phi;
        const double chord = R*std::cos(a) + std::sqrt(Ro*Ro - R*R*std::sin(a)*std::sin(a));
        EXPECT_NEAR(s.chord, chord, 1e-3*chord) << thetaI/deg;
        EXPECT_EQ(s.slopedSurfaces, 1.0);  // Eq 84
        // Eq 86: F2 at least its sloped-surface term by hand
        EXPECT_GE(s.denseFlow, n*1517*alpha/(6*std::sin(phi))*pi*chord*chord*chord*(1 - 1e-3));
        EXPECT_EQ(s.regime, thetaI <= phi + 0.5*pi ? LoadingRegime::buried : LoadingRegime::overloaded);
    }
    // "The movement in the dense phase increases dramatically when the drum
    // is extremely overloaded" (Sherritt 1991 §5.1.2): well above the
    // design-loaded F2, and holdup rising all the way into the buried range
    const double F2design = m.atDischargeAngle(pi).denseFlow;
    EXPECT_GT(m.atDischargeAngle(60*deg).denseFlow, 10*F2design);
    double last = 0;
    for (double t = 175*deg; t >= 40*deg; t -= 5*deg)
    {
        const double H = m.holdupAt(t);
        EXPECT_GT(H, last) << t/deg;
        last = H;
    }
}

TEST(TwoPhaseModel, OverloadHoldupIsBedPlusFlights)
{
    // Mass check on Sheikh's drum (with interference, as drumSolver): at a
    // buried theta_i everything under the bed surface through the first
    // discharging tip is solids. That tip sits somewhere in [theta_i,
    // theta_i + 2 pi/N]; the bed is the circular segment of the shell cut by
    // the surface line at distance d = R sin(theta - phi) from the axis,
    // Ro^2 acos(d/Ro) - d sqrt(Ro^2 - d^2). So H_2 lies between the segment
    // averaged over that spacing and the segment at theta_i plus what every
    // flight holds when full (its pocket at design loading, Eq 97).
    const TwoPhaseModel m(sheikhCase());
    const auto c = sheikhCase();
    const double phi = 35.69*deg;
    const double Ro = 0.1925;
    const double R = 0.5*c.exterior->tipDiameter();
    const int N = 12;
    const SherrittFlightSurface surf(*c.exterior, phi);
    auto segment = [&](double theta) {
        const double d = R*std::sin(theta - phi);
        return Ro*Ro*std::acos(d/Ro) - d*std::sqrt(Ro*Ro - d*d);
    };
    for (double thetaI : {45*deg, 60*deg, 80*deg, 100*deg})
    {
        const auto s = m.atDischargeAngle(thetaI);
        const double H2 = s.dischargingHoldup + s.nonDischargingHoldup;
        double mean = 0;
        const int K = 600;
        for (int k = 0; k < K; ++k)
        {
            mean += segment(thetaI + (k + 0.5)/K*2*pi/N)/K;
        }
        EXPECT_GT(H2, mean) << thetaI/deg;
        EXPECT_LT(H2, segment(thetaI) + N*surf.holdupVolume(pi)) << thetaI/deg;
    }
}

TEST(TwoPhaseModel, TinyFlightsBedHoldupIsTheCircularSegment)
{
    // Vanishing radial flights (a drum almost without flights, §3.7):
    // the surface through the tip at theta - phi runs to the shell, and
    // Sherritt's holdup of that flight, 1/2 int l^2 (Eq 97), is the circular
    // segment under it: d/dtheta of the segment area is -l^2/2 with the
    // pivot on the shell (independent geometry)
    const double D = 1.0;
    const double len = 1e-3;
    const double phi = 35*deg;
    const SherrittFlightSurface s(tabulateSherrittFlight(straightRadialFlightShape(D, len), 1, 1.0, 0.25*deg, false), phi);
    const double Ro = 0.5*D;
    const double R = Ro - len;
    for (double theta = 45*deg; theta <= 120*deg; theta += 15*deg)
    {
        const double d = R*std::sin(theta - phi);
        const double seg = Ro*Ro*std::acos(d/Ro) - d*std::sqrt(Ro*Ro - d*d);
        EXPECT_NEAR(s.holdupVolume(theta), seg, 5e-3*seg + 1e-4) << theta/deg;
    }
}

TEST(TwoPhaseModel, RefusesBadInput)
{
    auto msg = [](auto f) {
        try { f(); } catch (const InputError& e) { return std::string(e.what()); }
        return std::string("no error");
    };
    const TwoPhaseModel m(sheikhCase());
    EXPECT_NE(msg([&] { m.solveConstantHoldup(0.0); }).find("feedRate"), std::string::npos);
    EXPECT_THROW(m.solveConstantHoldup(-1), InputError);
    const std::string big = msg([&] { m.solveConstantHoldup(10.0); });
    EXPECT_NE(big.find("beyond what the drum can carry"), std::string::npos) << big;
    auto c = sheikhCase();
    c.drum.slope = 30*deg;
    EXPECT_NE(msg([&] { TwoPhaseModel{c}; }).find("drum.slope"), std::string::npos);
    c = sheikhCase();
    c.drum.speed = 0;
    EXPECT_NE(msg([&] { TwoPhaseModel{c}; }).find("drum.speed"), std::string::npos);
    c = sheikhCase();
    c.drum.shellDiameter = 0.3;  // tips outside
    EXPECT_NE(msg([&] { TwoPhaseModel{c}; }).find("tipDiameter"), std::string::npos);
    c = sheikhCase();
    c.material.repose = 95*deg;
    EXPECT_NE(msg([&] { TwoPhaseModel{c}; }).find("(0, 90)"), std::string::npos);
    c = sheikhCase();
    c.material.massFractions.pop_back();
    EXPECT_THROW(TwoPhaseModel{c}, InputError);
}

TEST(TwoPhaseModel, GasPressureSetsTheGasDensityOfTheVelocityAndTheDrift)
{
    // an ideal gas: at pressure p the gas of mass rate m moves as fast as the gas
    // of mass rate m p0/p at p0 (its density in proportion to the pressure), and
    // the drift is Eq 142's in air at p
    const double p = 50, p0 = particleDrag::standardPressureKPa, F0 = 0.015;
    auto thin = sheikhCase();
    thin.gas = {0.02, 20, GasFlow::cocurrent, p};
    auto given = thin;     // the same drift model, given instead of built from the gas
    given.options.drift = std::make_shared<SherrittSheetDrift>(particleDrag::Gas::air(20, p));
    auto dense = given;    // at p0 with the mass rate of the same velocity
    dense.gas.pressureKPa = p0;
    dense.gas.massRate = thin.gas.massRate*p0/p;
    auto sea = thin;
    sea.gas.pressureKPa = p0;
    const auto a = TwoPhaseModel(thin).solveConstantHoldup(F0).front();
    const auto b = TwoPhaseModel(given).solveConstantHoldup(F0).front();
    const auto c = TwoPhaseModel(dense).solveConstantHoldup(F0).front();
    const auto d = TwoPhaseModel(sea).solveConstantHoldup(F0).front();
    EXPECT_EQ(a.meanResidenceTime, b.meanResidenceTime);
    EXPECT_NEAR(c.meanResidenceTime, a.meanResidenceTime, 1e-9*a.meanResidenceTime);
    EXPECT_NEAR(c.airborneFraction, a.airborneFraction, 1e-9);
    // cocurrent: the thinner, faster gas carries the solids further per fall
    EXPECT_LT(a.meanResidenceTime, 0.99*d.meanResidenceTime);
    auto bad = thin;
    bad.gas.pressureKPa = 5;
    try
    {
        TwoPhaseModel{bad};
        ADD_FAILURE() << "5 kPa accepted";
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("gas.pressure_kPa"), std::string::npos) << e.what();
    }
}
