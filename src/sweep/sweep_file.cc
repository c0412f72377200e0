#include "src/sweep/sweep_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "src/output/json.h"
#include "src/scene/file_paths.h"
#include "src/scene/scene_loader.h"
#include "src/scene/yaml_reader.h"
#include "src/sweep/sampling.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kTopKeys = {"scene",  "set",        "grid", "zip",   "sample",
                                           "repeat", "warm_start", "keep", "output"};
const std::vector<std::string> kSampleMethods = {"latin-hypercube", "sobol"};

// A value as one line of YAML (flow style): what `--set key=...` takes back.
SweepValue ValueOf(const YamlValue& value) {
  YAML::Emitter emitter;
  emitter.SetSeqFormat(YAML::Flow);
  emitter.SetMapFormat(YAML::Flow);
  emitter << value.get();
  SweepValue result;
  result.node = value.get();
  result.text = emitter.c_str();
  result.where = value.where;
  std::string ignored;
  if (value.get().IsScalar()) {
    if (const auto number = ParseNumber(value.get().Scalar(), &ignored)) {
      result.numeric = true;
      result.number = *number;
    }
  }
  return result;
}

SweepValue NumberValue(double number, const Location& where) {
  SweepValue value;
  value.node = YAML::Node(number);
  value.text = FormatNumber(number);
  value.numeric = true;
  value.number = number;
  value.where = where;
  return value;
}

// A key of grid, zip or ranges: a scene key path, not yet named.
SweepKey ReadKey(const YamlMap& map, const std::string& key, const std::vector<SweepKey>& known,
                 int axis) {
  const Location where = map.KeyLocation(key);
  if (key.find('=') != std::string::npos || key.find(' ') != std::string::npos) {
    throw InputError(where, "expected a scene key by path, such as material.density");
  }
  for (const SweepKey& other : known) {
    if (other.key == key)
      throw InputError(where,
                       "'" + key + "' is named twice (grid, zip, ranges and set share their keys)");
  }
  return SweepKey{key, where, axis};
}

// The values of one key: a non-empty list.
std::vector<SweepValue> ReadValues(const YamlValue& list) {
  const auto items = ReadList(list);
  if (!list.get().IsSequence() || items.empty()) {
    Fail(list, "expected a list of values, such as [2.0e-6, 4.0e-6]");
  }
  std::vector<SweepValue> values;
  values.reserve(items.size());
  for (const YamlValue& item : items) values.push_back(ValueOf(item));
  return values;
}

// The design being read: keys, and the values along each axis.
struct Design {
  std::vector<SweepKey> keys;
  std::vector<int> slots;                                  // per key: its place on its axis
  std::vector<std::vector<std::vector<SweepValue>>> axes;  // axis -> key on it -> values
};

void ReadGrid(const YamlValue& value, Design* design) {
  const YamlMap map(value);
  if (map.Keys().empty()) Fail(value, "expected a map of scene keys to lists of values");
  for (const std::string& key : map.Keys()) {
    const int axis = static_cast<int>(design->axes.size());
    design->keys.push_back(ReadKey(map, key, design->keys, axis));
    design->slots.push_back(0);
    design->axes.push_back({ReadValues(map.Get(key))});
  }
}

void ReadZip(const YamlValue& value, Design* design) {
  const YamlMap map(value);
  if (map.Keys().empty()) Fail(value, "expected a map of scene keys to lists of equal length");
  const int axis = static_cast<int>(design->axes.size());
  design->axes.emplace_back();
  for (const std::string& key : map.Keys()) {
    design->keys.push_back(ReadKey(map, key, design->keys, axis));
    design->slots.push_back(static_cast<int>(design->axes[axis].size()));
    auto values = ReadValues(map.Get(key));
    const auto& first = design->axes[axis];
    if (!first.empty() && values.size() != first.front().size()) {
      Fail(map.Get(key), "a zip's lists are taken together: this one has " +
                             std::to_string(values.size()) + " values, '" + map.Keys().front() +
                             "' has " + std::to_string(first.front().size()));
    }
    design->axes[axis].push_back(std::move(values));
  }
}

// The number of grid points, refused above kMaxSweepTasks (before anything is built).
long long CombinationCount(const Design& design, const YamlValue& where, int repeat) {
  long long count = repeat;
  for (const auto& axis : design.axes) {
    count *= static_cast<long long>(axis.front().size());
    if (count > kMaxSweepTasks) {
      Fail(where, "the sweep has more than " + std::to_string(kMaxSweepTasks) + " tasks");
    }
  }
  return count;
}

