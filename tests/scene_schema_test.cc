// The scene schema (src/scene/scene_schema.h): docs/reference.md's scene tables are its rows, the
// registries it shares keys with agree with it, every row's key, given in a scene, is written
// back by scene.yaml (src/output/scene_yaml.h) and read again to the same value, every literal
// default is the loader's, and every numeric range is the loader's check.
//
// DRAPE_WRITE_SCHEMA_DOCS=1 drape_tests --gtest_filter='SceneSchema.*' writes the tables into
// docs/reference.md (between `<!-- schema: TABLE -->` and `<!-- /schema -->`) instead of
// comparing them.
#include "src/scene/scene_schema.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/obstacle_kinds.h"
#include "src/output/scene_yaml.h"
#include "src/scene/material_keys.h"
#include "src/scene/scene_loader.h"
#include "tests/test_paths.h"

namespace drape {
namespace scene_schema_test {

std::string ReferencePath() { return std::string(drape_tests::kSourceDir) + "/docs/reference.md"; }

std::string MarkerName(const std::string& table) { return table.empty() ? "top" : table; }

const char* const kBlockEnd = "<!-- /schema -->";

// The reference's schema blocks by table name: the lines between the markers.
std::map<std::string, std::string> ReferenceBlocks() {
  std::ifstream file(ReferencePath());
  std::map<std::string, std::string> blocks;
  std::string line, open;
  const std::string start = "<!-- schema: ";
  while (std::getline(file, line)) {
    if (line.rfind(start, 0) == 0) {
      open = line.substr(start.size(), line.size() - start.size() - 4);
      blocks[open];
    } else if (line == kBlockEnd) {
      open.clear();
    } else if (!open.empty()) {
      blocks[open] += line + "\n";
    }
  }
  return blocks;
}

// Writes every table between its markers (the markers stay where they are).
void WriteReferenceBlocks() {
  std::ifstream in(ReferencePath());
  std::ostringstream out;
  std::string line;
  bool skipping = false;
  const std::string start = "<!-- schema: ";
  while (std::getline(in, line)) {
    if (skipping && line != kBlockEnd) continue;
    skipping = false;
    out << line << "\n";
    if (line.rfind(start, 0) != 0) continue;
    const std::string name = line.substr(start.size(), line.size() - start.size() - 4);
    for (const std::string& table : SchemaTables()) {
      if (MarkerName(table) == name) out << SchemaMarkdown(table);
    }
    skipping = true;
  }
  in.close();
  std::ofstream(ReferencePath()) << out.str();
}

TEST(SceneSchema, TheReferenceTablesAreTheSchema) {
  if (std::getenv("DRAPE_WRITE_SCHEMA_DOCS") != nullptr) WriteReferenceBlocks();
  const auto blocks = ReferenceBlocks();
  std::set<std::string> tables;
  for (const std::string& table : SchemaTables()) {
    const std::string name = MarkerName(table);
    tables.insert(name);
    ASSERT_EQ(blocks.count(name), 1u)
        << "docs/reference.md has no block <!-- schema: " << name << " -->";
    EXPECT_EQ(blocks.at(name), SchemaMarkdown(table))
        << "docs/reference.md's table of " << name
        << " is not the schema's: regenerate it (tests/scene_schema_test.cc says how)";
  }
  for (const auto& [name, text] : blocks) {
    EXPECT_EQ(tables.count(name), 1u) << "docs/reference.md has a block of no table: " << name;
  }
}

TEST(SceneSchema, EveryRowIsDocumentedAndHasAnExample) {
  std::set<std::string> seen;
  for (const SchemaRow& row : SceneSchema()) {
    std::string kinds;
    for (const std::string& kind : row.kinds) kinds += "," + kind;
    EXPECT_TRUE(seen.insert(row.Path() + kinds).second) << row.Path() << " is listed twice";
    EXPECT_FALSE(row.example.empty()) << row.Path() << " has no example";
    const bool described = !row.doc.empty() || !row.default_text.empty();
    EXPECT_TRUE(described || row.key == "kind" || row.key == "model") << row.Path();
  }
}

// Each obstacle kind's keys (src/model/obstacle_kinds.h), and `friction`, are the rows that name
// the kind.
TEST(SceneSchema, ObstacleRowsAreTheKindsKeys) {
  for (const ObstacleKind& kind : ObstacleKinds()) {
    std::vector<std::string> keys = kind.keys;
    keys.insert(keys.end(), kind.optional_keys.begin(), kind.optional_keys.end());
    keys.push_back("friction");
    std::vector<std::string> rows = SchemaKeys("obstacles", kind.name);
    std::sort(keys.begin(), keys.end());
    std::sort(rows.begin(), rows.end());
    EXPECT_EQ(rows, keys) << kind.name;
  }
}

// The finite-volume keys of src/scene/material_keys.h are rows of the material and of a region,
// in the same unit.
TEST(SceneSchema, FiniteVolumeRowsAreTheMaterialKeys) {
  for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
    for (const char* table : {"material.finite_volume", "regions"}) {
      const auto rows = SchemaRows(table);
      const auto row = std::find_if(rows.begin(), rows.end(),
                                    [&](const SchemaRow* r) { return r->key == key.key; });
      ASSERT_NE(row, rows.end()) << table << "." << key.key;
      EXPECT_EQ((*row)->unit, key.unit) << table << "." << key.key;
    }
  }
}

TEST(SceneSchema, UnitsOfWrittenPathsAreTheirRowsOrTheirAncestors) {
  EXPECT_EQ(SchemaUnit("solver.time_limit"), "s");
  EXPECT_EQ(SchemaUnit("fixed[0].move"), "m");
  EXPECT_EQ(SchemaUnit("obstacles[1].sphere.radius"), "m");
  EXPECT_EQ(SchemaUnit("regions[0].nodes.within.radius"), "m");
  EXPECT_EQ(SchemaUnit("regions[0].nodes.row"), "");
  EXPECT_EQ(SchemaUnit("material.springs.shear.weft"), "N/m");
  EXPECT_EQ(SchemaUnit("material.finite_volume.D_warp"), "N*m");
  EXPECT_EQ(SchemaUnit("loads.forces[2].ramp.from"), "N");
  EXPECT_EQ(SchemaUnit("solver.newton.max_line_search"), "");
}

// ------------------------------------------------------------------------- the round trip

std::string BaseScene(SchemaRow::Base base) {
  const std::string fv_material =
      "material: {model: finite_volume, density: 0.2, finite_volume: {E_warp: 1000, E_weft: "
      "1000, G: 10, D_warp: 1.0e-5, D_weft: 1.0e-5}}\n";
  switch (base) {
    case SchemaRow::Base::kSprings:
      break;
    case SchemaRow::Base::kFiniteVolume:
      return "mesh: {kind: grid, nodes: [3, 3]}\n" + fv_material +
             "fixed: [{nodes: {corner: top-left}}]\n";
    case SchemaRow::Base::kDrapeTest:
      return "drape_test: {}\n" + fv_material;
  }
  return "mesh: {kind: grid, nodes: [3, 3], size: [1, 1]}\n"
         "material: {density: 0.2, springs: {structural: 100}}\n"
         "fixed: [{nodes: {corner: top-left}}]\n";
}

// The node at a path such as "fixed[0].nodes.edge"; a null node where there is none.
YAML::Node At(const YAML::Node& root, const std::string& path) {
  YAML::Node node = root;
  std::istringstream parts(path);
  std::string part;
  while (std::getline(parts, part, '.')) {
    const size_t bracket = part.find('[');
    const std::string key = part.substr(0, bracket);
    if (!node.IsMap() || !node[key]) return YAML::Node();
    node = node[key];
    if (bracket == std::string::npos) continue;
    const size_t index = std::stoul(part.substr(bracket + 1));
    if (!node.IsSequence() || index >= node.size()) return YAML::Node();
    node = node[index];
  }
  return node;
}

bool SameNumber(const std::string& a, const std::string& b) {
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a);
  const double y = std::strtod(b.c_str(), &end_b);
  if (*end_a != '\0' || *end_b != '\0' || a.empty() || b.empty()) return false;
  return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y));
}

