#include "src/run/run.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "src/model/self_contact.h"
#include "src/run/load_steps.h"
#include "src/scene/material_keys.h"
#include "src/scene/material_models.h"
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

bool AllFinite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// The last iterate at which the positions, the energy and the residual were all finite.
struct LastFinite {
  std::vector<double> positions;
  int iteration = -1;  // -1: none recorded yet (the start is used)
};

// What is not finite in a solver's final state, as "a non-finite position at node N (x)"; empty
// if all is finite.
std::string NonFiniteState(const Model& model, const Certificate& certificate) {
  std::string where = FirstNonFinite(model.positions);
  if (!where.empty()) return "a non-finite position at " + where;
  where = FirstNonFinite(certificate.node_forces);
  if (!where.empty()) return "a non-finite force at " + where;
  if (certificate.evaluable) return "";
  // Finite positions whose energy overflows: name the node that moved farthest from its start.
  int farthest = 0;
  double distance = -1.0;
  for (int node = 0; node < model.num_nodes && model.initial.size() == model.positions.size();
       ++node) {
    const double d = (Eigen::Vector3d(model.positions.data() + 3 * node) -
                      Eigen::Vector3d(model.initial.data() + 3 * node))
                         .norm();
    if (d > distance) {
      distance = d;
      farthest = node;
    }
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "a non-finite energy or force at the final positions (node %d moved farthest, "
                "%.3g m from its start)",
                farthest, distance);
  return text;
}

// No result may hold NaN or infinity. A solver whose state stopped being finite is taken back to
// its last finite iterate, which is certified and saved, marked not converged; its termination
// says where the values stopped being finite. The history and trace keep their finite rows only.
// If there is no finite iterate to go back to, the run is refused (InputError, nothing written).
void ReturnToLastFinite(const Scene& scene, const std::string& method, const LastFinite& last,
                        Model& model, RunResult* result) {
  const std::string what = NonFiniteState(model, result->certificate);
  if (what.empty()) return;
  const std::string after = " after " + std::to_string(result->summary.iterations) +
                            " iterations (" + result->summary.termination + ")";
  const std::vector<double>& back = last.iteration >= 0 ? last.positions : model.initial;
  if (static_cast<int>(back.size()) == model.num_dofs()) model.positions = back;
  UpdateSelfContact(&model, model.positions.data());  // the pairs near there
  // Constraint forces (Provot's) were those of the final state: they do not hold at this one.
  result->summary.constraint_forces.clear();
  result->certificate = ComputeCertificate(model, model.positions.data());
  if (!NonFiniteState(model, result->certificate).empty()) {
    throw InputError(scene.solver.where,
                     method + " produced " + what + after +
                         ": the scene's values or the method's step are too large for double "
                         "precision; nothing written");
  }
  SolverSummary& summary = result->summary;
  summary.converged = false;
  summary.residual_floor = 0.0;
  summary.termination = "non-finite state: " + method + " produced " + what + after +
                        "; the last finite iterate (iteration " +
                        std::to_string(std::max(last.iteration, 0)) + ") is saved";
  auto& history = summary.history;
  history.erase(std::remove_if(history.begin(), history.end(),
                               [](const IterationRecord& r) {
                                 return !std::isfinite(r.energy) ||
                                        !std::isfinite(r.relative_residual) ||
                                        !std::isfinite(r.time_s);
                               }),
                history.end());
  summary.trace.erase(
      std::remove_if(summary.trace.begin(), summary.trace.end(),
                     [](const std::vector<double>& row) { return !AllFinite(row); }),
      summary.trace.end());
  result->non_finite = true;
}

