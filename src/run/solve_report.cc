#include "src/run/solve_report.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace drape {

SolveReport ReportOf(const Scene& scene, const Model& model, RunResult result) {
  SolveReport report;
  report.result = std::move(result);
  if (HasDrapeCoefficient(scene, model)) report.drape = AnalyseDrape(scene, model);
  report.mesh_advice = AdviseMesh(scene, model);
  return report;
}

int LevelsToSolve(const Scene& scene, const Model& model) {
  if (scene.solver.levels > 0) return scene.solver.levels;
  if (!HasDrapeCoefficient(scene, model) || !(DiscRadius(scene) > 0.0)) return 1;
  // The coarser level must resolve the disc: 4 of its spacings across the disc's radius at least
  // (a 10 cm level under a 5 cm scene took 2,000 iterations to no equilibrium).
  if (2.0 * LatticeSpacing(scene.mesh) > 0.25 * DiscRadius(scene)) return 1;
  try {
    BuildModel(CoarsenedScene(scene, 2));
  } catch (const InputError&) {
    // A scene levels cannot coarsen (per-node loads), or whose coarser lattice cannot be built (a
    // selection that takes no node of it): the scene's mesh alone, as asked.
    return 1;
  }
  return 2;
}

SolveReport SolveAndReport(const Scene& scene, Model& model, const std::string& method,
                           const std::function<bool(const IterationRecord&)>& on_iteration,
                           bool automatic_levels) {
  Scene solved = scene;
  solved.solver.levels =
      automatic_levels ? LevelsToSolve(scene, model) : std::max(1, scene.solver.levels);
  if (solved.solver.levels <= 1) {
    return ReportOf(scene, model, RunSolve(scene, model, method, on_iteration));
  }
  // Levels the scene did not ask for do not change its answer: each starts flat.
  const LevelStart start = scene.solver.levels > 0 ? LevelStart::kFromCoarser : LevelStart::kFlat;
  LevelsReport levels;
  SolveReport report =
      ReportOf(scene, model, RunLevels(solved, model, method, on_iteration, &levels, start));
  report.levels = std::move(levels);
  return report;
}

double ReportedDrapeCoefficient(const SolveReport& report) {
  if (!report.drape) return std::nan("");
  const DrapeCoefficient& dc = report.drape->coefficient;
  return report.drape->disc_radius > 0.0 ? dc.cusick : dc.ratio;
}

std::optional<double> ReportedDrapeCoefficientError(const SolveReport& report) {
  if (!report.drape || !(report.drape->disc_radius > 0.0)) return std::nullopt;
  if (report.levels && report.levels->drape_error) return report.levels->drape_error->error();
  if (report.mesh_advice) return report.mesh_advice->expected_error;
  return std::nullopt;
}

std::optional<AccuracyOutcome> AccuracyOf(const Scene& scene, const SolveReport& report) {
  const std::optional<double> reached = ReportedDrapeCoefficientError(report);
  if (!scene.drape_test || !report.mesh_advice || !reached) return std::nullopt;
  AccuracyOutcome outcome;
  outcome.asked = report.mesh_advice->accuracy;
  outcome.reached = *reached;
  outcome.spacing_chosen = report.mesh_advice->spacing_chosen;
  outcome.binding = outcome.spacing_chosen || scene.drape_test->accuracy.has_value();
  outcome.spacing = report.mesh_advice->spacing;
  if (!report.result.converged && report.levels) {
    for (const LevelRecord& level : report.levels->levels) {
      if (!level.converged || !level.drape_coefficient || level.PassesThrough()) continue;
      outcome.best_converged = AccuracyOutcome::Level{
          level.spacing, *level.drape_coefficient,
          ExpectedDrapeError(level.spacing, report.mesh_advice->bending_length,
                             report.mesh_advice->error_per_spacing)};
    }
  }
  return outcome;
}

}  // namespace drape
