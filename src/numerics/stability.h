// Whether an equilibrium is a stable minimum: the unprojected Hessian over the free coordinates
// is positive definite.
#ifndef DRAPE_SRC_NUMERICS_STABILITY_H_
#define DRAPE_SRC_NUMERICS_STABILITY_H_

#include <vector>

#include "src/model/model.h"
#include "src/numerics/sparse_hessian.h"

namespace drape {

struct Stability {
  bool computed = false;        // false when the Hessian could not be evaluated
  bool stable = false;          // the free Hessian factorises as positive definite
  double min_eigenvalue = 0.0;  // estimate of the most negative eigenvalue when not stable, N/m
};

// `workspace`, when given, is the model's (src/numerics/sparse_hessian.h): the Hessian is assembled
// and factorised in it (its values and factor are overwritten).
Stability AnalyseStability(const Model& model, const double* positions,
                           HessianWorkspace* workspace = nullptr);

// For the assembled true Hessian `hessian` (its values()): false if it is positive definite (to
// the same tolerance as AnalyseStability); else true, with an estimate of its most negative
// eigenvalue and of the corresponding eigenvector (unit norm, over the free coordinates).
// `cholesky`, when given, is an analysis of hessian's pattern to factorise in (its factor is
// overwritten).
bool NegativeCurvature(const FreeHessian& hessian, double* eigenvalue,
                       std::vector<double>* direction, SparseCholesky* cholesky = nullptr);

}  // namespace drape

#endif  // DRAPE_SRC_NUMERICS_STABILITY_H_
