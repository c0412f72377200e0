// Repeated drops of a drape test (`drape solve SCENE --drops N`, or `drape_test.drops`): N solves
// of the scene's drape test that differ as real drops of one fabric differ, and the figures a lab
// reports over them (BS 5058 and ISO 9073-9 test several specimens; Jeong & Phillips 1998 report
// the drape coefficient of the most frequent fold count).
//
// What varies from drop to drop, drawn from a generator seeded by (drape_test.seed, drop number)
// alone, so that the same seeds give the same drops on any number of threads or ranks:
// - the placement of the specimen on the disc: the disc's centre moves from drape_test.offset by
//   a point drawn uniformly from a disc of radius drape_test.placement (a lab centres a specimen
//   to a millimetre or two; rotating the fabric on the axisymmetric tester is the same as turning
//   this displacement about the disc's centre);
// - an initial out-of-plane waviness of the overhang: the free nodes beyond the disc's rim start
//   at z + w g(θ) s², where s goes from 0 at the rim to 1 at the specimen's edge, g is a random
//   sum of the angular modes 1 … 12 (normal coefficients) scaled to max |g| = 1, and w is
//   drape_test.waviness (a laid specimen is never flat; the waviness picks among the fold
//   patterns the fabric can settle in, as a real drop does).
// Each drop is solved on the scene's own mesh alone (one level: the spread over drops is what is
// measured) into OUT/drops/NN/ with the files and certificate of a single solve; OUT/drops.csv
// has a row per drop, OUT/summary.json the statistics, OUT/report.html the pictures
// (src/sweep/drops_report.h).
#ifndef DRAPE_SRC_SWEEP_DROPS_H_
#define DRAPE_SRC_SWEEP_DROPS_H_

#include <Eigen/Core>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "src/analysis/mesh_rule.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

struct DropsOptions {
  int drops = 1;
  int threads = 0;           // local worker threads without MPI (0: the machine's cores)
  std::string directory;     // OUT
  std::string command_line;  // as run, for each drop's summary.json and OUT/summary.json
  std::vector<std::string> overrides;
  std::string calibration;  // the calibration applied, for the provenance ("" for none)
};

// One drop: its perturbation and its result (a row of drops.csv).
struct DropRecord {
  int drop = 0;                                      // 1-based
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // m: the disc's centre for this drop
  double waviness = 0.0;                             // m: the initial waviness's amplitude
  double drape_coefficient = 0.0;
  int folds = 0;
  double energy = 0.0;   // J
  std::string state;     // as a single solve says it ("stable minimum", ...), or why it failed
  bool counted = false;  // converged to a stable minimum, nothing through the disc
};

// A drop's shadow outline, for the report: r(θ_k) around `centre`, θ_k = 2π k / radius.size().
struct DropOutline {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // m
  std::vector<double> radius;                        // m
};

// The figures over the counted drops.
struct DropStatistics {
  int drops = 0;    // all drops
  int counted = 0;  // those the figures are over
  double mean = 0.0;
  double standard_deviation = 0.0;  // sample (n − 1); 0 for a single drop
  std::map<int, int> folds_histogram;
  std::vector<int> modal_folds;  // the most frequent fold count(s) (ties: all of them)
  int modal_drops = 0;           // drops with a most frequent count
  double modal_mean = 0.0;       // mean drape coefficient of those drops
};

struct DropsSummary {
  std::vector<DropRecord> drops;      // in drop order (coordinator only)
  std::vector<DropOutline> outlines;  // the same order; empty for a drop that failed
  DropStatistics statistics;
  // The mesh rule's advice for the drops' mesh (src/analysis/mesh_rule.h): each drop's drape
  // coefficient carries its discretisation error, which the spread over drops does not show.
  std::optional<MeshAdvice> mesh_advice;
  bool coordinator = true;  // false on the MPI ranks that only worked
  int workers = 1;
};

// The scene of drop `drop` (1-based): the drape test moved by its placement, expanded again,
// solved on one level. `scene.drape_test` must be set.
Scene DropScene(const Scene& scene, int drop, Eigen::Vector2d* offset = nullptr);

// A drop's folder, relative to OUT: drops/07 (2 digits below 100 drops, then 3, then 4).
std::string DropFolderName(int drop, int drops);

// Adds drop `drop`'s initial waviness to the model's free nodes beyond the disc's rim.
void AddDropWaviness(const Scene& drop_scene, int drop, Model* model);

DropStatistics ComputeDropStatistics(const std::vector<DropRecord>& drops);

// drops.csv: its header, a record as a row, and a row read back.
std::string DropsCsvHeader();
std::string DropCsvRow(const DropRecord& record);
DropRecord ParseDropCsvRow(const std::string& row);

// Solves the drops on the task farm (src/parallel/task_farm.h) and writes OUT. One line per
// finished drop on `log`. Throws std::runtime_error if OUT cannot be written (before any solve).
DropsSummary RunDrops(const Scene& scene, const DropsOptions& options, std::ostream& log);

// The stdout summary: "4 drops: drape coefficient 0.652 ± 0.021 (mean ± standard deviation), …",
// with the mesh rule's discretisation error where `mesh_advice` is given: "…, discretisation
// error about 0.16 (mesh rule for a 1.9 cm bending length); folds …".
std::string DropsLine(const DropStatistics& statistics,
                      const std::optional<MeshAdvice>& mesh_advice = std::nullopt);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_DROPS_H_
