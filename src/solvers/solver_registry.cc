// The code of each method, keyed by the names of the catalogue in src/scene/solver_methods.cc
// (which owns the descriptions, options, defaults and ranges). A new method adds one entry here,
// one in the catalogue and one file of its own.
#include <cassert>
#include <memory>

#include "src/scene/solver_methods.h"
#include "src/solvers/solver.h"
#include "src/solvers/solvers.h"

namespace drape {
namespace {

std::vector<SolverInfo> Factories() {
  return {
      {"newton", [] { return NewNewtonSolver(); }, /*uses_hessian_workspace=*/true},
      {"ceres-lbfgs", [] { return NewCeresLbfgsSolver(); }},
      {"ceres-lm", [] { return NewCeresLeastSquaresSolver(ceres::LEVENBERG_MARQUARDT); }},
      {"ceres-dogleg", [] { return NewCeresLeastSquaresSolver(ceres::DOGLEG); }},
      {"puiseux-fixed-point", [] { return NewPuiseuxFixedPointSolver(); }},
      {"puiseux-dynamic", [] { return NewPuiseuxDynamicSolver(); }},
      {"explicit-euler", [] { return NewExplicitEulerSolver(); }},
      {"nlopt-lbfgs", [] { return NewNloptSolver("nlopt-lbfgs"); }},
      {"nlopt-tnewton", [] { return NewNloptSolver("nlopt-tnewton"); }},
      {"nlopt-var2", [] { return NewNloptSolver("nlopt-var2"); }},
      {"nlopt-mma", [] { return NewNloptSolver("nlopt-mma"); }},
      {"nlopt-slsqp", [] { return NewNloptSolver("nlopt-slsqp"); }},
  };
}

}  // namespace

const std::vector<SolverInfo>& AllSolvers() {
  static const std::vector<SolverInfo> solvers = [] {
    auto factories = Factories();
    for (const auto& info : factories) {
      assert(FindSolverMethod(info.name) &&
             "a solver is registered under a name the catalogue lacks");
      (void)info;
    }
    return factories;
  }();
  return solvers;
}

}  // namespace drape
