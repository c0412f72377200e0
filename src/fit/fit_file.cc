// The fit-file schema (docs/reference.md, "Fitting"): keys, types, ranges and defaults,
// and the measurement data files. Every error is located in the file that holds it.
#include "src/fit/fit_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "src/analysis/levels.h"
#include "src/analysis/mesh_rule.h"
#include "src/fit/fit_methods.h"
#include "src/model/model.h"
#include "src/output/json.h"
#include "src/output/writers.h"
#include "src/run/load_steps.h"
#include "src/scene/file_paths.h"
#include "src/scene/material_models.h"
#include "src/scene/mesh_file.h"
#include "src/scene/number_text.h"
#include "src/scene/scene_loader.h"
#include "src/scene/yaml_reader.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------------------------- data files

// A data file's number: a scene's (yaml_reader.h), or a finite one below the scene's smallest
// magnitude, which a measurement may well be (drape's own nodes.csv holds residual forces of
// 1e-37 N): as a scene's number it is refused, so that products stay finite; as data, it is a
// value.
std::optional<double> ParseDataNumber(const std::string& text, std::string* error) {
  if (const auto number = ParseNumber(text, error)) return number;
  if (text.find_first_not_of("0123456789.eE+-") != std::string::npos) return std::nullopt;
  const auto number = WholeNumber(text);
  if (!number || !(std::abs(*number) < kSmallestInputMagnitude)) return std::nullopt;
  return number;
}

// The numbers of one comma- or blank-separated row; the column of each field for messages. With
// `booleans`, a field true or false is 1 or 0.
bool SplitNumbers(const std::string& line, std::vector<double>* numbers, std::vector<int>* columns,
                  int* bad_column, bool booleans) {
  numbers->clear();
  columns->clear();
  size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && (line[k] == ',' || std::isspace(static_cast<unsigned char>(line[k]))))
      ++k;
    if (k >= line.size()) break;
    size_t end = k;
    while (end < line.size() && line[end] != ',' &&
           !std::isspace(static_cast<unsigned char>(line[end])))
      ++end;
    std::string error;
    const std::string field = line.substr(k, end - k);
    const auto number = booleans && (field == "true" || field == "false")
                            ? std::optional<double>(field == "true" ? 1.0 : 0.0)
                            : ParseDataNumber(field, &error);
    if (!number) {
      *bad_column = static_cast<int>(k) + 1;
      return false;
    }
    numbers->push_back(*number);
    columns->push_back(static_cast<int>(k) + 1);
    k = end;
  }
  return true;
}

struct Rows {
  std::vector<std::vector<double>> values;
  std::vector<int> lines;
  std::vector<std::string> header;  // the first line's names, where it is a header
};

// The comma-separated names of a header line, trimmed.
std::vector<std::string> HeaderNames(const std::string& line) {
  std::vector<std::string> names;
  std::stringstream stream(line);
  std::string name;
  while (std::getline(stream, name, ',')) {
    const size_t first = name.find_first_not_of(" \t\r");
    const size_t last = name.find_last_not_of(" \t\r");
    names.push_back(first == std::string::npos ? "" : name.substr(first, last - first + 1));
  }
  return names;
}

std::ifstream OpenData(const std::string& path, const Location& where) {
  std::ifstream in(path);
  if (!in) throw InputError(where, "cannot read '" + path + "': " + std::strerror(errno));
  return in;
}

// Rows of numbers; a first line that is not numeric is a header. `first_line` is the file line of
// the stream's first line; `max_rows` < 0 reads to the end. Under the header of drape's own
// nodes.csv (NodesCsvColumns), its booleans (fixed_x, ..., in_contact: true or false) are 1 or 0.
Rows ReadRows(std::istream& in, const std::string& path, int first_line, int max_rows,
              bool allow_header) {
  Rows rows;
  std::string line;
  std::vector<double> numbers;
  std::vector<int> columns;
  bool booleans = false;
  for (int number = first_line;
       (max_rows < 0 || static_cast<int>(rows.values.size()) < max_rows) && std::getline(in, line);
       ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    int bad_column = 0;
    if (!SplitNumbers(line, &numbers, &columns, &bad_column, booleans)) {
      if (allow_header && number == first_line) {
        rows.header = HeaderNames(line);
        booleans = rows.header == NodesCsvColumns();
        continue;
      }
      throw InputError(Location{path, number, bad_column, ""}, "expected a number");
    }
    rows.values.push_back(numbers);
    rows.lines.push_back(number);
  }
  return rows;
}

