// The friction of the fabric on an obstacle (costs/obstacle_friction.h) and its passes
// (src/run/run.h, SettleObstacleFriction): the functor is Coulomb's smoothed law, and a sheet on a
// slope (configs/fv/sheet_on_slope.yaml) stays below the friction angle, creeping what the smoothed
// law says, and slides above it until a wall stops it, the slope's friction then μ times its push.
#include "costs/obstacle_friction.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <vector>

#include "src/model/contact.h"
#include "src/model/term.h"
#include "tests/test_scenes.h"

namespace drape {
namespace obstacle_friction_test {
namespace {

constexpr double kCoefficient = 0.4, kPush = 2.0, kSmoothing = 1e-3;  // μ, λ (N), ε (m)
const double kNormal[3] = {0.0, 0.6, 0.8}, kStart[3] = {0.1, -0.2, 0.3};

ObstacleFriction Friction() {
  return ObstacleFriction::Create(kCoefficient, kPush, kNormal, kStart, kSmoothing);
}

// −∇U at x, N.
Eigen::Vector3d Force(const Eigen::Vector3d& x) {
  const auto term = MakeTerm("plane_friction", {0}, Friction(), 1.0);
  double energy = 0.0;
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  EXPECT_TRUE(term->EnergyGradient(x.data(), &energy, gradient.data()));
  return -gradient;
}

const Eigen::Vector3d kStartPoint(kStart[0], kStart[1], kStart[2]);
const Eigen::Vector3d kNormalVector(kNormal[0], kNormal[1], kNormal[2]);
// Moves from the start: across n (0.6 ε, 3 ε, 40 ε), along n, and both.
const std::vector<Eigen::Vector3d> kMoves = {{6e-4, 0.0, 0.0},
                                             {0.0, 2.4e-3, -1.8e-3},
                                             {0.03, -0.024, 0.018},
                                             {0.0, 0.006, 0.008},
                                             {0.002, 0.006 + 8e-4, 0.008 - 6e-4}};

Eigen::Vector3d Across(const Eigen::Vector3d& move) {
  return move - move.dot(kNormalVector) * kNormalVector;
}

TEST(ObstacleFriction, ForceOpposesTheSlipAcrossTheNormalAndStaysBelowMuLambda) {
  for (const Eigen::Vector3d& move : kMoves) {
    SCOPED_TRACE(::testing::Message() << "move " << move.transpose());
    const Eigen::Vector3d force = Force(kStartPoint + move);
    const Eigen::Vector3d slip = Across(move);
    // The closed form −μ λ u / √(|u|² + ε²), to round-off of its size.
    const Eigen::Vector3d expected =
        -kCoefficient * kPush * slip / std::sqrt(slip.squaredNorm() + kSmoothing * kSmoothing);
    EXPECT_LE((force - expected).norm(), 1e-12 * kCoefficient * kPush);
    EXPECT_NEAR(force.dot(kNormalVector), 0.0, 1e-12 * kCoefficient * kPush);
    EXPECT_LT(force.norm(), kCoefficient * kPush);
  }
}

TEST(ObstacleFriction, NoEnergyAtTheStartNorAlongTheNormal) {
  const ObstacleFriction friction = Friction();
  double energy = 1.0;
  ASSERT_TRUE(friction(kStart, &energy));
  EXPECT_EQ(energy, 0.0);
  const Eigen::Vector3d along = kStartPoint + 0.01 * kNormalVector;
  ASSERT_TRUE(friction(along.data(), &energy));
  EXPECT_NEAR(energy, 0.0, 1e-15);
}

// The slip at which the friction balances a tangential force F = r μ λ (r < 1): the smoothed law
// u = ε r / √(1 − r²), the creep of a node that sticks (src/model/contact.h).
double Creep(double ratio) { return kSmoothing * ratio / std::sqrt(1.0 - ratio * ratio); }

TEST(ObstacleFriction, ANodeBelowTheLimitCreepsWhatTheSmoothedLawSays) {
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, 0.0, 0.0);  // across n
  for (double ratio : {0.1, 0.5, 0.9, 0.99}) {
    const Eigen::Vector3d force = Force(kStartPoint + Creep(ratio) * direction);
    EXPECT_NEAR(force.norm(), ratio * kCoefficient * kPush, 1e-12 * kCoefficient * kPush)
        << "r " << ratio;
  }
}

TEST(ObstacleFriction, StiffnessIsPositiveSemidefinite) {
  const auto term = MakeTerm("plane_friction", {0}, Friction(), 1.0);
  for (const Eigen::Vector3d& move : kMoves) {
    const Eigen::Vector3d x = kStartPoint + move;
    double energy = 0.0;
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
    ASSERT_TRUE(term->EnergyHessian(x.data(), &energy, gradient.data(), hessian.data()));
    const Eigen::Vector3d eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(hessian).eigenvalues();
    // μ λ / ε is the largest stiffness (at the start): round-off below it.
    EXPECT_GE(eigenvalues.minCoeff(), -1e-12 * kCoefficient * kPush / kSmoothing)
        << "move " << move.transpose();
  }
}

// The sheet of configs/fv/sheet_on_slope.yaml on a slope of tan θ = r μ (μ = 0.3), g = 9.81 m/s².
struct Slope {
  double ratio = 0.0;  // r = tan θ / μ
  testing::Solved solved;
};

constexpr double kSlopeFriction = 0.3, kGravity = 9.81;
constexpr double kSlopeThickness = 0.001;  // contact.thickness of the scene
constexpr double kWallGap = 0.02;          // m from the sheet's lower edge to the wall

Slope SolveOnSlope(double ratio, const std::vector<std::string>& more = {}) {
  const double angle = std::atan(ratio * kSlopeFriction);
  std::vector<std::string> overrides = {"loads.gravity=[" +
                                        std::to_string(kGravity * std::sin(angle)) + ", 0, " +
                                        std::to_string(-kGravity * std::cos(angle)) + "]"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return {ratio, testing::SolveConfig("configs/fv/sheet_on_slope.yaml", "newton", overrides)};
}

void ExpectCertifiedMinimum(const Slope& slope) {
  const RunResult& result = slope.solved.result;
  EXPECT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.stability.stable);
  EXPECT_TRUE(result.certificate.balanced);
  EXPECT_TRUE(result.contact.friction);
  EXPECT_TRUE(result.contact.friction_settled);
  EXPECT_LE(result.contact.friction_push_change, kFrictionPushTolerance);
}

// Each node's move down the slope (x), m.
std::vector<double> MovesDownTheSlope(const Model& model) {
  std::vector<double> moves;
  moves.reserve(model.num_nodes);
  for (int node = 0; node < model.num_nodes; ++node) {
    moves.push_back(model.positions[3 * node] - model.initial[3 * node]);
  }
  return moves;
}

TEST(ObstacleFriction, ASheetBelowTheFrictionAngleStaysCreepingTheSmoothedLaw) {
  const double slip = kFrictionSlipFraction * kSlopeThickness;  // ε of the scene
  for (double ratio : {0.5, 0.9}) {
    SCOPED_TRACE(::testing::Message() << "tan θ / μ = " << ratio);
    const Slope slope = SolveOnSlope(ratio);
    ExpectCertifiedMinimum(slope);
    // Every node carries its own weight's share along the slope (they all press with the same
    // ratio, so the sheet moves as a whole): u = ε r / √(1 − r²). The lagged push is within
    // kFrictionPushTolerance of the weight, and u's relative sensitivity to r is 1 / (1 − r²).
    const double creep = slip * ratio / std::sqrt(1.0 - ratio * ratio);
    const double tolerance = kFrictionPushTolerance / (1.0 - ratio * ratio) * creep;
    for (double move : MovesDownTheSlope(slope.solved.model)) EXPECT_NEAR(move, creep, tolerance);
    // The slope alone holds the sheet (the wall is not reached): its force is minus the weight.
    const Certificate& certificate = slope.solved.result.certificate;
    const Eigen::Vector3d& weight = certificate.applied_sum;
    EXPECT_LE((certificate.contact_sum_by_obstacle[0] + weight).norm(),
              kFrictionPushTolerance * weight.norm());
    EXPECT_EQ(certificate.contact_sum_by_obstacle[1].norm(), 0.0);
  }
}

TEST(ObstacleFriction, ASheetAboveTheFrictionAngleSlidesToTheWall) {
  for (double ratio : {1.1, 1.5}) {
    SCOPED_TRACE(::testing::Message() << "tan θ / μ = " << ratio);
    const Slope slope = SolveOnSlope(ratio);
    ExpectCertifiedMinimum(slope);
    // It slides until its lower edge keeps the clearance t off the wall: the gap less t, less the
    // wall's penalty depth (at most kAllowedPenetration × t) and the sheet's compression under its
    // weight (a strain below 1e-3 of E = 400 N/m: under 1e-4 of the gap).
    for (double move : MovesDownTheSlope(slope.solved.model)) {
      EXPECT_NEAR(move, kWallGap - kSlopeThickness, kAllowedPenetration * kSlopeThickness);
    }
    // Sliding, the slope's friction is μ times its push (to ε² / 2u² ≈ 1e-5 and the lag's
    // tolerance); the wall takes the rest of the weight down the slope.
    const Certificate& certificate = slope.solved.result.certificate;
    const Eigen::Vector3d& slope_force = certificate.contact_sum_by_obstacle[0];
    EXPECT_NEAR(-slope_force.x(), kSlopeFriction * slope_force.z(),
                kFrictionPushTolerance * kSlopeFriction * slope_force.z());
    EXPECT_NEAR(certificate.contact_sum_by_obstacle[1].x() + slope_force.x(),
                -certificate.applied_sum.x(),
                kFrictionPushTolerance * certificate.applied_sum.norm());
  }
}

// A sheet laid on the slope's layer edge starts with the pushes of its own weight, exact for a
// flat sheet: one solve. Laid 0.5 mm above it, nothing pushes at the start, so the first solve has
// no friction and the sheet slides to the wall; the second, with the pushes found there, brings it
// back to where friction holds it.
TEST(ObstacleFriction, ThePushesAreTakenAgainUntilTheySettle) {
  const Slope laid = SolveOnSlope(0.5);
  EXPECT_EQ(laid.solved.result.contact.friction_passes, 1);
  ExpectCertifiedMinimum(laid);
  const Slope above = SolveOnSlope(0.5, {"mesh.origin=[0, 0, 0.0015]"});
  ExpectCertifiedMinimum(above);
  EXPECT_GE(above.solved.result.contact.friction_passes, 2);
  const double slip = kFrictionSlipFraction * kSlopeThickness;
  const double creep = slip * 0.5 / std::sqrt(1.0 - 0.25);
  const std::vector<double> laid_moves = MovesDownTheSlope(laid.solved.model);
  const std::vector<double> above_moves = MovesDownTheSlope(above.solved.model);
  for (size_t k = 0; k < laid_moves.size(); ++k) {
    EXPECT_NEAR(above_moves[k], laid_moves[k], kFrictionPushTolerance / 0.75 * creep);
  }
  const Slope frictionless = SolveOnSlope(0.5, {"obstacles[0].plane.friction=0"});
  EXPECT_FALSE(frictionless.solved.result.contact.friction);
  for (double move : MovesDownTheSlope(frictionless.solved.model)) {
    EXPECT_NEAR(move, kWallGap - kSlopeThickness, kAllowedPenetration * kSlopeThickness);
  }
}

// Without the wall, friction alone holds the sheet below the friction angle (the scene is not
// refused for lacking a support down the slope); above it nothing does, and the solve says so.
TEST(ObstacleFriction, WithoutTheWallFrictionAloneHoldsTheSheetOrItRunsAway) {
  const Slope held = SolveOnSlope(0.5, {"obstacles=[{plane: {point: [0, 0, 0], normal: [0, 0, 1], "
                                        "friction: 0.3}}]",
                                        "solver.max_iterations=200"});
  ExpectCertifiedMinimum(held);
  const Slope sliding = SolveOnSlope(1.5, {"obstacles=[{plane: {point: [0, 0, 0], normal: [0, 0, "
                                           "1], friction: 0.3}}]",
                                           "solver.max_iterations=200"});
  EXPECT_FALSE(sliding.solved.result.converged);
}

// In load steps each step's kinks sit at the previous step's state and its friction carries the
// whole load so far, at the same ratio r: a node that sticks creeps the smoothed law's slip again
// in every step, N of them in all (src/model/contact.h says so).
TEST(ObstacleFriction, InLoadStepsAStuckSheetCreepsOnceAStep) {
  constexpr int kSteps = 4;
  constexpr double kRatio = 0.9;
  const Slope stepped = SolveOnSlope(
      kRatio, {"material.finite_volume.friction_load_steps=" + std::to_string(kSteps)});
  ExpectCertifiedMinimum(stepped);
  const double slip = kFrictionSlipFraction * kSlopeThickness;
  const double creep = kSteps * slip * kRatio / std::sqrt(1.0 - kRatio * kRatio);
  const double tolerance = kFrictionPushTolerance / (1.0 - kRatio * kRatio) * creep;
  for (double move : MovesDownTheSlope(stepped.solved.model)) {
    EXPECT_NEAR(move, creep, tolerance);
  }
}

}  // namespace
}  // namespace obstacle_friction_test
}  // namespace drape
