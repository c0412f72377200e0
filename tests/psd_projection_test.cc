// Making small symmetric matrices positive semidefinite (src/derivatives/psd_projection.h): the
// result is the eigen-decomposition's, with either filter, and a semidefinite matrix is left alone.
#include "src/derivatives/psd_projection.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <random>

namespace drape {
namespace {

using Matrix9 = Eigen::Matrix<double, 9, 9, Eigen::RowMajor>;

// A random symmetric 9×9 matrix G Gᵀ shifted down by `shift` (shift 0: semidefinite, of rank 6,
// as a 3-node term's Hessian that annihilates translations would be).
Matrix9 RandomSymmetric(std::mt19937* random, double shift) {
  std::normal_distribution<double> normal;
  Eigen::Matrix<double, 9, 6> gaussian;
  for (int k = 0; k < gaussian.size(); ++k) gaussian.data()[k] = normal(*random);
  Matrix9 matrix = gaussian * gaussian.transpose();
  matrix.diagonal().array() -= shift;
  return matrix;
}

// The reference: Eigen's dynamic-size decomposition, negative eigenvalues clamped or flipped.
Matrix9 ByDynamicDecomposition(const Matrix9& matrix, EigenvalueFilter filter) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen{Eigen::MatrixXd(matrix)};
  const Eigen::VectorXd values = filter == EigenvalueFilter::kAbsolute
                                     ? Eigen::VectorXd(eigen.eigenvalues().cwiseAbs())
                                     : Eigen::VectorXd(eigen.eigenvalues().cwiseMax(0.0));
  return eigen.eigenvectors() * values.asDiagonal() * eigen.eigenvectors().transpose();
}

TEST(PsdProjection, GivesTheEigenDecompositionsProjection) {
  std::mt19937 random(7);
  for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute}) {
    for (int trial = 0; trial < 50; ++trial) {
      const Matrix9 matrix = RandomSymmetric(&random, 2.0);  // some eigenvalues negative
      ASSERT_FALSE(IsSemidefinite(matrix));
      Matrix9 projected = matrix;
      EXPECT_TRUE(ProjectSymmetric(filter, &projected));
      const Matrix9 expected = ByDynamicDecomposition(matrix, filter);
      EXPECT_LT((projected - expected).cwiseAbs().maxCoeff(), 1e-12 * matrix.cwiseAbs().maxCoeff());
      EXPECT_TRUE(IsSemidefinite(projected));
    }
  }
}

TEST(PsdProjection, LeavesASemidefiniteMatrixAlone) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Matrix9 matrix = RandomSymmetric(&random, 0.0);
    EXPECT_TRUE(IsSemidefinite(matrix));
    Matrix9 projected = matrix;
    EXPECT_FALSE(ProjectSymmetric(EigenvalueFilter::kAbsolute, &projected));
    EXPECT_EQ(projected, matrix);
  }
  Matrix9 zero = Matrix9::Zero();
  EXPECT_FALSE(ProjectSymmetric(EigenvalueFilter::kClamp, &zero));
  EXPECT_TRUE(IsSemidefinite(zero));
}

}  // namespace
}  // namespace drape
