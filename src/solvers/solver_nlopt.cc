// NLopt's gradient-based minimisers (the design's alternative family) on the exact total energy
// over the free coordinates, with the gradient assembled from the terms' autodiff (EvaluateEnergy):
//   nlopt-lbfgs    NLOPT_LD_LBFGS (low-storage BFGS; vector storage `memory`, default 10)
//   nlopt-tnewton  NLOPT_LD_TNEWTON_PRECOND_RESTART (preconditioned truncated Newton, restarting)
//   nlopt-var2     NLOPT_LD_VAR2 (shifted limited-memory variable metric, rank 2)
//   nlopt-mma      NLOPT_LD_MMA (method of moving asymptotes, here without constraints)
//   nlopt-slsqp    NLOPT_LD_SLSQP (sequential quadratic programming; dense O(n²) memory, so
//                  refused above kMaxSlsqpDofs free coordinates)
// NLopt has no stop on the gradient: every objective evaluation is recorded in the shared
// IterationMonitor (so "iterations" are objective evaluations here), and when it says stop (the
// relative residual reached, a limit, an interrupt) the callback calls force_stop() on the one
// nlopt::opt of the solve (a copy would keep the callback bound to the original). NLopt's own
// tolerances are set to 0. NLopt reports roundoff-limited and forced stops by throwing; every
// outcome is mapped to a termination text, and the solve ends at the point where the residual was
// reached, else at the evaluated point of lowest energy.
//
// Precision: as for ceres-lbfgs (see src/solvers/solver_ceres_lbfgs.cc), line searches that compare
// total energies stall once energy changes fall below the roundoff of the energy. With
// `local_energy` (default 1) the objective is the energy measured from an anchor point as the
// integral of the gradient along the segment (trapezoid rule, exact for a quadratic energy),
//   f(x) = f(x_a) + ½ (g(x_a) + g(x)) · (x − x_a),
// with the anchor moved to every point whose f is the lowest so far; f then differs from the
// energy by a constant up to O(|x − x_a|³) and resolves tiny changes near the minimum.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <nlopt.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/derivatives/local_energy.h"
#include "src/model/equilibrium.h"
#include "src/model/self_contact.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

constexpr int kMaxSlsqpDofs = 1000;
// Evaluations without a new lowest value after which a run is stopped and restarted from the best
// point (NLopt's MMA can shrink its asymptotes until it repeats the same point for ever): at least
// this many, and twice the free dofs (truncated Newton spends about one gradient per inner
// conjugate-gradient step, at points that are not lower).
constexpr int kStallEvaluations = 200;
// Restarts in a row that do not lower the residual at the best point before the solve gives up.
constexpr int kFruitlessRestarts = 5;

// Option `key` of method `name`: as given, else its default in the catalogue.
double Option(const std::string& name, const SolverOptions& options, const char* key) {
  return *MethodOptionValue(name, options.method_options, key);
}

// What the objective callback needs: the model, the stop rule and the opt to stop.
struct Objective {
  Objective(Model& the_model, const DofMap& the_dofs, IterationMonitor& the_monitor)
      : model(the_model), dofs(the_dofs), monitor(the_monitor) {}

  Model& model;  // evaluated in place, so the monitor's callback sees the current point
  const DofMap& dofs;
  IterationMonitor& monitor;
  nlopt::opt* opt = nullptr;
  bool local_energy = true;
  std::vector<double> gradient;
  int evaluations = 0;
  bool monitor_stopped = false;
  bool converged_point = false;
  // The point to return: the converged one, else the lowest objective.
  std::vector<double> best_point;
  double best_value = std::numeric_limits<double>::infinity();
  double best_residual = std::numeric_limits<double>::infinity();
  std::vector<double> best_gradient;
  LocalEnergy local;  // the objective when local_energy is set (src/derivatives/local_energy.h)

