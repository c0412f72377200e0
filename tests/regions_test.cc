// Regions (src/model/regions.h): the material of each node, the rule that a control volume takes
// its own node's values, later regions winning, and the closed-form strip of two rigidities.
#include "src/model/regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/mesh.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

std::string Text(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// A finite-volume plate 8 cm × 4 cm (9 × 5 nodes, 1 cm apart) clamped along its left edge (its
// first two columns held), drooping under its weight, with the given regions.
std::string Plate(const std::string& regions, double d_warp = 2e-6, double d_weft = 1.5e-6) {
  return "mesh: {kind: grid, size: [0.08, 0.04], nodes: [9, 5]}\n"
         "material:\n"
         "  model: finite_volume\n"
         "  density: 0.12\n"
         "  finite_volume: {E_warp: 800, E_weft: 500, G: 5, D_warp: " +
         Text(d_warp) + ", D_weft: " + Text(d_weft) +
         "}\n"
         "fixed:\n"
         "  - nodes: {box: {min: [-1, -1, -1], max: [0.01, 1, 1]}}\n"
         "loads:\n"
         "  gravity: [0, 0, -9.81]\n"
         "solver: {method: newton, tolerance: 1.0e-10, max_iterations: 400}\n" +
         regions;
}

// Loads a scene from its text (written to a scratch file).
Scene SceneFromText(const std::string& text, const std::string& tag) {
  return LoadScene(testing::ScratchFile("regions_test_" + tag, "scene.yaml", text).path().string());
}

const std::string kLeftHalfDoubled =
    "regions:\n"
    "  - nodes: {box: {min: [-1, -1, -1], max: [0.04, 1, 1]}}\n"
    "    D_warp: 4.0e-6\n"
    "    D_weft: 3.0e-6\n";

// The node whose control volume a finite-volume term belongs to: the centre of a bending term
// (W, P, E, S, N or A, P, B), the corner of a membrane quarter section (P, A, B).
int OwnerOf(const Term& term) {
  return term.type() == "fv_bending" ? term.nodes()[1] : term.nodes()[0];
}

// A plate whose left half (x ≤ 4 cm: 5 of 9 columns) has twice the bending rigidity gives the
// same shape as the model assembled by hand from the plain plate's terms and the stiff plate's:
// each control volume's terms from the plate of its own node's material. A region ignored, or
// applied to a term by another rule (a neighbour's material, the mean of the two), fails.
TEST(Regions, LeftHalfTwiceAsRigidIsTheHandAssembledPlate) {
  const Scene with_region = SceneFromText(Plate(kLeftHalfDoubled), "a");
  Model regions = BuildModel(with_region);
  Model plain = BuildModel(SceneFromText(Plate(""), "b"));
  Model stiff = BuildModel(SceneFromText(Plate("", 4e-6, 3e-6), "c"));
  Model by_hand = BuildModel(SceneFromText(Plate(""), "d"));
  ASSERT_EQ(plain.terms.size(), stiff.terms.size());
  by_hand.terms.clear();
  int from_stiff = 0;
  for (size_t t = 0; t < plain.terms.size(); ++t) {
    const Term& term = *plain.terms[t];
    const bool fv = term.type() == "fv_bending" || term.type() == "fv_membrane";
    const bool left = fv && plain.position(OwnerOf(term)).x() <= 0.04 + 1e-12;
    ASSERT_EQ(stiff.terms[t]->nodes(), term.nodes());
    from_stiff += left && term.type() == "fv_bending" ? 1 : 0;
    by_hand.terms.push_back(std::move(left ? stiff.terms[t] : plain.terms[t]));
  }
  ASSERT_GT(from_stiff, 0);
  ValidateModel(by_hand);
  EXPECT_EQ(regions.TermCounts(), by_hand.TermCounts());
  ASSERT_EQ(regions.region_counts.size(), 1u);
  EXPECT_EQ(regions.region_counts[0].selected, 25);  // 5 columns × 5 rows

  Model plain_solved = BuildModel(SceneFromText(Plate(""), "e"));
  const RunResult a = RunSolve(with_region, regions, "newton");
  const RunResult b = RunSolve(with_region, by_hand, "newton");
  const RunResult c = RunSolve(with_region, plain_solved, "newton");
  ASSERT_TRUE(a.converged) << a.summary.termination;
  ASSERT_TRUE(b.converged) << b.summary.termination;
  ASSERT_TRUE(c.converged) << c.summary.termination;
  EXPECT_TRUE(a.stability.stable);
  double largest = 0.0, moved = 0.0;
  for (int k = 0; k < regions.num_nodes; ++k) {
    largest = std::max(largest, (regions.position(k) - by_hand.position(k)).norm());
    moved = std::max(moved, (regions.position(k) - plain_solved.position(k)).norm());
  }
  EXPECT_LT(largest, 1e-9 * regions.size);
  EXPECT_GT(moved, 1e-3 * regions.size);  // the stiffer half does change the shape
}

// The tip-loaded strip (configs/fv/cantilever_tip.yaml, 81 nodes, a load small enough for
// linear beam theory) whose clamped half has twice the rigidity: the tip deflection of a beam of
// rigidity 2D on [0, a] and D on [a, L] is P/(3D) [(L³ − (L − a)³)/2 + (L − a)³], so the ratio
// to the uniform strip's P L³/(3D) is known in closed form. The discrete interface is the
// control-volume boundary between node 39 (in the region) and node 40; the clamp acts at h/2.
TEST(Regions, StripWithAStiffHalfMatchesBeamTheory) {
  const int nodes = 81;
  const std::vector<std::string> base = {"mesh.nodes=[81, 1]",
                                         "loads.forces[0].total=[0, 0, -1.6e-6]"};
  const double h = 0.05 / (nodes - 1);
  std::vector<std::string> stiff = base;
  stiff.push_back("regions=[{nodes: {box: {min: [-1, -1, -1], max: [" + std::to_string(39.5 * h) +
                  ", 1, 1]}}, D_warp: 2.0e-5, D_weft: 2.0e-5}]");
  const auto uniform = testing::SolveConfig("configs/fv/cantilever_tip.yaml", "newton", base);
  const auto halves = testing::SolveConfig("configs/fv/cantilever_tip.yaml", "newton", stiff);
  ASSERT_TRUE(uniform.result.converged) << uniform.result.summary.termination;
  ASSERT_TRUE(halves.result.converged) << halves.result.summary.termination;
  EXPECT_EQ(halves.model.region_counts[0].selected, 40);
  const double length = 0.05 - 0.5 * h, a = 39.0 * h;
  const double rest = std::pow(length - a, 3);
  const double expected = (0.5 * (std::pow(length, 3) - rest) + rest) / std::pow(length, 3);
  const double ratio = testing::Position(halves.model, nodes - 1).z() /
                       testing::Position(uniform.model, nodes - 1).z();
  std::printf("tip deflection ratio %.6f, beam theory %.6f\n", ratio, expected);
  EXPECT_NEAR(ratio, expected, 2e-3);  // 1 if the region were ignored, 0.5 over the whole strip
}

// The plate with its tip (the last three columns, x >= 6 cm) a named region, pushed down by a
// pressure given on that region by name, or on the same box written out.
std::string PlateWithTipPressure(const std::string& tip_selection) {
  std::string text = Plate(
      "regions:\n"
      "  - name: tip\n"
      "    nodes: {box: {min: [0.055, -1, -1], max: [1, 1, 1]}}\n"
      "    density: 0.12\n");
  const std::string gravity = "  gravity: [0, 0, -9.81]\n";
  text.replace(text.find(gravity), gravity.size(),
               gravity + "  forces:\n    - nodes: " + tip_selection + "\n      pressure: -2\n");
  return text;
}

// A load on a region by name is the load on the region's selection: the same applied forces
// (p × the lumped area of the 15 tip nodes, along -z) and the same equilibrium, which balances.
TEST(Regions, APressureOnANamedRegionIsThePressureOnItsNodes) {
  const Scene by_name = SceneFromText(PlateWithTipPressure("{region: tip}"), "i");
  const Scene by_box =
      SceneFromText(PlateWithTipPressure("{box: {min: [0.055, -1, -1], max: [1, 1, 1]}}"), "j");
  Model named = BuildModel(by_name);
  Model boxed = BuildModel(by_box);
  const Mesh mesh = BuildMesh(by_name.mesh);
  double tip_area = 0.0;
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    if (mesh.nodes[k].x() > 0.055) tip_area += mesh.area[k];
  }
  EXPECT_NEAR(tip_area, 0.025 * 0.04, 1e-15);  // 2.5 columns of 1 cm cells
  Eigen::Vector3d load = Eigen::Vector3d::Zero();
  for (int k = 0; k < named.num_nodes; ++k) {
    load +=
        Eigen::Vector3d(named.applied[3 * k], named.applied[3 * k + 1], named.applied[3 * k + 2]) -
        named.mass[k] * Eigen::Vector3d(0, 0, -9.81);
  }
  EXPECT_NEAR((load - Eigen::Vector3d(0, 0, -2.0 * tip_area)).norm(), 0.0, 1e-15);
  EXPECT_EQ(named.applied, boxed.applied);

  const RunResult a = RunSolve(by_name, named, "newton");
  const RunResult b = RunSolve(by_box, boxed, "newton");
  ASSERT_TRUE(a.converged) << a.summary.termination;
  EXPECT_TRUE(a.certificate.balanced);
  EXPECT_TRUE(a.stability.stable);
  EXPECT_EQ(named.positions, boxed.positions);
  // The load bends the plate further than its weight alone.
  Model unloaded = BuildModel(SceneFromText(Plate(""), "k"));
  ASSERT_TRUE(RunSolve(SceneFromText(Plate(""), "l"), unloaded, "newton").converged);
  EXPECT_LT(testing::Position(named, 8).z(), testing::Position(unloaded, 8).z() - 1e-4);
}

