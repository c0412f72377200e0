// Making small symmetric matrices positive semidefinite (src/model/psd_projection.h): the
// restriction to the motions that are not translations gives the whole matrix's projection.
#include "src/model/psd_projection.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>

namespace drape {
namespace {

template <int kNodes>
void ExpectOrthonormalAndFreeOfTranslations() {
  const auto basis = TranslationFreeBasis<kNodes>();
  const auto gram = (basis.transpose() * basis).eval();
  EXPECT_LT((gram - decltype(gram)::Identity()).cwiseAbs().maxCoeff(), 1e-14) << kNodes;
  for (int d = 0; d < 3; ++d) {
    Eigen::Matrix<double, 3 * kNodes, 1> translation = Eigen::Matrix<double, 3 * kNodes, 1>::Zero();
    for (int i = 0; i < kNodes; ++i) translation[3 * i + d] = 1.0;
    EXPECT_LT((basis.transpose() * translation).cwiseAbs().maxCoeff(), 1e-14) << kNodes;
  }
}

TEST(PsdProjection, TranslationFreeBasisIsOrthonormalAndOrthogonalToTranslations) {
  ExpectOrthonormalAndFreeOfTranslations<2>();
  ExpectOrthonormalAndFreeOfTranslations<3>();
  ExpectOrthonormalAndFreeOfTranslations<4>();
  ExpectOrthonormalAndFreeOfTranslations<5>();
}

using Matrix15 = Eigen::Matrix<double, 15, 15, Eigen::RowMajor>;

// A symmetric 15×15 matrix that annihilates translations, as a 5-node term's Hessian does: a
// random 12×12 symmetric matrix shifted down by `shift` (shift 0: semidefinite), put into
// coordinates orthogonal to translations by a random orthonormal basis of them (not
// TranslationFreeBasis, so that the test does not lean on the code's own basis).
Matrix15 TranslationInvariant(std::mt19937* random, double shift) {
  std::normal_distribution<double> normal;
  Eigen::Matrix<double, 15, 15> gaussian;
  for (int k = 0; k < gaussian.size(); ++k) gaussian.data()[k] = normal(*random);
  Eigen::Matrix<double, 15, 15> with_translations;
  with_translations.setZero();
  for (int i = 0; i < 5; ++i) with_translations.block<3, 3>(3 * i, 0).setIdentity();
  with_translations.rightCols<12>() = gaussian.rightCols<12>();
  const Eigen::Matrix<double, 15, 15> q = with_translations.householderQr().householderQ();
  const Eigen::Matrix<double, 15, 12> motions = q.rightCols<12>();
  Eigen::Matrix<double, 12, 12> core = gaussian.topLeftCorner<12, 12>();
  core = (core * core.transpose()).eval();
  core.diagonal().array() -= shift;
  return motions * core * motions.transpose();
}

Matrix15 ByFullDecomposition(const Matrix15& matrix, EigenvalueFilter filter) {
  Matrix15 projected = matrix;
  ProjectSymmetric<15>(filter, 15, projected.data());
  return projected;
}

TEST(PsdProjection, TranslationFreeRestrictionGivesTheWholeMatrixsProjection) {
  std::mt19937 random(7);
  int changed = 0;
  for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute}) {
    for (int trial = 0; trial < 50; ++trial) {
      const Matrix15 matrix = TranslationInvariant(&random, 10.0);  // some eigenvalues negative
      const Matrix15 expected = ByFullDecomposition(matrix, filter);
      Matrix15 projected = matrix;
      const bool did_change = ProjectTranslationFree<5>(filter, projected.data());
      EXPECT_EQ(did_change, expected != matrix);
      changed += did_change;
      EXPECT_LT((projected - expected).cwiseAbs().maxCoeff(), 1e-12 * matrix.cwiseAbs().maxCoeff());
    }
  }
  EXPECT_GT(changed, 90);  // the shift leaves a negative eigenvalue in nearly every matrix
}

TEST(PsdProjection, TranslationFreeRestrictionLeavesASemidefiniteMatrixAlone) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Matrix15 matrix = TranslationInvariant(&random, 0.0);
    Matrix15 projected = matrix;
    EXPECT_FALSE(ProjectTranslationFree<5>(EigenvalueFilter::kAbsolute, projected.data()));
    EXPECT_EQ(projected, matrix);
  }
  Matrix15 zero = Matrix15::Zero();
  EXPECT_FALSE(ProjectTranslationFree<5>(EigenvalueFilter::kClamp, zero.data()));
}

}  // namespace
}  // namespace drape
