#include "src/numerics/round_off_floor.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/numerics/sparse_hessian.h"

namespace drape {

namespace {

// Σ_terms |∂E_t/∂x_k| for every coordinate k; false if a term is not finite.
bool ForceMagnitudes(const Model& model, const double* positions, std::vector<double>* sums) {
  sums->assign(model.num_dofs(), 0.0);
  double local_gradient[3 * 32];
  for (const auto& term : model.terms) {
    assert(term->num_coordinates() <= 3 * 32);
    double energy = 0.0;
    if (!term->EnergyGradient(positions, &energy, local_gradient)) return false;
    const auto& nodes = term->nodes();
    for (size_t a = 0; a < nodes.size(); ++a) {
      for (int c = 0; c < 3; ++c) (*sums)[3 * nodes[a] + c] += std::abs(local_gradient[3 * a + c]);
    }
  }
  return true;
}

}  // namespace

double RelativeResidualFloor(const Model& model, const double* positions, FreeHessian* hessian) {
  return ResidualFloorEstimator(model, hessian).At(positions);
}

double ResidualFloorEstimator::At(const double* positions) {
  const Model& model = model_;
  if (model.num_free_dofs() == 0) return 0.0;
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  std::vector<double> magnitudes;
  if (!ForceMagnitudes(model, positions, &magnitudes)) return INFINITY;
  if (!hessian_ || (own_hessian_ && own_hessian_->Stale())) {
    own_dofs_ = std::make_unique<const DofMap>(model);
    own_hessian_ = std::make_unique<FreeHessian>(model, *own_dofs_);
    hessian_ = own_hessian_.get();
  }
  FreeHessian& hessian = *hessian_;
  const DofMap& dofs = hessian.dofs();
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  if (!hessian.Assemble(positions, /*project=*/false, &assembly, &gradient)) return INFINITY;
  // Σ_j H_ij² δ_j² with δ_j = ε |x_j| / 2: the product of the squared entries with δ².
  std::vector<double> squared(hessian.values().size());
  for (size_t k = 0; k < squared.size(); ++k)
    squared[k] = hessian.values()[k] * hessian.values()[k];
  const int n = dofs.num_free();
  std::vector<double> delta_squared(n), spread(n);
  for (int f = 0; f < n; ++f) {
    const double delta = 0.5 * kEpsilon * std::abs(positions[dofs.free_to_global()[f]]);
    delta_squared[f] = delta * delta;
  }
  hessian.Multiply(squared, delta_squared.data(), spread.data());
  double sum = 0.0;
  for (int f = 0; f < n; ++f) {
    const double floor =
        kEpsilon * magnitudes[dofs.free_to_global()[f]] + std::sqrt(std::max(spread[f], 0.0));
    sum += floor * floor;
  }
  const double floor = std::sqrt(sum) / ReferenceForce(model, gradient);
  return std::isfinite(floor) ? floor : INFINITY;
}

}  // namespace drape
