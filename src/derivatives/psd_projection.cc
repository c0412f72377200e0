// ProjectSymmetric's definition, instantiated once for every size drape projects (the header says
// why here and not in each unit that calls it).
#include "src/derivatives/psd_projection.h"

#include <Eigen/Eigenvalues>

namespace drape {

template <int N>
bool ProjectSymmetric(EigenvalueFilter filter, int n, double* data) {
  using Matrix = Eigen::Matrix<double, N, N, Eigen::RowMajor>;
  Eigen::Map<Matrix> matrix(data, n, n);
  const double scale = matrix.cwiseAbs().maxCoeff();
  if (scale == 0.0) return false;
  const double tolerance = 1e-12 * scale;  // rounding of a semidefinite matrix's zero eigenvalues
  if (CholeskyShowsSemidefinite(matrix, tolerance)) return false;
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

template bool ProjectSymmetric<2>(EigenvalueFilter, int, double*);
template bool ProjectSymmetric<3>(EigenvalueFilter, int, double*);
template bool ProjectSymmetric<6>(EigenvalueFilter, int, double*);
template bool ProjectSymmetric<9>(EigenvalueFilter, int, double*);
template bool ProjectSymmetric<12>(EigenvalueFilter, int, double*);
template bool ProjectSymmetric<15>(EigenvalueFilter, int, double*);
template bool ProjectSymmetric<Eigen::Dynamic>(EigenvalueFilter, int, double*);

}  // namespace drape