// Grid and zip: every combination of the axes' positions, the last axis fastest, each repeated.
void MakeGridTasks(const Design& design, SweepSpec* spec) {
  std::vector<int> index(design.axes.size(), 0);
  while (true) {
    SweepTask task;
    task.axis_index = index;
    for (size_t k = 0; k < design.keys.size(); ++k) {
      const int axis = design.keys[k].axis;
      task.values.push_back(design.axes[axis][design.slots[k]][index[axis]]);
    }
    for (int r = 0; r < spec->repeat; ++r) {
      task.repeat = r;
      spec->tasks.push_back(task);
    }
    int a = static_cast<int>(index.size()) - 1;
    while (a >= 0 && ++index[a] == static_cast<int>(design.axes[a].front().size())) index[a--] = 0;
    if (a < 0) return;
  }
}

struct Range {
  double min = 0.0, max = 1.0;
  bool log = false;
  Location where;
};

Range ReadRange(const YamlValue& value) {
  const YamlMap map(value, {"min", "max", "scale"});
  Range range;
  range.where = value.where;
  range.min = ReadNumber(map.Get("min"));
  range.max = ReadNumber(map.Get("max"));
  if (const auto scale = map.Find("scale"))
    range.log = ReadChoice(*scale, {"linear", "log"}) == "log";
  if (!(range.min < range.max)) Fail(map.Get("max"), "expected max > min");
  if (range.log && !(range.min > 0.0)) Fail(map.Get("min"), "a log scale needs min > 0");
  return range;
}

double Scaled(const Range& range, double u) {
  if (!range.log) return range.min + u * (range.max - range.min);
  return std::exp(std::log(range.min) + u * (std::log(range.max) - std::log(range.min)));
}

void ReadSample(const YamlValue& value, SweepSpec* spec) {
  const YamlMap map(value, {"method", "count", "seed", "ranges"});
  spec->design = ReadChoice(map.Get("method"), kSampleMethods);
  const YamlValue count_value = map.Get("count");
  const int count = ReadIntAtLeast(count_value, 1);
  if (count * static_cast<long long>(spec->repeat) > kMaxSweepTasks) {
    Fail(count_value, "the sweep has more than " + std::to_string(kMaxSweepTasks) + " tasks");
  }
  int seed = 0;
  if (const auto given = map.Find("seed")) seed = ReadIntAtLeast(*given, 0);
  const YamlValue ranges_value = map.Get("ranges");
  const YamlMap ranges(ranges_value);
  if (ranges.Keys().empty()) Fail(ranges_value, "expected a map of scene keys to {min, max}");
  std::vector<Range> ranges_read;
  for (const std::string& key : ranges.Keys()) {
    spec->keys.push_back(ReadKey(ranges, key, spec->keys, static_cast<int>(spec->keys.size())));
    ranges_read.push_back(ReadRange(ranges.Get(key)));
  }
  const int dimensions = static_cast<int>(ranges_read.size());
  if (spec->design == "sobol" && dimensions > kSobolMaxDimensions) {
    Fail(ranges_value, "the Sobol sequence is available for up to " +
                           std::to_string(kSobolMaxDimensions) + " keys");
  }
  const auto unit = spec->design == "sobol" ? SobolSequence(count, dimensions, seed)
                                            : LatinHypercube(count, dimensions, seed);
  for (const auto& point : unit) {
    SweepTask task;
    for (int d = 0; d < dimensions; ++d) {
      task.values.push_back(NumberValue(Scaled(ranges_read[d], point[d]), ranges_read[d].where));
    }
    for (int r = 0; r < spec->repeat; ++r) {
      task.repeat = r;
      spec->tasks.push_back(task);
    }
  }
}

void ReadWarmStart(const YamlValue& value, SweepSpec* spec) {
  if (value.get().IsScalar()) {
    ReadChoice(value, {"none"});
    return;
  }
  const YamlMap map(value, {"along"});
  const YamlValue along = map.Get("along");
  spec->warm_key = ReadString(along);
  if (spec->design == "latin-hypercube" || spec->design == "sobol") {
    Fail(along, "warm starts follow an axis of a grid or zip; a sample has none");
  }
  for (const SweepKey& key : spec->keys) {
    if (key.key == spec->warm_key) spec->warm_axis = key.axis;
  }
  if (spec->warm_axis < 0) {
    std::vector<std::string> names;
    for (const SweepKey& key : spec->keys) names.push_back(key.key);
    Fail(along,
         "'" + spec->warm_key + "' is not a varied key" + SuggestionText(spec->warm_key, names));
  }
}

void ReadKeep(const YamlValue& value, SweepSpec* spec) {
  spec->keep.clear();
  for (const YamlValue& item : ReadList(value)) {
    const std::string kind = ReadChoice(item, SweepKeepKinds());
    if (std::count(spec->keep.begin(), spec->keep.end(), kind)) {
      Fail(item, "'" + kind + "' is listed twice");
    }
    spec->keep.push_back(kind);
  }
}

