// explicit-euler: Rusinko & Swan's agent-based scheme (seed 001, §3.2), in SI units with a time
// step dt. Every step, for the free coordinates:
//   F = −∇E (springs, gravity, loads: every term of the model),  a = F / m,
//   v ← (1 − f) v + a dt,  x ← x + v dt,
// with the friction f per step (the paper's v ← (1 − f) v + a, x ← x + v is dt = 1 in its units).
// With a stretch limit λ (option `stretch_limit`, by default the scene's springs.stretch_limit),
// Provot's constraint follows every step (§3.3): nodes are visited in breadth-first order from the
// fixed nodes, and a node whose spring to an already visited node is longer than λ L0 is moved
// back along that spring to λ L0. The velocity takes the correction too (v += Δx / dt), so that a
// node held by the constraint comes to rest instead of pressing on it for ever.
//
// At rest: the residual the IterationMonitor sees is the larger of the relative equilibrium
// residual and the friction force f m v / dt relative to the same reference force (the kinetic
// part). With the constraint, the residual is that of the constrained problem: the free forces
// after subtracting, on each spring at its limit, the tension (≥ 0) that the constraint carries,
// found leaf to root along the breadth-first tree. Writes the kinetic energy per step (trace).
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <vector>

#include "src/model/contact.h"
#include "src/model/equilibrium.h"
#include "src/model/stretch_limit.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

// Option `key`: as given, else its default in the catalogue (src/scene/solver_methods.cc), which
// is none for dt and stretch_limit (derived from the model).
std::optional<double> ExplicitEulerOption(const SolverOptions& options, const char* key) {
  return MethodOptionValue("explicit-euler", options.method_options, key);
}

Eigen::Vector3d At(const std::vector<double>& values, int node) {
  return Eigen::Vector3d(values[3 * node], values[3 * node + 1], values[3 * node + 2]);
}

// Provot's constraint: the visiting order, and each node's parent spring in the breadth-first tree.
class ProvotConstraint {
 public:
  ProvotConstraint(const Model& model, double limit) : limit_(limit), fixed_(model.fixed) {
    std::vector<std::vector<int>> incident(model.num_nodes);
    springs_ = ModelSprings(model);
    for (int s = 0; s < static_cast<int>(springs_.size()); ++s) {
      incident[springs_[s].a].push_back(s);
      incident[springs_[s].b].push_back(s);
    }
    std::vector<char> seen(model.num_nodes, 0);
    std::deque<int> queue;
    for (int n = 0; n < model.num_nodes; ++n) {
      if (Anchored(n)) {
        seen[n] = 1;
        queue.push_back(n);
      }
    }
    while (!queue.empty()) {
      const int n = queue.front();
      queue.pop_front();
      if (!Anchored(n)) order_.push_back(n);
      for (int s : incident[n]) {
        const int other = springs_[s].a == n ? springs_[s].b : springs_[s].a;
        if (seen[other]) continue;
        seen[other] = 1;
        queue.push_back(other);
      }
    }
    // Springs to nodes visited earlier, per node: the ones the constraint pulls it back along.
    std::vector<int> rank(model.num_nodes, -1);
    for (int k = 0; k < static_cast<int>(order_.size()); ++k) rank[order_[k]] = k;
    earlier_springs_.resize(model.num_nodes);
    for (int n : order_) {
      for (int s : incident[n]) {
        const int other = springs_[s].a == n ? springs_[s].b : springs_[s].a;
        if (rank[other] < rank[n]) earlier_springs_[n].push_back(s);  // anchored: rank −1
      }
    }
  }

  // Moves nodes (free coordinates only) so that no spring to an earlier node exceeds λ L0.
  void Apply(std::vector<double>* x) const {
    for (int n : order_) {
      for (int s : earlier_springs_[n]) {
        const int other = springs_[s].a == n ? springs_[s].b : springs_[s].a;
        const Eigen::Vector3d from = At(*x, other), to = At(*x, n);
        const double length = (to - from).norm(), allowed = limit_ * springs_[s].rest_length;
        if (!(length > allowed)) continue;
        const Eigen::Vector3d moved = from + (to - from) * (allowed / length);
        for (int c = 0; c < 3; ++c) {
          if (!fixed_[3 * n + c]) (*x)[3 * n + c] = moved[c];
        }
      }
    }
  }

