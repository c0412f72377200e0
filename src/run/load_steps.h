// The incremental form of the fabric's frictions (FiniteVolumeSpec::friction_load_steps,
// costs/fv_bending_friction_step.h): the loads ramped in N equal steps from the flat state, each
// step a minimisation whose frictions' kinks sit at the previous step's state.
#ifndef DRAPE_SRC_RUN_LOAD_STEPS_H_
#define DRAPE_SRC_RUN_LOAD_STEPS_H_

#include <functional>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/scene/scene.h"
#include "src/solvers/solver.h"

namespace drape {

// The load steps a solve of `scene` takes: friction_load_steps for a finite-volume fabric with a
// friction or on an obstacle with one (costs/obstacle_friction.h), else 0 (the loads at once).
int FrictionLoadSteps(const Scene& scene);

// The loads times `fraction` (gravity, every force, the pressure).
LoadsSpec ScaledLoads(const LoadsSpec& loads, double fraction);

struct LoadPathSummary {
  int total = 0;                  // N, the scene's steps
  int steps = 0;                  // the steps solved here: N − 1 (the last is the caller's), or
                                  // fewer where one was interrupted or stopped being finite
  int iterations = 0;             // theirs together, the frictions' continuation included
  double wall_time_s = 0.0;       // theirs together
  int unconverged_step = 0;       // the first step (1-based) that did not converge; 0: none
  std::vector<double> reference;  // step N − 1's positions, where the last step's kinks sit
};

// The steps before the last: from the flat state (model.initial; a warm start is not used, as the
// path must start where the frictions' kinks do), the scene at k/N of its loads for k = 1 … N − 1,
// each solved with `method` after the frictions' continuation, its kinks at the previous step's
// state. Then `model` becomes the last step's model, at the full loads with its kinks at step
// N − 1's state, positioned there: what RunSolve solves next. An interrupt (Ctrl-C, or
// `on_iteration` returning false) or a step whose state stops being finite ends the path there:
// the last step then starts from the last finite state, and unconverged_step says which step
// failed. Nothing is done without load steps (FrictionLoadSteps(scene) == 0) and `model` is left
// as it is.
LoadPathSummary RunLoadPath(const Scene& scene, Model& model, const std::string& method,
                            const std::function<bool(const IterationRecord&)>& on_iteration = {});

}  // namespace drape

#endif  // DRAPE_SRC_RUN_LOAD_STEPS_H_
