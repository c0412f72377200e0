// `drape compare`: every selected solver on every scene, measured against a reference solve of the
// same scene (newton to a relative residual of 1e-12), with the time each needs to reach a given
// accuracy. The measures are here; the report (tables, CSV, plots, HTML) is in compare_report.h.
#ifndef DRAPE_SRC_COMPARE_COMPARE_H_
#define DRAPE_SRC_COMPARE_COMPARE_H_

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "src/model/model.h"

namespace drape {

struct CompareOptions {
  std::vector<std::string> scenes;   // scene files
  std::vector<std::string> solvers;  // empty or {"all"}: every registered method
  std::string out_dir = "compare";
  int repeat = 1;                      // timed repeats of each run; the table shows the median
  double time_limit = 60.0;            // s per run (the scene's own limit if lower)
  std::vector<std::string> overrides;  // --set key.path=value, applied to every scene
  double reference_tolerance = 1e-12;  // relative residual asked of the reference newton solve
  bool plots = true;                   // run gnuplot (the report is written without it too)
  std::string
      tools_dir;  // where compare_*.gp live; empty: $DRAPE_TOOLS_DIR, else the embedded copies
  std::string command_line;  // the command as run (compare.json, report.md, report.html)
};

// Distance of every node from the reference positions (3 doubles per node).
struct PositionError {
  double max_m = 0.0;  // largest node distance, m
  double rms_m = 0.0;  // root mean square node distance, m
};
PositionError MeasurePositionError(const std::vector<double>& positions,
                                   const std::vector<double>& reference);

// One point of a convergence curve, measured in the iteration callback.
struct CurvePoint {
  int iteration = 0;
  double time_s = 0.0;  // solver clock minus the time spent in the callback
  double relative_residual = 0.0;
  double energy_gap = 0.0;  // E - E_ref, J
  PositionError error;
};

// kPassesThrough: the final state has fabric through a support disk, a mesh obstacle or itself
// (RunResult::PassesThrough): no drape, converged or not, whatever its Hessian says.
enum class RunStatus {
  kConverged,
  kNotConverged,
  kFailed,
  kRefused,
  kDifferentEquilibrium,
  kPassesThrough
};
const char* RunStatusName(RunStatus status);

struct RunRecord {
  std::string scene;
  std::string solver;
  RunStatus status = RunStatus::kFailed;
  std::string reason;  // the solver's termination, the refusal or the exception text
  int iterations = 0;
  std::vector<double> times_s;  // corrected wall time of each repeat
  double time_s = 0.0;          // median of times_s
  double callback_time_s = 0.0;
  double relative_residual = 0.0;
  double max_node_force = 0.0;  // N
  double energy = 0.0;          // J
  double energy_gap = 0.0;      // E - E_ref, J
  PositionError error;          // final positions against the reference
  // DC − DC_ref (Cusick's with a disk obstacle, else A_shadow/A_flat); NaN where the scene has
  // none.
  double drape_coefficient_gap = std::nan("");
  double size = 1.0;  // model.size, m (for relative distances)
  bool stability_computed = false;
  bool stable = false;
  double peak_memory_mb = 0.0;  // peak resident memory during the run above the start, MB
  std::vector<CurvePoint> curve;
  // False when the solver did not expose its iterates in model.positions during the callbacks:
  // the curve's position errors are NaN then (its residuals and energies are still measured).
  bool curve_positions_valid = true;
  std::vector<double> positions;  // final positions (3 per node)
};

struct SceneReference {
  std::string method;          // "newton" or the solver of the best converged fallback run
  double tolerance = 0;        // relative residual asked of it
  double scene_tolerance = 0;  // the scene's own tolerance, which the reference must reach
  bool converged = false;
  std::string termination;
  int iterations = 0;
  double time_s = 0.0;
  double energy = 0.0;             // J
  double relative_residual = 0.0;  // recomputed certificate
  double max_node_force = 0.0;     // N
  bool stable = false;
  bool stability_computed = false;
  double energy_tolerance = 0.0;  // |E - E_ref| beyond which a converged run is another equilibrium
  double drape_coefficient = std::nan("");  // NaN where the scene has none
  std::vector<double> positions;
};

struct SceneComparison {
  std::string name;
  std::string file;
  std::string error;  // non-empty when the scene could not be loaded or built
  int num_nodes = 0;
  int free_dofs = 0;
  double size = 1.0;
  SceneReference reference;
  std::vector<RunRecord> runs;
};

// The relative position errors (RMS distance / size) the speed table reports.
const std::vector<double>& AccuracyLevels();
// First corrected time at which the run's RMS distance / size is at most `level`; -1 if never,
// kTimeUnknown when the run's curve has no position errors.
constexpr double kTimeUnknown = -2.0;
double TimeToReach(const RunRecord& run, double level);

// Runs the reference and every solver on one scene. Never throws for a failing solver: each
// failure is recorded with its reason. `log` gets one line per run.
SceneComparison CompareScene(const std::string& scene_file, const CompareOptions& options,
                             std::ostream& log);

// The command: compares every scene, writes the report into options.out_dir, returns the exit
// code (0 when the report was written, 2 for bad usage such as an unknown solver name). Progress
// and diagnostics go to `log`; the result line ("report: DIR/report.md") to `result` (`log` when
// null).
int RunCompare(const CompareOptions& options, std::ostream& log, std::ostream* result = nullptr);

}  // namespace drape

#endif  // DRAPE_SRC_COMPARE_COMPARE_H_
