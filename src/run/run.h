// One equilibrium run: solve a model with a named method, then certify the result afresh.
#ifndef DRAPE_SRC_RUN_RUN_H_
#define DRAPE_SRC_RUN_RUN_H_

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "src/model/contact.h"
#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "src/model/self_intersection.h"
#include "src/numerics/round_off_floor.h"
#include "src/numerics/stability.h"
#include "src/scene/scene.h"
#include "src/solvers/solver.h"

namespace drape {

struct RunResult {
  SolverSummary summary;    // what the solver says
  Certificate certificate;  // recomputed at the final positions
  Stability stability;      // stable = false whenever certificate.unsound says why
  ContactReport contact;    // the penetration into the obstacles' clearance (with obstacles)
  SelfIntersections self_intersections;  // where the fabric crosses itself at the final positions
  bool converged = false;                // the solver's claim, confirmed by the certificate
  // The relative residual's round-off floor at the final positions (src/numerics/round_off_floor.h)
  // and whether the solve stopped there above the tolerance (then converged: the tolerance is
  // below what double precision can certify).
  double residual_floor = 0.0;
  bool at_floor = false;
  // The solver's state stopped being finite: what is saved is its last finite iterate, not
  // converged, and the termination says where (src/run/run.cc, ReturnToLastFinite).
  bool non_finite = false;
  // Converged, but not to a stable minimum (a saddle: stability.min_eigenvalue < 0).
  bool Saddle() const { return converged && stability.computed && !stability.stable; }
  // The final state is no drape at all, whatever its forces: the fabric passes through a support
  // disk or through itself. Such a state is never a stable minimum (exit status 3) and never
  // counted among a lab's drops or fabrics.
  bool PassesThrough() const {
    return contact.ThroughDisk() || contact.ThroughBody() || self_intersections.Any();
  }
};

// Solves with scene.solver (method, tolerance, limits, method options). `on_iteration` may be
// empty. Throws InputError if the method is unknown or refuses the model (e.g. too large), or if
// its state stopped being finite before any finite iterate was recorded.
RunResult RunSolve(const Scene& scene, Model& model, const std::string& method,
                   const std::function<bool(const IterationRecord&)>& on_iteration = {});

// One solve of `model` from its positions with `method` and scene.solver's tolerance, limits and
// options, without RunSolve's certificate (the stages of the continuation and of a load path).
SolverSummary SolveWithSceneOptions(
    const Scene& scene, Model& model, const std::string& method,
    const std::function<bool(const IterationRecord&)>& on_iteration = {});

// Whether the scene's fabric, or one of its regions, has a friction (in bending or in shear).
bool HasFriction(const Scene& scene);

// The obstacles' friction's passes (src/model/contact.h, kFrictionPushTolerance): `solve` solves
// `model` from its positions (false: stop after it, interrupted or not finite); where an obstacle
// has a friction and the pushes at the result moved by more than the tolerance from those the
// model's friction terms were made with, `model` is built again (its kinks at
// `friction_reference`, as for BuildModel) with the result's pushes, positioned at the result, and
// solved again, at most kMaxFrictionPasses times in all. Without a friction: one solve.
struct FrictionPasses {
  int passes = 0;            // solves
  double push_change = 0.0;  // FrictionPushChange at the last result
  bool settled = true;       // push_change ≤ kFrictionPushTolerance
};
FrictionPasses SettleObstacleFriction(const Scene& scene, Model& model,
                                      const std::vector<double>* friction_reference,
                                      const std::function<bool(Model&)>& solve);

// The options a solve of `method` takes from the scene: solver.<method>.<key> as given, and where
// the fabric has a bending friction, newton's max_expansions 0 unless given (src/run/run.cc,
// kFrictionMaxExpansions, has the evidence). The solvers take the catalogue's defaults for the
// rest (src/scene/solver_methods.h); scene.yaml writes these.
std::map<std::string, double> SolveMethodOptions(const Scene& scene, const std::string& method);

// The frictions' continuation, which RunSolve runs first: from model.positions, the stages of
// larger smoothing δ that a friction's kink at the flat state needs before the scene's own δ
// (costs/fv_bending_friction.h, costs/fv_shear_friction.h), each solved with `method` from the
// last; the result is left in `model`. Nothing is done (no stage) without friction. Returns the
// stages' iterations and time together. `friction_reference`: where the frictions' kinks sit, as
// for BuildModel (a load step of the incremental form; null: the flat state).
SolverSummary RunFrictionContinuation(
    const Scene& scene, Model& model, const std::string& method,
    const std::function<bool(const IterationRecord&)>& on_iteration = {},
    const std::vector<double>* friction_reference = nullptr);

}  // namespace drape

#endif  // DRAPE_SRC_RUN_RUN_H_
