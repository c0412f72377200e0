// The scene schema (src/scene/scene_schema.h): docs/reference.md's scene tables are its rows, the
// registries it shares keys with agree with it, and every row's key, given in a scene, is written
// back by scene.yaml (src/output/scene_yaml.h) and read again to the same value.
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

}  // namespace scene_schema_test
}  // namespace drape