// The frictions' smoothings δ (costs/fv_bending_friction.h, costs/fv_shear_friction.h) from which a
// solve starts, and the ratio of one stage's δ to the next: smaller ones are reached by
// continuation, each stage started from the last one's positions (Newton from the flat state
// straight at δ = 0.01 1/m took 1,773 iterations for the heavy cantilever of
// tests/fv_bending_friction_test.cc, where the stages take tens each).
//
// The bending friction's stages fall by √10: a stage's answer differs from the next one's where
// |κ| is below about δ, and Newton's quadratic model of √(κ² + δ²) holds only within δ of its
// kink, so a tenfold step leaves the next stage crawling there. Measured in session 34 (newton
// iterations in all, the same minimum to the energy's last digits either way):
// - the friction cotton of docs/benchmarks.md, one level, at 3.8, 4, 4.2 and 4.5 mm: 758, 303,
//   318 and 192 against 907, 425, 418 and 256 with stages 1, 0.1 1/m (at 4 mm 218 + 66 + 19
//   against 218 + 207: the last stage no longer crawls);
// - the limp fabric with H = 2e-4 N at 5 mm: 1,122 against 1,159;
// - a third of a decade (1, 0.46, 0.22, 0.1) took the cotton at 4 mm 288: the extra stage's setup
//   cancels what it saves;
// - where nothing crawls the extra stages cost their few iterations each: the heavy cantilever at
//   δ = 0.01 took 120 against 95.
// The shear friction's stages keep a tenfold step: √10 took the cotton with HG = 0.49 N/m at 5 mm
// 427 iterations against 390.
constexpr double kBendingContinuationStart = 1.0;                 // 1/m
constexpr double kBendingContinuationRatio = 3.1622776601683795;  // √10
constexpr double kShearContinuationStart = 0.1;                   // rad
constexpr double kShearContinuationRatio = 10.0;

// Whether the scene's fabric, or one of its regions, has one of the given frictions (a region
// gives them under their FiniteVolumeKeys() names).
bool HasFriction(const Scene& scene, std::initializer_list<double FiniteVolumeSpec::*> members) {
  if (!MaterialModelOf(scene.material.model).friction) return false;
  for (const auto member : members) {
    if (scene.material.finite_volume.*member > 0.0) return true;
  }
  for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
    if (std::find(members.begin(), members.end(), key.member) == members.end()) continue;
    for (const RegionSpec& region : scene.regions) {
      const auto given = region.finite_volume.find(key.key);
      if (given != region.finite_volume.end() && given->second > 0.0) return true;
    }
  }
  return false;
}

// Whether the scene's fabric, or one of its regions, has a bending friction (warp or weft).
bool HasBendingFriction(const Scene& scene) {
  return HasFriction(
      scene, {&FiniteVolumeSpec::bending_friction_warp, &FiniteVolumeSpec::bending_friction_weft});
}

struct Smoothings {
  double bending = 0.0;  // 1/m
  double shear = 0.0;    // rad
};

// The smoothings of the stages before the scene's own (none without friction, or with δ at or
// above the start): each friction's δ falls by its ratio a stage from its start until it is the
// scene's.
std::vector<Smoothings> ContinuationStages(const Scene& scene) {
  const FiniteVolumeSpec& fv = scene.material.finite_volume;
  const bool bending = HasBendingFriction(scene);
  const bool shear = HasFriction(scene, {&FiniteVolumeSpec::shear_friction});
  std::vector<Smoothings> stages;
  for (int k = 0;; ++k) {
    Smoothings stage{fv.bending_friction_smoothing, fv.shear_friction_smoothing};
    if (bending) {
      stage.bending = std::max(stage.bending,
                               kBendingContinuationStart / std::pow(kBendingContinuationRatio, k));
    }
    if (shear) {
      stage.shear =
          std::max(stage.shear, kShearContinuationStart / std::pow(kShearContinuationRatio, k));
    }
    if (stage.bending <= fv.bending_friction_smoothing * (1.0 + 1e-9) &&
        stage.shear <= fv.shear_friction_smoothing * (1.0 + 1e-9)) {
      return stages;
    }
    stages.push_back(stage);
  }
}

SolverOptions OptionsFor(const Scene& scene, const std::string& method) {
  SolverOptions options;
  options.tolerance = scene.solver.tolerance;
  options.max_iterations = EffectiveMaxIterations(scene.solver, method);
  options.time_limit = EffectiveTimeLimit(scene.solver, method);
  options.method_options = SolveMethodOptions(scene, method);
  return options;
}

