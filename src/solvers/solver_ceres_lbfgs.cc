// ceres-lbfgs: L-BFGS with a Wolfe line search (ceres::GradientProblemSolver) on the exact total
// energy over the free coordinates. The gradient is assembled term by term from small Jets
// (AutoDiffFirstOrderFunction would need the whole size at compile time). Stops on the relative
// equilibrium residual, not on Ceres' cost-relative tolerances (docs/architecture.md, fact 3).
//
// Precision: a line search comparing energies stalls around a relative residual of 1e-7, where
// energy changes fall below the roundoff of the total energy. When Ceres stops for that reason,
// the solve restarts from there with the energy measured locally (src/derivatives/local_energy.h),
// re-anchored at every iterate.
#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "src/derivatives/local_energy.h"
#include "src/model/equilibrium.h"
#include "src/model/self_contact.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

// Energy of the free coordinates; fixed ones stay where the model has them. Remembers the last
// point evaluated so the per-iteration residual needs no second evaluation.
class FreeEnergy : public ceres::FirstOrderFunction {
 public:
  FreeEnergy(const Model& model, const DofMap& dofs)
      : model_(model), dofs_(dofs), work_(model.positions), iterate_(model.positions) {}

  // The current iterate (after each accepted step): no trial point may be reached from it by
  // passing through an obstacle (src/model/contact.h); such a point is reported as not evaluable,
  // and the line search shortens the step.
  void SetIterate(const double* free) { dofs_.Scatter(free, iterate_.data()); }

  // From now on, the cost is the energy change from the point last evaluated, integrated from the
  // gradient: it starts at 0 there, so the double it is returned in resolves tiny changes.
  void UseLocalEnergy() {
    local_ = true;
    last_cost_ = 0.0;
    Anchor();
  }

  // In local mode, moves the anchor to the point last evaluated (the current iterate).
  void Anchor() {
    if (local_) local_energy_.Anchor(last_point_, last_free_gradient_, last_cost_);
  }

  bool Evaluate(const double* free, double* cost, double* free_gradient) const override {
    ++evaluations_;
    dofs_.Scatter(free, work_.data());
    if ((!model_.obstacles.empty() || model_.self_contact.enabled) &&
        StepSafeFraction(model_, iterate_.data(), work_.data()) < 1.0) {
      return false;
    }
    if (!EvaluateEnergy(model_, work_.data(), &last_energy_, &gradient_)) return false;
    const int n = dofs_.num_free();
    last_free_gradient_.resize(n);
    dofs_.Gather(gradient_.data(), last_free_gradient_.data());
    last_cost_ = last_energy_;
    if (local_) last_cost_ = local_energy_.At(free, last_free_gradient_.data());
    *cost = last_cost_;
    if (free_gradient)
      std::copy(last_free_gradient_.begin(), last_free_gradient_.end(), free_gradient);
    last_point_.assign(free, free + n);
    return true;
  }
  int NumParameters() const override { return dofs_.num_free(); }
  int evaluations() const { return evaluations_; }

  // Energy and global gradient at `free`, reusing the last evaluation when it was at that point.
  bool At(const double* free, double* energy, const std::vector<double>** gradient) const {
    if (static_cast<int>(last_point_.size()) != dofs_.num_free() ||
        !std::equal(last_point_.begin(), last_point_.end(), free)) {
      double cost;
      if (!Evaluate(free, &cost, nullptr)) return false;
    }
    *energy = last_energy_;
    *gradient = &gradient_;
    return true;
  }

 private:
  const Model& model_;
  const DofMap& dofs_;
  bool local_ = false;
  LocalEnergy local_energy_;
  mutable std::vector<double> work_, gradient_, last_point_, last_free_gradient_;
  std::vector<double> iterate_;
  mutable double last_energy_ = 0.0, last_cost_ = 0.0;
  mutable int evaluations_ = 0;
};

