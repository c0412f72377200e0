// A solve and what drape concludes from it, each computed once, for every command that reports
// it (drape solve's files and stdout line, drape compare): the solver's result with its
// certificate, stability and contact report (src/run/run.h), the drape analysis of a scene
// with a drape coefficient, and the per-level figures of a `solver.levels` run.
#ifndef DRAPE_SRC_RUN_SOLVE_REPORT_H_
#define DRAPE_SRC_RUN_SOLVE_REPORT_H_

#include <functional>
#include <optional>
#include <string>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/mesh_rule.h"
#include "src/model/model.h"
#include "src/run/run.h"
#include "src/run/run_levels.h"
#include "src/scene/scene.h"

namespace drape {

struct SolveReport {
  RunResult result;
  std::optional<DrapeAnalysis> drape;  // when HasDrapeCoefficient(scene, model)
  std::optional<LevelsReport> levels;  // when solved on more than one level
  // The mesh rule of a drape test on a lattice (AdviseMesh, src/analysis/mesh_rule.h).
  std::optional<MeshAdvice> mesh_advice;
};

// How many nested lattices a solve takes: solver.levels where given; where not, 2 for a drape test
// (a scene with a drape coefficient and a support disc) whose mesh can be coarsened once to a
// lattice with 4 spacings across the disc's radius at least (2 cm under the standard 18 cm disc),
// so that its drape coefficient comes with an error estimate (LevelsReport::drape_error), else 1.
// Levels not given start flat (LevelStart::kFlat): the answer is the plain solve's, the coarser
// level costs about a quarter of its time more.
int LevelsToSolve(const Scene& scene, const Model& model);

// Solves the scene with `method` (on LevelsToSolve nested lattices when that is > 1; with
// `automatic_levels` false, on as many as solver.levels gives, else one: a warm start, which
// levels would discard) and analyses the final state. `on_iteration` may be empty.
SolveReport SolveAndReport(const Scene& scene, Model& model, const std::string& method,
                           const std::function<bool(const IterationRecord&)>& on_iteration = {},
                           bool automatic_levels = true);

// The report of a state already solved (`result` from RunSolve at the model's positions): the
// drape analysis and the mesh rule added.
SolveReport ReportOf(const Scene& scene, const Model& model, RunResult result);

// The drape coefficient `drape compare` and the fit compare: Cusick's with a support disc, else
// A_shadow / A_flat; NaN for a scene without one.
double ReportedDrapeCoefficient(const SolveReport& report);

// The discretisation error of a drape test's drape coefficient, as the stdout line gives it: the
// levels' error bar (widened to the mesh rule's, src/analysis/mesh_rule.h) where the solve has
// one, else the mesh rule's expected error; none for a scene without a support disc or rule.
std::optional<double> ReportedDrapeCoefficientError(const SolveReport& report);

// What a drape test asked of its drape coefficient's error bar (drape_test.accuracy) and what the
// solve reached. The accuracy binds where the scene gives it or where it chose the lattice
// (drape_test.spacing_chosen): a run whose bar is wider then fails (exit 1). A scene that gives
// mesh.spacing and no accuracy chose its lattice itself: a wider bar is the coarse mesh's warning.
struct AccuracyOutcome {
  double asked = 0.0;    // drape_test.accuracy, else kDefaultDrapeAccuracy
  double reached = 0.0;  // ReportedDrapeCoefficientError
  bool binding = false;
  bool spacing_chosen = false;  // the loader chose mesh.spacing for `asked`
  double spacing = 0.0;         // m, the finest lattice's
  // Where the finest level stopped before equilibrium: the finest level that reached it, its
  // drape coefficient and that lattice's error bar (the mesh rule's), the best the run got.
  struct Level {
    double spacing = 0.0;
    double drape_coefficient = 0.0;
    double error = 0.0;
  };
  std::optional<Level> best_converged;
  bool met() const { return reached <= asked; }
  // Whether the run fails for it (exit 1, a DrapeWarning in Python): the accuracy binds and the
  // finest lattice stopped before equilibrium or its bar is wider than asked.
  bool Failed(bool converged) const { return binding && (!converged || !met()); }
};

// The outcome of a drape test on a lattice the mesh rule covers; none for any other scene.
std::optional<AccuracyOutcome> AccuracyOf(const Scene& scene, const SolveReport& report);

}  // namespace drape

#endif  // DRAPE_SRC_RUN_SOLVE_REPORT_H_
