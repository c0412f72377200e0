// Making a small symmetric matrix positive semidefinite: shared by the staged projection of the
// finite-volume terms (src/derivatives/fast_hessian.h) and the per-term projection of the assembled
// Hessian (src/numerics/sparse_hessian.cc).
#ifndef DRAPE_SRC_DERIVATIVES_PSD_PROJECTION_H_
#define DRAPE_SRC_DERIVATIVES_PSD_PROJECTION_H_

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "src/derivatives/small_product.h"

namespace drape {

// How negative eigenvalues are made nonnegative: set to zero (the nearest semidefinite matrix),
// or replaced by their magnitude, which keeps the curvature's size and only flips its sign (a
// compressed spring then resists sideways motion as much as a stretched one would).
enum class EigenvalueFilter { kClamp, kAbsolute };

// Whether a Cholesky factorisation shows a symmetric matrix to be semidefinite to `tolerance`:
// that of matrix + tolerance·I exists (its pivots are all positive). The shift keeps the
// factorisation stable on a singular semidefinite matrix (a term's Hessian annihilates
// translations, and at rest more), whose pivots would otherwise be of rounding size and of either
// sign (Eigen's unshifted LDLᵀ of a random 9×9 of rank 6 ended with a large negative one,
// tests/psd_projection_test.cc). Cholesky (LLᵀ) rather than LDLᵀ: no pivot search, and it stops at
// the first non-positive pivot; 0.70 against 0.99 µs at 15×15 (docs/benchmarks.md, session 14).
template <typename Matrix>
bool CholeskyShowsSemidefinite(const Matrix& matrix, double tolerance) {
  using Plain = typename Matrix::PlainObject;
  const Eigen::LLT<Plain> cholesky(matrix +
                                   tolerance * Plain::Identity(matrix.rows(), matrix.cols()));
  return cholesky.info() == Eigen::Success;
}

// The n×n symmetric matrix at `data` (row-major; N = n, or Eigen::Dynamic) made positive
// semidefinite in place: each negative eigenvalue set to zero (kClamp) or to its magnitude
// (kAbsolute). A matrix that a Cholesky factorisation already shows to be semidefinite (to
// roundoff: 1e-12 of its largest entry) is left alone, which spares the eigen-decomposition for
// most. Returns true if it changed. Defined in psd_projection.cc and instantiated there once for
// N = 2, 3, 6, 9, 12, 15 and Eigen::Dynamic (Eigen's eigensolvers are the heaviest code a unit
// can compile; docs/building.md): another N does not link until it is added there.
template <int N>
bool ProjectSymmetric(EigenvalueFilter filter, int n, double* data);

extern template bool ProjectSymmetric<2>(EigenvalueFilter, int, double*);
extern template bool ProjectSymmetric<3>(EigenvalueFilter, int, double*);
extern template bool ProjectSymmetric<6>(EigenvalueFilter, int, double*);
extern template bool ProjectSymmetric<9>(EigenvalueFilter, int, double*);
extern template bool ProjectSymmetric<12>(EigenvalueFilter, int, double*);
extern template bool ProjectSymmetric<15>(EigenvalueFilter, int, double*);
extern template bool ProjectSymmetric<Eigen::Dynamic>(EigenvalueFilter, int, double*);

// The same for a fixed-size symmetric Eigen matrix (either storage order).
template <int N, int kOptions>
bool ProjectSymmetric(EigenvalueFilter filter, Eigen::Matrix<double, N, N, kOptions>* matrix) {
  return ProjectSymmetric<N>(filter, N, matrix->data());
}

// Whether a symmetric matrix is positive semidefinite to roundoff (Cholesky, as above).
template <typename Matrix>
bool IsSemidefinite(const Matrix& matrix) {
  const double scale = matrix.cwiseAbs().maxCoeff();
  if (scale == 0.0) return true;
  return CholeskyShowsSemidefinite(matrix, 1e-12 * scale);
}

}  // namespace drape

#endif  // DRAPE_SRC_DERIVATIVES_PSD_PROJECTION_H_