  double Evaluate(const std::vector<double>& free, std::vector<double>& free_gradient) {
    if (monitor_stopped || stalled) return best_value;  // NLopt may evaluate once more
    dofs.Scatter(free.data(), model.positions.data());
    double energy;
    if (!EvaluateEnergy(model, model.positions.data(), &energy, &gradient)) {
      for (double& g : free_gradient) g = 0.0;
      return std::numeric_limits<double>::max();
    }
    std::vector<double> g(dofs.num_free());
    dofs.Gather(gradient.data(), g.data());
    for (double& entry : g) entry *= scale;
    if (!free_gradient.empty()) free_gradient = g;
    // No point may be reached from the best one through an obstacle (src/model/contact.h): such a
    // point gets a value far above the best (NLopt's line searches fail on an infinite one), so
    // the step is shortened; it is never recorded as an iterate.
    if (Crosses(free)) return CrossingValue(free, free_gradient);
    const double value = LocalValue(free, g, scale * energy);
    const double residual = RelativeResidual(model, gradient);
    if (value < best_value) {
      best_value = value;
      best_point = free;
      best_gradient = g;
      best_residual = residual;
      since_best = 0;
      if (local_energy) local.Anchor(free, g, value);
    }
    if (++since_best > std::max(kStallEvaluations, 2 * dofs.num_free()) &&
        opt) {  // no lower value for long: restart
      stalled = true;
      opt->force_stop();
    }
    if (monitor.Record(evaluations++, energy, residual)) {
      monitor_stopped = true;
      if (residual <= monitor_tolerance) {
        converged_point = true;
        best_point = free;
      }
      if (opt) opt->force_stop();
    }
    return value;
  }

  bool Crosses(const std::vector<double>& free) {
    if (model.obstacles.empty() && !model.self_contact.enabled) return false;
    if (best_point.empty()) return false;
    crossing_from.assign(model.positions.begin(), model.positions.end());
    dofs.Scatter(best_point.data(), crossing_from.data());
    return StepSafeFraction(model, crossing_from.data(), model.positions.data()) < 1.0;
  }
  std::vector<double> crossing_from;

  // The value of a point that crosses an obstacle: a bowl centred at the best point, rising to
  // kCrossingPenalty × (1 + |best value|) above it at `free`, so that the slope along the step is
  // positive and the line search backtracks.
  double CrossingValue(const std::vector<double>& free, std::vector<double>& free_gradient) const {
    double squared = 0.0;
    for (size_t k = 0; k < free.size(); ++k) {
      squared += (free[k] - best_point[k]) * (free[k] - best_point[k]);
    }
    const double rise = kCrossingPenalty * (1.0 + std::abs(best_value));
    const double curvature = squared > 0.0 ? rise / squared : 0.0;
    if (!free_gradient.empty()) {
      for (size_t k = 0; k < free.size(); ++k) {
        free_gradient[k] = 2.0 * curvature * (free[k] - best_point[k]);
      }
    }
    return best_value + rise;
  }
  static constexpr double kCrossingPenalty = 1e3;

  // Restarts from the best point: the local energy is measured from there again.
  void Reanchor() {
    stalled = false;
    since_best = 0;
    if (!local_energy || best_point.empty()) return;
    local.Anchor(best_point, best_gradient, 0.0);
    best_value = 0.0;
  }

  double LocalValue(const std::vector<double>& free, const std::vector<double>& g, double energy) {
    if (!local_energy) return energy;
    if (!local.anchored()) return 0.0;  // the first point is the anchor, at 0
    return local.At(free.data(), g.data());
  }

  double monitor_tolerance = 0.0;
  double scale = 1.0;  // objective = scale × energy
  int since_best = 0;  // evaluations since the lowest value
  bool stalled = false;
};

double Callback(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  return static_cast<Objective*>(data)->Evaluate(x, grad);
}

std::string ResultText(nlopt::result result) {
  switch (result) {
    case nlopt::SUCCESS:
      return "nlopt: success";
    case nlopt::STOPVAL_REACHED:
      return "nlopt: stopval reached";
    case nlopt::FTOL_REACHED:
      return "nlopt: ftol reached";
    case nlopt::XTOL_REACHED:
      return "nlopt: xtol reached";
    case nlopt::MAXEVAL_REACHED:
      return "nlopt: evaluation limit reached (max_iterations)";
    case nlopt::MAXTIME_REACHED:
      return "nlopt: time limit reached";
    case nlopt::ROUNDOFF_LIMITED:
      return "nlopt: roundoff limited (no further progress in double precision)";
    case nlopt::FORCED_STOP:
      return "nlopt: forced stop";
    case nlopt::OUT_OF_MEMORY:
      return "nlopt: out of memory";
    case nlopt::INVALID_ARGS:
      return "nlopt: invalid arguments";
    default:
      return "nlopt: failure";
  }
}

