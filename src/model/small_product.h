// Products of small fixed-size matrices, coefficient by coefficient.
#ifndef DRAPE_SRC_MODEL_SMALL_PRODUCT_H_
#define DRAPE_SRC_MODEL_SMALL_PRODUCT_H_

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

// aᵀ · m · a, with the inner product evaluated once.
template <typename A, typename M>
auto SmallCongruence(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<M>& m) {
  const auto inner = SmallProduct(a.transpose(), m);
  return SmallProduct(inner, a);
}

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_SMALL_PRODUCT_H_
