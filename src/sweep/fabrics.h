// `drape fabrics FABRICS.csv`: a laboratory's table of fabrics (src/sweep/fabric_table.h), each
// solved on a base scene's drape test — the standard tester (30 cm specimen, 18 cm disc, 5 mm
// lattice) unless `--scene` gives another — with the row's material in place of the scene's, and
// the predicted drape coefficient set beside the measured one.
//
// Each fabric is one task (or, with N drops, N tasks: the drops of src/sweep/drops.h, whose mean
// is the fabric's prediction) on the task farm (src/parallel/task_farm.h): local threads, MPI
// ranks or, with --only, one task of a Slurm array. A task solves into OUT/fabrics/NNN-name/ (its
// drops into drops/NN/ below it) with the files of `drape solve`, and keeps there its identity
// (variant.txt: the base scene's text, its overrides, the drop) and its record (record.csv): a
// re-run solves only the tasks whose folder has no record for the same identity.
//
// OUT/fabrics.csv has a row per fabric (the inputs as given, the SI parameters used, the
// prediction with its error bar, the fold count, the drops' mean and SD, the measurement and the
// difference, the run's state); OUT/fabrics.json the statistics over the fabrics with a measured
// drape coefficient; OUT/report.html the measured-against-predicted chart, the table and each
// fabric's shadow (src/sweep/fabrics_report.h).
#ifndef DRAPE_SRC_SWEEP_FABRICS_H_
#define DRAPE_SRC_SWEEP_FABRICS_H_

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "src/scene/calibration.h"
#include "src/scene/scene.h"
#include "src/sweep/fabric_table.h"

namespace drape {

// The standard tester `drape fabrics` solves on without --scene: its YAML text.
const std::string& StandardTesterScene();

struct FabricsOptions {
  std::string table;                   // FABRICS.csv
  std::string scene;                   // --scene; empty: StandardTesterScene()
  std::vector<std::string> overrides;  // --set, on every fabric after its material
  std::optional<int> drops;            // --drops; else drape_test.drops of the base scene
  std::optional<int> only;             // --only / --task-id: this task alone
  int threads = 0;                     // local worker threads without MPI (0: the cores)
  std::string out;                     // empty: out/<table's stem>
  std::string command_line;
  // --calibration FILE: read by RunFabricsCommand into `calibration`, applied to every fabric
  std::string calibration_file;
  Calibration calibration;
  // --calibrate KEY...: fit these constants instead (src/sweep/calibrate.h)
  std::vector<std::string> calibrate;
  bool mesh_warning = true;  // the coarse-mesh warning (once per calibration, not per grid point)
};

// One fabric as the run sees it: its row, its scene (loaded, checked) and its tasks' overrides.
struct FabricCase {
  FabricRow row;
  Scene scene;                         // the row's scene, with --set applied
  std::vector<std::string> overrides;  // the row's, then --set, then the outputs it needs
  std::string folder;                  // relative to OUT: fabrics/003-M3
};

struct FabricsSpec {
  FabricTable table;
  std::string scene_label;  // the base scene's file, or "the standard tester"
  std::string scene_text;   // its YAML
  std::string directory;    // OUT
  Calibration calibration;  // applied to every fabric's scene
  int drops = 1;
  std::vector<FabricCase> fabrics;
  int tasks() const { return static_cast<int>(fabrics.size()) * drops; }
};

// Reads the table and the base scene and loads every fabric's scene. Throws InputError before
// anything is solved: the table's own errors, and a row's material that the loader refuses,
// located at the row's cell (FABRICS.csv:LINE:COLUMN: kes.W: must be positive, got -3).
FabricsSpec LoadFabrics(const FabricsOptions& options);

// One task's record: a drop of a fabric, or its single solve.
struct FabricTaskRecord {
  int fabric = 0;  // index into FabricsSpec::fabrics
  int drop = 0;    // 1-based; 0 for a single solve
  bool solved = false;
  bool counted = false;  // converged to a stable minimum, nothing through the disc
  double drape_coefficient = 0.0;
  double drape_coefficient_error = 0.0;  // the single solve's error bar, or the mesh rule's
  int folds = 0;
  int iterations = 0;
  double time_s = 0.0;
  std::string state;          // as a single solve says it, or why it failed
  std::string drape_version;  // the drape that solved it (a re-run may keep an older one's)
};

// The prediction for one fabric: its single solve, or its drops' mean.
struct FabricPrediction {
  int tasks = 0, counted = 0;
  std::optional<double> drape_coefficient;   // none if nothing was counted
  double error = 0.0;                        // the error bar
  std::optional<double> standard_deviation;  // over drops (2 or more counted)
  int folds = 0;                             // the single solve's, or the most frequent
  std::string state;
};

FabricPrediction PredictFabric(const std::vector<FabricTaskRecord>& records);

// The statistics over the fabrics with both a measured and a predicted drape coefficient:
// Δ = predicted − measured.
struct FabricStatistics {
  int compared = 0;
  double mean_abs_difference = 0.0, mean_difference = 0.0, rms_difference = 0.0;
  // |Δ| ≤ error bar + measured SD (0 where not given)
  int within = 0;
};

struct FabricComparison {
  double predicted = 0.0, error = 0.0, measured = 0.0, measured_sd = 0.0;
};
FabricStatistics ComputeFabricStatistics(const std::vector<FabricComparison>& comparisons);

struct FabricsSummary {
  std::string directory;
  int fabrics = 0, tasks = 0, solved = 0, skipped = 0;
  int predicted = 0;  // fabrics with a counted prediction
  FabricStatistics statistics;
  std::vector<FabricPrediction> predictions;  // per fabric (coordinator, whole runs)
  bool interrupted = false;
  bool coordinator = true;
};

// Solves what is missing and writes OUT (coordinator only). One line per finished task on `log`.
// Throws std::runtime_error if OUT cannot be written (before any solve).
FabricsSummary RunFabrics(const FabricsSpec& spec, const FabricsOptions& options,
                          std::ostream& log);

// "7 fabrics: 7 predicted; against 7 measured: mean |Δ| 0.084, mean Δ −0.052, RMS 0.101; 3 of 7
// within the error bars".
std::string FabricsLine(const FabricsSummary& summary);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_FABRICS_H_
