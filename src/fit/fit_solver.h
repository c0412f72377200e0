// The outer loop of `drape fit`: minimise ½ Σ r(u)² over the (log-)parameters u within bounds, by
// a derivative-free NLopt method (LN_BOBYQA, LN_NELDERMEAD, LN_SBPLX, LN_COBYLA), or with the
// implicit derivatives of src/fit/fit_problem.h driving NLopt LD_LBFGS (gradient Jᵀr) or Ceres'
// Levenberg–Marquardt (Jacobian J). Then the statistics at the optimum: Gauss–Newton standard
// errors and correlation, and which directions the measurements cannot determine.
#ifndef DRAPE_SRC_FIT_FIT_SOLVER_H_
#define DRAPE_SRC_FIT_FIT_SOLVER_H_

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "src/fit/fit_problem.h"

namespace drape {

// One objective evaluation (for the derivative-free methods, one outer iteration).
struct FitIterationRecord {
  int evaluation = 0;  // 1-based
  double time_s = 0.0;
  double objective = 0.0;
  double best_objective = 0.0;
  std::vector<double> parameters;  // θ
  int inner_iterations = 0;        // newton iterations of all equilibria
  bool inner_converged = true;
  bool with_jacobian = false;  // the implicit methods' evaluations that also computed J
};

// Singular directions of the normalised Jacobian dr/du (residuals in measurement uncertainties,
// u = ln θ for log parameters). Along direction v_k, a unit change of u (a factor e of a log
// parameter) changes ‖r‖ by s_k measurement uncertainties. A direction is flat (the measurements
// cannot determine it) when s_k < 1 or s_k < 1e-8 s_max.
struct Identifiability {
  std::vector<double> singular_values;        // descending
  std::vector<Eigen::VectorXd> directions;    // right singular vectors, in u
  std::vector<bool> flat;                     // per direction
  std::vector<double> parameter_sensitivity;  // ‖∂r/∂u_j‖ per parameter alone
  std::vector<bool> identifiable;       // per parameter: no weight (> 0.3) in a flat direction
  std::vector<std::string> statements;  // in words, one per finding
};

struct FitResult {
  std::vector<double> parameters;       // θ at the optimum
  std::vector<double> standard_errors;  // θ units; infinity for an unidentifiable parameter
  Eigen::MatrixXd correlation;          // p × p (NaN where undefined)
  double objective = 0.0;               // ½ Σ r² at the optimum
  double residual_variance = 0.0;       // Σ r² / (m − p) (1 if m ≤ p)
  bool converged = false;
  std::string termination;
  int evaluations = 0;  // objective evaluations (each solves every equilibrium)
  int jacobian_evaluations = 0;
  double wall_time_s = 0.0;
  FitEvaluation final_evaluation;
  Eigen::MatrixXd jacobian;  // dr/du at the optimum, m × p
  bool jacobian_implicit = true;
  Identifiability identifiability;
  std::vector<FitIterationRecord> history;
};

struct FitOptions {
  std::function<void(const FitIterationRecord&)> on_evaluation;  // progress
};

// Runs the outer loop of problem.spec().method from the initial parameters.
FitResult RunFit(FitProblem& problem, const FitOptions& options = {});

// Standard errors, correlation and identifiability from the Jacobian at the optimum.
void ComputeStatistics(const FitProblem& problem, FitResult* result);

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_SOLVER_H_
