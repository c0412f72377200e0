// Factories of the solver methods (each defined in its own solver_*.cc file).
#ifndef DRAPE_SRC_SOLVERS_SOLVERS_H_
#define DRAPE_SRC_SOLVERS_SOLVERS_H_

#include <ceres/types.h>

#include <memory>
#include <string>

#include "src/solvers/solver.h"

namespace drape {

std::unique_ptr<Solver> NewNewtonSolver();
std::unique_ptr<Solver> NewCeresLbfgsSolver();
std::unique_ptr<Solver> NewCeresLeastSquaresSolver(ceres::TrustRegionStrategyType strategy);
std::unique_ptr<Solver> NewPuiseuxFixedPointSolver();
std::unique_ptr<Solver> NewPuiseuxDynamicSolver();
std::unique_ptr<Solver> NewExplicitEulerSolver();
// nlopt-lbfgs, nlopt-tnewton, nlopt-var2, nlopt-mma, nlopt-slsqp; nullptr for another name.
std::unique_ptr<Solver> NewNloptSolver(const std::string& name);

}  // namespace drape

#endif  // DRAPE_SRC_SOLVERS_SOLVERS_H_
