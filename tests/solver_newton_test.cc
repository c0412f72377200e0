// The newton solver and its parts: the assembled Hessian, its per-term projection, the CHOLMOD
// factorisation, and the solver's convergence (quadratic at the end).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "src/equilibrium.h"
#include "src/model.h"
#include "src/scene_loader.h"
#include "src/solvers.h"
#include "src/sparse_hessian.h"
#include "src/stability.h"
#include "tests/hand_built_models.h"

namespace drape {
namespace {

using testing::Chain;
using testing::ChainSpec;
using testing::Sheet;
using testing::SheetSpec;

Eigen::MatrixXd Dense(const FreeHessian& hessian, const std::vector<double>& values) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(hessian.size(), hessian.size());
  for (int column = 0; column < hessian.size(); ++column) {
    for (int p = hessian.column_starts()[column]; p < hessian.column_starts()[column + 1]; ++p) {
      dense(hessian.rows()[p], column) = values[p];
      dense(column, hessian.rows()[p]) = values[p];
    }
  }
  return dense;
}

// A small sheet, two corners fixed, shrunk by `scale` about its centre and shaken, so that its
// springs are stretched and compressed in all directions.
Model ShakenSheet(double scale) {
  SheetSpec spec;
  spec.nu = 4;
  spec.nv = 3;
  spec.fixed = {0, 3};
  Model model = Sheet(spec);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (!model.fixed[k]) model.positions[k] = scale * model.positions[k] + noise(random);
  }
  return model;
}

Eigen::VectorXd FreeGradient(const Model& model, const DofMap& dofs,
                             const std::vector<double>& positions) {
  double energy;
  std::vector<double> gradient;
  EXPECT_TRUE(EvaluateEnergy(model, positions.data(), &energy, &gradient));
  Eigen::VectorXd free(dofs.num_free());
  dofs.Gather(gradient.data(), free.data());
  return free;
}

TEST(FreeHessian, EqualsFiniteDifferencesOfTheAssembledGradient) {
  const Model model = ShakenSheet(0.9);
  const DofMap dofs(model);
  FreeHessian hessian(model, dofs);
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  ASSERT_TRUE(hessian.Assemble(model.positions.data(), false, &assembly, &gradient));
  const Eigen::MatrixXd exact = Dense(hessian, hessian.values());

  const double h = 1e-6;
  Eigen::MatrixXd differences(dofs.num_free(), dofs.num_free());
  for (int f = 0; f < dofs.num_free(); ++f) {
    std::vector<double> plus = model.positions, minus = model.positions;
    plus[dofs.free_to_global()[f]] += h;
    minus[dofs.free_to_global()[f]] -= h;
    differences.col(f) =
        (FreeGradient(model, dofs, plus) - FreeGradient(model, dofs, minus)) / (2.0 * h);
  }
  EXPECT_LT((exact - differences).cwiseAbs().maxCoeff(), 1e-6 * exact.cwiseAbs().maxCoeff());
  // The gradient is the model's, and the energy too.
  double energy;
  std::vector<double> reference;
  ASSERT_TRUE(EvaluateEnergy(model, model.positions.data(), &energy, &reference));
  EXPECT_NEAR(assembly.energy, energy, 1e-12 * assembly.energy_magnitude);
  for (size_t k = 0; k < reference.size(); ++k) EXPECT_NEAR(gradient[k], reference[k], 1e-10);
}

TEST(FreeHessian, ProjectedHessianIsPositiveSemidefiniteWhereTheTrueOneIsNot) {
  const Model model = ShakenSheet(0.8);  // many springs compressed
  const DofMap dofs(model);
  FreeHessian hessian(model, dofs);
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  ASSERT_TRUE(hessian.Assemble(model.positions.data(), true, &assembly, &gradient));
  EXPECT_GT(assembly.projected_terms, 0);
  const Eigen::MatrixXd exact = Dense(hessian, hessian.values());
  const Eigen::MatrixXd projected = Dense(hessian, hessian.projected_values());
  const double scale = exact.cwiseAbs().maxCoeff();
  EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact).eigenvalues().minCoeff(),
            -1e-3 * scale);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(projected).eigenvalues().minCoeff(),
            -1e-12 * scale);
}

