// Fibre friction in bending (costs/fv_bending_friction.h): its closed form on an arc, its
// invariances, the moment it adds (H where |κ| ≫ δ), and Peirce's heavy cantilever with a friction
// moment against a shooting reference, which H = 0 turns back into the elastica.
//
// Reference (derived here, computed in the test). The strip of cantilever_test.cc, clamped
// horizontally at s = 0 and free at s = ℓ, with weight w = ρ g per unit area and, per unit width,
// the bending moment M = D θ' + H on loading (θ the tangent's angle below the horizontal, θ' ≥ 0
// everywhere for this load). Where the load's moment M(s) = ∫_s^ℓ w (x(σ) − x(s)) dσ is below H the
// friction holds the strip straight:
//   θ' = max(M − H, 0)/D,   M' = −w (ℓ − s) cos θ,   θ(0) = 0,  M(ℓ) = 0,
//   x' = cos θ,  z' = −sin θ.
// Shooting on M(0) with bisection, RK4 with 20,000 steps. With H = 0 it is the elastica.
#include "costs/fv_bending_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/fabric_parameters.h"
#include "tests/rk4.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

double Energy(const FvBendingFriction& friction, const std::vector<double>& x) {
  double energy = 0.0;
  friction(x.data(), x.data() + 3, x.data() + 6, &energy);
  return energy;
}

// Nodes a, P, b on a circle of radius R, P at the top, arms of chord c.
std::vector<double> Arc(double radius, double chord, double turn = 0.0) {
  const double half = std::asin(0.5 * chord / radius);  // half the angle each arm subtends
  std::vector<double> x;
  for (int k = -1; k <= 1; ++k) {
    const double angle = 2.0 * half * k + turn;
    x.insert(x.end(), {radius * std::sin(angle), 0.0, radius * std::cos(angle) - radius});
  }
  return x;
}

TEST(FvBendingFriction, OnAnArcItIsTheSmoothedAbsoluteCurvatureTimesHArea) {
  const double h = 6e-4, size = 0.01, area = 1e-4, delta = 2.0;
  const FvBendingFriction friction(h, size, area, delta);
  for (const double radius : {0.05, 0.2, 2.0}) {
    const double chord = 0.01;
    // The turning angle between the arms is twice the angle one chord subtends.
    const double turning = 2.0 * 2.0 * std::asin(0.5 * chord / radius) / 2.0;
    const double kappa = 2.0 * std::tan(turning / 2.0) / size;
    const double expected = h * area * (std::sqrt(kappa * kappa + delta * delta) - delta);
    EXPECT_NEAR(Energy(friction, Arc(radius, chord)), expected, 1e-12 * h * area * kappa) << radius;
  }
}

TEST(FvBendingFriction, ZeroAndFlatWhenStraightInvariantUnderRigidMotions) {
  const FvBendingFriction friction(6e-4, 0.01, 1e-4, 1.0);
  EXPECT_EQ(Energy(friction, {-0.01, 0, 0, 0, 0, 0, 0.01, 0, 0}), 0.0);
  const std::vector<double> arc = Arc(0.1, 0.01);
  const std::vector<double> turned = Arc(0.1, 0.01, 0.7);  // the same arc rotated about y
  std::vector<double> moved = turned;
  for (int k = 0; k < 9; ++k) moved[k] += k % 3 == 1 ? 0.3 : -0.2;
  EXPECT_NEAR(Energy(friction, turned), Energy(friction, arc), 1e-15);
  EXPECT_NEAR(Energy(friction, moved), Energy(friction, arc), 1e-15);
}

// dU/dκ = H A κ/√(κ² + δ²): the friction moment per unit width, H where |κ| ≫ δ.
TEST(FvBendingFriction, ItsMomentIsTheFrictionMomentWhereTheCurvatureExceedsTheSmoothing) {
  const double h = 6e-4, size = 0.01, area = 1e-4;
  for (const double delta : {1.0, 0.1, 0.01}) {
    const FvBendingFriction friction(h, size, area, delta);
    const double k0 = 20.0, dk = 1e-4;    // 1/m
    auto energy_at = [&](double kappa) {  // an arc of curvature ≈ kappa through the arms' chord
      return Energy(friction, Arc(1.0 / kappa, size));
    };
    const double kappa0 = 2.0 * std::tan(std::asin(0.5 * size * k0)) / size;
    const double kappa1 = 2.0 * std::tan(std::asin(0.5 * size * (k0 + dk))) / size;
    const double moment = (energy_at(k0 + dk) - energy_at(k0)) / (kappa1 - kappa0) / area;
    EXPECT_NEAR(moment, h * kappa0 / std::hypot(kappa0, delta), 1e-5 * h) << delta;
    EXPECT_NEAR(moment, h, 0.5 * h * (delta / kappa0) * (delta / kappa0) + 1e-5 * h);
  }
}

TEST(FvBendingFriction, KesHysteresisConvertsToTheFrictionMoment) {
  // Cotton broad (Matsudaira et al. 2015): 2HB 0.124 gf·cm/cm, HB = 0.062 gf·cm/cm = 6.08e-4 N.
  EXPECT_NEAR(KesBendingFriction(0.124), 0.062 * 9.80665e-3, 1e-15);
}

struct Tip {
  double x = 0.0, z = 0.0;  // relative to the clamp, m (z < 0 downwards)
};

