// ceres-lm and ceres-dogleg: the energy terms as a nonlinear least-squares problem.
//
// Elastic terms are sums of squares already (E = ½|r|²). A linear potential E = −f·(x − x_ref)
// (gravity, applied loads) is not; it enters as r = sqrt(2 (E + C)) with C = |f| × 2 × the
// model's size, so ½r² = E + C has the exact gradient, at the price of a small fake Gauss–Newton
// stiffness f fᵀ / (2(E + C)) (docs/architecture.md, fact 1). Gauss–Newton drops the geometric
// stiffness (T/l)(I − uuᵀ) of taut springs, so on drapes these methods stall; they are kept as
// alternatives and their failures reported as such. Precision: the cost is a sum of shifts (~|f| ×
// size per loaded node) and Ceres accepts a step by its cost change, so these methods stop when the
// change falls under the cost's roundoff — measured at relative residuals of 1e-9 to 1e-6.
#include <ceres/iteration_callback.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <cstdio>
#include <memory>

#include "src/model/ceres_problem.h"
#include "src/model/equilibrium.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

class MonitorCallback : public ceres::IterationCallback {
 public:
  MonitorCallback(const Model& model, IterationMonitor* monitor)
      : model_(model), monitor_(monitor) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& iteration) override {
    if (iteration.iteration > 0 && !iteration.step_is_successful) return ceres::SOLVER_CONTINUE;
    double energy = 0.0;
    if (!EvaluateEnergy(model_, model_.positions.data(), &energy, &gradient_)) {
      monitor_->Stop("energy not finite at the iterate");
      stopped_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    stopped_ = monitor_->Record(iteration.iteration, energy, RelativeResidual(model_, gradient_));
    return stopped_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

  bool stopped() const { return stopped_; }

 private:
  const Model& model_;
  IterationMonitor* monitor_;
  std::vector<double> gradient_;
  bool stopped_ = false;
};

class CeresLeastSquaresSolver : public Solver {
 public:
  explicit CeresLeastSquaresSolver(ceres::TrustRegionStrategyType strategy) : strategy_(strategy) {}

  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    SolverSummary summary;
    IterationMonitor monitor(model, options, &summary);
    ceres::Problem problem;
    BuildProblem(model, &problem);
    MonitorCallback callback(model, &monitor);

    ceres::Solver::Options ceres_options;
    ceres_options.trust_region_strategy_type = strategy_;
    ceres_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    ceres_options.max_num_iterations = options.max_iterations;
    ceres_options.max_solver_time_in_seconds = options.time_limit;
    // Stop only on the equilibrium residual (the callback), never on Ceres' cost-relative rules.
    ceres_options.function_tolerance = 0.0;
    ceres_options.gradient_tolerance = 0.0;
    ceres_options.parameter_tolerance = 0.0;
    ceres_options.update_state_every_iteration = true;
    ceres_options.callbacks.push_back(&callback);
    ceres_options.logging_type = ceres::SILENT;

    ceres::Solver::Summary ceres_summary;
    ceres::Solve(ceres_options, &problem, &ceres_summary);
    if (!callback.stopped()) {
      summary.termination = "ceres stopped: " + ceres_summary.message;
      summary.wall_time_s = monitor.ElapsedSeconds();
      summary.converged = false;
    }
    summary.statistics["successful_steps"] = ceres_summary.num_successful_steps;
    summary.statistics["unsuccessful_steps"] = ceres_summary.num_unsuccessful_steps;
    return summary;
  }

 private:
  const ceres::TrustRegionStrategyType strategy_;
};

}  // namespace

std::unique_ptr<Solver> NewCeresLeastSquaresSolver(ceres::TrustRegionStrategyType strategy) {
  return std::make_unique<CeresLeastSquaresSolver>(strategy);
}

}  // namespace drape
