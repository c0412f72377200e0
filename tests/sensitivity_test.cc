// The implicit function theorem's sensitivities (src/run/sensitivity.h) against central
// differences of whole solves, and their refusals.
#include "src/run/sensitivity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"

namespace drape {
namespace {

// A sheet hung by two corners, 7 × 7 springs: geometrically nonlinear, quick.
constexpr char kSheet[] = R"(mesh: {size: [1.0, 1.0], nodes: [7, 7]}
material: {model: springs, density: 0.2, springs: {structural: 1000, shear: 500, flexion: 10}}
fixed: [{nodes: {corner: top-left}}, {nodes: {corner: top-right}}]
loads: {gravity: [0, 0, -9.81]}
solver: {method: newton, tolerance: 1.0e-12, max_iterations: 500}
)";

Scene SheetScene(const std::vector<std::string>& overrides = {}) {
  return LoadSceneText(kSheet, "<sheet>", ".", overrides);
}

std::vector<double> Solved(const std::vector<std::string>& overrides) {
  const Scene scene = SheetScene(overrides);
  Model model = BuildModel(scene);
  EXPECT_TRUE(RunSolve(scene, model, "newton").converged);
  return model.positions;
}

// The models of one key at value ∓ δ (Model is move-only: a list of one is built by moving).
std::vector<ParameterModels> One(ParameterModels parameter) {
  std::vector<ParameterModels> list;
  list.push_back(std::move(parameter));
  return list;
}

ParameterModels Parameter(const std::string& key, double value) {
  ParameterModels parameter;
  parameter.key = key;
  parameter.step = SensitivityStep(value);
  parameter.minus = BuildModel(SheetScene({key + "=" + std::to_string(value - parameter.step)}));
  parameter.plus = BuildModel(SheetScene({key + "=" + std::to_string(value + parameter.step)}));
  return parameter;
}

// dx/dp by the theorem against (x(p + h) − x(p − h)) / 2h of solves at h = 1e-3 p: agreement to
// 1e-5 of the largest derivative (the differences' truncation is O(h²) ≈ 1e-6, the solves' error
// 1e-12 / 2e-3).
TEST(Sensitivity, IsTheCentralDifferenceOfSolves) {
  const Scene scene = SheetScene();
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  ASSERT_TRUE(result.converged);
  const std::vector<std::pair<std::string, double>> keys = {
      {"material.density", 0.2}, {"material.springs.structural", 1000.0}};
  std::vector<ParameterModels> parameters;
  parameters.reserve(keys.size());
  for (const auto& [key, value] : keys) parameters.push_back(Parameter(key, value));
  const auto derivatives = PositionSensitivities(model, result, parameters);
  ASSERT_EQ(derivatives.size(), 2u);
  for (size_t k = 0; k < keys.size(); ++k) {
    const auto& [key, value] = keys[k];
    const double h = 1e-3 * value;
    const std::vector<double> plus = Solved({key + "=" + std::to_string(value + h)});
    const std::vector<double> minus = Solved({key + "=" + std::to_string(value - h)});
    double scale = 0.0, error = 0.0;
    for (size_t i = 0; i < plus.size(); ++i) {
      const double difference = (plus[i] - minus[i]) / (2 * h);
      scale = std::max(scale, std::abs(difference));
      error = std::max(error, std::abs(derivatives[k][i] - difference));
      if (model.fixed[i]) {
        EXPECT_EQ(derivatives[k][i], 0.0);
      }
    }
    EXPECT_GT(scale, 0.0) << key;
    EXPECT_LE(error, 1e-5 * scale) << key;
  }
}

// A heavier sheet hangs lower at every free node.
TEST(Sensitivity, AHeavierSheetHangsLower) {
  const Scene scene = SheetScene();
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  const auto derivatives =
      PositionSensitivities(model, result, One(Parameter("material.density", 0.2)));
  for (int node = 0; node < model.num_nodes; ++node) {
    if (!model.fixed[3 * node + 2]) {
      EXPECT_LT(derivatives[0][3 * node + 2], 0.0) << node;
    }
  }
}

TEST(Sensitivity, IsRefusedWithoutAConvergedEquilibrium) {
  const Scene scene = SheetScene({"solver.max_iterations=1"});
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  ASSERT_FALSE(result.converged);
  EXPECT_THROW(PositionSensitivities(model, result, One(Parameter("material.density", 0.2))),
               SensitivityError);
}

TEST(Sensitivity, IsRefusedForAKeyThatMovesTheNodes) {
  const Scene scene = SheetScene();
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  ParameterModels nodes;
  nodes.key = "mesh.nodes";
  nodes.step = 1.0;
  nodes.minus = BuildModel(SheetScene({"mesh.nodes=[6, 6]"}));
  nodes.plus = BuildModel(SheetScene({"mesh.nodes=[8, 8]"}));
  try {
    PositionSensitivities(model, result, One(std::move(nodes)));
    FAIL() << "accepted";
  } catch (const SensitivityError& error) {
    EXPECT_NE(std::string(error.what()).find("mesh.nodes: changing it changes the model's nodes"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace drape