// `actual` has everything `expected` has (maps may have more keys), numbers equal to 1e-9.
bool Covers(const YAML::Node& actual, const YAML::Node& expected) {
  if (expected.IsScalar()) {
    return actual.IsScalar() &&
           (actual.Scalar() == expected.Scalar() || SameNumber(actual.Scalar(), expected.Scalar()));
  }
  if (expected.IsSequence()) {
    if (!actual.IsSequence() || actual.size() != expected.size()) return false;
    for (size_t k = 0; k < expected.size(); ++k) {
      if (!Covers(actual[k], expected[k])) return false;
    }
    return true;
  }
  if (!actual.IsMap()) return false;
  for (const auto& entry : expected) {
    const std::string key = entry.first.as<std::string>();
    if (!actual[key] || !Covers(actual[key], entry.second)) return false;
  }
  return true;
}

std::string Written(const Scene& scene) {
  std::ostringstream text;
  WriteSceneYaml(scene, text);
  return text.str();
}

class EveryRow : public ::testing::TestWithParam<size_t> {};

TEST_P(EveryRow, IsWrittenBackAndReadAgain) {
  const SchemaRow& row = SceneSchema()[GetParam()];
  ASSERT_FALSE(row.example.empty()) << row.Path() << " has no example";
  const std::string directory = drape_tests::kSourceDir;
  const Scene scene =
      LoadSceneText(BaseScene(row.base), "<example of " + row.Path() + ">", directory, row.example);
  if (row.written_at == "-") return;  // the row's doc says why scene.yaml leaves it out
  const std::string& last = row.example.back();
  const std::string at = row.written_at.empty() ? last.substr(0, last.find('=')) : row.written_at;
  const std::string value =
      row.written_at.empty() ? last.substr(last.find('=') + 1) : row.written_value;
  const std::string first = Written(scene);
  const YAML::Node written = At(YAML::Load(first), at);
  ASSERT_TRUE(written.IsDefined() && !written.IsNull())
      << "scene.yaml does not write " << at << " (for " << row.Path() << "):\n"
      << first;
  if (!value.empty()) {
    EXPECT_TRUE(Covers(written, YAML::Load(value)))
        << at << " is written as " << YAML::Dump(written) << ", not " << value;
  }
  const std::string second = Written(LoadSceneText(first, "<scene.yaml>", directory));
  EXPECT_EQ(YAML::Dump(At(YAML::Load(second), at)), YAML::Dump(written))
      << at << " is not read back as written";
}