void RequireColumns(const Rows& rows, size_t row, size_t count, const std::string& path,
                    const std::string& what) {
  if (rows.values[row].size() != count) {
    throw InputError(Location{path, rows.lines[row], 1, ""},
                     "expected " + std::to_string(count) + " columns (" + what + "), got " +
                         std::to_string(rows.values[row].size()));
  }
}

int RowId(const Rows& rows, size_t row, const std::string& path) {
  const double id = rows.values[row][0];
  if (id < 0 || id != static_cast<int>(id)) {
    throw InputError(Location{path, rows.lines[row], 1, ""},
                     "expected a node id (a whole number "
                     ">= 0) in the first column");
  }
  return static_cast<int>(id);
}

// The vertices of a mesh file (PLY, STL or OBJ; src/scene/mesh_file.h) as a point cloud; the
// faces are not needed. `lines` is 0 for each point: a cloud's errors never name a point.
PositionData ReadMeshVertices(const std::string& path, const Location& where) {
  MeshFileData mesh;
  try {
    mesh = ReadMeshFile(path);
  } catch (const MeshFileError& error) {
    throw InputError(where, error.what());
  }
  if (mesh.vertices.empty()) throw InputError(where, "'" + path + "' holds no points");
  PositionData data;
  data.cloud = true;
  data.points = mesh.vertices;
  data.lines.assign(mesh.vertices.size(), 0);
  return data;
}

// ----------------------------------------------------------------------------- fit file

FitParameter ReadParameter(const YamlValue& value) {
  const YamlMap map(value, {"key", "initial", "bounds", "log"});
  FitParameter parameter;
  parameter.where = map.Get("key").where;
  parameter.key = ReadString(map.Get("key"));
  if (parameter.key.empty() || parameter.key.find('=') != std::string::npos) {
    Fail(map.Get("key"), "expected a scene key by path, such as material.finite_volume.D_warp");
  }
  if (const auto log = map.Find("log")) parameter.log = ReadBool(*log);
  const YamlValue initial = map.Get("initial");
  parameter.initial = parameter.log ? ReadPositive(initial) : ReadNumber(initial);
  const YamlValue bounds = map.Get("bounds");
  const std::vector<double> range = ReadNumbers(bounds, 2);
  parameter.lower = range[0];
  parameter.upper = range[1];
  if (!(parameter.lower < parameter.upper))
    Fail(bounds, "expected [lower, upper] with lower < upper");
  if (parameter.log && !(parameter.lower > 0)) {
    Fail(bounds, "a log parameter needs a positive lower bound");
  }
  if (parameter.initial < parameter.lower || parameter.initial > parameter.upper) {
    Fail(initial, "the initial value lies outside the bounds");
  }
  return parameter;
}

std::vector<FitParameter> ReadParameters(const YamlValue& value) {
  const auto items = ReadList(value);
  if (!value.get().IsSequence() || items.empty()) {
    Fail(value,
         "expected a list of parameters such as {key: material.finite_volume.D_warp, "
         "initial: 1.0e-5, bounds: [1.0e-7, 1.0e-3], log: true}");
  }
  std::vector<FitParameter> parameters;
  for (const auto& item : items) {
    parameters.push_back(ReadParameter(item));
    for (size_t k = 0; k + 1 < parameters.size(); ++k) {
      if (parameters[k].key == parameters.back().key) {
        throw InputError(parameters.back().where,
                         "'" + parameters.back().key + "' is fitted twice");
      }
    }
  }
  return parameters;
}

void ReadCommon(const YamlMap& map, FitMeasurement* measurement) {
  if (const auto weight = map.Find("weight")) measurement->weight = ReadPositive(*weight);
  if (const auto sigma = map.Find("sigma")) measurement->sigma = ReadPositive(*sigma);
}

