// The round-off floor of the residual: measured at the final state, reported,
// and a solve whose residual reaches it above the tolerance stops there, converged, saying so.
#include "src/numerics/round_off_floor.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "src/numerics/sparse_hessian.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// Code_Aster's SSNL114 cable, as in the issue: 325 m, 200 springs of 8e6 N/m, supports 6 m closer
// than its length; double precision cannot certify it to 1e-10.
Scene LongStiffCable() {
  const std::string text = R"(name: ssnl114-like
dimension: 2
mesh: {kind: chain, length: 325.0, nodes: 201}
material:
  model: springs
  density: 1.8
  springs: {structural: 8.0e6}
fixed:
  - nodes: {ids: [0]}
    move: [3.0, 0, 0]
  - nodes: {ids: [200]}
    move: [-3.0, 0, 0]
loads:
  gravity: [0, 0, -9.81]
solver: {method: newton, tolerance: 1.0e-10, max_iterations: 1000}
)";
  return LoadScene(testing::ScratchFile("floor_cable", "scene.yaml", text).path().string());
}

TEST(RoundOffFloor, IsZeroWithoutFreeCoordinatesAndGrowsWithTheDistanceFromTheOrigin) {
  Scene scene = LongStiffCable();
  Model model = BuildModel(scene);
  const double here = RelativeResidualFloor(model, model.positions.data());
  EXPECT_GT(here, 0.0);
  for (size_t k = 0; k < model.positions.size(); k += 3) model.positions[k] += 1e4;
  EXPECT_GT(RelativeResidualFloor(model, model.positions.data()), 10.0 * here);
}

// A solver's estimator keeps the Hessian's pattern between estimates: at each of several positions
// it gives what a fresh estimate gives there, to the last bit.
TEST(RoundOffFloor, AnEstimatorGivesAFreshEstimateAtEveryPosition) {
  Scene scene = LongStiffCable();
  Model model = BuildModel(scene);
  ResidualFloorEstimator estimator(model);
  for (int shift = 0; shift < 3; ++shift) {
    for (size_t k = 0; k < model.positions.size(); k += 3) {
      if (!model.fixed[k]) model.positions[k] += 1e3 * shift;
    }
    EXPECT_EQ(estimator.At(model.positions.data()),
              RelativeResidualFloor(model, model.positions.data()))
        << "shift " << shift;
  }
}

// The same with a FreeHessian the caller gives (RunSolve's, which the solver assembled in).
TEST(RoundOffFloor, AGivenHessianGivesAFreshEstimate) {
  Scene scene = LongStiffCable();
  Model model = BuildModel(scene);
  HessianWorkspace workspace(model);
  std::vector<double> elsewhere = model.positions;
  for (size_t k = 0; k < elsewhere.size(); k += 3) elsewhere[k] += 1e3;
  RelativeResidualFloor(model, elsewhere.data(), &workspace.hessian);  // values left from there
  EXPECT_EQ(RelativeResidualFloor(model, model.positions.data(), &workspace.hessian),
            RelativeResidualFloor(model, model.positions.data()));
}

// Before: "no step decreases the energy" or the iteration limit, converged no, at ~1e-8.
TEST(RoundOffFloor, TheStiffCableStopsAtTheFloorAndSaysSo) {
  Scene scene = LongStiffCable();
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  EXPECT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.at_floor);
  EXPECT_GT(result.residual_floor, 1e-10);
  EXPECT_LE(result.certificate.relative_residual, kFloorFactor * result.residual_floor);
  EXPECT_NE(result.summary.termination.find("round-off floor"), std::string::npos);
  EXPECT_NE(result.summary.termination.find("below what double precision can certify"),
            std::string::npos);
  EXPECT_LT(result.summary.iterations, 200);  // no stagnating iterations up to the limit
}

// A cantilever of 100 finite volumes asked for 1e-10 (before: 500 iterations, converged no).
TEST(RoundOffFloor, AHundredVolumeCantileverStopsAtTheFloor) {
  const auto solved = testing::SolveConfig(
      "configs/fv/cantilever.yaml", "newton",
      {"mesh.nodes=[101, 1]", "solver.tolerance=1e-10", "solver.max_iterations=500"});
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_TRUE(solved.result.at_floor);
  EXPECT_LT(solved.result.summary.iterations, 200);
}

// A tolerance the solve can reach is reached: the floor does not stop it early.
TEST(RoundOffFloor, AReachableToleranceIsReachedNotTheFloor) {
  const auto solved = testing::SolveConfig("configs/examples/chain.yaml", "newton");
  EXPECT_TRUE(solved.result.converged);
  EXPECT_FALSE(solved.result.at_floor);
  EXPECT_LE(solved.result.certificate.relative_residual, solved.scene.solver.tolerance);
  EXPECT_LT(solved.result.residual_floor, solved.scene.solver.tolerance);
}

}  // namespace
}  // namespace drape
