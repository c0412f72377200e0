// solver.levels: coarsened scenes, interpolation between lattices, Richardson extrapolation, and
// a refinement study whose limit and order are known (the tip-loaded finite-volume cantilever).
#include "src/analysis/levels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/model/mesh.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// q(h) = q₀ + C h^p sampled exactly: the extrapolation returns q₀ and p, for halving spacings and
// for the uneven ratios of a grid whose node count is not 2^k + 1.
TEST(Levels, ExtrapolationRecoversAKnownLimitAndOrder) {
  for (double order : {1.0, 2.0, 3.5}) {
    for (const std::vector<double>& h :
         {std::vector<double>{0.4, 0.2, 0.1}, std::vector<double>{0.083, 0.04, 0.0101}}) {
      std::vector<double> q;
      q.reserve(h.size());
      for (double x : h) q.push_back(0.7 - 0.3 * std::pow(x, order));
      const Extrapolation e = Extrapolate("drape_coefficient", h, q);
      ASSERT_TRUE(e.available) << e.reason;
      EXPECT_NEAR(e.observed_order, order, 1e-9);
      EXPECT_NEAR(e.value, 0.7, 1e-12);
      EXPECT_NEAR(e.error_estimate, 0.3 * std::pow(h.back(), order), 1e-12);
    }
  }
}

TEST(Levels, ExtrapolationRefusesWhatIsNotConverging) {
  const std::vector<double> h{0.4, 0.2, 0.1};
  EXPECT_FALSE(Extrapolate("energy", h, {1.0, 2.0, 1.5}).available);  // the change flips sign
  EXPECT_FALSE(Extrapolate("energy", h, {1.0, 1.1, 1.3}).available);  // grows: order < 0.1
  EXPECT_FALSE(Extrapolate("energy", {0.2, 0.1}, {1.0, 1.1}).available);
  EXPECT_NE(Extrapolate("energy", {0.2, 0.1}, {1.0, 1.1}).reason, "");
}

// Converged drape-test levels (coarsest first) with DC(h) = 0.5 + 0.3 h / 0.04 (first order, a
// known limit 0.5) and the given fold counts.
std::vector<LevelRecord> FirstOrderLevels(const std::vector<double>& spacing,
                                          const std::vector<int>& folds) {
  std::vector<LevelRecord> levels;
  for (size_t k = 0; k < spacing.size(); ++k) {
    LevelRecord level;
    level.spacing = spacing[k];
    level.converged = true;
    level.drape_coefficient = 0.5 + 0.3 * spacing[k] / 0.04;
    level.folds = folds[k];
    levels.push_back(level);
  }
  return levels;
}

std::vector<Extrapolation> DrapeExtrapolation(const std::vector<LevelRecord>& levels) {
  std::vector<double> h, q;
  for (const LevelRecord& level : levels) {
    h.push_back(level.spacing);
    q.push_back(*level.drape_coefficient);
  }
  return {Extrapolate("drape_coefficient", h, q)};
}

// The drape coefficient's error bar on a case of known order 1: with three levels, Richardson's
// estimate, the finest level's true error |DC(h) − 0.5|; with two, the change from the coarser
// level, which for first order is that error too. A fold count that changes between the two
// finest levels is flagged.
TEST(Levels, DrapeErrorBarOnAFirstOrderCase) {
  const std::vector<LevelRecord> three = FirstOrderLevels({0.04, 0.02, 0.01}, {8, 9, 9});
  const std::optional<DrapeErrorBar> richardson = DrapeErrorOf(three, DrapeExtrapolation(three));
  ASSERT_TRUE(richardson);
  EXPECT_DOUBLE_EQ(richardson->value, 0.575);
  EXPECT_NEAR(richardson->error(), 0.075, 1e-12);
  EXPECT_EQ(richardson->basis(), "Richardson, observed order 1.00");
  EXPECT_FALSE(richardson->mesh_rule_error);  // no rule here: the bar is the levels' alone
  EXPECT_FALSE(richardson->folds_differ);
  EXPECT_EQ(richardson->folds, (std::vector<int>{8, 9, 9}));

  const std::vector<LevelRecord> two = FirstOrderLevels({0.02, 0.01}, {9, 8});
  const std::optional<DrapeErrorBar> change = DrapeErrorOf(two, DrapeExtrapolation(two));
  ASSERT_TRUE(change);
  EXPECT_NEAR(change->error(), 0.075, 1e-12);
  EXPECT_EQ(change->basis(), "change from the 2 cm level");
  EXPECT_TRUE(change->folds_differ);
}

