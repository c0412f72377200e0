// The bending friction of a load step (costs/fv_bending_friction_step.h): its signed curvature on
// an arc, the monotone form it is from the flat state, its invariances and its kink at κ0. (The
// shared derivative check: tests/costs_test.cc; the load path: tests/load_steps_test.cc.)
#include "costs/fv_bending_friction_step.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "costs/fv_bending_friction.h"

namespace drape {
namespace {

constexpr double kFriction = 6e-4, kSize = 0.01, kArea = 1e-4, kSmoothing = 2.0;

// Nodes a, P, b on a circle of radius R in the xz plane, bending towards −z (`down`) or +z, and d
// across P along +y.
std::vector<double> StepArc(double radius, bool down) {
  const double chord = 0.01, half = std::asin(0.5 * chord / radius), side = down ? 1.0 : -1.0;
  std::vector<double> x;
  for (int k = -1; k <= 1; ++k) {
    const double angle = 2.0 * half * k;
    x.insert(x.end(), {radius * std::sin(angle), 0.0, side * (radius * std::cos(angle) - radius)});
  }
  x.insert(x.end(), {0.0, 0.01, 0.0});
  return x;
}

double SignedAt(const std::vector<double>& x, double sign) {
  double curvature = NAN;
  EXPECT_TRUE(FvBendingFrictionStep::SignedCurvature(x.data(), x.data() + 3, x.data() + 6,
                                                     x.data() + 9, kSize, sign, &curvature));
  return curvature;
}

double StepEnergy(const FvBendingFrictionStep& step, const std::vector<double>& x) {
  double energy = 0.0;
  EXPECT_TRUE(step(x.data(), x.data() + 3, x.data() + 6, x.data() + 9, &energy));
  return energy;
}

TEST(FvBendingFrictionStep, ItsCurvatureIsSignedByTheSideItBendsTo) {
  for (const double radius : {0.05, 0.5}) {
    const double kappa = 2.0 * std::tan(2.0 * std::asin(0.005 / radius) / 2.0) / kSize;
    EXPECT_NEAR(SignedAt(StepArc(radius, true), 1.0), kappa, 1e-12 * kappa) << radius;
    EXPECT_NEAR(SignedAt(StepArc(radius, false), 1.0), -kappa, 1e-12 * kappa) << radius;
    // d on the other side (σ = −1 with d at −y) gives the same sign.
    std::vector<double> low = StepArc(radius, true);
    low[10] = -0.01;
    EXPECT_NEAR(SignedAt(low, -1.0), kappa, 1e-12 * kappa) << radius;
  }
}

// From the flat state (κ0 = 0) the step's energy is the monotone form's.
TEST(FvBendingFrictionStep, FromTheFlatStateItIsTheMonotoneForm) {
  const FvBendingFrictionStep step(kFriction, kSize, kArea, kSmoothing, 0.0, 1.0);
  const FvBendingFriction monotone(kFriction, kSize, kArea, kSmoothing);
  for (const bool down : {true, false}) {
    const std::vector<double> x = StepArc(0.1, down);
    double expected = 0.0;
    monotone(x.data(), x.data() + 3, x.data() + 6, &expected);
    EXPECT_NEAR(StepEnergy(step, x), expected, 1e-12 * expected) << down;
  }
}

// The kink sits at κ0: there the energy is 0 and smallest, and H A (|κ − κ0| − δ…) away from it.
TEST(FvBendingFrictionStep, ItsKinkIsAtThePreviousCurvature) {
  const std::vector<double> reference = StepArc(0.1, true);
  const double previous = SignedAt(reference, 1.0);
  const FvBendingFrictionStep step(kFriction, kSize, kArea, kSmoothing, previous, 1.0);
  EXPECT_NEAR(StepEnergy(step, reference), 0.0, 1e-15);
  for (const double radius : {0.05, 0.2, 1.0}) {
    const std::vector<double> x = StepArc(radius, true);
    const double slip = SignedAt(x, 1.0) - previous;
    const double expected =
        kFriction * kArea * (std::sqrt(slip * slip + kSmoothing * kSmoothing) - kSmoothing);
    EXPECT_NEAR(StepEnergy(step, x), expected, 1e-12 * kFriction * kArea * std::abs(slip) + 1e-18);
    EXPECT_GT(StepEnergy(step, x), 0.0);
  }
}

TEST(FvBendingFrictionStep, InvariantUnderRigidMotions) {
  const FvBendingFrictionStep step(kFriction, kSize, kArea, kSmoothing, 3.0, 1.0);
  const std::vector<double> x = StepArc(0.08, false);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(0.3, -0.1, 2.0);
  std::vector<double> moved(x.size());
  for (int k = 0; k < 4; ++k) {
    Eigen::Map<Eigen::Vector3d>(moved.data() + 3 * k) =
        rotation * Eigen::Map<const Eigen::Vector3d>(x.data() + 3 * k) + shift;
  }
  EXPECT_NEAR(StepEnergy(step, moved), StepEnergy(step, x), 1e-12 * StepEnergy(step, x));
}

}  // namespace
}  // namespace drape
