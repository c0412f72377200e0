// Yarn friction in shear (costs/fv_shear_friction.h): its closed form on a sheared quarter, its
// invariances, the KES 2HG conversion, the scene keys, and a sheet in simple shear against the
// equilibrium of its shear forces, which HG = 0 turns back into the elastic one.
//
// Reference (derived here, computed in the test). A square sheet of side L, its bottom edge held,
// every node held in the sheet's plane (as a shear frame holds it: free, the thin sheet would
// wrinkle out of its plane rather than shear), its top edge pulled along x by a traction that
// gives each column a force in proportion to its width: τ per unit width in all. With
// inextensible columns every quarter shears by the same angle γ, the top edge moving by L sin γ,
// and the energy per unit width is
//   L (½ G γ² + HG (√(γ² + δ²) − δ)) − τ L sin γ,
// stationary where G γ + HG γ/√(γ² + δ²) = τ cos γ (bisection). The model adds what the reference
// leaves out, the columns' stretch and the sheet's bending in its plane as a beam, ≈ 4 τ/E rad
// (1.5e-4 rad measured with E = 2,000 N/m, 1.2e-6 with the 200,000 N/m here): a tolerance of
// 1e-3 γ + 5e-6 rad holds the rest to the reference.
#include "costs/fv_shear_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/fabric_parameters.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/term_checks.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

double Energy(const FvShearFriction& friction, const std::vector<double>& x) {
  double energy = 0.0;
  EXPECT_TRUE(friction(x.data(), x.data() + 3, x.data() + 6, &energy));
  return energy;
}

// A quarter P, A, B with arms l_a along x and l_b sheared by γ towards x, turned by `turn` about z.
std::vector<double> ShearedQuarter(double rest_a, double rest_b, double shear, double turn = 0.0) {
  const double c = std::cos(turn), s = std::sin(turn);
  const double bx = rest_b * std::sin(shear), by = rest_b * std::cos(shear);
  return {0, 0, 0, rest_a * c, rest_a * s, 0, bx * c - by * s, bx * s + by * c, 0};
}

TEST(FvShearFriction, OnAShearedQuarterItIsTheSmoothedAbsoluteShearTimesHgArea) {
  const double hg = 0.05, rest_a = 0.01, rest_b = 0.012, delta = 0.002;
  const FvShearFriction friction(hg, rest_a, rest_b, delta);
  for (const double shear : {-0.3, -0.01, 0.001, 0.05, 0.4}) {
    const double area = rest_a * rest_b / 4.0;
    const double expected = hg * area * (std::sqrt(shear * shear + delta * delta) - delta);
    EXPECT_NEAR(Energy(friction, ShearedQuarter(rest_a, rest_b, shear)), expected,
                1e-12 * hg * area)
        << shear;
  }
}

TEST(FvShearFriction, ZeroAtRestInvariantUnderRigidMotions) {
  const FvShearFriction friction(0.05, 0.01, 0.012, 0.002);
  EXPECT_EQ(Energy(friction, ShearedQuarter(0.01, 0.012, 0.0)), 0.0);
  const std::vector<double> quarter = ShearedQuarter(0.01, 0.012, 0.2);
  std::vector<double> moved = ShearedQuarter(0.01, 0.012, 0.2, 0.9);
  for (int k = 0; k < 9; ++k) moved[k] += k % 3 == 2 ? 0.3 : -0.2;
  EXPECT_NEAR(Energy(friction, moved), Energy(friction, quarter), 1e-15);
}

TEST(FvShearFriction, TheSharedChecksHoldAtRestAndSheared) {
  const auto term =
      MakeTerm("fv_shear_friction", {0, 1, 2}, FvShearFriction::Create(0.05, 0.01, 0.012, 0.01));
  const std::vector<double> rest = {0.001, 0.002, 0, 0.011, 0.002, 0, 0.001, 0.014, 0};
  testing::ExpectZeroForce(*term, rest);
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const std::vector<double> state = testing::Perturbed(rest, 0.002, seed);
    testing::ExpectDerivativesMatchDifferences(*term, state);
    testing::ExpectRigidMotionInvariant(*term, state);
    testing::ExpectForcesBalance(*term, state);
  }
}

