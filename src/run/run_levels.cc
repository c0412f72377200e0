#include "src/run/run_levels.h"

#include <algorithm>
#include <cassert>
#include <utility>
#include <vector>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/mesh_rule.h"

namespace drape {

RunResult RunLevels(const Scene& scene, Model& model, const std::string& method,
                    const std::function<bool(const IterationRecord&)>& on_iteration,
                    LevelsReport* report, LevelStart start) {
  const int count = std::max(1, scene.solver.levels);
  assert(count > 1 && "RunLevels solves two levels at least");
  std::vector<Scene> scenes;  // coarsest first; every level checked before any solve
  for (int level = count - 1; level >= 0; --level)
    scenes.push_back(CoarsenedScene(scene, 1 << level));
  report->levels.clear();
  Model previous;
  RunResult result;
  for (int k = 0; k < count; ++k) {
    const bool finest = k + 1 == count;
    Model coarse;
    if (!finest) coarse = BuildModel(scenes[k]);
    Model& current = finest ? model : coarse;
    // The coarser answer starts this level unless it passed through a disk or through itself.
    const bool interpolated =
        start == LevelStart::kFromCoarser && k > 0 && !report->levels.back().PassesThrough();
    LevelRecord record;
    record.started_flat = k > 0 && !interpolated;
    if (interpolated) ProlongPositions(scenes[k - 1], previous, scenes[k], &current);
    result = RunSolve(scenes[k], current, method, on_iteration);
    if (interpolated && result.PassesThrough()) {
      // The interpolated start led the fabric through a support disk or through itself: solve
      // from the flat start.
      record.restarted_flat = true;
      record.iterations = result.summary.iterations;
      record.wall_time_s = result.summary.wall_time_s;
      std::copy(current.initial.begin(), current.initial.end(), current.positions.begin());
      result = RunSolve(scenes[k], current, method, on_iteration);
    }
    record.spacing = LevelSpacing(scenes[k].mesh);
    record.nodes = current.num_nodes;
    record.iterations += result.summary.iterations;
    record.wall_time_s += result.summary.wall_time_s;
    record.energy = result.certificate.energy;
    record.converged = result.converged;
    record.stable = result.stability.computed && result.stability.stable;
    record.edges_through_disk = result.contact.edges_through_disk;
    record.edges_through_body = result.contact.edges_through_body;
    record.self_crossings = result.self_intersections.crossings;
    if (HasDrapeCoefficient(scenes[k], current)) {
      const DrapeAnalysis drape = AnalyseDrape(scenes[k], current);
      if (drape.disc_radius > 0.0) record.drape_coefficient = drape.coefficient.cusick;
      record.folds = drape.folds.count;
    }
    report->levels.push_back(record);
    if (!finest) previous = std::move(coarse);
  }
  const std::optional<MeshAdvice> advice = AdviseMesh(scene, model);
  AnalyseLevels(report, advice ? std::optional<double>(advice->bending_length) : std::nullopt);
  if (advice && report->drape_error) WidenToMeshRule(*advice, &*report->drape_error);
  return result;
}

}  // namespace drape
