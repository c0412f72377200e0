// `drape sweep`: every task of a sweep file (src/sweep/sweep_file.h) solved into its own folder
// OUT/tasks/NNNN/ by the code of `drape solve` (its result files and provenance, src/output/), one
// row each in OUT/sweep.csv. The tasks — whole warm-start chains, when the sweep has them — are
// run through the task farm (src/parallel/task_farm.h), so the same sweep spreads over MPI ranks
// or local threads; what each task computes depends only on the sweep file. A task's folder keeps
// its variant (variant.txt) and its row (row.csv): a rerun skips the tasks whose folder holds a
// row for the same variant, and sweep.csv is rewritten from the finished folders after every task.
#ifndef DRAPE_SRC_SWEEP_SWEEP_H_
#define DRAPE_SRC_SWEEP_SWEEP_H_

#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "src/analysis/mesh_rule.h"
#include "src/sweep/sweep_file.h"

namespace drape {

struct SweepOptions {
  std::string out;           // the output folder; empty: the sweep file's (spec.output_directory)
  std::optional<int> only;   // run this task alone (with the earlier tasks of its warm-start chain
                             // that are not finished yet)
  int threads = 0;           // local worker threads without MPI (0: the machine's cores)
  bool plots = true;         // sweep.html (its charts inline SVG)
  std::string command_line;  // the command as run (each task's summary.json)
};

struct SweepSummary {
  std::string directory;
  int tasks = 0;      // tasks in the sweep
  int solved = 0;     // solved by this run (all ranks)
  int skipped = 0;    // finished before, kept (restart)
  int rows = 0;       // rows in sweep.csv
  int converged = 0;  // rows that converged
  std::set<int> converged_tasks;
  bool interrupted = false;
  bool coordinator = true;  // false on the MPI ranks that only worked
  int workers = 1;
};

// The columns of sweep.csv and row.csv for `spec`.
std::vector<std::string> SweepColumns(const SweepSpec& spec);

// The folder of task `task` inside `directory`: tasks/0007.
std::string TaskFolder(const std::string& directory, const SweepSpec& spec, int task);

// What makes a task's result: its scene (file and content), its overrides and its warm start (the
// identity of the task it starts from). A finished folder whose variant.txt differs is stale.
// One per task, in task order.
std::vector<std::string> TaskIdentities(const SweepSpec& spec);

// Runs the sweep; progress (one line per finished task) on `log`. Throws std::runtime_error if
// the output folder cannot be written (before any solve). Tasks never throw: a failed task is a
// row saying so.
SweepSummary RunSweep(const SweepSpec& spec, const SweepOptions& options, std::ostream& log);

// The mesh rule's warning over several scenes (a sweep's tasks, a table's fabrics), labelled
// `labels` (their numbers or names) and called `what` ("task", "fabric"): "2 of 7 fabrics on a mesh
// coarser than their fabric's mesh rule (fabrics M1, M2; each row's ERROR_COLUMN includes the
// rule's error); the furthest off, fabric M2: <drape solve's warning>", or nothing when none is
// coarse. A scene without advice (none, or it could not be loaded) counts as not coarse.
std::optional<std::string> CoarseMeshesLine(const std::vector<std::string>& labels,
                                            const std::vector<std::optional<MeshAdvice>>& advice,
                                            const std::string& what,
                                            const std::string& error_column);

// FNV-1a, 64 bits, as 16 hex digits: the fingerprint of a base scene's text in the identities of
// a sweep's or a fabric table's tasks.
std::string Fingerprint(const std::string& bytes);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_SWEEP_H_
