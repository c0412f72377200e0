#include "costs/zero_length_spring.h"

#include <gtest/gtest.h>

#include "tests/term_checks.h"

namespace drape {
namespace {

TEST(ZeroLengthSpring, DerivativesMatchDifferences) {
  const auto term = MakeTerm("structural", {0, 1}, ZeroLengthSpring::Create(12.0));
  for (unsigned seed = 1; seed <= 10; ++seed) {
    testing::ExpectDerivativesMatchDifferences(*term, testing::RandomPositions(2, 1.0, seed));
  }
  testing::ExpectDerivativesMatchDifferences(*term, {0, 0, 0, 0.1, 0, 0});
  testing::ExpectDerivativesMatchDifferences(*term, {0.1, 0, 0, 0.1, 0, 0});  // coincident
}

TEST(ZeroLengthSpring, ForceIsLinearAndHessianConstant) {
  const double k = 12.0;
  const auto term = MakeTerm("structural", {0, 1}, ZeroLengthSpring::Create(k));
  const std::vector<double> positions = {0.1, -0.2, 0.3, 0.4, 0.5, -0.6};
  double energy, gradient[6], hessian[36];
  ASSERT_TRUE(term->EnergyHessian(positions.data(), &energy, gradient, hessian));
  for (int c = 0; c < 3; ++c) {
    const double d = positions[3 + c] - positions[c];
    EXPECT_NEAR(gradient[3 + c], k * d, 1e-12);
    EXPECT_NEAR(gradient[c], -k * d, 1e-12);
    EXPECT_NEAR(hessian[c * 6 + c], k, 1e-12);
    EXPECT_NEAR(hessian[c * 6 + 3 + c], -k, 1e-12);
  }
}

TEST(ZeroLengthSpring, InvariantUnderRigidMotionAndBalanced) {
  const auto term = MakeTerm("structural", {0, 1}, ZeroLengthSpring::Create(12.0));
  const auto positions = testing::RandomPositions(2, 1.0, 3);
  testing::ExpectRigidMotionInvariant(*term, positions);
  testing::ExpectForcesBalance(*term, positions);
  testing::ExpectZeroForce(*term, {0.2, 0.2, 0.2, 0.2, 0.2, 0.2});
}

}  // namespace
}  // namespace drape
