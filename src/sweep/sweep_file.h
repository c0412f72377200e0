// The sweep file of `drape sweep` (docs/reference.md, "Sweeps"): a base scene and the variations of
// its keys — a full grid, zipped lists, or a Latin-hypercube / Sobol sample of ranges — repeated
// `repeat` times, optionally warm-started along one axis, with the outputs each task keeps. Every
// error is located (file:line:column: key.path: what), and every task's scene is loaded and
// validated before anything is solved.
#ifndef DRAPE_SRC_SWEEP_SWEEP_FILE_H_
#define DRAPE_SRC_SWEEP_SWEEP_FILE_H_

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <vector>

#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"

namespace drape {

// One varied scene key, as `--set` names it.
struct SweepKey {
  std::string key;  // e.g. material.finite_volume.kes.W
  Location where;   // where the sweep file names it
  int axis = 0;     // the axis it belongs to (a zip's keys share one axis)
};

// One value of a key in one task: as YAML (what the scene is given), as YAML text (what the task's
// identity and messages show) and, if it is a number, the number.
struct SweepValue {
  YAML::Node node;
  std::string text;
  bool numeric = false;
  double number = 0.0;
  Location where;  // the value in the sweep file (a sample's: its range)
};

// One task: a value for every key, and which repeat it is.
struct SweepTask {
  std::vector<SweepValue> values;  // in the order of SweepSpec::keys
  std::vector<int> axis_index;     // per axis: the value's position along it (grid and zip)
  int repeat = 0;                  // 0 .. repeat-1
  int chain = 0;                   // its chain (SweepSpec::chains)
  int warm_from = -1;              // the task before it in its chain (warm starts only), or -1
};

struct SweepSpec {
  std::string file;        // the sweep file
  std::string scene_file;  // the base scene, resolved against the sweep file's folder
  // The base scene, read and parsed once by LoadSweepFile: every task's scene is loaded from it.
  std::shared_ptr<const SceneDocument> scene;
  Location scene_where;
  std::string design;                // grid, zip, grid+zip, latin-hypercube or sobol
  std::vector<SweepKey> keys;        // in the order written (grid keys, then zip keys)
  std::vector<int> axis_sizes;       // grid and zip designs: values per axis (a zip is one axis)
  std::vector<SweepKey> fixed_keys;  // `set:` keys, the same in every task
  std::vector<SweepValue> fixed_values;
  int repeat = 1;
  int warm_axis = -1;  // the axis warm starts follow, -1 for cold starts
  std::string warm_key;
  std::vector<std::string> keep;         // summary, shape, pictures, history, profile
  std::vector<SweepTask> tasks;          // task k is tasks[k]
  std::vector<std::vector<int>> chains;  // task numbers, each chain in solving order
  std::string output_directory;          // default out/<sweep file's stem> beside the file
};

// The largest number of tasks a sweep file may ask for.
constexpr int kMaxSweepTasks = 100000;

// Reads the sweep file at `path` and checks every task's scene (LoadScene with the task's
// overrides). Throws InputError, located in the sweep file (a task's bad key or value: at the
// value that gave it, saying which task), before anything is solved.
SweepSpec LoadSweepFile(const std::string& path);

// The values task `task` sets on the base scene: its values, then the `set:` values, then
// output.write from `keep`; TaskOverrides is the same as `--set` text (the task's identity).
std::vector<SceneValue> TaskValues(const SweepSpec& spec, int task);
std::vector<std::string> TaskOverrides(const SweepSpec& spec, int task);

// Task `task`'s scene, loaded from the base scene read once.
Scene TaskScene(const SweepSpec& spec, int task);

// The names `keep` accepts: summary, shape, pictures, history, profile.
const std::vector<std::string>& SweepKeepKinds();

// The output.write kinds that `keep` stands for (each a row of src/scene/output_kinds.h).
std::vector<std::string> OutputKindsOf(const std::vector<std::string>& keep);

// The chain (index into spec.chains) holding task `task`, and the task before it in its chain
// (-1 if it starts its chain or the sweep has no warm starts).
int ChainOf(const SweepSpec& spec, int task);
int WarmStartSource(const SweepSpec& spec, int task);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_SWEEP_FILE_H_