std::string RowName(const ::testing::TestParamInfo<size_t>& info) {
  const SchemaRow& row = SceneSchema()[info.param];
  const auto twins =
      std::count_if(SceneSchema().begin(), SceneSchema().end(),
                    [&](const SchemaRow& other) { return other.Path() == row.Path(); });
  std::string name = row.Path() + (twins > 1 ? "_" + row.kinds.front() : "");
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(SceneSchema, EveryRow, ::testing::Range<size_t>(0, SceneSchema().size()),
                         RowName);

// ------------------------------------------------------------------------- the defaults

// Where a list table's first item is given without the row's key, and the path of the key in it.
struct ListItem {
  std::string table, override_text, prefix;
};
const std::vector<ListItem>& ListItems() {
  static const std::vector<ListItem> items = {
      {"material.lines", "material.lines=[{nodes: {row: 1}, structural: 30}]",
       "material.lines[0]."},
      {"obstacles", "obstacles=[{pin: {position: [0, 0, -1]}}]", "obstacles[0].pin."},
      {"fixed", "", "fixed[0]."},
  };
  return items;
}

// The scene a row's default is read from: the row's base; the mesh kind the row applies to; a
// list table's item without the key; and the row's example but its last override (what the key
// needs beside it, e.g. a friction for its smoothing).
std::vector<std::string> DefaultContext(const SchemaRow& row, std::string* path) {
  std::vector<std::string> overrides(row.example.begin(), row.example.end() - 1);
  *path = row.Path();
  if (row.table == "mesh" && !row.kinds.empty() && row.kinds.front() != "grid") {
    overrides.push_back("mesh={kind: " + row.kinds.front() + "}");
    overrides.push_back("fixed=[{nodes: {ids: [0]}}]");
  }
  // A mesh obstacle's optional keys: on the smallest mesh, not the list's pin.
  if (row.table == "obstacles" && row.kinds == std::vector<std::string>{"mesh"}) {
    overrides.push_back("obstacles=[{mesh: {file: tests/data/meshes/octahedron.obj}}]");
    *path = "obstacles[0].mesh." + row.key;
    return overrides;
  }
  for (const ListItem& item : ListItems()) {
    if (item.table != row.table) continue;
    if (!item.override_text.empty()) overrides.push_back(item.override_text);
    *path = item.prefix + row.key;
  }
  return overrides;
}

std::string NumberText(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// The rule: a row's default is checked when it is typed (SchemaRow::default_value) and the
// key is not converted to another one (the kes measurements, written as the SI keys). scene.yaml
// shows the default where it writes the key; the keys it expands (a drape test's, into the mesh
// and obstacles) or leaves out at their default (the frictions) are read from the loaded Scene.
std::map<std::string, std::string (*)(const Scene&)> SceneDefaults() {
  return {
      {"material.finite_volume.bending_friction_warp",
       [](const Scene& s) { return NumberText(s.material.finite_volume.bending_friction_warp); }},
      {"material.finite_volume.bending_friction_weft",
       [](const Scene& s) { return NumberText(s.material.finite_volume.bending_friction_weft); }},
      {"material.finite_volume.shear_friction",
       [](const Scene& s) { return NumberText(s.material.finite_volume.shear_friction); }},
      {"material.finite_volume.friction_load_steps",
       [](const Scene& s) { return std::to_string(s.material.finite_volume.friction_load_steps); }},
      {"drape_test.specimen_diameter",
       [](const Scene& s) { return NumberText(s.drape_test->specimen_diameter); }},
      {"drape_test.disc_diameter",
       [](const Scene& s) { return NumberText(s.drape_test->disc_diameter); }},
      {"drape_test.offset",
       [](const Scene& s) {
         return "[" + NumberText(s.drape_test->offset.x()) + ", " +
                NumberText(s.drape_test->offset.y()) + "]";
       }},
      {"drape_test.drops", [](const Scene& s) { return std::to_string(s.drape_test->drops); }},
      {"drape_test.placement", [](const Scene& s) { return NumberText(s.drape_test->placement); }},
      {"drape_test.waviness", [](const Scene& s) { return NumberText(s.drape_test->waviness); }},
      {"drape_test.seed", [](const Scene& s) { return std::to_string(s.drape_test->seed); }},
  };
}

bool WrittenElsewhere(const SchemaRow& row) {
  return row.written_at == "-" ||
         (!row.written_at.empty() && row.written_at.find('[') == std::string::npos &&
          row.written_at != row.Path());
}

void RemoveAt(YAML::Node node, const std::vector<std::string>& parts, size_t k) {
  if (!node.IsMap()) return;
  if (k + 1 == parts.size()) {
    node.remove(parts[k]);
  } else if (node[parts[k]]) {
    RemoveAt(node[parts[k]], parts, k + 1);
  }
}

// The base scene without the row's key: the springs base, but for the keys only a finite-volume
// material or a drape test has.
std::string DefaultBase(const SchemaRow& row) {
  const bool own_base = row.table.rfind("material.finite_volume", 0) == 0 ||
                        row.table.rfind("drape_test", 0) == 0 || row.Path() == "drape_test";
  YAML::Node base = YAML::Load(BaseScene(own_base ? row.base : SchemaRow::Base::kSprings));
  std::vector<std::string> parts;
  std::istringstream path(row.Path());
  for (std::string part; std::getline(path, part, '.');) parts.push_back(part);
  RemoveAt(base, parts, 0);
  return YAML::Dump(base);
}

// Checks one row's default against the loaded scene; false when the rule skips the row.
bool CheckDefault(const SchemaRow& row) {
  const std::string literal = row.default_yaml;
  if (literal.empty()) return false;
  std::string path;
  const auto overrides = DefaultContext(row, &path);
  const Scene scene = LoadSceneText(DefaultBase(row), "<default of " + row.Path() + ">",
                                    drape_tests::kSourceDir, overrides);
  const auto from_scene = SceneDefaults();
  if (from_scene.count(row.Path()) == 1) {
    const std::string loaded = from_scene.at(row.Path())(scene);
    EXPECT_TRUE(Covers(YAML::Load(loaded), YAML::Load(literal)))
        << row.Path() << ": the loader's default is " << loaded << ", the schema's " << literal;
    return true;
  }
  if (WrittenElsewhere(row)) return false;
  const std::string text = Written(scene);
  const YAML::Node written = At(YAML::Load(text), path);
  EXPECT_TRUE(written.IsDefined() && !written.IsNull() && Covers(written, YAML::Load(literal)))
      << row.Path() << ": scene.yaml writes " << (written ? YAML::Dump(written) : "nothing")
      << " at " << path << " when it is not given, the schema's default is " << literal << "\n"
      << text;
  return true;
}

TEST(SceneSchema, LiteralDefaultsAreTheLoadersDefaults) {
  std::vector<std::string> checked, skipped;
  for (const SchemaRow& row : SceneSchema()) {
    (CheckDefault(row) ? checked : skipped).push_back(row.Path());
  }
  // Every row with a typed default but those converted to another key (the kes measurements).
  std::string list;
  for (const std::string& path : checked) list += " " + path;
  EXPECT_EQ(checked.size(), 47u) << "rows whose default is checked (a row added with a literal "
                                    "default is checked too: update the count):"
                                 << list;
  for (const std::string& path : skipped) {
    const auto row = std::find_if(SceneSchema().begin(), SceneSchema().end(),
                                  [&](const SchemaRow& r) { return r.Path() == path; });
    if (row->default_yaml.empty()) continue;
    EXPECT_EQ(row->table, "material.finite_volume.kes") << path << "'s default is not checked";
  }
}

// ------------------------------------------------------------------------- the ranges

// A number, a whole number, or a spring family (`number or {warp, weft}`).
bool NumericType(const SchemaRow& row) {
  return row.value == ValueType::kNumber || row.value == ValueType::kInteger ||
         row.type.rfind("number or", 0) == 0;
}

// Where the row's key stands in the scene its example gives: the written path for a list item.
std::string RangeTarget(const SchemaRow& row) {
  const std::string& at = row.written_at;
  const std::string end = "." + row.key;
  const bool item = at.find('[') != std::string::npos && at.size() > end.size() &&
                    at.compare(at.size() - end.size(), end.size(), end) == 0;
  return item ? at : row.Path();
}

// The values just outside the range: a bound itself when it is excluded, else one step beyond
// (1 for whole numbers, a millionth of the bound's size otherwise).
std::vector<double> OutsideValues(const SchemaRange& range) {
  auto step = [&](double bound) {
    return range.integer ? 1.0 : 1e-6 * std::max(1.0, std::abs(bound));
  };
  std::vector<double> values;
  if (std::isfinite(range.lower)) {
    values.push_back(range.lower_inclusive ? range.lower - step(range.lower) : range.lower);
  }
  if (std::isfinite(range.upper)) {
    values.push_back(range.upper_inclusive ? range.upper + step(range.upper) : range.upper);
  }
  return values;
}

// The values just inside the range: a bound itself when it is included, else one step within.
std::vector<double> InsideValues(const SchemaRange& range) {
  auto step = [&](double bound) {
    return range.integer ? 1.0 : 1e-6 * std::max(1.0, std::abs(bound));
  };
  std::vector<double> values;
  if (std::isfinite(range.lower)) {
    values.push_back(range.lower_inclusive ? range.lower : range.lower + step(range.lower));
  }
  if (std::isfinite(range.upper)) {
    values.push_back(range.upper_inclusive ? range.upper : range.upper - step(range.upper));
  }
  return values;
}

// The error the loader raises for the row's example with `value` at the key, if any.
std::optional<InputError> LoadWith(const SchemaRow& row, double value) {
  std::vector<std::string> overrides = row.example;
  overrides.push_back(RangeTarget(row) + "=" + NumberText(value));
  try {
    LoadSceneText(BaseScene(row.base), "<range of " + row.Path() + ">", drape_tests::kSourceDir,
                  overrides);
  } catch (const InputError& error) {
    return error;
  }
  return std::nullopt;
}

class EveryRange : public ::testing::TestWithParam<size_t> {};

// A value just outside the row's range is refused, located at the key; a value just inside is
// not refused at the key (another key's check may still refuse the scene: mesh.max_nodes 2 under
// a 3 × 3 grid is refused at `mesh`).
TEST_P(EveryRange, IsTheLoadersCheck) {
  const SchemaRow& row = SceneSchema()[GetParam()];
  const auto& range = row.bounds;
  ASSERT_TRUE(range.has_value());
  const std::string target = RangeTarget(row);
  for (const double value : OutsideValues(*range)) {
    ASSERT_FALSE(range->Contains(value));
    const auto error = LoadWith(row, value);
    ASSERT_TRUE(error.has_value()) << target << " = " << NumberText(value) << " is accepted, "
                                   << "outside the schema's range " << row.range;
    EXPECT_EQ(error->where().key, target) << error->what();
  }
  for (const double value : InsideValues(*range)) {
    ASSERT_TRUE(range->Contains(value));
    const auto error = LoadWith(row, value);
    EXPECT_TRUE(!error.has_value() || error->where().key != target)
        << target << " = " << NumberText(value) << ", within " << row.range
        << ", is refused: " << error->what();
  }
}

// The rows with a numeric type and a structured range.
std::vector<size_t> RangedRows() {
  std::vector<size_t> rows;
  for (size_t k = 0; k < SceneSchema().size(); ++k) {
    if (SceneSchema()[k].bounds && NumericType(SceneSchema()[k])) rows.push_back(k);
  }
  return rows;
}

INSTANTIATE_TEST_SUITE_P(SceneSchema, EveryRange, ::testing::ValuesIn(RangedRows()), RowName);

// A numeric row without a range takes any sign at its key: ±1e-9 and 0 (±1 for a whole number;
// small, as D_12 is bounded by D_warp and D_weft) are not refused there.
TEST(SceneSchema, NumericRowsWithoutARangeTakeAnyNumber) {
  size_t checked = 0;
  for (const SchemaRow& row : SceneSchema()) {
    if (row.bounds || !row.range.empty() || !NumericType(row) || row.example.empty()) continue;
    ++checked;
    const double size = row.value == ValueType::kInteger ? 1.0 : 1e-9;
    for (const double value : {-size, 0.0, size}) {
      const auto error = LoadWith(row, value);
      EXPECT_TRUE(!error.has_value() || error->where().key != RangeTarget(row))
          << RangeTarget(row) << " = " << value
          << " is refused, but the schema gives no range: " << error->what();
    }
  }
  EXPECT_EQ(checked, 8u) << "numeric rows without a range: update the count";
}

// A range's text (the reference's) and refusal (the loader's message) say its bounds.
TEST(SceneSchema, RangesSayTheirBounds) {
  EXPECT_EQ(Above(0).Text(), "> 0");
  EXPECT_EQ(AtLeast(0).Text(), "≥ 0");
  EXPECT_EQ(Whole(Between(1, 8)).Text(), "1–8");
  EXPECT_EQ(Whole(Between(2, 1e8)).Text(), "in [2, 100000000]");
  EXPECT_EQ(Above(0).Refusal(-1), "must be positive, got -1");
  EXPECT_EQ(AtLeast(0).Refusal(-0.5), "must not be negative, got -0.5");
  EXPECT_EQ(Above(1).Refusal(1), "must be greater than 1, got 1");
  EXPECT_EQ(Whole(AtLeast(3)).Refusal(2), "must be at least 3, got 2");
  EXPECT_EQ(Whole(Between(1, 8)).Refusal(9), "must be at most 8, got 9");
  EXPECT_FALSE(Whole(Between(1, 8)).Contains(1.5));
}

// Every plain row's type, range and default text come from its typed value, bounds and default.
TEST(SceneSchema, PlainRowsSayTheirTypedValues) {
  for (const SchemaRow& row : SceneSchema()) {
    if (row.bounds) {
      EXPECT_EQ(row.range, row.bounds->Text()) << row.Path();
    }
    const std::string text = FieldValueText(row.default_value);
    if (!text.empty()) {
      EXPECT_EQ(row.default_text.rfind("`" + text + "`", 0), 0u) << row.Path();
    }
    if (row.field) {
      EXPECT_NE(row.value, ValueType::kOther) << row.Path() << ": a bound row of a composite value";
    }
  }
}

}  // namespace scene_schema_test
}  // namespace drape