FitMeasurement ReadMeasurementKind(const std::string& kind, const YamlValue& value,
                                   const std::string& directory) {
  FitMeasurement measurement;
  measurement.where = value.where;
  if (kind == "drape_coefficient") {
    const YamlMap map(value, {"value", "weight", "sigma", "disc_radius"});
    measurement.kind = FitMeasurement::Kind::kDrapeCoefficient;
    measurement.value = ReadPositive(map.Get("value"));
    if (const auto radius = map.Find("disc_radius"))
      measurement.disc_radius = ReadPositive(*radius);
    measurement.sigma = 0.01;
    ReadCommon(map, &measurement);
  } else if (kind == "bending_length") {
    const YamlMap map(value, {"value", "weight", "sigma", "direction"});
    measurement.kind = FitMeasurement::Kind::kBendingLength;
    measurement.value = ReadPositive(map.Get("value"));
    if (const auto direction = map.Find("direction")) {
      measurement.direction = ReadChoice(*direction, {"warp", "weft"});
    }
    measurement.sigma = 0.001;
    ReadCommon(map, &measurement);
  } else {
    const YamlMap map(value, {"file", "weight", "sigma"});
    const YamlValue file = map.Get("file");
    measurement.file = ResolvePath(directory, ReadString(file));
    if (kind == "positions") {
      measurement.kind = FitMeasurement::Kind::kPositions;
      measurement.positions = ReadPositionFile(measurement.file, file.where);
      measurement.sigma = 0.001;
    } else {
      measurement.kind = FitMeasurement::Kind::kReactions;
      measurement.reactions = ReadReactionFile(measurement.file, file.where);
      double largest = 0.0;
      for (const auto& force : measurement.reactions.forces)
        largest = std::max(largest, force.norm());
      measurement.sigma = largest > 0 ? 0.01 * largest : 1e-3;
    }
    ReadCommon(map, &measurement);
  }
  return measurement;
}

const std::vector<std::string>& MeasurementKinds() {
  static const std::vector<std::string> kinds = {"drape_coefficient", "positions", "bending_length",
                                                 "reactions", "scene"};
  return kinds;
}

std::vector<FitMeasurement> ReadMeasurements(const YamlValue& value, const std::string& directory,
                                             std::vector<FitSpecimen>* specimens, bool nested);

// `- scene: other.yaml` with a sibling `measurements:` list, or `- scene: {file: other.yaml,
// measurements: [...]}`.
FitSpecimen ReadSpecimen(const YamlMap& item, const std::string& directory) {
  FitSpecimen specimen;
  const YamlValue scene = item.Get("scene");
  specimen.where = scene.where;
  std::optional<YamlValue> measurements = item.Find("measurements");
  if (scene.get().IsMap()) {
    if (measurements)
      Fail(*measurements, "give the measurements inside scene: {file, measurements}");
    const YamlMap map(scene, {"file", "measurements"});
    specimen.scene_file = ResolvePath(directory, ReadString(map.Get("file")));
    measurements.emplace(map.Get("measurements"));  // not operator= (clang-tidy: it may throw)
  } else {
    specimen.scene_file = ResolvePath(directory, ReadString(scene));
    if (!measurements) {
      Fail(scene,
           "another specimen needs its own measurements: add `measurements: [...]` to this "
           "item, or write scene: {file: " +
               ReadString(scene) + ", measurements: [...]}");
    }
  }
  specimen.measurements = ReadMeasurements(*measurements, directory, nullptr, true);
  return specimen;
}

std::vector<FitMeasurement> ReadMeasurements(const YamlValue& value, const std::string& directory,
                                             std::vector<FitSpecimen>* specimens, bool nested) {
  const auto items = ReadList(value);
  if (!value.get().IsSequence() || items.empty()) {
    Fail(value, "expected a list of measurements such as - drape_coefficient: {value: 0.62}");
  }
  std::vector<FitMeasurement> measurements;
  for (const auto& item : items) {
    std::vector<std::string> allowed = MeasurementKinds();
    allowed.push_back("measurements");
    const YamlMap map(item, allowed);
    std::vector<std::string> kinds;
    for (const auto& key : map.Keys()) {
      if (key != "measurements") kinds.push_back(key);
    }
    if (kinds.size() != 1) {
      Fail(item,
           "expected exactly one measurement kind (drape_coefficient, positions, "
           "bending_length, reactions or scene) in this item");
    }
    if (kinds[0] == "scene") {
      if (nested) Fail(map.Get("scene"), "a specimen's measurements cannot name another scene");
      specimens->push_back(ReadSpecimen(map, directory));
      continue;
    }
    if (map.Has("measurements")) {
      Fail(map.Get("measurements"), "only a `scene:` item has its own measurements");
    }
    measurements.push_back(ReadMeasurementKind(kinds[0], map.Get(kinds[0]), directory));
  }
  return measurements;
}