  // ‖free forces + constraint forces‖: the residual of the constrained problem. Each spring at
  // its limit may carry a tension t ≥ 0 beyond its elastic one (pulling its two ends together);
  // the tensions minimise the residual, found by projected Gauss-Seidel sweeps warm-started from
  // the previous call's (they converge as the motion does). `forces` = −∇E, 3 per node.
  double ConstrainedResidualNorm(const std::vector<double>& x, std::vector<double> forces) {
    tension_.resize(springs_.size(), 0.0);
    std::vector<int> active;
    std::vector<Eigen::Vector3d> direction(springs_.size());
    for (int s = 0; s < static_cast<int>(springs_.size()); ++s) {
      const Eigen::Vector3d d = At(x, springs_[s].b) - At(x, springs_[s].a);
      const double length = d.norm();
      if (!(length >= limit_ * springs_[s].rest_length * (1.0 - 1e-6))) {
        tension_[s] = 0.0;
        continue;
      }
      direction[s] = d / length;
      active.push_back(s);
      AddTension(s, direction[s], tension_[s], &forces);
    }
    for (int sweep = 0; sweep < kSweeps; ++sweep) {
      for (int s : active) {
        const Eigen::Vector3d& u = direction[s];
        const int a = springs_[s].a, b = springs_[s].b;
        // d|r|²/dt over the free coordinates of the two ends, and its curvature.
        double slope = 0.0, curvature = 0.0;
        for (int c = 0; c < 3; ++c) {
          if (!fixed_[3 * a + c]) slope += forces[3 * a + c] * u[c], curvature += u[c] * u[c];
          if (!fixed_[3 * b + c]) slope -= forces[3 * b + c] * u[c], curvature += u[c] * u[c];
        }
        if (!(curvature > 0.0)) continue;
        const double updated = std::max(0.0, tension_[s] - slope / curvature);
        AddTension(s, u, updated - tension_[s], &forces);
        tension_[s] = updated;
      }
    }
    double sum = 0.0;
    for (size_t k = 0; k < forces.size(); ++k) {
      if (!fixed_[k]) sum += forces[k] * forces[k];
    }
    active_ = active;
    directions_ = direction;
    return std::sqrt(sum);
  }

  // The constraint's forces on the nodes (3 per node, N): the tensions found by the last
  // ConstrainedResidualNorm, on the springs at their limit there.
  std::vector<double> ConstraintForces(int num_dofs) const {
    std::vector<double> forces(num_dofs, 0.0);
    for (int s : active_) AddTension(s, directions_[s], tension_[s], &forces);
    return forces;
  }

 private:
  static constexpr int kSweeps = 4;

  // A tension t in spring s (unit vector u from a to b) pulls a towards b and b towards a.
  void AddTension(int s, const Eigen::Vector3d& u, double t, std::vector<double>* forces) const {
    for (int c = 0; c < 3; ++c) {
      (*forces)[3 * springs_[s].a + c] += t * u[c];
      (*forces)[3 * springs_[s].b + c] -= t * u[c];
    }
  }

  bool Anchored(int n) const { return fixed_[3 * n] && fixed_[3 * n + 1] && fixed_[3 * n + 2]; }

  const double limit_;
  const std::vector<char>& fixed_;
  std::vector<SpringLink> springs_;
  std::vector<int> order_;  // free nodes, breadth-first from the anchored ones
  std::vector<std::vector<int>> earlier_springs_;
  std::vector<double> tension_;  // N, the constraint's tension per spring (warm start)
  std::vector<int> active_;      // springs at their limit at the last ConstrainedResidualNorm
  std::vector<Eigen::Vector3d> directions_;
};

// A stable step for the undamped scheme: 1/ω_max with ω_max² ≤ max_i 2 Σ k / m_i (Gershgorin's
// bound on M⁻¹K) over the springs' axial stiffness and, for a node with contact terms, each
// contact's stiffness where the stiffness rule keeps it, U'' = 2 k g at g = f t
// (src/model/contact.h). Without that, a node resting on an obstacle bounced on the stiff
// penalty and the scheme gained energy (a sheet dropped onto a pin was flung off it).
double DefaultTimeStep(const Model& model) {
  std::vector<double> stiffness(model.num_nodes, 0.0);
  for (const SpringLink& spring : ModelSprings(model)) {
    stiffness[spring.a] += spring.stiffness;
    stiffness[spring.b] += spring.stiffness;
  }
  if (!model.contact_terms.empty()) {
    const double contact = 2.0 * ContactStiffness(model.contact, model) * kAllowedPenetration *
                           model.contact.thickness;
    for (const Model::ContactTerm& term : model.contact_terms) {
      // An edge's m points pass (1 − s_j) and s_j of their stiffness to its two nodes: a row of
      // its Hessian sums to at most Σ_j (1 − s_j) = m/2 times a point's.
      const double share = term.edge_points > 0 ? 0.5 * term.edge_points : 1.0;
      for (int node : model.terms[term.term]->nodes()) stiffness[node] += share * contact;
    }
  }
  double omega_squared = 0.0;
  for (int n = 0; n < model.num_nodes; ++n) {
    if (model.mass[n] > 0.0)
      omega_squared = std::max(omega_squared, 2.0 * stiffness[n] / model.mass[n]);
  }
  return omega_squared > 0.0 ? 1.0 / std::sqrt(omega_squared) : 1e-3;
}

// Motionless: the friction force below kStillFraction × tolerance × the reference force for
// kStillSteps steps in a row while the residual is not. This happens only with Provot's constraint,
// which can hold nodes still away from equilibrium (it does not pass the constraint's reaction on
// to the inner node): the solve stops there, not converged.
constexpr double kStillFraction = 1e-6;
constexpr int kStillSteps = 1000;

