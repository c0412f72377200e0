// The fabric's contact with itself (src/model/self_contact.h): which pairs get terms and when,
// the step filter that keeps a step from passing one layer through another, and two layers
// pressed together resting the fabric's thickness apart with the supports carrying the load.
#include "src/model/self_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <fstream>
#include <string>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/model/self_intersection.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// Two squares as an OBJ: the lower one at z = 0, of n + 2 nodes a side, reaching a cell beyond
// the upper one all round; the upper one at z = `gap`, n × n nodes of the same cell over `side` m,
// off the lower one's lattice by 0.3 and 0.37 of a cell, so that no node lies over or under a
// side of the other square. (Offset by a third of a cell in both directions, every node lies
// exactly over a diagonal of the other: there the nearest parts of the pairs change, the
// distance's curvature jumps, and newton stalled at a relative residual of 0.017.)
std::string TwoSquaresObj(double side, int n, double gap) {
  std::string obj;
  const double cell = side / (n - 1);
  const auto square = [&](int nodes, double x, double y, double z) {
    for (int i = 0; i < nodes; ++i) {
      for (int j = 0; j < nodes; ++j) {
        obj += "v " + std::to_string(x + i * cell) + " " + std::to_string(y + j * cell) + " " +
               std::to_string(z) + "\n";
      }
    }
  };
  square(n + 2, -1.3 * cell, -1.37 * cell, 0.0);
  square(n, 0.0, 0.0, gap);
  const auto faces = [&](int nodes, int base) {  // OBJ counts from 1
    for (int i = 0; i + 1 < nodes; ++i) {
      for (int j = 0; j + 1 < nodes; ++j) {
        const int a = base + nodes * i + j, b = a + nodes, c = a + nodes + 1, d = a + 1;
        obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
        obj += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
      }
    }
  };
  faces(n + 2, 1);
  faces(n, 1 + (n + 2) * (n + 2));
  return obj;
}

constexpr int kSide = 6;                           // nodes along the upper square's side
constexpr int kLower = (kSide + 2) * (kSide + 2);  // the lower square's nodes, the first ones
constexpr double kSize = 0.1;                      // m
constexpr double kGap = 0.01;                      // m, the upper square's start above the lower

// The lower square held, the upper one free to move up and down only, under gravity: it falls
// onto the lower one.
Scene TwoSquaresScene(const testing::ScratchFolder& folder, const std::string& self = "true") {
  const std::string obj = (folder / "squares.obj").string();
  std::ofstream(obj) << TwoSquaresObj(kSize, kSide, kGap);
  std::string lower, upper;
  for (int k = 0; k < kLower; ++k) lower += (k ? ", " : "") + std::to_string(k);
  for (int k = kLower; k < kLower + kSide * kSide; ++k) {
    upper += (k > kLower ? ", " : "") + std::to_string(k);
  }
  const std::string text =
      "name: pressed\nmesh: {kind: file, path: " + obj +
      "}\n"
      "material:\n  model: springs\n  density: 0.2\n  springs: {structural: 100, shear: 50}\n"
      "fixed:\n  - nodes: {ids: [" +
      lower + "]}\n  - nodes: {ids: [" + upper +
      "]}\n    dofs: [x, y]\n"
      "loads: {gravity: [0, 0, -9.81]}\n"
      "contact: {self: " +
      self +
      "}\n"
      "solver: {method: newton, tolerance: 1.0e-9, max_iterations: 2000}\n"
      "output: {directory: " +
      (folder / "out").string() + ", write: [summary]}\n";
  return LoadSceneText(text, "<two squares>", folder.path().string());
}

TEST(SelfContact, AFlatSheetHasNoTermsAndNoForceAtRest) {
  const Scene scene = testing::LoadConfig("configs/examples/hanging_sheet.yaml");
  const Model model = BuildModel(scene);
  ASSERT_TRUE(model.self_contact.enabled);
  // Every pair of the flat lattice is a rest-shape neighbour or farther than the build radius.
  EXPECT_TRUE(model.self_contact.point_triangle.empty());
  EXPECT_TRUE(model.self_contact.edge_edge.empty());
  EXPECT_EQ(model.self_contact.first_term, static_cast<int>(model.terms.size()));
  EXPECT_DOUBLE_EQ(model.self_contact.clearance, 2.0 * scene.contact.thickness);
}