// Tasks that differ only along the warm-start axis (same repeat), in the order of that axis; with
// no warm starts, one chain per task.
void MakeChains(SweepSpec* spec) {
  std::map<std::vector<int>, int> chain_of;
  for (int t = 0; t < static_cast<int>(spec->tasks.size()); ++t) {
    const SweepTask& task = spec->tasks[t];
    if (spec->warm_axis < 0) {
      spec->chains.push_back({t});
      continue;
    }
    std::vector<int> group = task.axis_index;
    group[spec->warm_axis] = -1;
    group.push_back(task.repeat);
    const auto found = chain_of.find(group);
    if (found == chain_of.end()) {
      chain_of[group] = static_cast<int>(spec->chains.size());
      spec->chains.push_back({t});
    } else {
      spec->chains[found->second].push_back(t);
    }
  }
  for (size_t c = 0; c < spec->chains.size(); ++c) {
    auto& chain = spec->chains[c];
    if (spec->warm_axis >= 0) {
      std::stable_sort(chain.begin(), chain.end(), [&](int a, int b) {
        return spec->tasks[a].axis_index[spec->warm_axis] <
               spec->tasks[b].axis_index[spec->warm_axis];
      });
    }
    for (size_t k = 0; k < chain.size(); ++k) {
      spec->tasks[chain[k]].chain = static_cast<int>(c);
      spec->tasks[chain[k]].warm_from = k == 0 ? -1 : chain[k - 1];
    }
  }
}

void ReadScene(const YamlMap& top, SweepSpec* spec) {
  const YamlValue scene = top.Get("scene");
  spec->scene_where = scene.where;
  const std::string given = ReadString(scene);
  if (given.empty()) Fail(scene, "expected the base scene's file name");
  spec->scene_file = ResolvePath(DirectoryOf(spec->file), given);
  std::error_code error;
  if (!fs::is_regular_file(spec->scene_file, error)) {
    Fail(scene, "cannot read the scene file " + spec->scene_file + ": " +
                    (fs::exists(spec->scene_file, error) ? "it is not a file" : "no such file"));
  }
}

void ReadDesign(const YamlMap& top, SweepSpec* spec) {
  const auto grid = top.Find("grid");
  const auto zip = top.Find("zip");
  const auto sample = top.Find("sample");
  if (sample && (grid || zip)) {
    throw InputError(top.KeyLocation("sample"),
                     "a sample replaces grid and zip: give one or the other");
  }
  if (sample) {
    ReadSample(*sample, spec);
    return;
  }
  if (!grid && !zip) {
    Fail(top.value(),
         "expected the variations: grid, zip (or both: the zip is one more axis of "
         "the grid) or sample");
  }
  Design design;
  if (grid) ReadGrid(*grid, &design);
  if (zip) ReadZip(*zip, &design);
  CombinationCount(design, grid ? *grid : *zip, spec->repeat);
  spec->design = grid && zip ? "grid+zip" : grid ? "grid" : "zip";
  spec->keys = design.keys;
  for (const auto& axis : design.axes) {
    spec->axis_sizes.push_back(static_cast<int>(axis.front().size()));
  }
  MakeGridTasks(design, spec);
}

// `set:` — scene keys given one value for every task.
void ReadFixed(const YamlValue& value, SweepSpec* spec) {
  const YamlMap map(value);
  for (const std::string& key : map.Keys()) {
    std::vector<SweepKey> known = spec->keys;
    known.insert(known.end(), spec->fixed_keys.begin(), spec->fixed_keys.end());
    spec->fixed_keys.push_back(ReadKey(map, key, known, -1));
    spec->fixed_values.push_back(ValueOf(map.Get(key)));
  }
}

void ReadTop(const YamlValue& root, SweepSpec* spec) {
  if (!root.get().IsMap()) Fail(root, "expected a sweep: scene, grid / zip / sample, ...");
  const YamlMap top(root, kTopKeys);
  ReadScene(top, spec);
  if (const auto repeat = top.Find("repeat")) spec->repeat = ReadIntAtLeast(*repeat, 1);
  ReadDesign(top, spec);
  if (const auto fixed = top.Find("set")) ReadFixed(*fixed, spec);
  if (const auto warm = top.Find("warm_start")) ReadWarmStart(*warm, spec);
  if (const auto keep = top.Find("keep")) ReadKeep(*keep, spec);
  spec->output_directory =
      DefaultResultFolder(DirectoryOf(spec->file), fs::path(spec->file).stem().string());
  if (const auto output = top.Find("output")) {
    const YamlMap map(*output, {"directory"});
    if (const auto folder = map.Find("directory")) {
      const std::string given = ReadString(*folder);
      if (given.empty()) Fail(*folder, "expected a folder, got nothing");
      spec->output_directory = ResolvePath(DirectoryOf(spec->file), given);
    }
  }
  MakeChains(spec);
}

