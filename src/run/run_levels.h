// The driver of `solver.levels: N`: the scene solved on N nested lattices, coarse to fine
// (src/analysis/levels.h coarsens the scene, interpolates an answer onto the finer lattice and
// extrapolates the levels' figures to h → 0).
#ifndef DRAPE_SRC_RUN_RUN_LEVELS_H_
#define DRAPE_SRC_RUN_RUN_LEVELS_H_

#include <functional>
#include <string>

#include "src/analysis/levels.h"
#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene.h"

namespace drape {

// How each level after the coarsest starts: from the coarser level's answer interpolated (grid
// sequencing; the finer level need not keep the coarse level's folds: docs/benchmarks.md, "Starts
// near the answer"), or from the flat start, like a solve on that mesh alone (the finest level's
// answer is the plain solve's, bit for bit; the coarser levels only measure how the answer
// changes with the spacing).
enum class LevelStart { kFromCoarser, kFlat };

// Solves scene.solver.levels levels; the finest is `model` (built from `scene`), whose RunResult
// is returned. `report` gets the per-level figures, the extrapolations (refused where a level is
// coarser than the fabric's bending length: AnalyseLevels) and the error bar,
// widened to the mesh rule's expected error where that is larger (WidenToMeshRule).
RunResult RunLevels(const Scene& scene, Model& model, const std::string& method,
                    const std::function<bool(const IterationRecord&)>& on_iteration,
                    LevelsReport* report, LevelStart start = LevelStart::kFromCoarser);

}  // namespace drape

#endif  // DRAPE_SRC_RUN_RUN_LEVELS_H_