// Reads the specimen's scene file, once for the whole fit.
void ReadSpecimenScene(FitSpecimen* specimen) {
  std::error_code missing;
  if (!std::filesystem::is_regular_file(specimen->scene_file, missing)) {
    throw InputError(specimen->where, "cannot read the scene file " + specimen->scene_file + ": " +
                                          (std::filesystem::exists(specimen->scene_file, missing)
                                               ? "it is not a file"
                                               : "no such file"));
  }
  specimen->scene =
      std::make_shared<const SceneDocument>(SceneDocument::Read(specimen->scene_file));
}

// The specimen's scene with every parameter at its initial value. A bad key named by a fitted
// parameter is located at that parameter (a bad `--set` of the command stays as it is).
Scene LoadSpecimenScene(const FitSpec& spec, const FitSpecimen& specimen) {
  std::vector<double> initial;
  for (const auto& parameter : spec.parameters) initial.push_back(parameter.initial);
  try {
    return SpecimenSceneAt(spec, specimen, initial);
  } catch (const InputError& error) {
    if (error.where().file != "--set") throw;
    // Locate a bad key at the parameter that names it (the fit's --set overrides come first, then
    // one per parameter, in order).
    const int index = error.where().line - 1 - static_cast<int>(spec.scene_overrides.size());
    if (index < 0 || index >= static_cast<int>(spec.parameters.size())) throw;
    const std::string& key = error.where().key;
    throw InputError(spec.parameters[index].where, "not a numeric key of " + specimen.scene_file +
                                                       ": " + (key.empty() ? "" : key + ": ") +
                                                       error.problem());
  }
}

// Checks a specimen's scene with every parameter at its initial value (`scene`, from
// LoadSpecimenScene), and each measurement against the model (ids in range, reactions at fixed
// nodes, a surface for a drape coefficient). Returns the warnings (FitMeshWarning).
std::vector<std::string> CheckSpecimen(const FitSpecimen& specimen, const Scene& scene) {
  if (FrictionLoadSteps(scene) > 0) {
    throw InputError(scene.material.finite_volume.where,
                     "friction_load_steps: a fit solves each equilibrium with its loads at once, "
                     "not along the incremental friction's load path; leave the key out (the "
                     "monotone form is the same wherever the fabric's curvatures grow along the "
                     "path: docs/reference.md, \"Fibre friction in bending\")");
  }
  const Model model = BuildModel(scene);
  std::vector<std::string> warnings;
  for (const auto& measurement : specimen.measurements) {
    using Kind = FitMeasurement::Kind;
    if (measurement.kind == Kind::kPositions && !measurement.positions.cloud) {
      const auto& ids = measurement.positions.ids;
      for (size_t k = 0; k < ids.size(); ++k) {
        const int id = ids[k];
        if (id >= model.num_nodes) {
          throw InputError(Location{measurement.file, measurement.positions.lines[k], 1, ""},
                           "node id " + std::to_string(id) + " is out of range (the scene has " +
                               std::to_string(model.num_nodes) + " nodes)");
        }
      }
    }
    if (measurement.kind == Kind::kPositions && measurement.positions.cloud &&
        model.triangles.empty()) {
      throw InputError(measurement.where,
                       "a point cloud needs a surface mesh (a grid, circle or arc)");
    }
    if (measurement.kind == Kind::kReactions) {
      const auto& ids = measurement.reactions.ids;
      for (size_t k = 0; k < ids.size(); ++k) {
        const int id = ids[k];
        if (id >= model.num_nodes || !model.fixed[3 * id] || !model.fixed[3 * id + 1] ||
            !model.fixed[3 * id + 2]) {
          throw InputError(Location{measurement.file, measurement.reactions.lines[k], 1, ""},
                           "node " + std::to_string(id) + " is not a fixed node of the scene");
        }
      }
    }
    if (measurement.kind == Kind::kDrapeCoefficient && model.triangles.empty()) {
      throw InputError(measurement.where, "a drape coefficient needs a surface mesh");
    }
    if (std::string warning = FitMeshWarning(scene, model, measurement); !warning.empty()) {
      warnings.push_back(std::move(warning));
    }
    if (measurement.kind == Kind::kBendingLength &&
        !MaterialModelOf(scene.material.model).peirce_test) {
      throw InputError(measurement.where, "the virtual Peirce test needs material.model: " +
                                              MaterialModelsWith(&MaterialModelRow::peirce_test));
    }
  }
  return warnings;
}

