// puiseux-fixed-point: the equilibrium iteration of Puiseux (seed 000, §3.1), the reference
// solver of the mass-spring model. With A⁰ the stiffness-weighted Laplacian factorised once,
//   A⁰_L x_L^{n+1} = [A(xⁿ) xⁿ]_L − A⁰_LD x_D + f_L,
// which is x^{n+1} = xⁿ + (A⁰_L)⁻¹ R_L(xⁿ) with R the residual force; the support reactions
// f_D = −φ_D come out of the certificate. Each coordinate has its own free set (nodes fixed in some
// directions only). Slow (linear convergence) but very stable, as the paper says.
#include <memory>
#include <string>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/model/spring_laplacian.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

class PuiseuxFixedPointSolver : public Solver {
 public:
  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    const std::string unsupported = UnsupportedTermType(model);
    if (!unsupported.empty()) {
      throw InputError(
          "puiseux-fixed-point handles springs and constant forces only; this "
          "scene has '" +
          unsupported + "' terms");
    }
    SolverSummary summary;
    IterationMonitor monitor(model, options, &summary);
    SpringLaplacianSolver laplacian;
    std::string error;
    if (!laplacian.Factorize(model, 0.0, 0.0, &error)) {
      monitor.Stop(error);
      return summary;
    }
    const double omega =
        *MethodOptionValue("puiseux-fixed-point", options.method_options, "relaxation");
    std::vector<double> gradient, residual(model.num_dofs()), step(model.num_dofs(), 0.0);
    for (int iteration = 0;; ++iteration) {
      double energy;
      if (!EvaluateEnergy(model, model.positions.data(), &energy, &gradient)) {
        monitor.Stop("energy not finite at the iterate");
        break;
      }
      if (monitor.Record(iteration, energy, RelativeResidual(model, gradient))) break;
      for (int k = 0; k < model.num_dofs(); ++k) residual[k] = -gradient[k];
      laplacian.Solve(residual, &step);
      for (int k = 0; k < model.num_dofs(); ++k) {
        if (!model.fixed[k]) model.positions[k] += omega * step[k];
      }
    }
    summary.statistics["factorizations"] = 1;
    return summary;
  }
};

}  // namespace

std::unique_ptr<Solver> NewPuiseuxFixedPointSolver() {
  return std::make_unique<PuiseuxFixedPointSolver>();
}

}  // namespace drape
