// The stability certificate: positive definite free Hessian ⇒ stable; otherwise an estimate of
// the most negative eigenvalue.
#include "src/numerics/stability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/numerics/sparse_hessian.h"
#include "src/solvers/solvers.h"
#include "tests/assembled_hessian.h"
#include "tests/hand_built_models.h"

namespace drape {
namespace {

using testing::Chain;
using testing::ChainSpec;

// The true free Hessian of `model` at its positions.
struct TrueHessian : testing::AssembledHessian {
  explicit TrueHessian(const Model& model) : AssembledHessian(model, /*project=*/false) {}
};

TEST(Stability, AHangingChainAtEquilibriumIsStable) {
  ChainSpec spec;
  spec.length = 0.8;
  spec.rest_length = 0.1;
  Model model = Chain(spec);
  SolverOptions options;
  ASSERT_TRUE(FindSolver("newton")->make()->Solve(model, options).converged);
  const Stability stability = AnalyseStability(model, model.positions.data());
  EXPECT_TRUE(stability.computed);
  EXPECT_TRUE(stability.stable);
}

// No gravity: 10 springs of rest length 0.1 m between supports 0.8 m apart. The uniformly
// compressed straight chain is an equilibrium, but its springs push with T = k (l − L) < 0 and
// the transverse stiffness T/l of each is negative. Across the chain (y or z), the Hessian is
// (T/l) times the path Laplacian of N springs with fixed ends, whose largest eigenvalue is
// 2 + 2 cos(π/N): λ_min = (T/l)(2 + 2 cos(π/N)).
ChainSpec CompressedChain() {
  ChainSpec spec;
  spec.nodes = 11;
  spec.length = 0.8;
  spec.rest_length = 0.1;
  spec.gravity = {0.0, 0.0, 0.0};
  return spec;
}

double CompressedChainMinEigenvalue() {
  const ChainSpec spec = CompressedChain();
  const double l = spec.length / (spec.nodes - 1),
               tension = spec.stiffness * (l - spec.rest_length);
  return tension / l * (2.0 + 2.0 * std::cos(M_PI / (spec.nodes - 1)));
}

TEST(Stability, AStraightChainCompressedBetweenItsSupportsIsASaddle) {
  const Model model = Chain(CompressedChain());
  const double expected = CompressedChainMinEigenvalue();
  const Stability stability = AnalyseStability(model, model.positions.data());
  EXPECT_TRUE(stability.computed);
  EXPECT_FALSE(stability.stable);
  EXPECT_NEAR(stability.min_eigenvalue, expected, 0.05 * std::abs(expected));
}

// A stiffness of 1e-320 (subnormal) made the shift τ underflow to 0, and the search for the most
// negative eigenvalue multiplied 0 by 10 for ever. It ends now (in
// milliseconds; a hang fails by the suite's timeout), with a number.
TEST(Stability, TheEigenvalueSearchEndsForASubnormalStiffness) {
  ChainSpec spec = CompressedChain();
  spec.stiffness = 1e-320;
  const Model model = Chain(spec);
  const Stability stability = AnalyseStability(model, model.positions.data());
  EXPECT_FALSE(std::isnan(stability.min_eigenvalue));
}

TEST(Stability, AStretchedStraightChainIsStable) {
  ChainSpec spec;
  spec.length = 1.2;
  spec.rest_length = 0.1;
  spec.gravity = {0.0, 0.0, 0.0};
  const Model model = Chain(spec);
  EXPECT_TRUE(AnalyseStability(model, model.positions.data()).stable);
}

TEST(Stability, NegativeCurvatureGivesTheBucklingModeOfACompressedChain) {
  const Model model = Chain(CompressedChain());
  const double expected = CompressedChainMinEigenvalue();
  const TrueHessian hessian(model);
  double eigenvalue = 0.0;
  std::vector<double> v;
  ASSERT_TRUE(NegativeCurvature(hessian.hessian, &eigenvalue, &v));
  EXPECT_NEAR(eigenvalue, expected, 0.05 * std::abs(expected));
  ASSERT_EQ(v.size(), static_cast<size_t>(hessian.hessian.size()));
  EXPECT_NEAR(std::inner_product(v.begin(), v.end(), v.begin(), 0.0), 1.0, 1e-12);
  std::vector<double> hv(v.size());  // H v = λ v: an eigenvector of that eigenvalue
  hessian.hessian.Multiply(hessian.hessian.values(), v.data(), hv.data());
  double defect = 0.0;
  for (size_t k = 0; k < v.size(); ++k) defect += std::pow(hv[k] - eigenvalue * v[k], 2);
  EXPECT_LT(std::sqrt(defect), 0.05 * std::abs(expected));
}

TEST(Stability, NegativeCurvatureIsFalseForAPositiveDefiniteHessian) {
  ChainSpec spec;  // stretched
  spec.length = 1.2;
  spec.rest_length = 0.1;
  spec.gravity = {0.0, 0.0, 0.0};
  const Model model = Chain(spec);
  const TrueHessian hessian(model);
  double eigenvalue = 0.0;
  std::vector<double> v;
  EXPECT_FALSE(NegativeCurvature(hessian.hessian, &eigenvalue, &v));
}

// RunSolve certifies in the workspace the solver used (HessianWorkspace): whatever was assembled
// and factorised in it before, the verdict and the eigenvalue estimate are a fresh analysis's, to
// the last bit.
TEST(Stability, AWorkspaceUsedBeforeGivesTheVerdictOfAFreshAnalysis) {
  ChainSpec spec;
  spec.length = 0.8;
  spec.rest_length = 0.1;
  Model hanging = Chain(spec);
  HessianWorkspace used_by_newton(hanging);
  SolverOptions options;
  options.workspace = &used_by_newton;
  ASSERT_TRUE(FindSolver("newton")->make()->Solve(hanging, options).converged);
  const Stability fresh_hanging = AnalyseStability(hanging, hanging.positions.data());
  const Stability shared_hanging =
      AnalyseStability(hanging, hanging.positions.data(), &used_by_newton);
  EXPECT_TRUE(shared_hanging.stable);
  EXPECT_EQ(shared_hanging.stable, fresh_hanging.stable);

  const Model compressed = Chain(CompressedChain());
  HessianWorkspace workspace(compressed);
  std::vector<double> elsewhere = compressed.positions;  // a stretched, positive definite state
  for (size_t k = 0; k < elsewhere.size(); k += 3) elsewhere[k] *= 1.5;
  ASSERT_TRUE(AnalyseStability(compressed, elsewhere.data(), &workspace).stable);
  const Stability fresh = AnalyseStability(compressed, compressed.positions.data());
  const Stability shared = AnalyseStability(compressed, compressed.positions.data(), &workspace);
  EXPECT_FALSE(shared.stable);
  EXPECT_EQ(shared.min_eigenvalue, fresh.min_eigenvalue);

  double fresh_eigenvalue = 0.0, shared_eigenvalue = 0.0;
  std::vector<double> fresh_mode, shared_mode;
  ASSERT_TRUE(NegativeCurvature(workspace.hessian, &fresh_eigenvalue, &fresh_mode));
  ASSERT_TRUE(
      NegativeCurvature(workspace.hessian, &shared_eigenvalue, &shared_mode, &workspace.cholesky));
  EXPECT_EQ(shared_eigenvalue, fresh_eigenvalue);
  EXPECT_EQ(shared_mode, fresh_mode);
}

TEST(Stability, NothingFreeIsTriviallyStable) {
  ChainSpec spec;
  spec.nodes = 2;
  const Model model = Chain(spec);
  const Stability stability = AnalyseStability(model, model.positions.data());
  EXPECT_TRUE(stability.computed);
  EXPECT_TRUE(stability.stable);
}

}  // namespace
}  // namespace drape
