// puiseux-dynamic: the implicit dynamic scheme of Puiseux (seed 000, §4, eq. 15),
//   (A⁰ + M/dt² + β/(2dt) I) x^{n+1} = Aⁿxⁿ + fⁿ + M/dt² (2xⁿ − xⁿ⁻¹) + β/(2dt) xⁿ⁻¹,
// solved here for the step δ = x^{n+1} − xⁿ:
//   (A⁰ + M/dt² + β/(2dt) I) δ = R(xⁿ) + (M/dt² − β/(2dt) I)(xⁿ − xⁿ⁻¹),
// with R the residual force and the matrix factorised once. The fabric starts at rest. Stops (the
// paper's rules): relative residual r < tolerance (converged), kinetic energy w_c < ε² (at rest),
// t > t_max; plus the iteration and time limits. The kinetic energy of the nodes, w_c = ½Σ m|v|²,
// and of the centre of gravity, w_cg = ½ M |v_G|², with v = δ/dt, go to its trace,
// kinetic_puiseux-dynamic.csv.
#include <cassert>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/model/spring_laplacian.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

// Option `key`: as given, else its default in the catalogue (src/scene/solver_methods.cc).
std::optional<double> PuiseuxDynamicOption(const SolverOptions& options, const char* key) {
  return MethodOptionValue("puiseux-dynamic", options.method_options, key);
}

struct KineticEnergy {
  double nodes = 0.0;   // w_c, J
  double centre = 0.0;  // w_cg, J
};

KineticEnergy Kinetic(const Model& model, const std::vector<double>& step, double dt) {
  KineticEnergy kinetic;
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  double total_mass = 0.0;
  for (int node = 0; node < model.num_nodes; ++node) {
    const Eigen::Vector3d v(step[3 * node] / dt, step[3 * node + 1] / dt, step[3 * node + 2] / dt);
    kinetic.nodes += 0.5 * model.mass[node] * v.squaredNorm();
    momentum += model.mass[node] * v;
    total_mass += model.mass[node];
  }
  if (total_mass > 0.0) kinetic.centre = 0.5 * momentum.squaredNorm() / total_mass;
  return kinetic;
}

class PuiseuxDynamicSolver : public Solver {
 public:
  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    const std::string unsupported = UnsupportedTermType(model);
    if (!unsupported.empty()) {
      throw InputError(
          "puiseux-dynamic handles springs and constant forces only; this scene "
          "has '" +
          unsupported + "' terms");
    }
    // The scene loader checks the ranges (dt > 0, beta >= 0) where the options are given.
    const double dt = *PuiseuxDynamicOption(options, "dt"),
                 beta = *PuiseuxDynamicOption(options, "beta");
    const double t_max = *PuiseuxDynamicOption(options, "t_max");
    const double epsilon = PuiseuxDynamicOption(options, "epsilon").value_or(options.tolerance);
    assert(dt > 0.0 && beta >= 0.0);

    SolverSummary summary;
    summary.trace_columns = {"step", "t", "w_c", "w_cg", "residual"};
    IterationMonitor monitor(model, options, &summary);
    SpringLaplacianSolver system;
    std::string error;
    if (!system.Factorize(model, 1.0 / (dt * dt), beta / (2.0 * dt), &error)) {
      monitor.Stop(error);
      return summary;
    }
    const int dofs = model.num_dofs();
    std::vector<double> gradient, rhs(dofs), step(dofs, 0.0), velocity_step(dofs, 0.0);
    for (int n = 0;; ++n) {
      double energy;
      if (!EvaluateEnergy(model, model.positions.data(), &energy, &gradient)) {
        monitor.Stop("energy not finite at the iterate");
        break;
      }
      const double residual = RelativeResidual(model, gradient);
      const KineticEnergy kinetic = Kinetic(model, velocity_step, dt);
      summary.trace.push_back({double(n), n * dt, kinetic.nodes, kinetic.centre, residual});
      if (monitor.Record(n, energy, residual)) break;
      char text[160];
      if (n * dt >= t_max * (1.0 - 1e-12)) {
        std::snprintf(text, sizeof text, "t_max = %g s reached (relative residual %.3g)", t_max,
                      residual);
        monitor.Stop(text);
        break;
      }
      if (n > 0 && kinetic.nodes < epsilon * epsilon) {
        std::snprintf(text, sizeof text,
                      "at rest: kinetic energy %.3g J < epsilon^2 (relative residual %.3g)",
                      kinetic.nodes, residual);
        monitor.Stop(text);
        break;
      }
      for (int node = 0; node < model.num_nodes; ++node) {
        const double inertia = model.mass[node] / (dt * dt) - beta / (2.0 * dt);
        for (int c = 0; c < 3; ++c) {
          const int k = 3 * node + c;
          rhs[k] = -gradient[k] + inertia * velocity_step[k];
        }
      }
      system.Solve(rhs, &step);
      for (int k = 0; k < dofs; ++k) {
        velocity_step[k] = model.fixed[k] ? 0.0 : step[k];
        model.positions[k] += velocity_step[k];
      }
    }
    summary.statistics["dt"] = dt;
    summary.statistics["beta"] = beta;
    summary.statistics["t_final"] = summary.iterations * dt;
    return summary;
  }
};

}  // namespace

std::unique_ptr<Solver> NewPuiseuxDynamicSolver() {
  return std::make_unique<PuiseuxDynamicSolver>();
}

}  // namespace drape
