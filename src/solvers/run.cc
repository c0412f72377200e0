#include "src/solvers/run.h"

#include <algorithm>
#include <cstdio>

namespace drape {

RunResult RunSolve(const Scene& scene, Model& model, const std::string& method,
                   const std::function<bool(const IterationRecord&)>& on_iteration) {
  const SolverInfo* info = FindSolver(method);
  if (!info) throw InputError(scene.solver.where, "unknown solver '" + method + "'");
  SolverOptions options;
  options.tolerance = scene.solver.tolerance;
  options.max_iterations = scene.solver.max_iterations;
  options.time_limit = scene.solver.time_limit;
  if (auto it = scene.solver.method_options.find(method); it != scene.solver.method_options.end()) {
    options.method_options = it->second;
  }
  options.on_iteration = on_iteration;

  RunResult result;
  result.summary = info->make()->Solve(model, options);
  result.summary.solver = method;
  const std::vector<double>* constraint =
      result.summary.constraint_forces.empty() ? nullptr : &result.summary.constraint_forces;
  result.certificate = ComputeCertificate(model, model.positions.data(), constraint);
  result.residual_floor = RelativeResidualFloor(model, model.positions.data());
  if (result.certificate.unsound.empty()) {
    result.stability = AnalyseStability(model, model.positions.data());
  } else {  // a state that cannot be certified is not called stable
    result.stability.computed = true;
    result.stability.stable = false;
  }
  // The solver's claim stands only if the forces recomputed at its final positions confirm it: to
  // the tolerance, or (when it stopped at the round-off floor) to the floor measured here.
  result.at_floor = result.summary.converged && result.summary.residual_floor > 0.0;
  const double accepted = result.at_floor
                              ? std::max(options.tolerance, kFloorFactor * result.residual_floor)
                              : options.tolerance;
  result.converged = result.summary.converged && result.certificate.evaluable &&
                     result.certificate.unsound.empty() &&
                     result.certificate.relative_residual <= accepted;
  if (result.summary.converged && !result.converged) {
    char text[200];
    std::snprintf(text, sizeof text, "; but the recomputed relative residual is %.3g",
                  result.certificate.relative_residual);
    result.summary.termination += result.certificate.unsound.empty()
                                      ? std::string(text)
                                      : "; but " + result.certificate.unsound;
  } else if (!result.certificate.unsound.empty()) {
    result.summary.termination += "; " + result.certificate.unsound;
  }
  return result;
}

}  // namespace drape