TEST(FvShearFriction, KesHysteresisConvertsToTheFrictionForce) {
  // 2HG 1.0 gf/cm: HG = 0.5 gf/cm = 0.5 × 9.80665e-3 N / 1e-2 m.
  EXPECT_NEAR(KesShearFriction(1.0), 0.5 * 0.980665, 1e-15);
}

// The simple-shear sheet of the reference: side 4 cm, 5 × 5 nodes, G = 2 N/m, τ (N/m), HG (N/m).
std::string ShearScene(double tau, const std::string& friction_keys) {
  const double spacing = 0.01;
  const double traction = 2.0 * tau / spacing;  // Pa: the top row's lumped areas sum to W h/2
  return R"(name: simple-shear
mesh: {kind: grid, size: [0.04, 0.04], nodes: [5, 5]}
material:
  model: finite_volume
  density: 0.2
  finite_volume: {E_warp: 2.0e5, E_weft: 2.0e5, G: 2, D_warp: 1.0e-6, D_weft: 1.0e-6)" +
         friction_keys + R"(}
fixed:
  - nodes: {all: true}
    dofs: [z]
  - nodes: {edge: bottom}
loads:
  forces:
    - nodes: {edge: top}
      traction: [)" +
         std::to_string(traction) + R"(, 0, 0]
solver: {method: newton, tolerance: 1.0e-10, max_iterations: 500}
)";
}

Scene LoadText(const std::string& text) {
  return LoadScene(testing::ScratchFile("shear_friction", "scene.yaml", text).path().string());
}

// The root of G γ + HG γ/√(γ² + δ²) = τ cos γ in (0, π/2).
double ReferenceShear(double g, double hg, double delta, double tau) {
  double low = 0.0, high = 1.5;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (low + high);
    const double excess = g * mid + hg * mid / std::hypot(mid, delta) - tau * std::cos(mid);
    (excess < 0.0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

struct ShearResult {
  double shear = 0.0;  // rad, of the middle column
  bool sound = false;  // converged to a stable minimum
  std::string termination;
};

ShearResult SolveShear(double tau, const std::string& friction_keys) {
  const Scene scene = LoadText(ShearScene(tau, friction_keys));
  Model model = BuildModel(scene);
  const RunResult run = RunSolve(scene, model, "newton");
  const Eigen::Vector3d column = testing::Position(model, 4 * 5 + 2) - testing::Position(model, 2);
  return {std::asin(column.x() / column.norm()), run.converged && run.stability.stable,
          run.summary.termination};
}

TEST(FvShearFriction, SimpleShearMatchesTheEquilibriumOfItsShearForces) {
  const double g = 2.0, tau = 0.06;
  const ShearResult elastic = SolveShear(tau, "");
  ASSERT_TRUE(elastic.sound) << elastic.termination;
  EXPECT_NEAR(elastic.shear, ReferenceShear(g, 0.0, 1.0, tau), 1e-3 * elastic.shear + 5e-6);
  for (const double hg : {0.03, 0.09}) {  // below τ: it shears less; above: it stays nearly square
    SCOPED_TRACE(hg);
    const double delta = 0.001;
    const ShearResult result = SolveShear(tau, ", shear_friction: " + std::to_string(hg));
    ASSERT_TRUE(result.sound) << result.termination;
    EXPECT_NE(result.termination.find("continuation"), std::string::npos) << result.termination;
    const double expected = ReferenceShear(g, hg, delta, tau);
    EXPECT_NEAR(result.shear, expected, 1e-3 * expected + 5e-6);
    EXPECT_LT(result.shear, elastic.shear);
  }
}

TEST(FvShearFriction, KesTwoHgGivesTheSameFabricAsShearFriction) {
  const Scene si = LoadText(ShearScene(0.06, ", shear_friction: 0.4903325"));
  const Scene kes = LoadText(ShearScene(0.06, ", kes: {2HG: 1.0}"));
  EXPECT_NEAR(si.material.finite_volume.shear_friction, kes.material.finite_volume.shear_friction,
              1e-15);
  EXPECT_THROW(LoadText(ShearScene(0.06, ", shear_friction: 0.4, kes: {2HG: 1.0}")), InputError);
  EXPECT_THROW(LoadText(ShearScene(0.06, ", shear_friction: -0.4")), InputError);
  EXPECT_THROW(LoadText(ShearScene(0.06, ", shear_friction_smoothing: 0")), InputError);
}

}  // namespace
}  // namespace drape
