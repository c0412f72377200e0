#include "costs/spring_stretch.h"

#include <gtest/gtest.h>

#include "tests/term_checks.h"

namespace drape {
namespace {

using testing::RandomPositions;

TEST(SpringStretch, DerivativesMatchDifferencesAtRandomStates) {
  const auto term = MakeTerm("structural", {0, 1}, SpringStretch::Create(250.0, 0.1));
  for (unsigned seed = 1; seed <= 20; ++seed) {
    testing::ExpectDerivativesMatchDifferences(*term, RandomPositions(2, 0.3, seed));
  }
}

TEST(SpringStretch, DerivativesMatchDifferencesAtFlatRestState) {
  const auto term = MakeTerm("structural", {0, 1}, SpringStretch::Create(250.0, 0.1));
  testing::ExpectDerivativesMatchDifferences(*term, {0, 0, 0, 0.1, 0, 0});
}

TEST(SpringStretch, ZeroForceAtRestLengthInAnyDirection) {
  const auto term = MakeTerm("structural", {0, 1}, SpringStretch::Create(250.0, 0.1));
  testing::ExpectZeroForce(*term, {0.2, 0.1, 0.0, 0.2, 0.1, 0.1});
  testing::ExpectZeroForce(*term, {0.0, 0.0, 0.0, 0.06, 0.0, 0.08});
}

TEST(SpringStretch, ForceIsHookesLawAlongTheSpring) {
  const double k = 250.0, rest = 0.1;
  const auto term = MakeTerm("structural", {0, 1}, SpringStretch::Create(k, rest));
  const std::vector<double> positions = {0, 0, 0, 0.09, 0, 0.12};  // length 0.15
  double energy, gradient[6];
  ASSERT_TRUE(term->EnergyGradient(positions.data(), &energy, gradient));
  EXPECT_NEAR(energy, 0.5 * k * 0.05 * 0.05, 1e-14);
  // Force on node 1 pulls it back towards node 0 with magnitude k (l − L0).
  EXPECT_NEAR(-gradient[3], -k * 0.05 * 0.6, 1e-12);
  EXPECT_NEAR(-gradient[5], -k * 0.05 * 0.8, 1e-12);
}

TEST(SpringStretch, InvariantUnderRigidMotionAndBalanced) {
  const auto term = MakeTerm("structural", {0, 1}, SpringStretch::Create(250.0, 0.1));
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto positions = RandomPositions(2, 0.3, seed);
    testing::ExpectRigidMotionInvariant(*term, positions);
    testing::ExpectForcesBalance(*term, positions);
  }
}

TEST(SpringStretch, FiniteDerivativesWhereNodesCoincide) {
  const auto term = MakeTerm("structural", {0, 1}, SpringStretch::Create(250.0, 0.1));
  const std::vector<double> positions = {0.1, 0.2, 0.3, 0.1, 0.2, 0.3};
  double energy, gradient[6], hessian[36];
  EXPECT_TRUE(term->EnergyHessian(positions.data(), &energy, gradient, hessian));
  EXPECT_NEAR(energy, 0.5 * 250.0 * 0.01, 1e-12);
}

}  // namespace
}  // namespace drape