// NLopt's Luksan methods (lbfgs, var2, tnewton) also stop ("success") when the largest gradient
// entry falls below a fixed absolute tolerance, which a small scene's forces in newtons reach
// before the relative residual does; scaled too far up (gradient ~1 at the tolerance) they fail at
// the first step. Measured on configs/examples/chain.yaml, scale = 1 / (reference force ×
// √tolerance) (1/N) works for all five methods: the objective is scale × energy.
//
// SLSQP has no gradient test, and its quasi-Newton matrix starts as the identity: its first step
// is −scale × gradient, which at that scale is ~1/√tolerance metres (1,000 m at 1e-6) and lands
// far outside the fabric or through an obstacle, after which its line search (NLopt issue #86:
// SLSQP fails when the gradients are large) rarely recovers. So its scale makes the first step
// kSlsqpFirstStep × the mesh spacing (size / √nodes) for the largest free gradient entry.
// Measured with `drape solve … --set solver.method=nlopt-slsqp`: configs/examples/chain.yaml 101
// evaluations (232 at the Luksan scale), pulled_sheet.yaml relative residual 7.4e-5 after 30 s
// (0.062), a sheet dropped onto a pin (tests/contact_test.cc) converged in 753 (never lowered its
// energy); first steps of 0.01–1 spacing all converge there.
constexpr double kSlsqpFirstStep = 0.1;

double ObjectiveScale(const Model& model, const DofMap& dofs, nlopt::algorithm algorithm,
                      double tolerance) {
  double energy;
  std::vector<double> gradient;
  if (!EvaluateEnergy(model, model.positions.data(), &energy, &gradient)) return 1.0;
  double scale;
  if (algorithm == nlopt::LD_SLSQP) {
    std::vector<double> free_gradient(dofs.num_free());
    dofs.Gather(gradient.data(), free_gradient.data());
    double largest = 0.0;
    for (double entry : free_gradient) largest = std::max(largest, std::abs(entry));
    const double spacing =
        model.size / std::sqrt(std::max(1.0, static_cast<double>(model.num_nodes)));
    scale = kSlsqpFirstStep * spacing / largest;
  } else {
    scale = 1.0 / (ReferenceForce(model, gradient) * std::sqrt(std::max(tolerance, 1e-16)));
  }
  return std::isfinite(scale) && scale > 0.0 ? scale : 1.0;
}

class NloptSolver : public Solver {
 public:
  NloptSolver(std::string name, nlopt::algorithm algorithm)
      : name_(std::move(name)), algorithm_(algorithm) {}

  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    const DofMap dofs(model);
    const int n = dofs.num_free();
    if (algorithm_ == nlopt::LD_SLSQP && n > kMaxSlsqpDofs) {
      throw InputError("nlopt-slsqp is limited to " + std::to_string(kMaxSlsqpDofs) +
                       " free degrees of freedom (its quasi-Newton matrix is dense, O(n^2) "
                       "memory and O(n^3) time); this scene has " +
                       std::to_string(n) + ": use nlopt-lbfgs, ceres-lbfgs or newton");
    }
    SolverSummary summary;
    IterationMonitor monitor(model, options, &summary);
    Objective objective(model, dofs, monitor);
    objective.local_energy = Option(name_, options, "local_energy") != 0.0;
    objective.monitor_tolerance = options.tolerance;
    objective.scale = ObjectiveScale(model, dofs, algorithm_, options.tolerance);
    std::vector<double> x(n);
    dofs.Gather(model.positions.data(), x.data());
    if (n == 0) {
      double energy;
      std::vector<double> gradient;
      EvaluateEnergy(model, model.positions.data(), &energy, &gradient);
      monitor.Record(0, energy, RelativeResidual(model, gradient));
      return summary;
    }

