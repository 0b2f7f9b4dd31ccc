// Drift models against particleDrag directly and Eq 142 by hand
#include "drum/drift/driftModel.hpp"
#include "drum/io/inputError.hpp"
#include "particleDrag/loneParticleFall.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace drum;

TEST(DriftModel, IsolatedUsesMeanGasVelocitySherrittUsesSheetVelocity)
{
    const auto air = particleDrag::Gas::air(20);
    const auto iso = makeDriftModel("isolated", air);
    const auto she = makeDriftModel("sherritt", air);
    DriftQuery q{500e-6, 2650, 4.0, 6.6, 30.0, 1.0, 0.0};
    const particleDrag::Particle p{500e-6, 2650};
    const particleDrag::DragLaw law;
    EXPECT_DOUBLE_EQ(iso->displacement(q), particleDrag::loneParticleAdvance(law, p, air, 4.0, 6.6, 0.0));
    // Eq 142 by hand: 1.546 y^0.763 spill^-0.857 L^-0.437
    const double cv = 1.546*std::pow(6.6, 0.763)/std::pow(30.0, 0.857)/std::pow(1.0, 0.437);
    ASSERT_LT(cv, 1.0);
    EXPECT_NEAR(she->displacement(q), particleDrag::loneParticleAdvance(law, p, air, cv*4.0, 6.6, 0.0), 1e-12);
    EXPECT_LT(she->displacement(q), iso->displacement(q));
    // lab-scale fall: the cap makes the two equal
    DriftQuery lab{500e-6, 2650, 1.0, 0.2, 0.05, 2.0, 0.02};
    EXPECT_DOUBLE_EQ(she->displacement(lab), iso->displacement(lab));
    // no gas: y sin(alpha)
    lab.gasVelocity = 0;
    EXPECT_NEAR(iso->displacement(lab), 0.2*std::sin(0.02), 1e-15);
    EXPECT_THROW(makeDriftModel("cfd?", air), InputError);
    lab.fallHeight = -1;
    EXPECT_THROW(iso->displacement(lab), InputError);
}
