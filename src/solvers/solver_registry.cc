// The list of methods. A new method adds one entry here and one file of its own.
#include <memory>

#include "src/solvers/solver.h"
#include "src/solvers/solvers.h"

namespace drape {

const std::vector<SolverInfo>& AllSolvers() {
  static const std::vector<SolverInfo> solvers = {
      {"newton",
       "Newton on the exact energy: nested-Jet Hessians, per-term PSD projection far from the "
       "solution, CHOLMOD supernodal Cholesky, pseudo-time regularisation M/dt^2 and an Armijo "
       "line search; quadratic near the end (the default)",
       {"regularization", "max_line_search", "max_expansions", "exact_hessian_residual",
        "absolute_projection_above", "exact_retry_steps", "escape_saddles"},
       [] { return NewNewtonSolver(); }},
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
      {"puiseux-fixed-point",
       "Puiseux's fixed point: A0 x(n+1) = A(xn) xn + f with A0 factorised once; springs and "
       "constant forces only; the reference solver of the mass-spring model",
       {"relaxation"},
       [] { return NewPuiseuxFixedPointSolver(); }},
      {"puiseux-dynamic",
       "Puiseux's implicit dynamic scheme (A0 + M/dt^2 + beta/2dt) x(n+1) = ...; stops at rest, "
       "at t_max or on the residual; writes kinetic.csv",
       {"dt", "beta", "t_max", "epsilon"},
       [] { return NewPuiseuxDynamicSolver(); }},
      {"explicit-euler",
       "Rusinko & Swan's explicit Euler with friction: v <- (1-f)v + a dt, x <- x + v dt, and "
       "Provot's stretch-limit constraint breadth-first from the fixed nodes; stops at rest",
       {"dt", "friction", "stretch_limit"},
       [] { return NewExplicitEulerSolver(); }},
      {"nlopt-lbfgs",
       "NLopt LD_LBFGS on the exact energy (vector storage `memory`, default 10); stops on the "
       "relative residual; iterations = energy evaluations",
       {"memory", "local_energy"},
       [] { return NewNloptSolver("nlopt-lbfgs"); }},
      {"nlopt-tnewton",
       "NLopt LD_TNEWTON_PRECOND_RESTART (preconditioned truncated Newton) on the exact energy",
       {"memory", "local_energy"},
       [] { return NewNloptSolver("nlopt-tnewton"); }},
      {"nlopt-var2",
       "NLopt LD_VAR2 (shifted limited-memory variable metric) on the exact energy",
       {"memory", "local_energy"},
       [] { return NewNloptSolver("nlopt-var2"); }},
      {"nlopt-mma",
       "NLopt LD_MMA (method of moving asymptotes) on the exact energy",
       {"local_energy"},
       [] { return NewNloptSolver("nlopt-mma"); }},
      {"nlopt-slsqp",
       "NLopt LD_SLSQP (dense SQP) on the exact energy; refused above 1,000 free dofs",
       {"local_energy"},
       [] { return NewNloptSolver("nlopt-slsqp"); }},
  };
  return solvers;
}

}  // namespace drape
