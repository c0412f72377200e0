// Products of small fixed-size matrices (src/derivatives/small_product.h) against Eigen's own
// products.
#include "src/derivatives/small_product.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

namespace drape {
namespace {

TEST(SmallProduct, EqualsEigensProduct) {
  const Eigen::Matrix<double, 15, 12> a = Eigen::Matrix<double, 15, 12>::Random();
  const Eigen::Matrix<double, 12, 15> b = Eigen::Matrix<double, 12, 15>::Random();
  const Eigen::Matrix<double, 15, 15> expected = a * b;
  EXPECT_LT((SmallProduct(a, b) - expected).cwiseAbs().maxCoeff(), 1e-13);
}

// aᵀ m a of a 12×15 a and a symmetric 12×12 m (the bending term's congruence), and aᵀ a of an
// 8×15 a (its Gauss–Newton part): Eigen's products to rounding, and exactly symmetric.
TEST(SmallProduct, SymmetricProductsEqualEigensAndAreExactlySymmetric) {
  const Eigen::Matrix<double, 12, 15> a = Eigen::Matrix<double, 12, 15>::Random();
  Eigen::Matrix<double, 12, 12> m = Eigen::Matrix<double, 12, 12>::Random();
  m = (m + m.transpose()).eval();
  const Eigen::Matrix<double, 15, 15> congruence = SymmetricCongruence(a, m);
  const Eigen::Matrix<double, 15, 15> expected = a.transpose() * m * a;
  EXPECT_LT((congruence - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(congruence, congruence.transpose());

  const Eigen::Matrix<double, 8, 15> j = Eigen::Matrix<double, 8, 15>::Random();
  const Eigen::Matrix<double, 15, 15> gram = SymmetricProduct(j, j);
  const Eigen::Matrix<double, 15, 15> expected_gram = j.transpose() * j;
  EXPECT_LT((gram - expected_gram).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_EQ(gram, gram.transpose());
}

}  // namespace
}  // namespace drape