// Each term's Hessian projected by a full eigen-decomposition (negative eigenvalues replaced by
// their magnitudes, or by zero), summed over the free coordinates: what FreeHessian's projection
// must give, whatever shortcut it takes (the 3×3 block of a spring).
Eigen::MatrixXd ProjectedByFullDecomposition(const Model& model, const DofMap& dofs,
                                             EigenvalueFilter filter) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(dofs.num_free(), dofs.num_free());
  for (const auto& term : model.terms) {
    const int n = term->num_coordinates();
    std::vector<double> gradient(n), values(n * n);
    double energy;
    EXPECT_TRUE(
        term->EnergyHessian(model.positions.data(), &energy, gradient.data(), values.data()));
    const Eigen::MatrixXd local = Eigen::Map<Eigen::MatrixXd>(values.data(), n, n);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(local);
    const Eigen::VectorXd filtered = filter == EigenvalueFilter::kAbsolute
                                         ? Eigen::VectorXd(eigen.eigenvalues().cwiseAbs())
                                         : Eigen::VectorXd(eigen.eigenvalues().cwiseMax(0.0));
    const Eigen::MatrixXd projected =
        eigen.eigenvectors() * filtered.asDiagonal() * eigen.eigenvectors().transpose();
    for (int r = 0; r < n; ++r) {
      const int row = dofs.global_to_free()[3 * term->nodes()[r / 3] + r % 3];
      for (int c = 0; c < n; ++c) {
        const int column = dofs.global_to_free()[3 * term->nodes()[c / 3] + c % 3];
        if (row >= 0 && column >= 0) sum(row, column) += projected(r, c);
      }
    }
  }
  return sum;
}

TEST(FreeHessian, ProjectsEachSpringAsItsFullEigenDecompositionWould) {
  const Model model = ShakenSheet(0.8);
  const DofMap dofs(model);
  for (EigenvalueFilter filter : {EigenvalueFilter::kAbsolute, EigenvalueFilter::kClamp}) {
    FreeHessian hessian(model, dofs);
    hessian.set_eigenvalue_filter(filter);
    FreeHessian::Assembly assembly;
    std::vector<double> gradient;
    ASSERT_TRUE(hessian.Assemble(model.positions.data(), true, &assembly, &gradient));
    ASSERT_GT(assembly.projected_terms, 0);
    const Eigen::MatrixXd expected = ProjectedByFullDecomposition(model, dofs, filter);
    const Eigen::MatrixXd projected = Dense(hessian, hessian.projected_values());
    EXPECT_LT((projected - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
  }
}

TEST(SparseCholesky, SolvesAPositiveDefiniteSystemAndRefusesAnIndefiniteOne) {
  const Model model = ShakenSheet(0.8);
  const DofMap dofs(model);
  FreeHessian hessian(model, dofs);
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  ASSERT_TRUE(hessian.Assemble(model.positions.data(), true, &assembly, &gradient));
  SparseCholesky cholesky(hessian);
  EXPECT_FALSE(cholesky.Factorize(hessian.values(), nullptr));

  const std::vector<double> shift(hessian.size(), 1.0);
  ASSERT_TRUE(cholesky.Factorize(hessian.projected_values(), &shift));
  std::vector<double> b(hessian.size()), x, product(hessian.size());
  for (int k = 0; k < hessian.size(); ++k) b[k] = std::cos(k);
  cholesky.Solve(b, &x);
  hessian.Multiply(hessian.projected_values(), x.data(), product.data());
  for (int k = 0; k < hessian.size(); ++k) EXPECT_NEAR(product[k] + x[k], b[k], 1e-9);
}

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
  // Energy goes down monotonically (up to rounding) along the history.
  for (size_t k = 1; k < summary.history.size(); ++k) {
    EXPECT_LE(summary.history[k].energy, summary.history[k - 1].energy + 1e-12);
  }
  EXPECT_LE(ComputeCertificate(model, model.positions.data()).relative_residual, 1e-8);
}

TEST(Newton, LeavesASaddleThatStallsItAndEndsAtAStableDrape) {
  // A 30 cm square clamped between discs with a soft warp (D_warp = 4e-5 N·m): from the flat
  // start the iterates come near a saddle, where the energy is flat to rounding and no
  // regularised Newton step lowers it (with |eigenvalue| filtering throughout, newton stalled
  // there at a relative residual of 5e-7). A step along the most negative curvature leaves it.
  const Scene scene = LoadScene(std::string(DRAPE_SOURCE_DIR) + "/configs/fit/drape_fv.yaml",
                                {"material.finite_volume.D_warp=4e-5"});
  Model model = BuildModel(scene);
  const SolverSummary summary = SolveNewton(model, 1e-8, 1000);
  ASSERT_TRUE(summary.converged) << summary.termination;
  EXPECT_TRUE(AnalyseStability(model, model.positions.data()).stable);
}

TEST(Newton, AModelWithoutFreeCoordinatesIsEvaluatedNotSolved) {
  ChainSpec spec;
  spec.nodes = 2;
  Model model = Chain(spec);
  const SolverSummary summary = SolveNewton(model, 1e-8);
  EXPECT_EQ(summary.iterations, 0);
  ASSERT_EQ(summary.history.size(), 1u);
}

}  // namespace
}  // namespace drape
