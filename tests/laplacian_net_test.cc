// A net of zero-rest-length springs under a uniform load: its equilibrium is exactly a discrete
// Laplace problem, solved here directly and compared with the solvers.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <vector>

#include "tests/test_scenes.h"

namespace drape {
namespace {

// Heights of the net with its border at z = 0: for every interior node p,
//   Σ_q k_pq (z_q − z_p) + f = 0, warp neighbours with k_warp, weft neighbours with k_weft.
std::vector<double> SolveLaplace(int n, double k_warp, double k_weft, double load) {
  auto id = [n](int i, int j) { return j * n + i; };
  auto interior = [n](int i, int j) { return i > 0 && j > 0 && i < n - 1 && j < n - 1; };
  std::vector<int> unknown(n * n, -1);
  int count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (interior(i, j)) unknown[id(i, j)] = count++;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Constant(count, load);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (!interior(i, j)) continue;
      const int row = unknown[id(i, j)];
      const int neighbours[4][3] = {{i - 1, j, 0}, {i + 1, j, 0}, {i, j - 1, 1}, {i, j + 1, 1}};
      for (const auto& q : neighbours) {
        const double k = q[2] == 0 ? k_warp : k_weft;
        entries.emplace_back(row, row, k);
        if (interior(q[0], q[1])) entries.emplace_back(row, unknown[id(q[0], q[1])], -k);
      }
    }
  }
  Eigen::SparseMatrix<double> laplacian(count, count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::VectorXd z =
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(laplacian).solve(rhs);
  std::vector<double> heights(n * n, 0.0);
  for (int p = 0; p < n * n; ++p)
    if (unknown[p] >= 0) heights[p] = z[unknown[p]];
  return heights;
}

void ExpectMatchesLaplace(const testing::Solved& solved) {
  const int n = 11;
  ASSERT_EQ(solved.model.num_nodes, n * n);
  const auto expected = SolveLaplace(n, 40.0, 25.0, -0.01);
  double largest = 0.0;
  for (double z : expected) largest = std::max(largest, std::abs(z));
  ASSERT_GT(largest, 0.0);
  for (int p = 0; p < n * n; ++p) {
    const Eigen::Vector3d position = testing::Position(solved.model, p);
    EXPECT_NEAR(position.z(), expected[p], 1e-8 * largest) << "node " << p;
    // In the plane, a uniform grid is already harmonic: the nodes do not move sideways.
    EXPECT_NEAR(position.x(), solved.model.initial[3 * p], 1e-8 * largest);
    EXPECT_NEAR(position.y(), solved.model.initial[3 * p + 1], 1e-8 * largest);
  }
  // The supports carry the whole load, up to the free forces left unbalanced (Cauchy–Schwarz:
  // their sum is at most √dofs × their norm).
  const auto& certificate = solved.result.certificate;
  const double unbalanced = std::sqrt(solved.model.num_dofs()) * certificate.relative_residual *
                            certificate.reference_force;
  EXPECT_NEAR(certificate.reaction_sum.z(), 0.01 * n * n, unbalanced + 1e-12);
}

TEST(LaplacianNet, CeresLbfgsSolvesTheDiscreteLaplacian) {
  const auto solved = testing::SolveConfig("configs/validation/laplacian_net.yaml", "ceres-lbfgs");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesLaplace(solved);
}

// Least squares carries the loads as shifted square roots; the cost's roundoff limits it to a
// relative residual near 1e-9 here (src/solvers/solver_ceres_least_squares.cc), so it is asked for
// 1e-8.
TEST(LaplacianNet, CeresLevenbergMarquardtSolvesTheDiscreteLaplacian) {
  const auto solved = testing::SolveConfig("configs/validation/laplacian_net.yaml", "ceres-lm",
                                           {"solver.tolerance=1e-8"});
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesLaplace(solved);
}

// A0 is exactly this net's stiffness, so Puiseux's fixed point solves it in one step.
TEST(LaplacianNet, PuiseuxFixedPointSolvesItInOneStep) {
  const auto solved =
      testing::SolveConfig("configs/validation/laplacian_net.yaml", "puiseux-fixed-point");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_LE(solved.result.summary.iterations, 2);
  ExpectMatchesLaplace(solved);
}

TEST(LaplacianNet, NewtonSolvesTheDiscreteLaplacian) {
  const auto solved = testing::SolveConfig("configs/validation/laplacian_net.yaml", "newton");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesLaplace(solved);
}

}  // namespace
}  // namespace drape
