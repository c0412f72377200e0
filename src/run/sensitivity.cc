#include "src/run/sensitivity.h"

#include <cmath>

#include "src/model/equilibrium.h"
#include "src/numerics/sparse_hessian.h"

namespace drape {
namespace {

void RequireStableEquilibrium(const RunResult& result) {
  if (!result.converged) {
    throw SensitivityError("the solve did not converge (" + result.summary.termination +
                           "): its positions are no equilibrium to differentiate");
  }
  if (result.stability.computed && !result.stability.stable) {
    throw SensitivityError("the equilibrium is a saddle (most negative eigenvalue " +
                           std::to_string(result.stability.min_eigenvalue) +
                           " N/m): its positions do not follow the parameters smoothly");
  }
}

void RequireSameDofs(const Model& model, const ParameterModels& key) {
  for (const Model* other : {&key.minus, &key.plus}) {
    if (other->num_nodes != model.num_nodes || other->fixed != model.fixed) {
      throw SensitivityError(key.key +
                             ": changing it changes the model's nodes or supports; "
                             "only parameters of the energy have sensitivities");
    }
  }
}

// ∂g/∂p over all coordinates: the central difference of the gradient at `positions`.
std::vector<double> GradientDerivative(const ParameterModels& key,
                                       const std::vector<double>& positions) {
  double energy = 0.0;
  std::vector<double> minus, plus;
  if (!EvaluateEnergy(key.minus, positions.data(), &energy, &minus) ||
      !EvaluateEnergy(key.plus, positions.data(), &energy, &plus)) {
    throw SensitivityError(key.key +
                           ": the energy is not defined at the equilibrium when the parameter "
                           "moves by " +
                           std::to_string(key.step));
  }
  std::vector<double> derivative(plus.size());
  for (size_t k = 0; k < plus.size(); ++k) {
    derivative[k] = (plus[k] - minus[k]) / (2.0 * key.step);
  }
  return derivative;
}

}  // namespace

double SensitivityStep(double value) { return value != 0.0 ? 1e-4 * std::abs(value) : 1e-6; }

EquilibriumDerivatives DifferentiateEquilibrium(const Model& model,
                                                const std::vector<double>& positions,
                                                const std::vector<ParameterModels>& keys) {
  for (const ParameterModels& key : keys) RequireSameDofs(model, key);
  EquilibriumDerivatives derivatives;
  for (const ParameterModels& key : keys) {
    derivatives.forces.push_back(GradientDerivative(key, positions));
  }
  if (model.num_free_dofs() == 0) {
    derivatives.positions.assign(keys.size(), std::vector<double>(model.num_dofs(), 0.0));
    return derivatives;
  }
  HessianWorkspace workspace(model);
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  if (!workspace.hessian.Assemble(positions.data(), /*project=*/false, &assembly, &gradient)) {
    throw SensitivityError("the Hessian cannot be evaluated at the equilibrium");
  }
  if (!workspace.cholesky.Factorize(workspace.hessian.values(), nullptr)) {
    throw SensitivityError(
        "the Hessian at the equilibrium is not positive definite: not a stable minimum");
  }
  const std::vector<int>& global = workspace.dofs.free_to_global();
  for (const std::vector<double>& force : derivatives.forces) {
    std::vector<double> rhs(global.size()), free;
    for (size_t f = 0; f < global.size(); ++f) rhs[f] = -force[global[f]];
    workspace.cholesky.Solve(rhs, &free);
    std::vector<double> all(model.num_dofs(), 0.0);
    workspace.dofs.Scatter(free.data(), all.data());
    derivatives.positions.push_back(std::move(all));
  }
  return derivatives;
}

std::vector<std::vector<double>> PositionSensitivities(const Model& model, const RunResult& result,
                                                       const std::vector<ParameterModels>& keys) {
  RequireStableEquilibrium(result);
  return DifferentiateEquilibrium(model, model.positions, keys).positions;
}

}  // namespace drape
