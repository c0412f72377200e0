#include "src/analysis/solve_report.h"

#include <cmath>
#include <utility>

namespace drape {

SolveReport ReportOf(const Scene& scene, const Model& model, RunResult result) {
  SolveReport report;
  report.result = std::move(result);
  if (HasDrapeCoefficient(scene, model)) report.drape = AnalyseDrape(scene, model);
  return report;
}

SolveReport SolveAndReport(const Scene& scene, Model& model, const std::string& method,
                           const std::function<bool(const IterationRecord&)>& on_iteration) {
  if (scene.solver.levels <= 1) {
    return ReportOf(scene, model, RunSolve(scene, model, method, on_iteration));
  }
  LevelsReport levels;
  SolveReport report =
      ReportOf(scene, model, RunLevels(scene, model, method, on_iteration, &levels));
  report.levels = std::move(levels);
  return report;
}

double ReportedDrapeCoefficient(const SolveReport& report) {
  if (!report.drape) return std::nan("");
  const DrapeCoefficient& dc = report.drape->coefficient;
  return report.drape->disc_radius > 0.0 ? dc.cusick : dc.ratio;
}

}  // namespace drape
