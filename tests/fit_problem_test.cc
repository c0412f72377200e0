// The fit as a function of the parameters: residual layout, warm starts, and the implicit
// derivatives dr/du = ∂r/∂x (−H⁻¹ ∂g/∂u) (+ ∂r/∂u) checked against central differences of
// whole, re-solved equilibria.
#include "src/fit/fit_problem.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/fit_test_support.h"

namespace drape::testing {
namespace {

// Every measurement kind on the finite-volume drape, three parameters (log and linear).
std::string AllKindsFit(const std::string& folder) {
  const TrueSolve solved = SolveTruth("configs/fit/drape_fv.yaml", {});
  WriteNodePositions(solved.model, 0.0, 0, folder + "/nodes.csv");
  WriteScan(solved.model, 0.0, 0, folder + "/scan.csv");
  // Measured reactions at two clamped nodes (arbitrary values: only derivatives are compared).
  WriteTextFile(folder + "/forces.csv", "id,fx,fy,fz\n60,0,0,0.001\n49,0.0001,0,0.001\n");
  const std::string path = folder + "/fit_all.yaml";
  WriteTextFile(path, "scene: " + SourcePath("configs/fit/drape_fv.yaml") +
                          "\nparameters:\n"
                          "  - {key: material.finite_volume.D_warp, initial: 8.0e-5, bounds: "
                          "[1.0e-6, 1.0e-3], log: true}\n"
                          "  - {key: material.finite_volume.D_weft, initial: 6.0e-5, bounds: "
                          "[1.0e-6, 1.0e-3], log: true}\n"
                          "  - {key: material.finite_volume.G, initial: 4, bounds: [0, 100]}\n"
                          "measurements:\n"
                          "  - positions: {file: nodes.csv}\n"
                          "  - positions: {file: scan.csv}\n"
                          "  - drape_coefficient: {value: 0.6, disc_radius: 0.06}\n"
                          "  - bending_length: {value: 0.04}\n"
                          "  - reactions: {file: forces.csv}\n");
  return path;
}

TEST(FitProblemTest, ImplicitJacobianMatchesFiniteDifferencesOfTheEquilibria) {
  const std::string folder = FitTempDir("implicit");
  FitProblem problem(LoadFitFile(AllKindsFit(folder)));
  ASSERT_EQ(problem.blocks().size(), 5u);
  std::vector<double> u = problem.ToUnknowns({8.0e-5, 6.0e-5, 4.0});
  const FitEvaluation evaluation = problem.Evaluate(u);
  ASSERT_TRUE(evaluation.converged);
  Eigen::MatrixXd implicit;
  ASSERT_TRUE(problem.ImplicitJacobian(&implicit));
  // Steps in u: 1e-4, and 2e-3 for the drape coefficient, whose rasterised shadow has a noise of
  // ~1e-6 (a step of 1e-4 changes it by only ~1e-5).
  const Eigen::MatrixXd finite = problem.FiniteDifferenceJacobian(u, 1e-4);
  const Eigen::MatrixXd coarse = problem.FiniteDifferenceJacobian(u, 2e-3);
  for (const auto& block : problem.blocks()) {
    const bool shadow = block.label == "drape_coefficient";
    for (int j = 0; j < problem.num_parameters(); ++j) {
      const Eigen::VectorXd a = implicit.col(j).segment(block.offset, block.count);
      const Eigen::VectorXd b =
          (shadow ? coarse : finite).col(j).segment(block.offset, block.count);
      const double tolerance = shadow ? 1e-2 : 1e-4;
      EXPECT_LE((a - b).norm(), tolerance * b.norm() + 1e-9)
          << block.label << ", parameter " << j << ": implicit " << a.norm() << ", finite "
          << b.norm();
    }
  }
}

TEST(FitProblemTest, WarmStartsFromTheNearestEquilibrium) {
  const std::string folder = FitTempDir("warm");
  WriteTextFile(folder + "/fit_warm.yaml",
                "scene: " + SourcePath("configs/fit/sheet_springs.yaml") +
                    "\nparameters:\n  - {key: material.springs.structural, initial: 20, bounds: "
                    "[1, 1000], log: true}\nmeasurements:\n  - positions: {file: nodes.csv}\n");
  const TrueSolve solved = SolveTruth("configs/fit/sheet_springs.yaml", {});
  WriteNodePositions(solved.model, 0.0, 0, folder + "/nodes.csv");
  FitProblem problem(LoadFitFile(folder + "/fit_warm.yaml"));
  const std::vector<double> u = problem.ToUnknowns({20.0});
  const FitEvaluation cold = problem.Evaluate(u);
  const FitEvaluation again = problem.Evaluate(u);
  EXPECT_GT(cold.inner_iterations, 3);
  EXPECT_EQ(again.inner_iterations, 0);  // already in equilibrium
  EXPECT_NEAR(cold.objective, again.objective, 1e-9 * cold.objective);
  // The residual layout: 3 per free node, (model − measured) / 1 mm.
  EXPECT_EQ(problem.num_residuals(), 3 * (81 - 4));
  EXPECT_NEAR(cold.objective, 0.0, 1e-12);  // the truth is structural: 20 (the scene's value)
}

TEST(FitProblemTest, EvaluatesWithoutReadingItsSceneFileAgain) {
  // The scene is read once by LoadFitFile: the fit evaluates with the file gone.
  const std::string folder = FitTempDir("read_once");
  std::filesystem::copy_file(SourcePath("configs/fit/sheet_springs.yaml"), folder + "/sheet.yaml",
                             std::filesystem::copy_options::overwrite_existing);
  WriteTextFile(folder + "/fit.yaml",
                "scene: sheet.yaml\nparameters:\n  - {key: material.springs.structural, initial: "
                "30, bounds: [1, 1000], log: true}\nmeasurements:\n  - positions: {file: "
                "nodes.csv}\n");
  const TrueSolve solved = SolveTruth("configs/fit/sheet_springs.yaml", {});
  WriteNodePositions(solved.model, 0.0, 0, folder + "/nodes.csv");
  FitProblem problem(LoadFitFile(folder + "/fit.yaml"));
  std::filesystem::remove(folder + "/sheet.yaml");
  EXPECT_NEAR(problem.Evaluate(problem.ToUnknowns({20.0})).objective, 0.0, 1e-12);
  EXPECT_GT(problem.Evaluate(problem.ToUnknowns({30.0})).objective, 1e-6);
}

TEST(FitProblemTest, MapsLogAndLinearParameters) {
  const std::string folder = FitTempDir("maps");
  FitProblem problem(LoadFitFile(AllKindsFit(folder)));
  const std::vector<double> theta = {2e-5, 3e-5, 7.0};
  const std::vector<double> u = problem.ToUnknowns(theta);
  EXPECT_NEAR(u[0], std::log(2e-5), 1e-12);
  EXPECT_NEAR(u[2], 7.0 / 100.0, 1e-12);  // θ / (upper − lower)
  const std::vector<double> back = problem.ToParameters(u);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(back[j], theta[j], 1e-12 * theta[j]);
  const std::vector<double> derivative = problem.ParameterDerivatives(u);
  EXPECT_NEAR(derivative[0], 2e-5, 1e-15);
  EXPECT_NEAR(derivative[2], 100.0, 1e-12);
}

}  // namespace
}  // namespace drape::testing