// Three levels the coarsest of which is coarser than the fabric's bending length give no
// extrapolation, however cleanly they converge: the bar falls back to the change from the next
// coarser level. A bending length longer than every level keeps Richardson's.
TEST(Levels, NoExtrapolationFromALevelCoarserThanTheBendingLength) {
  LevelsReport report;
  report.levels = FirstOrderLevels({0.02, 0.01, 0.005}, {9, 9, 9});
  for (LevelRecord& level : report.levels) level.energy = -1e-3 * (1.0 - level.spacing);
  AnalyseLevels(&report);
  ASSERT_TRUE(report.drape_error);
  ASSERT_EQ(report.drape_error->levels_basis, "Richardson, observed order 1.00");
  const LevelsReport clean = report;

  AnalyseLevels(&report, 0.025);  // every level finer than c: kept
  EXPECT_EQ(report.drape_error->levels_basis, "Richardson, observed order 1.00");

  AnalyseLevels(&report, 0.019);  // the cotton tester's c under a 2 cm level
  ASSERT_EQ(report.extrapolations.size(), clean.extrapolations.size());
  for (const Extrapolation& e : report.extrapolations) {
    EXPECT_FALSE(e.available) << e.quantity;
    EXPECT_NE(e.reason.find("coarser than the fabric's bending length (1.9 cm)"), std::string::npos)
        << e.reason;
  }
  ASSERT_TRUE(report.drape_error);
  EXPECT_EQ(report.drape_error->levels_basis, "change from the 1 cm level");
  EXPECT_NEAR(report.drape_error->levels_error, 0.0375, 1e-12);  // 0.3 (1 cm − 5 mm) / 4 cm
}

// No error bar from levels that cannot give one: an unconverged level, fabric through the disc,
// a single level, a scene without a drape coefficient.
TEST(Levels, NoDrapeErrorBarWhereALevelCannotGiveOne) {
  std::vector<LevelRecord> levels = FirstOrderLevels({0.02, 0.01}, {9, 9});
  levels[0].converged = false;
  EXPECT_FALSE(DrapeErrorOf(levels, {}));
  levels = FirstOrderLevels({0.02, 0.01}, {9, 9});
  levels[1].edges_through_disk = 3;
  EXPECT_FALSE(DrapeErrorOf(levels, {}));
  EXPECT_FALSE(DrapeErrorOf(FirstOrderLevels({0.01}, {9}), {}));
  levels = FirstOrderLevels({0.02, 0.01}, {9, 9});
  levels[0].drape_coefficient.reset();
  EXPECT_FALSE(DrapeErrorOf(levels, {}));
}

// A coarser scene: the same strip on a lattice of twice the spacing, its clamp (ids [0, 1]) still
// the first two nodes; a circle's spacing doubles; a spring sheet's flexion stiffness falls 16×.
TEST(Levels, CoarsenedScenesKeepTheSpecimen) {
  const Scene strip = testing::LoadConfig("configs/fv/cantilever_tip.yaml");
  const Scene coarse = CoarsenedScene(strip, 4);
  EXPECT_EQ(coarse.mesh.nodes[0], 21);
  EXPECT_EQ(coarse.mesh.nodes[1], 1);
  EXPECT_EQ(coarse.fixed[0].nodes.ids, (std::vector<int>{0, 1}));
  const Scene disc = CoarsenedScene(
      testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml", {"mesh.spacing=0.01"}), 2);
  EXPECT_DOUBLE_EQ(disc.mesh.spacing, 0.02);
  const Scene sheet = testing::LoadConfig("configs/hard/two_corner_sheet.yaml");
  const Scene coarse_sheet = CoarsenedScene(sheet, 2);
  EXPECT_EQ(coarse_sheet.mesh.nodes[0], 16);  // 30 nodes: 29 steps → 14.5 → 15
  EXPECT_NEAR(coarse_sheet.material.springs.flexion.warp,
              sheet.material.springs.flexion.warp * std::pow(15.0 / 29.0, 4), 1e-12);
}

// Interpolating a solved coarse lattice onto the fine one reproduces an affine deformation
// exactly (bilinear interpolation), also beyond the coarse circle's outline (linear
// extrapolation). The map stretches no lattice edge by more than 1 %, so the stretch limit
// leaves it as it is (no node is fixed: a clamp that stays put would stretch its neighbours'
// edges).
TEST(Levels, ProlongationIsExactForAnAffineMap) {
  Scene fine_scene = testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml",
                                         {"mesh.spacing=0.02", "loads.gravity=[0, 0, 0]"});
  fine_scene.obstacles.clear();  // the drape test's disc and clamp
  fine_scene.fixed.clear();
  const Scene coarse_scene = CoarsenedScene(fine_scene, 2);
  Model coarse = BuildModel(coarse_scene);
  Model fine = BuildModel(fine_scene);
  const double c = std::cos(0.3), s = std::sin(0.3);
  auto affine = [c, s](const double* x, double* y) {  // a rotation about z after a 0.6 % stretch
    const double u = 1.006 * x[0], v = 0.997 * x[1] + 0.002 * x[0];
    y[0] = c * u - s * v + 0.01;
    y[1] = s * u + c * v;
    y[2] = x[2] - 0.002 * x[0];
  };
  for (int k = 0; k < coarse.num_nodes; ++k) {
    affine(coarse.initial.data() + 3 * k, coarse.positions.data() + 3 * k);
  }
  ProlongPositions(coarse_scene, coarse, fine_scene, &fine);
  for (int k = 0; k < fine.num_nodes; ++k) {
    double expected[3];
    affine(fine.initial.data() + 3 * k, expected);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(fine.positions[3 * k + axis], expected[axis], 1e-12) << k << " " << axis;
    }
  }
  EXPECT_GT(fine.num_nodes, 100);
}