RunResult RunSolveOnce(const Scene& scene, Model& model, const SolverInfo& info,
                       const std::string& method,
                       const std::function<bool(const IterationRecord&)>& on_iteration) {
  const SolverInfo* const found = &info;
  SolverOptions options = OptionsFor(scene, method);
  // Keeps the last finite iterate (an O(n) check and copy per iteration) for ReturnToLastFinite.
  LastFinite last;
  options.on_iteration = [&](const IterationRecord& record) {
    if (std::isfinite(record.energy) && std::isfinite(record.relative_residual) &&
        AllFinite(model.positions)) {
      last.positions = model.positions;
      last.iteration = record.iteration;
    }
    return !on_iteration || on_iteration(record);
  };

  // One free Hessian and CHOLMOD analysis for the solve and the certificate after it (built after
  // the solve for a method that does not use it: it would only add to that method's memory).
  // The fabric's contact with itself where the solve starts (a warm start is not where the model
  // was built); newton updates it as it goes, and the pattern is built again if it did.
  UpdateSelfContact(&model, model.positions.data());
  std::unique_ptr<HessianWorkspace> workspace;
  const bool has_free = model.num_free_dofs() > 0;
  if (has_free && found->uses_hessian_workspace) {
    workspace = std::make_unique<HessianWorkspace>(model);
  }
  const int generation = model.self_contact.generation;
  options.workspace = workspace.get();
  RunResult result;
  result.summary = found->make()->Solve(model, options);
  result.summary.solver = method;
  // The certificate's energy has every pair near the final state (newton's have them already; the
  // other methods keep their start's, and a pair that came near without a term counts now).
  UpdateSelfContact(&model, model.positions.data());
  const std::vector<double>* constraint =
      result.summary.constraint_forces.empty() ? nullptr : &result.summary.constraint_forces;
  result.certificate = ComputeCertificate(model, model.positions.data(), constraint);
  ReturnToLastFinite(scene, method, last, model, &result);
  result.contact = MeasureContact(scene.obstacles, scene.contact, model, model.positions.data(),
                                  result.certificate.contact_forces);
  result.self_intersections = FindSelfIntersections(model, model.positions);
  // The pattern of the terms the model has now (newton, or the return to the last finite iterate,
  // may have replaced the self-contact terms).
  if (model.self_contact.generation != generation) workspace.reset();
  if (has_free && !workspace) workspace = std::make_unique<HessianWorkspace>(model);
  FreeHessian* hessian = workspace ? &workspace->hessian : nullptr;
  result.residual_floor = RelativeResidualFloor(model, model.positions.data(), hessian);
  if (result.certificate.unsound.empty()) {
    result.stability = AnalyseStability(model, model.positions.data(), workspace.get());
  } else {  // a state that cannot be certified is not called stable
    result.stability.computed = true;
    result.stability.stable = false;
  }
  // The solver's claim stands only if the forces recomputed at its final positions confirm it: to
  // the tolerance, or (when it stopped at the round-off floor) to the floor measured here; and the
  // whole fabric balances (reactions + contact + constraint = −(weight + loads), to what the free
  // residual forces can account for).
  result.at_floor = result.summary.converged && result.summary.residual_floor > 0.0;
  const double accepted = result.at_floor
                              ? std::max(options.tolerance, kFloorFactor * result.residual_floor)
                              : options.tolerance;
  const Certificate& certificate = result.certificate;
  const bool residual_confirmed = certificate.relative_residual <= accepted;
  result.converged = result.summary.converged && certificate.evaluable &&
                     certificate.unsound.empty() && residual_confirmed && certificate.balanced;
  std::string& termination = result.summary.termination;
  if (result.summary.converged && !result.converged) {
    char text[240];
    if (!certificate.unsound.empty()) {
      termination += "; but " + certificate.unsound;
    } else if (!residual_confirmed) {
      std::snprintf(text, sizeof text, "; but the recomputed relative residual is %.3g",
                    certificate.relative_residual);
      termination += text;
    } else {
      std::snprintf(text, sizeof text,
                    "; but the forces do not balance: reactions + contact + constraint differ "
                    "from the weight and loads by %.3g of the reference force",
                    certificate.balance_error);
      termination += text;
    }
  } else if (!certificate.unsound.empty()) {
    termination += "; " + certificate.unsound;
  }
  return result;
}

