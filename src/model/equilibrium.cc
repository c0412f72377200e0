#include "src/model/equilibrium.h"

#include <cassert>
#include <cmath>
#include <cstdio>

#include "src/model/contact.h"

namespace drape {

DofMap::DofMap(const Model& model) : global_to_free_(model.num_dofs(), -1) {
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (model.fixed[k]) continue;
    global_to_free_[k] = static_cast<int>(free_to_global_.size());
    free_to_global_.push_back(k);
  }
}

void DofMap::Gather(const double* global, double* free) const {
  for (int f = 0; f < num_free(); ++f) free[f] = global[free_to_global_[f]];
}

void DofMap::Scatter(const double* free, double* global) const {
  for (int f = 0; f < num_free(); ++f) global[free_to_global_[f]] = free[f];
}

bool EvaluateEnergy(const Model& model, const double* positions, double* energy,
                    std::vector<double>* gradient, std::map<std::string, double>* energy_by_type) {
  double total = 0.0;
  if (gradient) gradient->assign(model.num_dofs(), 0.0);
  double local_gradient[3 * 32];
  for (const auto& term : model.terms) {
    assert(term->num_coordinates() <= 3 * 32);
    double e = 0.0;
    if (gradient) {
      if (!term->EnergyGradient(positions, &e, local_gradient)) return false;
      const auto& nodes = term->nodes();
      for (size_t a = 0; a < nodes.size(); ++a) {
        for (int c = 0; c < 3; ++c) (*gradient)[3 * nodes[a] + c] += local_gradient[3 * a + c];
      }
    } else if (!term->Energy(positions, &e)) {
      return false;
    }
    if (energy_by_type) (*energy_by_type)[term->type()] += e;
    total += e;
  }
  *energy = total;
  return std::isfinite(total);
}

namespace {

double FixedForceNorm(const Model& model, const std::vector<double>& gradient) {
  double sum = 0.0;
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (model.fixed[k]) sum += gradient[k] * gradient[k];
  }
  return std::sqrt(sum);
}

double FreeForceNorm(const Model& model, const std::vector<double>& gradient) {
  double sum = 0.0;
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (!model.fixed[k]) sum += gradient[k] * gradient[k];
  }
  return std::sqrt(sum);
}

}  // namespace

double ReferenceForce(const Model& model, const std::vector<double>& gradient) {
  double applied = 0.0;
  for (double f : model.applied) applied += f * f;
  if (applied > 0.0) return std::sqrt(applied);
  const double reactions = FixedForceNorm(model, gradient);
  return reactions > 0.0 ? reactions : 1.0;
}

double RelativeResidual(const Model& model, const std::vector<double>& gradient) {
  return FreeForceNorm(model, gradient) / ReferenceForce(model, gradient);
}

namespace {

// −∇ of the contact terms per node, in total and per obstacle.
void AddContactForces(const Model& model, const double* positions, Certificate* certificate) {
  if (model.contact_terms.empty()) return;
  certificate->contact_forces.assign(model.num_dofs(), 0.0);
  certificate->contact_sum_by_obstacle.assign(model.obstacles.size(), Eigen::Vector3d::Zero());
  double local_gradient[3 * 32];
  for (const Model::ContactTerm& contact : model.contact_terms) {
    const Term& term = *model.terms[contact.term];
    double energy = 0.0;
    if (!term.EnergyGradient(positions, &energy, local_gradient)) continue;
    const auto& nodes = term.nodes();
    for (size_t a = 0; a < nodes.size(); ++a) {
      for (int c = 0; c < 3; ++c) {
        certificate->contact_forces[3 * nodes[a] + c] -= local_gradient[3 * a + c];
        certificate->contact_sum_by_obstacle[contact.obstacle][c] -= local_gradient[3 * a + c];
        certificate->contact_sum[c] -= local_gradient[3 * a + c];
      }
    }
  }
}

// Empty if the state can be certified; else what is wrong with it.
std::string StateProblem(const Model& model, const double* positions) {
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (!std::isfinite(positions[k])) return "positions not finite";
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  const bool started = static_cast<int>(model.initial.size()) == model.num_dofs();
  const double* start = started ? model.initial.data() : positions;
  for (int node = 0; node < model.num_nodes; ++node) centre += NodeAt(start, node);
  if (model.num_nodes > 0) centre /= model.num_nodes;
  double extent = model.size > 0.0 ? model.size : 1.0;
  for (int node = 0; node < model.num_nodes; ++node) {
    extent = std::max(extent, (NodeAt(start, node) - centre).norm());
  }
  for (int node = 0; node < model.num_nodes; ++node) {
    const double distance = (NodeAt(positions, node) - centre).norm();
    if (distance > kRunawayFactor * extent) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "run away: node %d is %.3g m from where the fabric started (more than %g x "
                    "its size)",
                    node, distance, kRunawayFactor);
      return text;
    }
  }
  for (int node = 0; node < model.num_nodes; ++node) {
    for (size_t o = 0; o < model.obstacles.size(); ++o) {
      const double distance = ObstacleDistance(model.obstacles[o], NodeAt(positions, node).data());
      if (distance < 0.0) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "node %d is inside obstacle %zu (%.3g m below its surface, beyond the "
                      "clearance layer)",
                      node, o + 1, -distance);
        return text;
      }
    }
  }
  return "";
}

