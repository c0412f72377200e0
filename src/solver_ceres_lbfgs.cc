// ceres-lbfgs: L-BFGS with a Wolfe line search (ceres::GradientProblemSolver) on the exact total
// energy over the free coordinates. The gradient is assembled term by term from small Jets
// (AutoDiffFirstOrderFunction would need the whole size at compile time). Stops on the relative
// equilibrium residual, not on Ceres' cost-relative tolerances (architecture.md, fact 3).
#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "src/equilibrium.h"
#include "src/solvers.h"

namespace drape {

namespace {

// Energy of the free coordinates; fixed ones stay where the model has them. Remembers the last
// point evaluated so the per-iteration residual needs no second evaluation.
class FreeEnergy : public ceres::FirstOrderFunction {
 public:
  FreeEnergy(const Model& model, const DofMap& dofs)
      : model_(model), dofs_(dofs), work_(model.positions) {}

  bool Evaluate(const double* free, double* cost, double* free_gradient) const override {
    dofs_.Scatter(free, work_.data());
    if (!EvaluateEnergy(model_, work_.data(), cost, &gradient_)) return false;
    if (free_gradient) dofs_.Gather(gradient_.data(), free_gradient);
    last_point_.assign(free, free + dofs_.num_free());
    last_energy_ = *cost;
    return true;
  }
  int NumParameters() const override { return dofs_.num_free(); }

  // Energy and global gradient at `free`, reusing the last evaluation when it was at that point.
  bool At(const double* free, double* energy, const std::vector<double>** gradient) const {
    if (!std::equal(last_point_.begin(), last_point_.end(), free) ||
        static_cast<int>(last_point_.size()) != dofs_.num_free()) {
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
  mutable std::vector<double> work_, gradient_, last_point_;
  mutable double last_energy_ = 0.0;
};

class MonitorCallback : public ceres::IterationCallback {
 public:
  MonitorCallback(const Model& model, const FreeEnergy& energy, const std::vector<double>& free,
                  IterationMonitor* monitor)
      : model_(model), energy_(energy), free_(free), monitor_(monitor) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& iteration) override {
    double energy;
    const std::vector<double>* gradient;
    if (!energy_.At(free_.data(), &energy, &gradient)) {
      monitor_->Stop("energy not finite at the iterate");
      stopped_ = true;
    } else {
      stopped_ = monitor_->Record(iteration.iteration, energy, RelativeResidual(model_, *gradient));
    }
    return stopped_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
  bool stopped() const { return stopped_; }

 private:
  const Model& model_;
  const FreeEnergy& energy_;
  const std::vector<double>& free_;
  IterationMonitor* monitor_;
  bool stopped_ = false;
};

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
    MonitorCallback callback(model, *energy, free, &monitor);

    ceres::GradientProblemSolver::Options ceres_options;
    ceres_options.line_search_direction_type = ceres::LBFGS;
    const auto memory = options.method_options.find("memory");
    ceres_options.max_lbfgs_rank =
        memory != options.method_options.end() ? static_cast<int>(memory->second) : 20;
    ceres_options.max_num_iterations = options.max_iterations;
    ceres_options.max_solver_time_in_seconds = options.time_limit;
    ceres_options.function_tolerance = 0.0;
    ceres_options.gradient_tolerance = 0.0;
    ceres_options.parameter_tolerance = 0.0;
    ceres_options.update_state_every_iteration = true;
    ceres_options.callbacks.push_back(&callback);
    ceres_options.logging_type = ceres::SILENT;

    ceres::GradientProblemSolver::Summary ceres_summary;
    if (dofs.num_free() > 0) {
      ceres::Solve(ceres_options, problem, free.data(), &ceres_summary);
    } else {
      callback(ceres::IterationSummary());
    }
    dofs.Scatter(free.data(), model.positions.data());
    if (!callback.stopped()) {
      summary.termination = "ceres stopped: " + ceres_summary.message;
      summary.wall_time_s = monitor.ElapsedSeconds();
      summary.converged = false;
    }
    summary.statistics["energy_evaluations"] = ceres_summary.num_cost_evaluations;
    return summary;
  }
};

}  // namespace

std::unique_ptr<Solver> NewCeresLbfgsSolver() { return std::make_unique<CeresLbfgsSolver>(); }

}  // namespace drape