void ReadTop(const YamlValue& root, FitSpec* spec) {
  const YamlMap top(root, {"scene", "parameters", "measurements", "method", "output",
                           "max_evaluations", "tolerance"});
  const std::string directory = DirectoryOf(spec->file);
  FitSpecimen main;
  main.where = top.Get("scene").where;
  main.scene_file = ResolvePath(directory, ReadString(top.Get("scene")));
  spec->parameters = ReadParameters(top.Get("parameters"));
  std::vector<FitSpecimen> others;
  main.measurements = ReadMeasurements(top.Get("measurements"), directory, &others, false);
  spec->specimens.push_back(main);
  for (auto& other : others) spec->specimens.push_back(other);
  if (const auto method = top.Find("method")) {
    spec->method = ReadChoice(*method, FitMethods());
    spec->method_where = method->where;
  }
  if (const auto count = top.Find("max_evaluations"))
    spec->max_evaluations = ReadIntAtLeast(*count, 1);
  if (const auto tolerance = top.Find("tolerance")) spec->tolerance = ReadPositive(*tolerance);
  // Like a scene's output.directory: relative to the fit file's folder.
  spec->output_directory = DefaultResultFolder(directory, spec->name);
  if (const auto output = top.Find("output")) {
    const YamlMap map(*output, {"directory"});
    if (const auto folder = map.Find("directory")) {
      const std::string given = ReadString(*folder);
      if (given.empty()) Fail(*folder, "expected a folder, got nothing");
      spec->output_directory = ResolvePath(directory, given);
    }
  }
}

// drape's own nodes.csv (src/output/writers.h, NodesCsvColumns): each node's id and position, but
// the nodes fixed in all three directions (the scene holds them where it says: measuring them
// adds residuals that are zero by construction, which would understate the fit's uncertainties).
PositionData DrapeNodePositions(const Rows& rows, const std::string& path) {
  const auto column = [&](const char* name) {
    const auto& names = NodesCsvColumns();
    return static_cast<size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const size_t x = column("x_m"), fixed_x = column("fixed_x");
  assert(column("id") == 0 && column("z_m") == x + 2 && column("fixed_z") == fixed_x + 2);
  PositionData data;
  for (size_t row = 0; row < rows.values.size(); ++row) {
    RequireColumns(rows, row, NodesCsvColumns().size(), path, "drape's nodes.csv");
    const std::vector<double>& values = rows.values[row];
    if (values[fixed_x] != 0 && values[fixed_x + 1] != 0 && values[fixed_x + 2] != 0) continue;
    data.ids.push_back(RowId(rows, row, path));
    data.points.emplace_back(values[x], values[x + 1], values[x + 2]);
    data.lines.push_back(rows.lines[row]);
  }
  return data;
}

}  // namespace