    // NLopt's methods also stop on their own internal tests (reported as ftol/xtol reached or
    // roundoff limited) although its tolerances are 0, or stall: then the solve restarts from the
    // best point, with the local energy measured from there (value 0), while restarts still lower
    // the residual at the best point (kFruitlessRestarts).
    std::string outcome;
    int restarts = 0, fruitless = 0;
    double lowest_residual = INFINITY;
    for (;;) {
      outcome = RunOnce(options, &objective, &x);
      if (objective.monitor_stopped || !(Restartable(outcome) || objective.stalled)) break;
      fruitless = objective.best_residual < lowest_residual ? 0 : fruitless + 1;
      lowest_residual = std::min(lowest_residual, objective.best_residual);
      if (fruitless >= kFruitlessRestarts) break;
      x = objective.best_point;
      objective.Reanchor();
      ++restarts;
    }
    if (!objective.monitor_stopped) monitor.Stop(outcome);
    if (!objective.best_point.empty()) x = objective.best_point;
    dofs.Scatter(x.data(), model.positions.data());
    summary.statistics["restarts"] = restarts;
    summary.statistics["energy_evaluations"] = objective.evaluations;
    return summary;
  }

 private:
  static bool Restartable(const std::string& outcome) {
    return outcome == ResultText(nlopt::FTOL_REACHED) ||
           outcome == ResultText(nlopt::XTOL_REACHED) || outcome == ResultText(nlopt::SUCCESS) ||
           outcome == ResultText(nlopt::ROUNDOFF_LIMITED);
  }

  // One call of optimize() from `x`, on a fresh nlopt::opt (never copied: the callback data
  // points at this one). Returns the outcome in words.
  std::string RunOnce(const SolverOptions& options, Objective* objective,
                      std::vector<double>* x) const {
    nlopt::opt opt(algorithm_, static_cast<unsigned>(x->size()));
    objective->opt = &opt;
    opt.set_min_objective(Callback, objective);
    opt.set_ftol_rel(0.0);
    opt.set_ftol_abs(0.0);
    opt.set_xtol_rel(0.0);
    opt.set_xtol_abs(0.0);
    opt.set_maxeval(std::max(1, options.max_iterations + 1 - objective->evaluations));
    opt.set_maxtime(std::max(1e-3, options.time_limit - objective->monitor.ElapsedSeconds()));
    if (algorithm_ == nlopt::LD_LBFGS || algorithm_ == nlopt::LD_TNEWTON_PRECOND_RESTART ||
        algorithm_ == nlopt::LD_VAR2) {
      opt.set_vector_storage(static_cast<unsigned>(Option(name_, options, "memory")));
    }
    double value = 0.0;
    std::string outcome;
    try {
      outcome = ResultText(opt.optimize(*x, value));
    } catch (const nlopt::roundoff_limited&) {
      outcome = ResultText(nlopt::ROUNDOFF_LIMITED);
    } catch (const nlopt::forced_stop&) {
      outcome = ResultText(nlopt::FORCED_STOP);
    } catch (const std::invalid_argument& error) {
      outcome = std::string("nlopt: invalid arguments (") + error.what() + ")";
    } catch (const std::bad_alloc&) {
      outcome = ResultText(nlopt::OUT_OF_MEMORY);
    } catch (const std::runtime_error& error) {
      outcome = std::string("nlopt: failure (") + error.what() + ")";
    }
    objective->opt = nullptr;
    return outcome;
  }

  const std::string name_;
  const nlopt::algorithm algorithm_;
};

}  // namespace

std::unique_ptr<Solver> NewNloptSolver(const std::string& name) {
  if (name == "nlopt-lbfgs") return std::make_unique<NloptSolver>(name, nlopt::LD_LBFGS);
  if (name == "nlopt-tnewton")
    return std::make_unique<NloptSolver>(name, nlopt::LD_TNEWTON_PRECOND_RESTART);
  if (name == "nlopt-var2") return std::make_unique<NloptSolver>(name, nlopt::LD_VAR2);
  if (name == "nlopt-mma") return std::make_unique<NloptSolver>(name, nlopt::LD_MMA);
  if (name == "nlopt-slsqp") return std::make_unique<NloptSolver>(name, nlopt::LD_SLSQP);
  return nullptr;
}

}  // namespace drape
