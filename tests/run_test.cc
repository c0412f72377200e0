// RunSolve: the solver's claim is confirmed by the certificate (residual, soundness, balance), and
// a run whose state stops being finite saves its last finite iterate.
#include "src/run/run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "costs/constant_force_potential.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

Scene LoadText(const std::string& name, const std::string& text) {
  return LoadScene(testing::ScratchFile("run_test_" + name, "scene.yaml", text).path().string());
}

constexpr char kChain[] =
    "mesh: {kind: chain, length: 0.4, nodes: 5}\n"
    "material: {node_mass: 0.01, springs: {structural: 50}}\n"
    "fixed:\n  - nodes: {ids: [0, 4]}\n"
    "loads: {gravity: [0, 0, -9.81]}\n"
    "solver: {method: newton, tolerance: 1.0e-10}\n";

// Where the fabric has a bending friction, newton takes no step doublings unless the scene asks for
// them (src/run/run.cc, kFrictionMaxExpansions); other methods and frictionless fabrics take the
// options as given (the shear friction too).
TEST(SolveMethodOptions, NewtonOnAFabricWithABendingFrictionDoesNotDoubleItsSteps) {
  const std::string cotton = testing::SourcePath("configs/fv/drape_tester_cotton_30.yaml");
  const std::string friction = "material.finite_volume.kes.2HB_warp=0.124";
  const Scene elastic = LoadScene(cotton);
  ASSERT_FALSE(HasFriction(elastic));
  EXPECT_EQ(SolveMethodOptions(elastic, "newton").count("max_expansions"), 0u);
  const Scene rubbing = LoadScene(cotton, {friction});
  ASSERT_TRUE(HasFriction(rubbing));
  EXPECT_EQ(SolveMethodOptions(rubbing, "newton").at("max_expansions"), 0.0);
  EXPECT_EQ(SolveMethodOptions(rubbing, "ceres-lbfgs").count("max_expansions"), 0u);
  const Scene shear = LoadScene(cotton, {"material.finite_volume.shear_friction=0.49"});
  ASSERT_TRUE(HasFriction(shear));
  EXPECT_EQ(SolveMethodOptions(shear, "newton").count("max_expansions"), 0u);
  const Scene asked = LoadScene(cotton, {friction, "solver.newton.max_expansions=2"});
  EXPECT_EQ(SolveMethodOptions(asked, "newton").at("max_expansions"), 2.0);
}

// The balance "reactions + contact + constraint = −(weight + loads)" is part of convergence: a
// model with a force the balance does not know of (a term outside `applied`, as a bug in a model
// builder would make) reaches the tolerance but is not converged. Before, `balanced: false` was
// reported and the run still converged.
TEST(RunSolve, AnUnbalancedResultIsNotConverged) {
  const Scene scene = LoadText("balance", kChain);
  Model balanced_model = BuildModel(scene);
  const RunResult balanced = RunSolve(scene, balanced_model, "newton");
  ASSERT_TRUE(balanced.converged) << balanced.summary.termination;
  EXPECT_TRUE(balanced.certificate.balanced);

  Model model = BuildModel(scene);
  const double force[3] = {0.0, 0.0, -0.05};
  model.terms.push_back(MakeTerm("force", {2},
                                 ConstantForcePotential::Create(force, model.positions.data() + 6),
                                 0.05 * 2.0 * model.size));
  const RunResult result = RunSolve(scene, model, "newton");
  EXPECT_TRUE(result.summary.history.back().relative_residual <= 1e-10);
  EXPECT_FALSE(result.certificate.balanced);
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.summary.termination.find("do not balance"), std::string::npos)
      << result.summary.termination;
}

// An explicit step far beyond stability (a stiff chain, dt at the top of its range) overflows:
// the last finite iterate is kept, certified, marked not converged and "non-finite state", with
// the node named. Before, the run was refused (InputError) and nothing saved.
TEST(RunSolve, ARunThatStopsBeingFiniteKeepsItsLastFiniteIterate) {
  const Scene scene = LoadText("diverging",
                               "mesh: {kind: chain, length: 0.4, nodes: 5}\n"
                               "material: {node_mass: 0.001, springs: {structural: 1e6}}\n"
                               "fixed:\n  - nodes: {ids: [0, 4]}\n"
                               "loads: {gravity: [0, 0, -9.81]}\n"
                               "solver: {method: explicit-euler, explicit-euler: {dt: 100}}\n");
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "explicit-euler");
  EXPECT_TRUE(result.non_finite);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.summary.termination.rfind("non-finite state: explicit-euler produced a "
                                             "non-finite",
                                             0),
            0u)
      << result.summary.termination;
  EXPECT_NE(result.summary.termination.find("node "), std::string::npos);  // where
  EXPECT_NE(result.summary.termination.find("last finite iterate"), std::string::npos);
  for (double x : model.positions) EXPECT_TRUE(std::isfinite(x));
  EXPECT_TRUE(result.certificate.evaluable);
  for (double f : result.certificate.node_forces) EXPECT_TRUE(std::isfinite(f));
  for (const IterationRecord& record : result.summary.history) {
    EXPECT_TRUE(std::isfinite(record.energy));
    EXPECT_TRUE(std::isfinite(record.relative_residual));
  }
}

}  // namespace
}  // namespace drape