// x ← x + v dt for the free coordinates, each node's move cut where it would pass through an
// obstacle (src/model/contact.h); a node so stopped loses its velocity.
void MoveAroundObstacles(const Model& model, double dt, std::vector<double>* v,
                         std::vector<double>* x) {
  for (int node = 0; node < model.num_nodes; ++node) {
    double to[3];
    for (int c = 0; c < 3; ++c) {
      const int k = 3 * node + c;
      to[c] = (*x)[k] + (model.fixed[k] ? 0.0 : (*v)[k] * dt);
    }
    const double fraction =
        model.obstacles.empty() ? 1.0 : NodeSafeFraction(model, x->data() + 3 * node, to);
    for (int c = 0; c < 3; ++c) {
      const int k = 3 * node + c;
      if (model.fixed[k]) continue;
      (*x)[k] += fraction * (*v)[k] * dt;
      if (fraction < 1.0) (*v)[k] = 0.0;
    }
  }
}

class ExplicitEulerSolver : public Solver {
 public:
  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    for (int k = 0; k < model.num_dofs(); ++k) {
      if (!model.fixed[k] && !(model.mass[k / 3] > 0.0)) {
        throw InputError("explicit-euler: node " + std::to_string(k / 3) +
                         " is free but has no mass (give the material a density or node_mass)");
      }
    }
    // The scene loader checks the ranges where the options are given (located); the model's
    // stretch limit is checked where the scene gives it.
    const double dt = ExplicitEulerOption(options, "dt").value_or(DefaultTimeStep(model));
    const double friction = *ExplicitEulerOption(options, "friction");
    const double limit =
        ExplicitEulerOption(options, "stretch_limit").value_or(model.stretch_limit);
    assert(dt > 0.0 && friction >= 0.0 && friction < 1.0 && (limit == 0.0 || limit > 1.0));
    std::unique_ptr<ProvotConstraint> provot;  // mutable: keeps its tensions between steps
    if (limit > 0.0) provot = std::make_unique<ProvotConstraint>(model, limit);

    SolverSummary summary;
    summary.trace_columns = {"step", "time_s", "kinetic_energy"};
    summary.statistics["dt"] = dt;
    summary.statistics["friction"] = friction;
    summary.statistics["stretch_limit"] = limit;
    IterationMonitor monitor(model, options, &summary);
    std::vector<double>& x = model.positions;
    std::vector<double> v(model.num_dofs(), 0.0), gradient, forces(model.num_dofs()), before;
    int still_steps = 0;  // consecutive steps without motion
    for (int step = 0;; ++step) {
      double energy;
      if (!EvaluateEnergy(model, x.data(), &energy, &gradient)) {
        monitor.Stop("energy not finite (the step dt is too large?)");
        break;
      }
      for (int k = 0; k < model.num_dofs(); ++k) forces[k] = -gradient[k];
      const double reference = ReferenceForce(model, gradient);
      const double residual =
          (provot ? provot->ConstrainedResidualNorm(x, forces) : FreeNorm(model, forces)) /
          reference;
      double kinetic = 0.0, friction_force = 0.0;
      for (int k = 0; k < model.num_dofs(); ++k) {
        kinetic += 0.5 * model.mass[k / 3] * v[k] * v[k];
        const double f = friction * model.mass[k / 3] * v[k] / dt;
        friction_force += f * f;
      }
      summary.trace.push_back({double(step), step * dt, kinetic});
      summary.statistics["kinetic_energy"] = kinetic;
      const double at_rest = std::max(residual, std::sqrt(friction_force) / reference);
      summary.statistics["rest_residual"] = at_rest;
      if (monitor.Record(step, energy, at_rest)) break;
      const double motion = std::sqrt(friction_force) / reference;
      still_steps = motion <= kStillFraction * options.tolerance ? still_steps + 1 : 0;
      if (still_steps >= kStillSteps) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "at rest for %d steps but not in equilibrium (residual %.3g): Provot's "
                      "constraint holds the nodes there",
                      kStillSteps, residual);
        monitor.Stop(text);
        break;
      }
      for (int k = 0; k < model.num_dofs(); ++k) {
        if (model.fixed[k]) continue;
        v[k] = (1.0 - friction) * v[k] + forces[k] / model.mass[k / 3] * dt;
      }
      MoveAroundObstacles(model, dt, &v, &x);
      if (provot) {
        before = x;
        provot->Apply(&x);
        for (int k = 0; k < model.num_dofs(); ++k) v[k] += (x[k] - before[k]) / dt;
      }
    }
    if (provot) summary.constraint_forces = provot->ConstraintForces(model.num_dofs());
    summary.statistics["simulated_time_s"] = summary.iterations * dt;
    return summary;
  }

 private:
  static double FreeNorm(const Model& model, const std::vector<double>& forces) {
    double sum = 0.0;
    for (int k = 0; k < model.num_dofs(); ++k) {
      if (!model.fixed[k]) sum += forces[k] * forces[k];
    }
    return std::sqrt(sum);
  }
};

}  // namespace

std::unique_ptr<Solver> NewExplicitEulerSolver() { return std::make_unique<ExplicitEulerSolver>(); }

}  // namespace drape