// Overlapping regions: the later one wins, key by key; nodes in no region keep the scene's
// material; the counts say how many nodes each region selects and keeps.
TEST(Regions, TheLaterRegionWinsKeyByKey) {
  const Scene scene = SceneFromText(Plate("regions:\n"
                                          "  - nodes: {column: 0}\n"  // 5 nodes, x = 0
                                          "    D_warp: 4.0e-6\n"
                                          "    density: 0.2\n"
                                          "  - nodes: {ij: [[0, 0], [1, 0]]}\n"
                                          "    D_warp: 8.0e-6\n"),
                                    "f");
  const NodeMaterials materials = AssignMaterials(scene, BuildMesh(scene.mesh));
  ASSERT_EQ(materials.counts.size(), 2u);
  EXPECT_EQ(materials.counts[0].selected, 5);
  EXPECT_EQ(materials.counts[0].last, 4);
  EXPECT_EQ(materials.counts[1].selected, 2);
  EXPECT_EQ(materials.counts[1].last, 2);
  EXPECT_EQ(materials.at(0).finite_volume.D_warp, 8.0e-6);  // (0, 0): both, the later wins
  EXPECT_EQ(materials.at(0).mass_value, 0.2);               // ... and the earlier's density stays
  EXPECT_EQ(materials.at(1).finite_volume.D_warp, 8.0e-6);  // (1, 0): the second only
  EXPECT_EQ(materials.at(1).mass_value, 0.12);
  EXPECT_EQ(materials.at(9).finite_volume.D_warp, 4.0e-6);  // (0, 1): the first only
  EXPECT_EQ(materials.at(2).finite_volume.D_warp, 2.0e-6);  // (2, 0): none
  EXPECT_EQ(materials.at(9).finite_volume.D_weft, 1.5e-6);  // not given: the scene's
  const Model model = BuildModel(scene);
  EXPECT_DOUBLE_EQ(model.mass[9], 0.2 / 0.12 * model.mass[17]);  // (0, 1) and (8, 1): same area
}

