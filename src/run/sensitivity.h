// The derivatives of an equilibrium's positions with respect to scene parameters, by the implicit
// function theorem: the one implementation, for Python's drape.sensitivities and for the fit's
// implicit Jacobian (implicit-lm, implicit-lbfgs). At a stable equilibrium x*(p) the free forces
// vanish, g(x*(p), p) = 0, so
//   H dx*/dp = −∂g/∂p,
// H the free Hessian at x* (exact, as newton and the stability certificate assemble it). H is
// factorised once (CHOLMOD); each parameter costs one solve and ∂g/∂p, the central difference of
// the gradient at the fixed positions x* between the models built with p ± δ (δ = 1e-4 |p|, or
// 1e-6 for p = 0): exact up to round-off for the energies linear in a stiffness, a density or a
// load, and O(δ²) otherwise. Refused, with the reason, where the equilibrium is not a converged,
// stable minimum (H not positive definite) or a parameter changes the model's nodes or supports.
#ifndef DRAPE_SRC_RUN_SENSITIVITY_H_
#define DRAPE_SRC_RUN_SENSITIVITY_H_

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "src/model/model.h"
#include "src/run/run.h"

namespace drape {

// Why sensitivities cannot be had here (a saddle, an unconverged solve, a key that moves nodes).
class SensitivityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The step of the central difference for a parameter of value `value`.
double SensitivityStep(double value);

// One parameter: the models built with it at value − δ and value + δ (the same nodes and supports
// as the solved model), and δ.
struct ParameterModels {
  std::string key;
  Model minus, plus;
  double step = 0.0;
};

// For each parameter k, over all 3n coordinates: positions[k] = dx*/dp (0 on the fixed ones) and
// forces[k] = ∂g/∂p at the fixed positions (on a fixed coordinate, the direct dependence of its
// reaction on p). Index [k][3 * node + c].
struct EquilibriumDerivatives {
  std::vector<std::vector<double>> positions;
  std::vector<std::vector<double>> forces;
};

// The derivatives at `positions`, an equilibrium of `model`, without asking how it was reached
// (the fit's inner solves, src/fit/fit_problem.cc). Throws SensitivityError where the Hessian
// cannot be evaluated or is not positive definite there, or a parameter changes the nodes.
EquilibriumDerivatives DifferentiateEquilibrium(const Model& model,
                                                const std::vector<double>& positions,
                                                const std::vector<ParameterModels>& keys);

// dx*/dp for each parameter, after checking that `result`, the solve of `model` (its positions the
// equilibrium), is a converged, stable minimum: DifferentiateEquilibrium(...).positions.
std::vector<std::vector<double>> PositionSensitivities(const Model& model, const RunResult& result,
                                                       const std::vector<ParameterModels>& keys);

}  // namespace drape

#endif  // DRAPE_SRC_RUN_SENSITIVITY_H_