void CheckBalance(const Model& model, Certificate* certificate) {
  for (int node = 0; node < model.num_nodes; ++node) {
    certificate->applied_sum += model.applied_force(node);
  }
  const Eigen::Vector3d total = certificate->reaction_sum + certificate->contact_sum +
                                certificate->constraint_sum + certificate->applied_sum;
  certificate->balance_error = total.norm() / certificate->reference_force;
  int free_nodes = 0;
  for (int node = 0; node < model.num_nodes; ++node) {
    if (!model.fully_fixed(node)) {
      ++free_nodes;
    }
  }
  const double bound = std::sqrt(std::max(free_nodes, 1)) * certificate->relative_residual;
  certificate->balanced = certificate->balance_error <= 1.01 * bound + 1e-9;
}

}  // namespace

Certificate ComputeCertificate(const Model& model, const double* positions,
                               const std::vector<double>* constraint_forces) {
  Certificate certificate;
  certificate.unsound = StateProblem(model, positions);
  std::vector<double> gradient;
  certificate.evaluable =
      EvaluateEnergy(model, positions, &certificate.energy, &gradient, &certificate.energy_by_type);
  if (!certificate.evaluable) {
    certificate.relative_residual = INFINITY;
    certificate.max_node_force = INFINITY;
    certificate.balance_error = INFINITY;
    if (certificate.unsound.empty()) certificate.unsound = "energy or forces not finite";
    return certificate;
  }
  // A constraint force F_c on a node adds to the model's −∇E: the residual is −(∇E − F_c).
  if (constraint_forces) {
    assert(static_cast<int>(constraint_forces->size()) == model.num_dofs());
    for (int k = 0; k < model.num_dofs(); ++k) {
      gradient[k] -= (*constraint_forces)[k];
      certificate.constraint_sum[k % 3] += (*constraint_forces)[k];
    }
  }
  certificate.reference_force = ReferenceForce(model, gradient);
  certificate.relative_residual = RelativeResidual(model, gradient);
  // The force on a node from the model is −∇E; a support's reaction balances it: R = +∇E.
  certificate.node_forces.resize(model.num_dofs());
  for (int node = 0; node < model.num_nodes; ++node) {
    double free_squared = 0.0;
    for (int c = 0; c < 3; ++c) {
      const int k = 3 * node + c;
      if (model.fixed[k]) {
        certificate.node_forces[k] = gradient[k];
        certificate.reaction_sum[c] += gradient[k];
      } else {
        certificate.node_forces[k] = -gradient[k];
        free_squared += gradient[k] * gradient[k];
      }
    }
    certificate.max_node_force = std::max(certificate.max_node_force, std::sqrt(free_squared));
  }
  AddContactForces(model, positions, &certificate);
  CheckBalance(model, &certificate);
  return certificate;
}

}  // namespace drape