// The obstacles' friction in the result: its passes in the contact report and the termination,
// and normal forces that did not settle, which leave the state short of Coulomb's law.
void NoteFrictionPasses(const Scene& scene, const FrictionPasses& passes, RunResult* result) {
  if (!HasObstacleFriction(scene.obstacles)) return;
  ContactReport& contact = result->contact;
  contact.friction = true;
  contact.friction_passes = passes.passes;
  contact.friction_push_change = passes.push_change;
  contact.friction_settled = passes.settled;
  char text[200];
  std::snprintf(text, sizeof text,
                "; %d solve%s of the obstacles' friction, its normal forces moved by %.2g of the "
                "load in the last",
                passes.passes, passes.passes == 1 ? "" : "s", passes.push_change);
  result->summary.termination += text;
  if (!passes.settled && result->converged) {
    result->converged = false;
    std::snprintf(text, sizeof text,
                  "; but the obstacles' friction did not settle: its normal forces moved by %.2g "
                  "of the load in the last of %d solves (at most %g)",
                  passes.push_change, passes.passes, kFrictionPushTolerance);
    result->summary.termination += text;
  }
}

// The load path's steps in the result: their iterations and time, and a step that did not
// converge, which leaves the path's end not the equilibrium the incremental form defines.
void NoteLoadPath(const LoadPathSummary& path, RunResult* result) {
  result->summary.iterations += path.iterations;
  result->summary.wall_time_s += path.wall_time_s;
  result->summary.termination += "; the last of " + std::to_string(path.total) +
                                 " load steps of the incremental friction, after " +
                                 std::to_string(path.iterations) + " iterations in " +
                                 std::to_string(path.steps) + " before it";
  if (path.unconverged_step > 0 && result->converged) {
    result->converged = false;
    result->summary.termination +=
        "; but load step " + std::to_string(path.unconverged_step) + " did not converge";
  }
}

}  // namespace

RunResult RunSolve(const Scene& scene, Model& model, const std::string& method,
                   const std::function<bool(const IterationRecord&)>& on_iteration) {
  const SolverInfo* info = FindSolver(method);
  if (!info) throw InputError(scene.solver.where, "unknown solver '" + method + "'");
  const LoadPathSummary path = RunLoadPath(scene, model, method, on_iteration);
  const std::vector<double>* reference = path.steps > 0 ? &path.reference : nullptr;
  const SolverSummary continuation =
      RunFrictionContinuation(scene, model, method, on_iteration, reference);
  RunResult result;
  int iterations = 0;
  double wall_time_s = 0.0;
  const FrictionPasses passes = SettleObstacleFriction(scene, model, reference, [&](Model& pass) {
    result = RunSolveOnce(scene, pass, *info, method, on_iteration);
    iterations += result.summary.iterations;
    wall_time_s += result.summary.wall_time_s;
    // A solve that did not converge (friction too weak to hold the fabric: it slid away) is
    // not made better by taking its pushes again.
    return result.converged && !InterruptRequested();
  });
  result.summary.iterations = iterations;
  result.summary.wall_time_s = wall_time_s;
  NoteFrictionPasses(scene, passes, &result);
  if (continuation.iterations > 0) {
    result.summary.iterations += continuation.iterations;
    result.summary.wall_time_s += continuation.wall_time_s;
    result.summary.termination += "; after " + std::to_string(continuation.iterations) +
                                  " iterations of continuation in the friction's smoothing";
  }
  if (path.steps > 0) NoteLoadPath(path, &result);
  return result;
}

SolverSummary SolveWithSceneOptions(
    const Scene& scene, Model& model, const std::string& method,
    const std::function<bool(const IterationRecord&)>& on_iteration) {
  const SolverInfo* info = FindSolver(method);
  if (!info) throw InputError(scene.solver.where, "unknown solver '" + method + "'");
  SolverOptions options = OptionsFor(scene, method);
  options.on_iteration = [&](const IterationRecord& record) {
    return !on_iteration || on_iteration(record);
  };
  UpdateSelfContact(&model, model.positions.data());
  std::unique_ptr<HessianWorkspace> workspace;
  if (model.num_free_dofs() > 0 && info->uses_hessian_workspace) {
    workspace = std::make_unique<HessianWorkspace>(model);
  }
  options.workspace = workspace.get();
  return info->make()->Solve(model, options);
}