TEST(SelfContact, OffForAChainAndWhenTheSceneSaysSo) {
  const Model chain = BuildModel(testing::LoadConfig("configs/examples/chain.yaml"));
  EXPECT_FALSE(chain.self_contact.enabled);
  const Model off = BuildModel(
      testing::LoadConfig("configs/examples/hanging_sheet.yaml", {"contact.self=false"}));
  EXPECT_FALSE(off.self_contact.enabled);
  EXPECT_EQ(SelfSafeFraction(off, off.positions.data(), off.positions.data()), 1.0);
}

TEST(SelfContact, ALayerThatComesNearGetsItsTermsAndTheModelSaysItChanged) {
  testing::ScratchFolder folder("self_contact_terms");
  Model model = BuildModel(TwoSquaresScene(folder));
  ASSERT_TRUE(model.self_contact.enabled);
  EXPECT_TRUE(model.self_contact.point_triangle.empty());  // 1 cm apart: beyond the build radius
  const int generation = model.self_contact.generation;
  std::vector<double> lowered = model.positions;
  const double clearance = model.self_contact.clearance;
  for (int k = kLower; k < model.num_nodes; ++k) lowered[3 * k + 2] = clearance;
  ASSERT_TRUE(UpdateSelfContact(&model, lowered.data()));
  EXPECT_EQ(model.self_contact.generation, generation + 1);
  EXPECT_FALSE(model.self_contact.point_triangle.empty());
  EXPECT_EQ(model.terms.size(), model.self_contact.first_term +
                                    model.self_contact.point_triangle.size() +
                                    model.self_contact.edge_edge.size());
  // Asked again at the same positions, nothing changes.
  EXPECT_FALSE(UpdateSelfContact(&model, lowered.data()));
  EXPECT_EQ(model.self_contact.generation, generation + 1);
}

TEST(SelfContact, AStepThatWouldTunnelThroughTheOtherLayerIsCutShort) {
  testing::ScratchFolder folder("self_contact_tunnel");
  const Model model = BuildModel(TwoSquaresScene(folder));
  const double clearance = model.self_contact.clearance;
  // From 1 mm above the lower square (inside the clearance) to 4 mm below it: straight through.
  std::vector<double> from = model.positions, to = model.positions;
  const double start = 0.001, end = -0.004;
  for (int k = kLower; k < model.num_nodes; ++k) {
    from[3 * k + 2] = start;
    to[3 * k + 2] = end;
  }
  // Neither end crosses anything: the upper square only passes through the lower one on the way.
  ASSERT_FALSE(FindSelfIntersections(model, from).Any());
  ASSERT_FALSE(FindSelfIntersections(model, to).Any());
  const double fraction = SelfSafeFraction(model, from.data(), to.data());
  // The upper square may come down to half its distance min(d₀, C)/2 = 0.5 mm, and no farther:
  // (1 − 0.5) / 5 of the step, stopped within 1 % of the floor's margin above it.
  const double floor = 0.5 * std::min(start, clearance);
  const double expected = (start - floor) / (start - end);
  EXPECT_LE(fraction, expected);
  EXPECT_GE(fraction, expected * (1.0 - 0.02));
  for (int k = kLower; k < model.num_nodes; ++k) {
    EXPECT_GE(from[3 * k + 2] + fraction * (to[3 * k + 2] - from[3 * k + 2]), floor) << k;
  }
}

// Two squares pressed together by the upper one's weight: it rests on the lower one the fabric's
// thickness C apart, less the penalty's give (at most f C = 0.1 C for the whole load, the
// stiffness rule of src/model/contact.h), and the lower square's supports carry both weights.
TEST(SelfContact, TwoLayersPressedTogetherStopAtTheThicknessAndCarryTheLoad) {
  testing::ScratchFolder folder("self_contact_pressed");
  const Scene scene = TwoSquaresScene(folder);
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  ASSERT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.stability.stable);
  EXPECT_FALSE(result.self_intersections.Any());
  const double clearance = model.self_contact.clearance;
  for (int k = kLower; k < model.num_nodes; ++k) {
    const double height = model.positions[3 * k + 2];
    EXPECT_LE(height, clearance) << "node " << k;
    EXPECT_GE(height, (1.0 - kAllowedPenetration) * clearance) << "node " << k;
  }
  // The lower square's vertical reactions balance the weight of both squares.
  const Certificate& certificate = result.certificate;
  double lower_reaction = 0.0, weight = 0.0;
  for (int k = 0; k < model.num_nodes; ++k) {
    if (k < kLower) lower_reaction += certificate.node_forces[3 * k + 2];
    weight += model.applied[3 * k + 2];
  }
  EXPECT_NEAR(lower_reaction, -weight, 1e-6 * std::abs(weight));
}

}  // namespace
}  // namespace drape
