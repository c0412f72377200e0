// A model's free Hessian assembled at its positions, and a dense copy of it: shared by the tests
// of the assembly (sparse_hessian_test.cc) and of the stability certificate (stability_test.cc).
#ifndef DRAPE_TESTS_ASSEMBLED_HESSIAN_H_
#define DRAPE_TESTS_ASSEMBLED_HESSIAN_H_

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "src/model/model.h"
#include "src/numerics/sparse_hessian.h"

namespace drape::testing {

// `project`: also the per-term positive semidefinite projection H₊, with `filter`.
struct AssembledHessian {
  AssembledHessian(const Model& model, bool project,
                   EigenvalueFilter filter = EigenvalueFilter::kClamp)
      : dofs(model), hessian(model, dofs) {
    hessian.set_eigenvalue_filter(filter);
    EXPECT_TRUE(hessian.Assemble(model.positions.data(), project, &assembly, &gradient));
  }
  const DofMap dofs;
  FreeHessian hessian;
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;  // of the whole model, all coordinates
};

// The symmetric matrix whose upper triangle `values` holds in `hessian`'s pattern.
inline Eigen::MatrixXd Dense(const FreeHessian& hessian, const std::vector<double>& values) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(hessian.size(), hessian.size());
  for (int column = 0; column < hessian.size(); ++column) {
    for (int p = hessian.column_starts()[column]; p < hessian.column_starts()[column + 1]; ++p) {
      dense(hessian.rows()[p], column) = values[p];
      dense(column, hessian.rows()[p]) = values[p];
    }
  }
  return dense;
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_ASSEMBLED_HESSIAN_H_
