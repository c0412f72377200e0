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
//
// Obstacles: no trial point may be reached from the last accepted iterate by a node passing
// through an obstacle (src/model/contact.h). An ObstacleGuard (a ceres::EvaluationCallback) sees
// every new trial point; one that crosses makes the guard's residual block fail to evaluate, which
// Ceres treats as a step of infinite cost: rejected, and the trust region shrinks.
#include <ceres/evaluation_callback.h>
#include <ceres/iteration_callback.h>
#include <ceres/problem.h>
#include <ceres/sized_cost_function.h>
#include <ceres/solver.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "src/model/ceres_problem.h"
#include "src/model/equilibrium.h"
#include "src/model/self_contact.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

// Remembers the last accepted iterate and judges each new trial point against it.
class ObstacleGuard : public ceres::EvaluationCallback {
 public:
  explicit ObstacleGuard(const Model& model) : model_(model), iterate_(model.positions) {}

  // With an evaluation callback, Ceres has copied the trial point into model.positions.
  void PrepareForEvaluation(bool /*evaluate_jacobians*/, bool new_evaluation_point) override {
    if (!new_evaluation_point) return;
    crossing_ = StepSafeFraction(model_, iterate_.data(), model_.positions.data()) < 1.0;
    if (crossing_) ++refused_;
  }
  // model.positions is the accepted iterate.
  void Accept() { iterate_ = model_.positions; }
  bool crossing() const { return crossing_; }
  int refused() const { return refused_; }

 private:
  const Model& model_;
  std::vector<double> iterate_;
  bool crossing_ = false;
  int refused_ = 0;
};

// A residual that is always 0 but cannot be evaluated at a point the guard refuses.
class GuardResidual : public ceres::SizedCostFunction<1, 3> {
 public:
  explicit GuardResidual(const ObstacleGuard& guard) : guard_(guard) {}
  bool Evaluate(double const* const* /*parameters*/, double* residuals,
                double** jacobians) const override {
    if (guard_.crossing()) return false;
    residuals[0] = 0.0;
    if (jacobians && jacobians[0]) std::fill(jacobians[0], jacobians[0] + 3, 0.0);
    return true;
  }

 private:
  const ObstacleGuard& guard_;
};

// Adds the guard's residual on the first node that is not fully fixed (Ceres drops a residual
// whose blocks are all constant). False if every node is fixed.
bool AddGuard(Model& model, const ObstacleGuard& guard, ceres::Problem* problem) {
  for (int node = 0; node < model.num_nodes; ++node) {
    if (model.fixed[3 * node] && model.fixed[3 * node + 1] && model.fixed[3 * node + 2]) continue;
    problem->AddResidualBlock(new GuardResidual(guard), nullptr, model.positions.data() + 3 * node);
    return true;
  }
  return false;
}

class LeastSquaresMonitorCallback : public ceres::IterationCallback {
 public:
  LeastSquaresMonitorCallback(const Model& model, ObstacleGuard* guard, IterationMonitor* monitor)
      : model_(model), guard_(guard), monitor_(monitor) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& iteration) override {
    if (iteration.iteration > 0 && !iteration.step_is_successful) return ceres::SOLVER_CONTINUE;
    if (guard_) guard_->Accept();
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
  ObstacleGuard* guard_;  // null without obstacles
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
    ObstacleGuard guard(model);
    ceres::Problem::Options problem_options;
    const bool guarded = !model.obstacles.empty() || model.self_contact.enabled;
    if (guarded) problem_options.evaluation_callback = &guard;
    ceres::Problem problem(problem_options);
    BuildProblem(model, &problem);
    if (guarded) AddGuard(model, guard, &problem);
    LeastSquaresMonitorCallback callback(model, guarded ? &guard : nullptr, &monitor);

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
    if (guarded) summary.statistics["steps_refused_at_obstacles"] = guard.refused();
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
