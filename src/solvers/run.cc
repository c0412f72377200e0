#include "src/solvers/run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "src/scene/solver_methods.h"

namespace drape {
namespace {

// The first non-finite value among `values` (3 per node), as "node N (x)"; empty if none.
std::string FirstNonFinite(const std::vector<double>& values) {
  for (size_t k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k])) {
      return "node " + std::to_string(k / 3) + " (" + "xyz"[k % 3] + ")";
    }
  }
  return "";
}

// No result may hold NaN or infinity: a run whose positions or nodal forces are not finite stops
// here, located at the scene's solver section, and nothing is written.
void RequireFinite(const Scene& scene, const Model& model, const RunResult& result,
                   const std::string& method) {
  std::string where = FirstNonFinite(model.positions), what = "position";
  if (where.empty()) {
    where = FirstNonFinite(result.certificate.node_forces);
    what = "force";
  }
  if (where.empty() && !result.certificate.evaluable) {
    where = "the final positions";
    what = "energy or force";
  }
  if (where.empty()) return;
  throw InputError(scene.solver.where,
                   method + " produced a non-finite " + what + " at " + where + " after " +
                       std::to_string(result.summary.iterations) + " iterations (" +
                       result.summary.termination +
                       "): the scene's values or the method's step are too large for double "
                       "precision; nothing written");
}

}  // namespace

RunResult RunSolve(const Scene& scene, Model& model, const std::string& method,
                   const std::function<bool(const IterationRecord&)>& on_iteration) {
  const SolverInfo* info = FindSolver(method);
  if (!info) throw InputError(scene.solver.where, "unknown solver '" + method + "'");
  SolverOptions options;
  options.tolerance = scene.solver.tolerance;
  options.max_iterations = EffectiveMaxIterations(scene.solver, method);
  options.time_limit = EffectiveTimeLimit(scene.solver, method);
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
  RequireFinite(scene, model, result, method);
  result.contact = MeasureContact(scene.obstacles, scene.contact, model, model.positions.data());
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