// The heavy cantilever with a friction moment (above): length ℓ, w/D and H/D.
class FrictionCantilever {
 public:
  FrictionCantilever(double length, double w_over_d, double h_over_d)
      : length_(length), w_(w_over_d), h_(h_over_d) {}

  Tip Solve() const {
    double low = 0.0, high = 0.5 * w_ * length_ * length_ * 1.01;  // M(0)/D
    for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
      const double mid = 0.5 * (low + high);
      (Shoot(mid).end_moment < 0.0 ? low : high) = mid;
    }
    const Shot shot = Shoot(0.5 * (low + high));
    return {shot.x, -shot.z_down};
  }

 private:
  struct Shot {
    double x, z_down, end_moment;
  };
  // State: θ, M/D, x, z_down.
  void Derivative(double s, const double* y, double* dy) const {
    dy[0] = std::max(y[1] - h_, 0.0);
    dy[1] = -w_ * (length_ - s) * std::cos(y[0]);
    dy[2] = std::cos(y[0]);
    dy[3] = std::sin(y[0]);
  }
  Shot Shoot(double root_moment) const {
    double y[4] = {0.0, root_moment, 0.0, 0.0};
    testing::IntegrateRk4<4>(
        [this](double s, const double* state, double* rate) { Derivative(s, state, rate); },
        length_, 20000, y);
    return {y[2], y[3], y[1]};
  }
  double length_, w_, h_;
};

struct StripTip {
  Tip model, reference;
  bool converged = false;
  int iterations = 0;
};

// configs/fv/cantilever.yaml (4 cm, c = 2 cm) with the friction H (N) in both directions,
// smoothed over δ (1/m), on `nodes` nodes. The discrete clamp: cantilever_test.cc.
StripTip SolveStrip(double friction, double smoothing, int nodes) {
  const std::string h = std::to_string(friction);
  const Scene scene = testing::LoadConfig(
      "configs/fv/cantilever.yaml",
      {"mesh.nodes=[" + std::to_string(nodes) + ", 1]",
       "material.finite_volume.bending_friction_warp=" + h,
       "material.finite_volume.bending_friction_weft=" + h,
       "material.finite_volume.bending_friction_smoothing=" + std::to_string(smoothing)});
  Model model = BuildModel(scene);
  const RunResult run = RunSolve(scene, model, "newton");
  StripTip result;
  result.converged = run.converged && run.stability.stable;
  result.iterations = run.summary.iterations;
  const double spacing = scene.mesh.size.x() / (nodes - 1);
  const double d = scene.material.finite_volume.D_warp;
  const double w = scene.material.mass_value * 9.81;
  result.reference =
      FrictionCantilever(scene.mesh.size.x() - 0.5 * spacing, w / d, friction / d).Solve();
  const Eigen::Vector3d tip = testing::Position(model, nodes - 1);
  result.model = {tip.x() - 0.5 * spacing, tip.z()};
  return result;
}

// H = 2e-4 N against the root moment w L²/2 ≈ 9.4e-4 N: the outer 1.8 cm or so stays straight.
TEST(FvBendingFriction, HeavyCantileverMatchesTheShootingReference) {
  const double friction = 2e-4;
  const StripTip elastic = SolveStrip(0.0, 1.0, 81);
  const StripTip rubbing = SolveStrip(friction, 0.01, 81);
  ASSERT_TRUE(elastic.converged && rubbing.converged);
  // H = 0: the reference is the elastica, as in cantilever_test.cc.
  EXPECT_NEAR(elastic.model.z, elastic.reference.z, 1e-3 * std::abs(elastic.reference.z));
  // Friction stiffens the strip: a smaller deflection, matched to 0.1 %.
  EXPECT_LT(std::abs(rubbing.reference.z), 0.9 * std::abs(elastic.reference.z));
  EXPECT_NEAR(rubbing.model.z, rubbing.reference.z, 1e-3 * std::abs(rubbing.reference.z));
  EXPECT_NEAR(rubbing.model.x, rubbing.reference.x, 1e-3 * rubbing.reference.x);
  std::printf("tip z: elastic %.6g (reference %.6g), H %.3g N: %.6g (reference %.6g), %d its\n",
              elastic.model.z, elastic.reference.z, friction, rubbing.model.z, rubbing.reference.z,
              rubbing.iterations);
}

// The answer converges as the smoothing δ → 0 (the kink at the flat state is smoothed over
// curvatures below δ; here the strip's straight tip has κ ≈ 0 and its root κ ≈ 30 1/m).
TEST(FvBendingFriction, TheAnswerConvergesAsTheSmoothingGoesToZero) {
  double previous_change = 0.0, previous_z = 0.0;
  int k = 0;
  for (const double smoothing : {1.0, 0.1, 0.01, 0.001}) {
    const StripTip tip = SolveStrip(2e-4, smoothing, 41);
    ASSERT_TRUE(tip.converged) << smoothing;
    if (k > 0) {
      const double change = std::abs(tip.model.z - previous_z);
      if (k > 1) {
        EXPECT_LT(change, 0.5 * previous_change) << smoothing;
      }
      previous_change = change;
    }
    previous_z = tip.model.z;
    ++k;
  }
  EXPECT_LT(previous_change, 1e-3 * std::abs(previous_z));
}

}  // namespace
}  // namespace drape
