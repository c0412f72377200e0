#include "costs/constant_force_potential.h"

#include <gtest/gtest.h>

#include "tests/term_checks.h"

namespace drape {
namespace {

TEST(ConstantForcePotential, DerivativesMatchDifferences) {
  const double force[3] = {0.5, -1.0, -9.81e-3}, reference[3] = {0.1, 0.2, 0.0};
  const auto term = MakeTerm("gravity", {0}, ConstantForcePotential::Create(force, reference));
  testing::ExpectDerivativesMatchDifferences(*term, testing::RandomPositions(1, 1.0, 5));
  testing::ExpectDerivativesMatchDifferences(*term, {0.1, 0.2, 0.0});
}

TEST(ConstantForcePotential, GradientIsMinusTheForceAndEnergyZeroAtReference) {
  const double force[3] = {0.5, -1.0, -9.81e-3}, reference[3] = {0.1, 0.2, 0.0};
  const auto term = MakeTerm("load", {0}, ConstantForcePotential::Create(force, reference));
  const std::vector<double> positions = {0.3, 0.0, -1.0};
  double energy, gradient[3], hessian[9];
  ASSERT_TRUE(term->EnergyHessian(positions.data(), &energy, gradient, hessian));
  double expected = 0.0;
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(gradient[c], -force[c]);
    expected -= force[c] * (positions[c] - reference[c]);
  }
  EXPECT_NEAR(energy, expected, 1e-15);
  for (double h : hessian) EXPECT_EQ(h, 0.0);
  double at_reference;
  ASSERT_TRUE(term->Energy(reference, &at_reference));
  EXPECT_EQ(at_reference, 0.0);
}

TEST(ConstantForcePotential, LeastSquaresFormHasTheExactGradient) {
  const double force[3] = {0.0, 0.0, -0.02}, reference[3] = {0.0, 0.0, 0.0};
  const auto term =
      MakeTerm("gravity", {0}, ConstantForcePotential::Create(force, reference), /*shift=*/5.0);
  std::unique_ptr<ceres::CostFunction> cost(term->NewCostFunction());
  double x[3] = {0.1, 0.2, -0.3}, residual, jacobian[3];
  const double* parameters[] = {x};
  double* jacobians[] = {jacobian};
  ASSERT_TRUE(cost->Evaluate(parameters, &residual, jacobians));
  double energy;
  ASSERT_TRUE(term->Energy(x, &energy));
  EXPECT_NEAR(0.5 * residual * residual, energy + 5.0, 1e-12);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(residual * jacobian[c], -force[c], 1e-12);
}

}  // namespace
}  // namespace drape