std::string TaskText(const SweepSpec& spec, int task) {
  std::string text;
  for (size_t k = 0; k < spec.keys.size(); ++k) {
    text += (text.empty() ? "" : ", ") + spec.keys[k].key + "=" + spec.tasks[task].values[k].text;
  }
  return "task " + std::to_string(task) + " (" + text + ")";
}

// Loads task `task`'s scene; a bad key or value named by the sweep is located at the sweep file's
// value, anything else where the scene says, with the task named.
void CheckTask(const SweepSpec& spec, int task) {
  try {
    TaskScene(spec, task);
  } catch (const InputError& error) {
    const int index = error.where().line - 1;
    const std::string detail =
        (error.where().key.empty() ? "" : error.where().key + ": ") + error.problem();
    const int varied = static_cast<int>(spec.keys.size());
    if (error.where().file == "--set" && index >= 0 && index < varied) {
      throw InputError(spec.tasks[task].values[index].where,
                       TaskText(spec, task) + ", in " + spec.scene_file + ": " + detail);
    }
    if (error.where().file == "--set" && index >= varied &&
        index < varied + static_cast<int>(spec.fixed_keys.size())) {
      throw InputError(spec.fixed_values[index - varied].where,
                       "in " + spec.scene_file + ": " + detail);
    }
    if (error.where().line == 0)
      throw InputError(error.problem() + " (" + TaskText(spec, task) + ")");
    throw InputError(error.where(), error.problem() + " (" + TaskText(spec, task) + ")");
  }
}

}  // namespace

const std::vector<std::string>& SweepKeepKinds() {
  static const std::vector<std::string> kinds = {"summary", "shape", "pictures", "history",
                                                 "profile"};
  return kinds;
}

std::vector<std::string> OutputKindsOf(const std::vector<std::string>& keep) {
  std::vector<std::string> kinds;
  for (const std::string& kind : keep) {
    if (kind == "summary") kinds.push_back("summary");
    if (kind == "shape") kinds.insert(kinds.end(), {"nodes", "vtk", "obj", "gltf"});
    if (kind == "pictures") kinds.push_back("png");
    if (kind == "history") kinds.push_back("history");
    if (kind == "profile") kinds.push_back("profile");
  }
  return kinds;
}

std::vector<std::string> TaskOverrides(const SweepSpec& spec, int task) {
  std::vector<std::string> overrides;
  for (size_t k = 0; k < spec.keys.size(); ++k) {
    overrides.push_back(spec.keys[k].key + "=" + spec.tasks[task].values[k].text);
  }
  for (size_t k = 0; k < spec.fixed_keys.size(); ++k) {
    overrides.push_back(spec.fixed_keys[k].key + "=" + spec.fixed_values[k].text);
  }
  std::string write;
  for (const std::string& kind : OutputKindsOf(spec.keep))
    write += (write.empty() ? "" : ",") + kind;
  overrides.push_back("output.write=[" + write + "]");
  return overrides;
}

std::vector<SceneValue> TaskValues(const SweepSpec& spec, int task) {
  std::vector<SceneValue> values;
  for (size_t k = 0; k < spec.keys.size(); ++k) {
    values.push_back({spec.keys[k].key, spec.tasks[task].values[k].node});
  }
  for (size_t k = 0; k < spec.fixed_keys.size(); ++k) {
    values.push_back({spec.fixed_keys[k].key, spec.fixed_values[k].node});
  }
  YAML::Node write(YAML::NodeType::Sequence);
  for (const std::string& kind : OutputKindsOf(spec.keep)) write.push_back(kind);
  values.push_back({"output.write", write});
  return values;
}

Scene TaskScene(const SweepSpec& spec, int task) {
  assert(spec.scene && "LoadSweepFile reads the base scene");
  return spec.scene->Load({}, TaskValues(spec, task));
}

int ChainOf(const SweepSpec& spec, int task) { return spec.tasks[task].chain; }

int WarmStartSource(const SweepSpec& spec, int task) { return spec.tasks[task].warm_from; }

SweepSpec LoadSweepFile(const std::string& path) {
  SweepSpec spec;
  spec.file = path;
  spec.keep = {"summary"};
  const YAML::Node document = ReadYamlFile(path, "sweep file");
  YamlOrigins origins(path);
  ReadTop(YamlRoot(document, origins), &spec);
  spec.scene = std::make_shared<const SceneDocument>(SceneDocument::Read(spec.scene_file));
  for (int task = 0; task < static_cast<int>(spec.tasks.size()); ++task) CheckTask(spec, task);
  return spec;
}

}  // namespace drape
