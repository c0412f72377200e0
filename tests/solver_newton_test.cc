// The newton solver: default method, convergence (quadratic at the end), its work, saddles. Its
// parts (the assembled Hessian, the projection, the factorisation) in sparse_hessian_test.cc.
#include <gtest/gtest.h>

#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "src/numerics/stability.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "src/solvers/solvers.h"
#include "tests/hand_built_models.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

using testing::Chain;
using testing::ChainSpec;
using testing::Sheet;
using testing::SheetSpec;

SolverSummary SolveNewton(Model& model, double tolerance, int max_iterations = 200) {
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  return FindSolver("newton")->make()->Solve(model, options);
}

TEST(Newton, IsTheFirstAndDefaultMethod) {
  ASSERT_FALSE(AllSolvers().empty());
  EXPECT_EQ(AllSolvers().front().name, "newton");
  EXPECT_EQ(SolverSpec().method, "newton");
}

TEST(Newton, ConvergesQuadraticallyOnAHangingChain) {
  ChainSpec spec;
  spec.length = 0.8;  // ten springs of 0.1 m between supports 0.8 m apart: a slack chain
  spec.rest_length = 0.1;
  Model model = Chain(spec);
  const SolverSummary summary = SolveNewton(model, 1e-12);
  ASSERT_TRUE(summary.converged) << summary.termination;
  // Once the residual is small, each step squares it (up to a bounded factor).
  int quadratic_steps = 0;
  for (size_t k = 1; k < summary.history.size(); ++k) {
    const double previous = summary.history[k - 1].relative_residual;
    const double current = summary.history[k].relative_residual;
    if (previous > 0.1 || current < 1e-12) continue;  // below 1e-12: rounding
    EXPECT_LT(current, 1e3 * previous * previous) << "step " << k;
    ++quadratic_steps;
  }
  EXPECT_GE(quadratic_steps, 2);
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  EXPECT_LE(certificate.relative_residual, 1e-12);
}

TEST(Newton, HangsASheetFromTwoCornersAndReportsItsWork) {
  SheetSpec spec;
  spec.nu = spec.nv = 15;
  spec.fixed = {testing::GridId(spec, 0, spec.nv - 1),
                testing::GridId(spec, spec.nu - 1, spec.nv - 1)};
  Model model = Sheet(spec);
  const SolverSummary summary = SolveNewton(model, 1e-8);
  ASSERT_TRUE(summary.converged) << summary.termination;
  EXPECT_EQ(summary.history.size(), static_cast<size_t>(summary.iterations + 1));
  EXPECT_GE(summary.statistics.at("factorizations"), summary.iterations);
  EXPECT_GT(summary.statistics.at("energy_evaluations"), 0);
  EXPECT_GT(summary.statistics.at("assembly_s"), 0.0);
  // H₊ is assembled at the start and then for the steps that use it, ahead where H is blocked:
  // an H₊ that then went unused (the residual fell below the block) is counted as such.
  const double projected = summary.statistics.at("projected_assemblies");
  const double unused = summary.statistics.at("projected_assemblies_unused");
  EXPECT_GE(projected, 1.0);
  EXPECT_LE(unused, projected);
  EXPECT_LE(projected - unused, 1.0 + summary.statistics.at("factorizations") -
                                    summary.statistics.at("exact_hessian_steps"));
  // Energy goes down monotonically (up to rounding) along the history.
  for (size_t k = 1; k < summary.history.size(); ++k) {
    EXPECT_LE(summary.history[k].energy, summary.history[k - 1].energy + 1e-12);
  }
  EXPECT_LE(ComputeCertificate(model, model.positions.data()).relative_residual, 1e-8);
}

// Rusinko & Swan's arc disc on a pin (configs/netlogo/disc_arc.yaml): its drape lies below this
// energy, J. The flat disc balanced on the pin, a saddle, is at −0.00431 J; the drape the fabric's
// contact with itself allows at −0.01363 J (its folds press together; before that contact, newton
// found −0.01387 J with 16,576 crossings of a triangle's side and a triangle: no drape at all).
constexpr double kArcDiscDrapeAbove = -0.0136;

TEST(Newton, LeavesASaddleThatStallsItAndEndsAtAStableDrape) {
  // Rusinko & Swan's arc disc on a pin: from the symmetric flat start newton comes to the flat
  // disc balanced on the pin, a saddle by symmetry (most negative eigenvalue −1.24 N/m). With a
  // tolerance below what that saddle's rounding lets the residual reach, no regularised step
  // lowers the energy there (at a relative residual of about 1.5e-9): newton stalls before the
  // residual is met. Had the stall no escape, newton would stop there, converged no, after 11
  // iterations (checked by disabling it); a step along the most negative curvature leaves it for
  // the drape. (Before, this test used a finite-volume drape whose path reached such a saddle
  // only by the rounding of one build and one set of BLAS kernels.)
  const Scene scene =
      LoadScene(std::string(drape_tests::kSourceDir) + "/configs/netlogo/disc_arc.yaml",
                {"solver.tolerance=1e-13"});
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  ASSERT_TRUE(result.converged) << result.summary.termination;
  EXPECT_GE(result.summary.statistics.at("saddle_escapes"), 1.0);
  EXPECT_TRUE(result.stability.stable) << result.stability.min_eigenvalue;
  EXPECT_FALSE(result.PassesThrough());
  EXPECT_LT(result.certificate.energy, kArcDiscDrapeAbove);
}

TEST(Newton, AModelWithoutFreeCoordinatesIsEvaluatedNotSolved) {
  ChainSpec spec;
  spec.nodes = 2;
  Model model = Chain(spec);
  const SolverSummary summary = SolveNewton(model, 1e-8);
  EXPECT_EQ(summary.iterations, 0);
  ASSERT_EQ(summary.history.size(), 1u);
}

// A saddle is not an answer. On Rusinko & Swan's arc disc on a pin newton used
// to stop after 10 iterations on the flat disc balanced on the pin (a saddle, most negative
// eigenvalue −1.24 N/m, energy −0.00431 J, drape ratio 0.94) and exit 0; now it leaves it along
// the negative curvature and finds the drape (kArcDiscDrapeAbove).
TEST(Newton, LeavesTheSaddleOfTheFlatDiscOnAPin) {
  const Scene scene =
      LoadScene(std::string(drape_tests::kSourceDir) + "/configs/netlogo/disc_arc.yaml");
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  EXPECT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.stability.stable) << result.stability.min_eigenvalue;
  EXPECT_FALSE(result.Saddle());
  EXPECT_FALSE(result.PassesThrough());
  EXPECT_LT(result.certificate.energy, kArcDiscDrapeAbove);
  EXPECT_GE(result.summary.statistics.at("saddle_escapes"), 1.0);
}

// With escape_saddles: 0 it stops there, and the result says it is a saddle.
TEST(Newton, WithoutEscapeTheSaddleIsReportedAsOne) {
  const Scene scene =
      LoadScene(std::string(drape_tests::kSourceDir) + "/configs/netlogo/disc_arc.yaml",
                {"solver.newton.escape_saddles=0"});
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  EXPECT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.Saddle());
  EXPECT_LT(result.stability.min_eigenvalue, -0.1);
}

}  // namespace
}  // namespace drape