// newton's max_expansions where the fabric has a bending friction: none. Doubling an accepted
// full step (newton's default, 4 doublings: src/solvers/solver_newton.cc says why) carries control
// volumes far past the kink of √(κ² + δ²), where Newton's quadratic model no longer holds; the
// next step's gain ratio is then negative, μ grows and the steps shrink: stage δ = 1 1/m of the
// friction cotton at 3.8 mm alternated accepted 16-fold steps with negative gains for 1,452
// iterations, with μ about 1e-4 where the elastic solve's falls to 1e-9. Measured in session 36
// (newton iterations in all, one level, with 0 against 4 doublings):
// - the friction cotton of docs/benchmarks.md at 3, 3.5, 3.8, 4, 4.2, 4.5, 5 mm: 181, 634, 894,
//   212, 213, 150, 138 against 299, 359, 1,518, 299, 267, 200, 166 (2,422 against 3,108), the
//   same drape coefficients to 0.001 and 4 folds each;
// - the limp fabric with H = 2e-4 N at 5 and 6 mm: 346, 518 against 768, 324 (the paths reach
//   other minima: DC 0.345, 0.374 against 0.358, 0.394, energies 1 % above and 3 % below);
// - one doubling: 2,159 and 747 on the same cases.
// Lower on 7 of the 9, a median ratio of 0.75. The shear friction keeps the doublings: the cotton
// with HG = 0.49 N/m at 5 mm took 395 iterations against 390, to another minimum (DC 0.747, 10
// folds, against 0.723, 8, energy 4 % above), and the simple shear of
// tests/fv_shear_friction_test.cc with HG above the load stopped short of its tolerance (no step
// lowered the energy). A scene's own solver.newton.max_expansions stands.
constexpr double kFrictionMaxExpansions = 0;

std::map<std::string, double> SolveMethodOptions(const Scene& scene, const std::string& method) {
  std::map<std::string, double> options;
  if (auto it = scene.solver.method_options.find(method); it != scene.solver.method_options.end()) {
    options = it->second;
  }
  if (method == "newton" && HasBendingFriction(scene)) {
    options.emplace("max_expansions", kFrictionMaxExpansions);
  }
  return options;
}

bool HasFriction(const Scene& scene) {
  return HasBendingFriction(scene) || HasFriction(scene, {&FiniteVolumeSpec::shear_friction});
}

FrictionPasses SettleObstacleFriction(const Scene& scene, Model& model,
                                      const std::vector<double>* friction_reference,
                                      const std::function<bool(Model&)>& solve) {
  FrictionPasses passes;
  for (;;) {
    const bool go_on = solve(model);
    ++passes.passes;
    if (!HasObstacleFriction(scene.obstacles) || !AllFinite(model.positions)) return passes;
    passes.push_change = FrictionPushChange(model, model.positions.data());
    passes.settled = passes.push_change <= kFrictionPushTolerance;
    if (passes.settled || !go_on || passes.passes >= kMaxFrictionPasses) return passes;
    const std::vector<double> pushed_at = model.positions;
    Model next = BuildModel(scene, friction_reference, &pushed_at);
    next.positions = pushed_at;
    model = std::move(next);
  }
}

SolverSummary RunFrictionContinuation(
    const Scene& scene, Model& model, const std::string& method,
    const std::function<bool(const IterationRecord&)>& on_iteration,
    const std::vector<double>* reference) {
  SolverSummary total;
  bool solved = reference != nullptr;  // a state was solved before this stage
  for (const Smoothings& smoothings : ContinuationStages(scene)) {
    Scene stage = scene;
    stage.material.finite_volume.bending_friction_smoothing = smoothings.bending;
    stage.material.finite_volume.shear_friction_smoothing = smoothings.shear;
    // The obstacles' friction's pushes: those of the last state solved (a load step's, or a
    // stage's), or at the flat start the fabric's own weight's (AddObstacleFrictionTerms).
    Model stage_model = BuildModel(stage, reference, solved ? &model.positions : nullptr);
    solved = true;
    assert(stage_model.positions.size() == model.positions.size());
    stage_model.positions = model.positions;
    const SolverSummary summary = SolveWithSceneOptions(stage, stage_model, method, on_iteration);
    total.iterations += summary.iterations;
    total.wall_time_s += summary.wall_time_s;
    if (!AllFinite(stage_model.positions)) break;  // the scene's own solve starts from the last
    model.positions = stage_model.positions;
  }
  return total;
}

}  // namespace drape