// The default twist D_66 = √(D_warp D_weft)/3 (docs/reference.md, "Twist") follows a region's own
// bending rigidities; a region's D_66 is its own.
TEST(Regions, ARegionKeepsTheDefaultTwistRuleOrGivesItsOwn) {
  const Scene scene = SceneFromText(Plate("regions:\n"
                                          "  - nodes: {column: 0}\n"
                                          "    D_warp: 6.0e-6\n"
                                          "  - nodes: {column: 1}\n"
                                          "    D_warp: 6.0e-6\n"
                                          "    D_66: 1.0e-7\n"),
                                    "f");
  const NodeMaterials materials = AssignMaterials(scene, BuildMesh(scene.mesh));
  EXPECT_NEAR(materials.at(2).finite_volume.D_66, std::sqrt(2.0e-6 * 1.5e-6) / 3, 1e-20);
  EXPECT_NEAR(materials.at(0).finite_volume.D_66, std::sqrt(6.0e-6 * 1.5e-6) / 3, 1e-20);
  EXPECT_EQ(materials.at(1).finite_volume.D_66, 1.0e-7);
}

// A region that gives the scene's own values changes nothing: the same terms and the same
// energy, bitwise.
TEST(Regions, ARegionOfTheScenesOwnValuesChangesNothing) {
  const Scene scene = SceneFromText(Plate("regions:\n"
                                          "  - nodes: {all: true}\n"
                                          "    D_warp: 2.0e-6\n"
                                          "    E_weft: 500\n"),
                                    "g");
  const Model with = BuildModel(scene);
  const Model without = BuildModel(SceneFromText(Plate(""), "h"));
  ASSERT_EQ(with.terms.size(), without.terms.size());
  std::vector<double> moved = with.positions;
  for (size_t i = 0; i < moved.size(); ++i) moved[i] += 1e-3 * std::sin(0.7 * i);
  for (size_t t = 0; t < with.terms.size(); ++t) {
    double a = 0.0, b = 0.0;
    ASSERT_TRUE(with.terms[t]->Energy(moved.data(), &a));
    ASSERT_TRUE(without.terms[t]->Energy(moved.data(), &b));
    EXPECT_EQ(a, b) << with.terms[t]->type();
  }
}

}  // namespace
}  // namespace drape
