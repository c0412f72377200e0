// The incremental friction's load path (src/run/load_steps.h): the loads it scales, when it
// applies, that one step is the monotone form, and that on a load path along which every
// curvature grows (a heavy cantilever under its growing weight) its steps reach the monotone
// form's equilibrium as the smoothing δ → 0 (the deformation theory and the incremental one agree
// under monotone loading).
#include "src/run/load_steps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace load_steps_test {
namespace {

// The Peirce strip of docs/drape-tester.md ("The bending length with friction") as a 3-D sheet of
// three rows (the incremental friction signs a curvature across the fabric): 6 cm of the cotton's
// warp over the platform, H = 4.9e-4 N (2HB = 0.1 gf·cm/cm), clamped by its first two columns.
std::string CantileverText(int nodes_per_row) {
  const int n = nodes_per_row;
  return "name: cantilever-3d-friction\n"
         "mesh: {kind: grid, size: [0.06, 0.025], nodes: [" +
         std::to_string(n) +
         ", 3]}\n"
         "material:\n  model: finite_volume\n  density: 0.12\n"
         "  finite_volume: {E_warp: 7967.9, E_weft: 4903.32, G: 50.5692, D_warp: 1.1768e-05,\n"
         "    D_weft: 7.84532e-06, bending_friction_warp: 4.903325e-4,\n"
         "    bending_friction_weft: 4.903325e-4}\n"
         "fixed:\n  - nodes: {ids: [0, 1, " +
         std::to_string(n) + ", " + std::to_string(n + 1) + ", " + std::to_string(2 * n) + ", " +
         std::to_string(2 * n + 1) +
         "]}\n"
         "loads: {gravity: [0, 0, -9.80665]}\n"
         "solver: {method: newton, tolerance: 1.0e-9, max_iterations: 3000}\n";
}

Scene LoadCantilever(const std::vector<std::string>& overrides, int nodes_per_row = 21) {
  const testing::ScratchFile file("load_steps", "scene.yaml", CantileverText(nodes_per_row));
  return LoadScene(file.path().string(), overrides);
}

// The solved tip (the first row's last node).
Eigen::Vector3d SolvedTip(const Scene& scene) {
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  EXPECT_TRUE(result.converged) << result.summary.termination;
  const int tip = model.grid_index.size() / 3 - 1;
  return testing::Position(model, tip);
}

TEST(LoadSteps, ScaleEveryLoad) {
  LoadsSpec loads;
  loads.gravity = Eigen::Vector3d(0, 0, -9.8);
  ForceSpec force;
  force.value = Eigen::Vector3d(1, 2, 3);
  force.values = {Eigen::Vector3d(4, 5, 6)};
  force.ramp_to = Eigen::Vector3d(7, 8, 9);
  force.pressure = 10;
  loads.forces = {force};
  loads.pressure = PressureSpec{11, {}};
  const LoadsSpec quarter = ScaledLoads(loads, 0.25);
  EXPECT_EQ(*quarter.gravity, Eigen::Vector3d(0, 0, -2.45));
  EXPECT_EQ(quarter.forces[0].value, Eigen::Vector3d(0.25, 0.5, 0.75));
  EXPECT_EQ(quarter.forces[0].values[0], Eigen::Vector3d(1, 1.25, 1.5));
  EXPECT_EQ(quarter.forces[0].ramp_to, Eigen::Vector3d(1.75, 2, 2.25));
  EXPECT_EQ(quarter.forces[0].pressure, 2.5);
  EXPECT_EQ(quarter.pressure->pressure, 2.75);
}

TEST(LoadSteps, OnlyAFabricWithFrictionTakesThem) {
  EXPECT_EQ(FrictionLoadSteps(LoadCantilever({})), 0);
  EXPECT_EQ(FrictionLoadSteps(LoadCantilever({"material.finite_volume.friction_load_steps=4"})), 4);
  EXPECT_EQ(FrictionLoadSteps(LoadCantilever({"material.finite_volume.friction_load_steps=4",
                                              "material.finite_volume.bending_friction_warp=0",
                                              "material.finite_volume.bending_friction_weft=0"})),
            0);
  EXPECT_THROW(LoadCantilever({"material.finite_volume.friction_load_steps=-1"}), InputError);
}

// A strip has no direction across it to sign a curvature by: the incremental friction is refused.
TEST(LoadSteps, AStripIsRefused) {
  Scene strip = testing::LoadConfig("configs/fv/cantilever.yaml",
                                    {"material.finite_volume.bending_friction_warp=1e-4",
                                     "material.finite_volume.friction_load_steps=2"});
  EXPECT_THROW(BuildModel(strip), InputError);
}

// One step from the flat state is the monotone form (the signed curvature of a sheet bending
// about one axis is its curvature's magnitude).
TEST(LoadSteps, OneStepIsTheMonotoneForm) {
  const Eigen::Vector3d monotone = SolvedTip(LoadCantilever({}));
  const Eigen::Vector3d one =
      SolvedTip(LoadCantilever({"material.finite_volume.friction_load_steps=1"}));
  EXPECT_LT((one - monotone).norm(), 1e-9);
}

// Under its growing weight every curvature of the cantilever grows, so the steps' equilibrium is
// the monotone form's, up to the smoothing: each step's kink is smoothed over δ about a curvature
// change of κ/N, which weakens the friction where κ/N is not ≫ δ. The difference falls with δ
// (on the development machine, 4 steps: 4.2e-5 m at δ = 0.1 1/m, 3.8e-6 at 0.01 and 3.8e-7 at
// 0.001).
TEST(LoadSteps, UnderMonotoneLoadingTheyReachTheMonotoneForm) {
  double previous = INFINITY;
  for (const char* smoothing : {"0.1", "0.01", "0.001"}) {
    const std::string delta =
        std::string("material.finite_volume.bending_friction_smoothing=") + smoothing;
    const Eigen::Vector3d monotone = SolvedTip(LoadCantilever({delta}));
    const Eigen::Vector3d steps =
        SolvedTip(LoadCantilever({delta, "material.finite_volume.friction_load_steps=4"}));
    const double difference = (steps - monotone).norm();
    EXPECT_LT(difference, 0.3 * previous) << smoothing;
    previous = difference;
  }
  EXPECT_LT(previous, 2e-6);  // m, at δ = 0.001 1/m
}

}  // namespace
}  // namespace load_steps_test
}  // namespace drape