// The largest stretch (relative elongation) of a lattice edge (the mesh's warp, weft and shear
// links: sides and diagonals) from the flat start to the model's positions.
double LargestLatticeStretch(const Mesh& mesh, const Model& model) {
  double largest = 0.0;
  for (const std::vector<Link>* links : {&mesh.warp, &mesh.weft, &mesh.shear}) {
    for (const auto& [a, b] : *links) {
      const Eigen::Vector3d now = Eigen::Vector3d(model.positions.data() + 3 * b) -
                                  Eigen::Vector3d(model.positions.data() + 3 * a);
      const Eigen::Vector3d rest = Eigen::Vector3d(model.initial.data() + 3 * b) -
                                   Eigen::Vector3d(model.initial.data() + 3 * a);
      largest = std::max(largest, now.norm() / rest.norm() - 1.0);
    }
  }
  return largest;
}

// A drape tester solved on a 4 cm lattice, interpolated onto the 2 cm one: bilinear
// interpolation alone cuts across the support disc's rim (nodes inside the disc, edges beside them
// stretched by up to 78 %); the interpolated start has no node in the disc's contact layer or
// under it, no lattice edge stretched by more than the 1 % limit (with the slack of the passes'
// stopping rule), and its clamp where it was.
TEST(Levels, ProlongationOverADiscRimLeavesTheDiscAndKeepsTheLengths) {
  const Scene fine_scene =
      testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml", {"mesh.spacing=0.02"});
  const Scene coarse_scene = CoarsenedScene(fine_scene, 2);
  Model coarse = BuildModel(coarse_scene);
  ASSERT_TRUE(RunSolve(coarse_scene, coarse, "newton", {}).converged);
  Model fine = BuildModel(fine_scene);
  ProlongPositions(coarse_scene, coarse, fine_scene, &fine);
  const Certificate start = ComputeCertificate(fine, fine.positions.data());
  EXPECT_LT(start.energy_by_type.at("disk_contact"), 1e-12);
  EXPECT_LT(LargestLatticeStretch(BuildMesh(fine_scene.mesh), fine), 0.0125);
  for (int k = 0; k < fine.num_nodes; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      if (fine.fixed[3 * k + axis]) {
        EXPECT_EQ(fine.positions[3 * k + axis], fine.initial[3 * k + axis]);
      }
    }
  }
  // The start does hang over the rim: 1 cm (ten contact thicknesses) below it at least. (The 4 cm
  // lattice's edges rest on the rim's corner, so its skirt hangs about 2 cm deep, where with node
  // contact alone its edges cut the corner and it hung 3 cm deep.)
  double lowest = 0.0;
  for (int k = 0; k < fine.num_nodes; ++k) lowest = std::min(lowest, fine.positions[3 * k + 2]);
  EXPECT_LT(lowest, fine_scene.obstacles.at(0).center.z() - 0.01);
}

// Levels need a lattice to coarsen: located errors at solver.levels otherwise.
TEST(Levels, UnscalableScenesAreRefusedAtTheKey) {
  const Scene strip = testing::LoadConfig("configs/fv/cantilever_tip.yaml",
                                          {"mesh.nodes=[11, 1]", "solver.levels=4"});
  try {
    CoarsenedScene(strip, 8);
    FAIL() << "coarsened 11 nodes 8 times";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find(":2:15: solver.levels: 4 is too many for mesh.nodes 11"), std::string::npos)
        << what;
  }
  Scene chain = testing::LoadConfig("configs/hard/compressed_chain.yaml", {"solver.levels=2"});
  EXPECT_THROW(CoarsenedScene(chain, 2), InputError);
}

}  // namespace
}  // namespace drape