// Records every iteration in the monitor, numbering them across restarts.
class LbfgsMonitorCallback : public ceres::IterationCallback {
 public:
  LbfgsMonitorCallback(Model& model, const DofMap& dofs, FreeEnergy& energy,
                       const std::vector<double>& free, IterationMonitor* monitor)
      : model_(model), dofs_(dofs), energy_(energy), free_(free), monitor_(monitor) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& iteration) override {
    if (iteration.iteration == 0 && recorded_ > 0) return ceres::SOLVER_CONTINUE;  // a restart
    double energy;
    const std::vector<double>* gradient;
    if (!energy_.At(free_.data(), &energy, &gradient)) {
      monitor_->Stop("energy not finite at the iterate");
      stopped_ = true;
    } else {
      last_residual_ = RelativeResidual(model_, *gradient);
      dofs_.Scatter(free_.data(), model_.positions.data());  // what the caller's callback sees
      stopped_ = monitor_->Record(recorded_, energy, last_residual_);
      ++recorded_;
      energy_.Anchor();
      energy_.SetIterate(free_.data());
    }
    return stopped_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
  bool stopped() const { return stopped_; }
  int recorded() const { return recorded_; }
  double last_residual() const { return last_residual_; }

 private:
  Model& model_;
  const DofMap& dofs_;
  FreeEnergy& energy_;
  const std::vector<double>& free_;
  IterationMonitor* monitor_;
  bool stopped_ = false;
  int recorded_ = 0;
  double last_residual_ = INFINITY;
};

ceres::GradientProblemSolver::Options CeresOptions(const SolverOptions& options,
                                                   ceres::IterationCallback* callback) {
  ceres::GradientProblemSolver::Options ceres_options;
  ceres_options.line_search_direction_type = ceres::LBFGS;
  ceres_options.max_lbfgs_rank =
      static_cast<int>(*MethodOptionValue("ceres-lbfgs", options.method_options, "memory"));
  ceres_options.max_num_iterations = options.max_iterations;
  ceres_options.max_solver_time_in_seconds = options.time_limit;
  // Ceres fails a line search once step × |direction| falls below this absolute length (1e-9 by
  // default): near equilibrium the steps are that small and still useful.
  ceres_options.min_line_search_step_size = 1e-300;
  ceres_options.function_tolerance = 0.0;
  ceres_options.gradient_tolerance = 0.0;
  ceres_options.parameter_tolerance = 0.0;
  ceres_options.update_state_every_iteration = true;
  ceres_options.callbacks.push_back(callback);
  ceres_options.logging_type = ceres::SILENT;
  return ceres_options;
}

class CeresLbfgsSolver : public Solver {
 public:
  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    SolverSummary summary;
    IterationMonitor monitor(model, options, &summary);
    const DofMap dofs(model);
    std::vector<double> free(dofs.num_free());
    dofs.Gather(model.positions.data(), free.data());
    auto* energy = new FreeEnergy(model, dofs);
    ceres::GradientProblem problem(energy);  // takes ownership
    LbfgsMonitorCallback callback(model, dofs, *energy, free, &monitor);
    ceres::GradientProblemSolver::Options ceres_options = CeresOptions(options, &callback);

    ceres::GradientProblemSolver::Summary ceres_summary;
    int restarts = 0;
    double residual_at_restart = INFINITY;
    if (dofs.num_free() == 0) callback(ceres::IterationSummary());
    while (dofs.num_free() > 0 && !callback.stopped()) {
      ceres_options.max_num_iterations = std::max(1, options.max_iterations - callback.recorded());
      ceres_options.max_solver_time_in_seconds = options.time_limit - monitor.ElapsedSeconds();
      ceres::Solve(ceres_options, problem, free.data(), &ceres_summary);
      if (callback.stopped()) break;
      // Ceres stopped on its own: at the roundoff of the energy, or its line search failed. Go on
      // with the local energy from here while that still halves the residual.
      if (restarts > 0 && !(callback.last_residual() < 0.5 * residual_at_restart)) {
        summary.termination = "ceres stopped: " + ceres_summary.message;
        summary.wall_time_s = monitor.ElapsedSeconds();
        break;
      }
      residual_at_restart = callback.last_residual();
      double unused;
      const std::vector<double>* gradient;
      if (!energy->At(free.data(), &unused, &gradient)) break;
      energy->UseLocalEnergy();
      ++restarts;
    }
    dofs.Scatter(free.data(), model.positions.data());
    summary.statistics["energy_evaluations"] = energy->evaluations();
    summary.statistics["local_energy_restarts"] = restarts;
    return summary;
  }
};

}  // namespace

std::unique_ptr<Solver> NewCeresLbfgsSolver() { return std::make_unique<CeresLbfgsSolver>(); }

}  // namespace drape
