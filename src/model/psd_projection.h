// Making a small symmetric matrix positive semidefinite: shared by the staged projection of the
// finite-volume terms (src/model/fast_hessian.h) and the per-term projection of the assembled
// Hessian (src/numerics/sparse_hessian.cc).
#ifndef DRAPE_SRC_MODEL_PSD_PROJECTION_H_
#define DRAPE_SRC_MODEL_PSD_PROJECTION_H_

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "src/model/small_product.h"

namespace drape {

// How negative eigenvalues are made nonnegative: set to zero (the nearest semidefinite matrix),
// or replaced by their magnitude, which keeps the curvature's size and only flips its sign (a
// compressed spring then resists sideways motion as much as a stretched one would).
enum class EigenvalueFilter { kClamp, kAbsolute };

// Whether an LDLᵀ factorisation shows a symmetric matrix to be semidefinite to `tolerance` (every
// pivot at least −tolerance).
template <typename Matrix>
bool LdltShowsSemidefinite(const Matrix& matrix, double tolerance) {
  const Eigen::LDLT<typename Matrix::PlainObject> ldlt(matrix);
  return ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() >= -tolerance;
}

// The n×n symmetric matrix at `data` (row-major; N = n, or Eigen::Dynamic) made positive
// semidefinite in place: each negative eigenvalue set to zero (kClamp) or to its magnitude
// (kAbsolute). A matrix that an LDLᵀ factorisation already shows to be semidefinite (to roundoff:
// 1e-12 of its largest entry) is left alone, which spares the eigen-decomposition for most. Returns
// true if it changed.
template <int N>
bool ProjectSymmetric(EigenvalueFilter filter, int n, double* data) {
  using Matrix = Eigen::Matrix<double, N, N, Eigen::RowMajor>;
  Eigen::Map<Matrix> matrix(data, n, n);
  const double scale = matrix.cwiseAbs().maxCoeff();
  if (scale == 0.0) return false;
  const double tolerance = 1e-12 * scale;  // rounding of a semidefinite matrix's zero eigenvalues
  if (LdltShowsSemidefinite(matrix, tolerance)) return false;
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(matrix);
  const auto& values = eigen.eigenvalues();
  if (values.minCoeff() >= -tolerance) return false;
  using Vector = Eigen::Matrix<double, N, 1>;
  const Vector filtered = filter == EigenvalueFilter::kAbsolute ? Vector(values.cwiseAbs())
                                                                : Vector(values.cwiseMax(0.0));
  const Matrix scaled = eigen.eigenvectors() * filtered.asDiagonal();
  matrix = SmallProduct(scaled, eigen.eigenvectors().transpose());
  return true;
}

// An orthonormal basis of the coordinates of kNodes nodes (3 each, node-major) orthogonal to the
// rigid translations: V = Q ⊗ I₃, where Q holds the first kNodes − 1 columns of the Householder
// reflection that swaps (1, …, 1)/√kNodes and the last unit vector. With s = 1/√kNodes,
// Q_ij = δ_ij − s²/(1 − s) for i < kNodes − 1 and Q_ij = s in the last row: its columns are
// orthonormal and each sums to 1 − (kNodes − 1)s²/(1 − s) + s = 0.
template <int kNodes>
Eigen::Matrix<double, 3 * kNodes, 3 * (kNodes - 1)> TranslationFreeBasis() {
  static_assert(kNodes >= 2, "a translation leaves no coordinate of a single node");
  const double s = 1.0 / std::sqrt(static_cast<double>(kNodes));
  Eigen::Matrix<double, 3 * kNodes, 3 * (kNodes - 1)> basis;
  basis.setZero();
  for (int i = 0; i < kNodes; ++i) {
    for (int j = 0; j < kNodes - 1; ++j) {
      const double q = i == kNodes - 1 ? s : (i == j ? 1.0 : 0.0) - s * s / (1.0 - s);
      for (int d = 0; d < 3; ++d) basis(3 * i + d, 3 * j + d) = q;
    }
  }
  return basis;
}

// ProjectSymmetric for the Hessian (row-major, 3·kNodes square, at `data`) of a term that rigid
// translations leave unchanged, so that H = V (Vᵀ H V) Vᵀ with V = TranslationFreeBasis: the
// eigenvalues of H are those of the 3(kNodes − 1) square restriction Vᵀ H V and three zeros, and
// its eigenvectors are V times the restriction's. Only the restriction is decomposed (for the
// 5-node bending term a 12×12 matrix instead of 15×15, measured 13.7 → 10.6 µs), and the change
// is added as a correction of the rank of the negative eigenvalues: H₊ = H + Σ_{λ<0} (f(λ) − λ)
// (V u)(V u)ᵀ, f the filter. The result is ProjectSymmetric's to rounding
// (tests/psd_projection_test.cc); the same tolerance decides whether anything changes.
template <int kNodes>
bool ProjectTranslationFree(EigenvalueFilter filter, double* data) {
  constexpr int kFull = 3 * kNodes, kFree = 3 * (kNodes - 1);
  using Restricted = Eigen::Matrix<double, kFree, kFree>;
  static const Eigen::Matrix<double, kFull, kFree> basis = TranslationFreeBasis<kNodes>();
  Eigen::Map<Eigen::Matrix<double, kFull, kFull, Eigen::RowMajor>> matrix(data);
  const double scale = matrix.cwiseAbs().maxCoeff();
  if (scale == 0.0) return false;
  const double tolerance = 1e-12 * scale;
  const Restricted restricted = SmallCongruence(basis, matrix);
  if (LdltShowsSemidefinite(restricted, tolerance)) return false;
  const Eigen::SelfAdjointEigenSolver<Restricted> eigen(restricted);
  const auto& values = eigen.eigenvalues();  // ascending
  if (values[0] >= -tolerance) return false;
  const double gain = filter == EigenvalueFilter::kAbsolute ? -2.0 : -1.0;  // (f(λ) − λ) / λ
  for (int k = 0; k < kFree && values[k] < 0.0; ++k) {
    const Eigen::Matrix<double, kFull, 1> direction = basis * eigen.eigenvectors().col(k);
    matrix.noalias() += (gain * values[k]) * direction * direction.transpose();
  }
  return true;
}

// The same for a fixed-size symmetric Eigen matrix (either storage order).
template <int N, int kOptions>
bool ProjectSymmetric(EigenvalueFilter filter, Eigen::Matrix<double, N, N, kOptions>* matrix) {
  return ProjectSymmetric<N>(filter, N, matrix->data());
}

// Whether a symmetric matrix is positive semidefinite to roundoff (LDLᵀ, as above).
template <typename Matrix>
bool IsSemidefinite(const Matrix& matrix) {
  const double scale = matrix.cwiseAbs().maxCoeff();
  if (scale == 0.0) return true;
  return LdltShowsSemidefinite(matrix, 1e-12 * scale);
}

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_PSD_PROJECTION_H_
