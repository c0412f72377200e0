#include "costs/tension_only_spring.h"

#include <gtest/gtest.h>

#include "costs/spring_stretch.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

using testing::RandomPositions;

TEST(TensionOnlySpring, DerivativesMatchDifferencesWhenTaut) {
  const auto term = MakeTerm("structural", {0, 1}, TensionOnlySpring::Create(80.0, 0.05));
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const auto positions = RandomPositions(2, 0.5, seed);  // mostly longer than 0.05
    double energy;
    ASSERT_TRUE(term->Energy(positions.data(), &energy));
    if (energy > 0.0) testing::ExpectDerivativesMatchDifferences(*term, positions);
  }
}

// At exactly the rest length the Hessian jumps (0 on the slack side, k uu^T on the taut side), so
// central differences straddle the kink there: check the flat sheet just taut, and at rest that
// the force is zero and the derivatives finite.
TEST(TensionOnlySpring, DerivativesMatchDifferencesAtFlatRestState) {
  const auto term = MakeTerm("structural", {0, 1}, TensionOnlySpring::Create(80.0, 0.1));
  testing::ExpectDerivativesMatchDifferences(*term, {0, 0, 0, 0.1 * (1 + 1e-4), 0, 0});
  const std::vector<double> at_rest = {0, 0, 0, 0.1, 0, 0};
  testing::ExpectZeroForce(*term, at_rest);
  double energy, gradient[6], hessian[36];
  EXPECT_TRUE(term->EnergyHessian(at_rest.data(), &energy, gradient, hessian));
}

TEST(TensionOnlySpring, NoForceNoStiffnessWhenSlack) {
  const auto term = MakeTerm("structural", {0, 1}, TensionOnlySpring::Create(80.0, 0.1));
  const std::vector<double> positions = {0, 0, 0, 0.05, 0.02, 0.0};
  double energy, gradient[6], hessian[36];
  ASSERT_TRUE(term->EnergyHessian(positions.data(), &energy, gradient, hessian));
  EXPECT_EQ(energy, 0.0);
  for (double g : gradient) EXPECT_EQ(g, 0.0);
  for (double h : hessian) EXPECT_EQ(h, 0.0);
}

TEST(TensionOnlySpring, EqualsElasticSpringWhenTaut) {
  const auto tension_only = MakeTerm("structural", {0, 1}, TensionOnlySpring::Create(80.0, 0.1));
  const auto elastic = MakeTerm("structural", {0, 1}, SpringStretch::Create(80.0, 0.1));
  const std::vector<double> positions = {0, 0, 0, 0.1, 0.07, -0.02};
  double a, b, ga[6], gb[6];
  ASSERT_TRUE(tension_only->EnergyGradient(positions.data(), &a, ga));
  ASSERT_TRUE(elastic->EnergyGradient(positions.data(), &b, gb));
  EXPECT_DOUBLE_EQ(a, b);
  for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(ga[k], gb[k]);
}

TEST(TensionOnlySpring, InvariantUnderRigidMotionAndBalanced) {
  const auto term = MakeTerm("structural", {0, 1}, TensionOnlySpring::Create(80.0, 0.05));
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto positions = RandomPositions(2, 0.5, seed);
    testing::ExpectRigidMotionInvariant(*term, positions);
    testing::ExpectForcesBalance(*term, positions);
  }
}

}  // namespace
}  // namespace drape
