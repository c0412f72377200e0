// Products of small fixed-size matrices, coefficient by coefficient.
#ifndef DRAPE_SRC_DERIVATIVES_SMALL_PRODUCT_H_
#define DRAPE_SRC_DERIVATIVES_SMALL_PRODUCT_H_

#include <Eigen/Core>

namespace drape {

// a · b as a plain matrix, each coefficient a dot product. Eigen hands a product whose rows +
// columns + depth reach 20 to its blocked general kernel, whose packing costs more than the
// arithmetic at the sizes of a term's local derivatives: 15×12 · 12×12 · 12×15 takes 1.1 µs this
// way against 2.2 µs (docs/benchmarks.md, session 12).
template <typename A, typename B>
auto SmallProduct(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return a.lazyProduct(b).eval();
}

// aᵀ b where the product is known to be symmetric (b = m a with m symmetric, or b = a): its upper
// triangle by dot products of columns, mirrored. About half the work of the full product: the
// bending term's 15×15 congruence takes 0.51 µs this way against 0.95 µs as two SmallProducts
// (docs/benchmarks.md, session 14).
template <typename A, typename B>
auto SymmetricProduct(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  constexpr int kSize = A::ColsAtCompileTime;
  static_assert(kSize != Eigen::Dynamic && kSize == B::ColsAtCompileTime);
  Eigen::Matrix<double, kSize, kSize> product;
  for (int r = 0; r < kSize; ++r) {
    for (int c = r; c < kSize; ++c) product(r, c) = product(c, r) = a.col(r).dot(b.col(c));
  }
  return product;
}

// aᵀ m a for a symmetric m, with m a formed once.
template <typename A, typename M>
auto SymmetricCongruence(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<M>& m) {
  return SymmetricProduct(a, SmallProduct(m, a));
}

}  // namespace drape

#endif  // DRAPE_SRC_DERIVATIVES_SMALL_PRODUCT_H_
