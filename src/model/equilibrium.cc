#include "src/model/equilibrium.h"

#include <cassert>
#include <cmath>

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

Certificate ComputeCertificate(const Model& model, const double* positions) {
  Certificate certificate;
  std::vector<double> gradient;
  certificate.evaluable =
      EvaluateEnergy(model, positions, &certificate.energy, &gradient, &certificate.energy_by_type);
  if (!certificate.evaluable) {
    certificate.relative_residual = INFINITY;
    certificate.max_node_force = INFINITY;
    return certificate;
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
  return certificate;
}

}  // namespace drape
