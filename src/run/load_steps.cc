#include "src/run/load_steps.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "src/run/run.h"

namespace drape {
namespace {

// One step: the continuation in the frictions' smoothing, then `method` at the scene's own, in
// as many passes as the obstacles' friction needs (SettleObstacleFriction).
SolverSummary SolveStep(const Scene& step, Model& model, const std::string& method,
                        const std::function<bool(const IterationRecord&)>& on_iteration,
                        const std::vector<double>* reference) {
  const SolverSummary continuation =
      RunFrictionContinuation(step, model, method, on_iteration, reference);
  SolverSummary summary;
  int iterations = continuation.iterations;
  double wall_time_s = continuation.wall_time_s;
  const FrictionPasses passes = SettleObstacleFriction(step, model, reference, [&](Model& pass) {
    summary = SolveWithSceneOptions(step, pass, method, on_iteration);
    iterations += summary.iterations;
    wall_time_s += summary.wall_time_s;
    return summary.converged && !InterruptRequested();
  });
  summary.iterations = iterations;
  summary.wall_time_s = wall_time_s;
  summary.converged = summary.converged && passes.settled;
  return summary;
}

}  // namespace

int FrictionLoadSteps(const Scene& scene) {
  const bool friction = HasFriction(scene) || HasObstacleFriction(scene.obstacles);
  return friction ? scene.material.finite_volume.friction_load_steps : 0;
}

LoadsSpec ScaledLoads(const LoadsSpec& loads, double fraction) {
  LoadsSpec scaled = loads;
  if (scaled.gravity) *scaled.gravity *= fraction;
  for (ForceSpec& force : scaled.forces) {
    force.value *= fraction;
    for (Eigen::Vector3d& value : force.values) value *= fraction;
    force.ramp_to *= fraction;
    force.pressure *= fraction;
  }
  if (scaled.pressure) scaled.pressure->pressure *= fraction;
  return scaled;
}

LoadPathSummary RunLoadPath(const Scene& scene, Model& model, const std::string& method,
                            const std::function<bool(const IterationRecord&)>& on_iteration) {
  LoadPathSummary path;
  const int steps = FrictionLoadSteps(scene);
  path.total = steps;
  if (steps == 0) return path;
  std::vector<double> positions = model.initial;
  const std::vector<double>* reference = nullptr;  // the first step's kinks: the flat state
  for (int k = 1; k < steps; ++k) {
    Scene step = scene;
    step.loads = ScaledLoads(scene.loads, static_cast<double>(k) / steps);
    // The obstacles' friction's pushes: the previous step's, or in the first the fabric's own
    // weight's where it lies on a rough body (AddObstacleFrictionTerms).
    Model step_model = BuildModel(step, reference, k > 1 ? &positions : nullptr);
    step_model.positions = positions;
    const SolverSummary summary = SolveStep(step, step_model, method, on_iteration, reference);
    path.steps = k;
    path.iterations += summary.iterations;
    path.wall_time_s += summary.wall_time_s;
    if (!summary.converged && path.unconverged_step == 0) path.unconverged_step = k;
    const bool finite = std::all_of(step_model.positions.begin(), step_model.positions.end(),
                                    [](double x) { return std::isfinite(x); });
    if (!finite) break;  // the last step starts from the last finite state
    positions = step_model.positions;
    reference = &positions;
    if (InterruptRequested() || summary.termination == kStoppedByCaller) break;
  }
  Model last = BuildModel(scene, reference, &positions);
  last.positions = positions;
  model = std::move(last);
  path.reference = std::move(positions);
  return path;
}

}  // namespace drape
