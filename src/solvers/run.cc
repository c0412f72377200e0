#include "src/solvers/run.h"

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
  result.certificate = ComputeCertificate(model, model.positions.data());
  result.stability = AnalyseStability(model, model.positions.data());
  // The solver's claim stands only if the forces recomputed at its final positions confirm it.
  result.converged = result.summary.converged && result.certificate.evaluable &&
                     result.certificate.relative_residual <= options.tolerance;
  if (result.summary.converged && !result.converged) {
    char text[200];
    std::snprintf(text, sizeof text, "%s; but the recomputed relative residual is %.3g",
                  result.summary.termination.c_str(), result.certificate.relative_residual);
    result.summary.termination = text;
  }
  return result;
}

}  // namespace drape
