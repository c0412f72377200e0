// The list of methods. A new method adds one entry here and one file of its own.
#include <memory>

#include "src/solver.h"
#include "src/solvers.h"

namespace drape {

const std::vector<SolverInfo>& AllSolvers() {
  static const std::vector<SolverInfo> solvers = {
      {"ceres-lbfgs",
       "L-BFGS on the exact energy (ceres::GradientProblemSolver, per-term autodiff gradients)",
       {"memory"},
       [] { return NewCeresLbfgsSolver(); }},
      {"ceres-lm",
       "Levenberg-Marquardt on the terms as least squares (linear potentials shifted); fails on "
       "taut drapes (no geometric stiffness)",
       {},
       [] { return NewCeresLeastSquaresSolver(ceres::LEVENBERG_MARQUARDT); }},
      {"ceres-dogleg",
       "Powell's dogleg on the terms as least squares (linear potentials shifted)",
       {},
       [] { return NewCeresLeastSquaresSolver(ceres::DOGLEG); }},
  };
  return solvers;
}

}  // namespace drape