PositionData ReadPositionFile(const std::string& path, const Location& where) {
  const std::string extension = fs::path(path).extension().string();
  if (extension == ".ply" || extension == ".stl" || extension == ".obj") {
    return ReadMeshVertices(path, where);
  }
  std::ifstream in = OpenData(path, where);
  const Rows rows = ReadRows(in, path, 1, -1, true);
  if (rows.values.empty()) throw InputError(where, "'" + path + "' holds no points");
  if (rows.header == NodesCsvColumns()) return DrapeNodePositions(rows, path);
  PositionData data;
  data.cloud = extension == ".xyz" || rows.values[0].size() == 3;
  for (size_t row = 0; row < rows.values.size(); ++row) {
    if (data.cloud) {
      RequireColumns(rows, row, 3, path, "x,y,z");
      data.points.emplace_back(rows.values[row][0], rows.values[row][1], rows.values[row][2]);
    } else {
      RequireColumns(rows, row, 4, path, "id,x,y,z");
      data.ids.push_back(RowId(rows, row, path));
      data.points.emplace_back(rows.values[row][1], rows.values[row][2], rows.values[row][3]);
    }
  }
  data.lines = rows.lines;
  return data;
}

ReactionData ReadReactionFile(const std::string& path, const Location& where) {
  std::ifstream in = OpenData(path, where);
  const Rows rows = ReadRows(in, path, 1, -1, true);
  if (rows.values.empty()) throw InputError(where, "'" + path + "' holds no reactions");
  ReactionData data;
  for (size_t row = 0; row < rows.values.size(); ++row) {
    RequireColumns(rows, row, 4, path, "id,fx,fy,fz");
    data.ids.push_back(RowId(rows, row, path));
    data.forces.emplace_back(rows.values[row][1], rows.values[row][2], rows.values[row][3]);
  }
  data.lines = rows.lines;
  return data;
}

Scene SpecimenSceneAt(const FitSpec& spec, const FitSpecimen& specimen,
                      const std::vector<double>& theta) {
  assert(specimen.scene && "LoadFitFile reads every specimen's scene");
  std::vector<SceneValue> values;
  for (size_t j = 0; j < theta.size(); ++j) {
    values.push_back({spec.parameters[j].key, YAML::Node(theta[j])});
  }
  Scene scene = specimen.scene->Load(spec.scene_overrides, values);
  if (specimen.chosen_spacing) scene.mesh.spacing = *specimen.chosen_spacing;
  return scene;
}

FitSpec LoadFitFile(const std::string& path, const std::vector<std::string>& scene_overrides) {
  FitSpec spec;
  spec.file = path;
  spec.scene_overrides = scene_overrides;
  spec.name = fs::path(path).stem().string();
  spec.root = Location{path, 1, 1, ""};
  const YAML::Node document = ReadYamlFile(path, "fit file");
  YamlOrigins origins(path);
  ReadTop(YamlRoot(document, origins), &spec);
  std::vector<Scene> initial;  // each specimen's scene at the initial parameters
  for (auto& specimen : spec.specimens) {
    ReadSpecimenScene(&specimen);
    initial.push_back(LoadSpecimenScene(spec, specimen));
    if (initial.back().drape_test && initial.back().drape_test->spacing_chosen) {
      specimen.chosen_spacing = initial.back().mesh.spacing;
    }
  }
  for (size_t k = 0; k < spec.specimens.size(); ++k) {
    for (std::string& warning : CheckSpecimen(spec.specimens[k], initial[k])) {
      spec.warnings.push_back(std::move(warning));
    }
  }
  return spec;
}

std::string FitMeshWarning(const Scene& scene, const Model& model,
                           const FitMeasurement& measurement) {
  if (measurement.kind != FitMeasurement::Kind::kDrapeCoefficient) return "";
  const std::optional<MeshAdvice> advice = AdviseMesh(scene, model);
  if (!advice || !(advice->expected_error > measurement.sigma)) return "";
  const Location& where = measurement.where;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) + ": " +
         where.key + ": the drape coefficient on the " + LengthText(advice->spacing, 2) +
         " mesh of " + scene.file + " carries a discretisation error of about " +
         RoundedNumber(advice->expected_error, 2) + " (" + MeshRuleBasis(advice->bending_length) +
         ", at the initial parameters), " +
         RoundedNumber(advice->expected_error / measurement.sigma, 3) +
         " times the measurement's sigma " + RoundedNumber(measurement.sigma, 3) +
         ": the fitted parameters absorb it as a bias; " + LengthText(advice->spacing_needed, 2) +
         " or finer keeps it within " + RoundedNumber(advice->accuracy, 2);
}

}  // namespace drape
