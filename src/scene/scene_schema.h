// The scene schema: one row per scene key, the one table of what a scene may say. The loader
// (src/scene/scene_loader.cc) takes each map's allowed keys from it, docs/reference.md's scene
// tables are generated from it (between `<!-- schema: TABLE -->` and `<!-- /schema -->`), and
// tests/scene_schema_test.cc holds the reference to the rows and loads, writes (scene.yaml) and
// re-reads every row's example. It also holds the loader to the rows' literal defaults
// (SchemaRow::DefaultLiteral) and numeric ranges (SchemaRow::Bounds): a value just outside a
// range must be refused at its key.
//
// Adding a scene key: its row in SceneSchema() (src/scene/scene_schema.cc), its reading in the
// loader and its writing in src/output/scene_yaml.cc, and the regenerated reference table
// (DRAPE_WRITE_SCHEMA_DOCS=1 drape_tests --gtest_filter='SceneSchema*'). Each piece left out
// fails a test: a key without a row is an unknown key to the loader; a row without its line in
// the reference, a key scene.yaml does not write back, a range the loader does not check or a
// default the loader does not give fails tests/scene_schema_test.cc.
//
// The finite-volume keys come from src/scene/material_keys.h, the solver methods' options from
// src/scene/solver_methods.h; the obstacle kinds' keys are checked against src/model/
// obstacle_kinds.h by the test (the model layer is above this one).
#ifndef DRAPE_SRC_SCENE_SCENE_SCHEMA_H_
#define DRAPE_SRC_SCENE_SCENE_SCHEMA_H_

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace drape {

// A row's range as numbers, parsed from its text: "> 0", "≥ 1", "< 5", "≤ 5", "1–8",
// "in [2, 10⁸]", "0" (that value only). Whole numbers when the row's type says "integer" or
// "whole number". tests/scene_schema_test.cc loads a value just outside it and expects the
// loader's error at the key.
struct SchemaRange {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_inclusive = false;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_inclusive = false;
  bool integer = false;

  bool Contains(double value) const;
};

// `range` as numbers; none for prose ("strictly increasing", "> min", "not zero", "any sign",
// "each > 0 (…)") and for no range.
std::optional<SchemaRange> ParseSchemaRange(const std::string& range, bool integer);

struct SchemaRow {
  // The reference table the row is listed in: "" (the top level), "mesh", "material.springs",
  // "loads.forces" (the keys of each item of a list), "nodes" (a node selection, anywhere).
  std::string table;
  std::string key;                 // within the table's map: "E_warp"
  std::vector<std::string> kinds;  // the kinds (or cases) that take it; empty: all
  std::string type;                // "[3]", "integer", "`xy` \| `xz`" (markdown); "" a number
  std::string unit;                // SI: "N/m", "m"; "" none
  std::string range;               // "> 0", "≥ 1"; "" any
  std::string default_text;        // markdown: "`0.001`", "**required**", "none"
  std::string doc;                 // markdown, one line

  // The round trip (tests/scene_schema_test.cc): the `--set` overrides that give the key on the
  // base scene, where scene.yaml writes it (default: the last override's path) and the value it
  // writes there (YAML; default: the last override's value, when `written_at` is not given).
  // written_at "-": scene.yaml does not write the key (`doc` says why).
  enum class Base { kSprings, kFiniteVolume, kDrapeTest };
  Base base = Base::kSprings;
  std::vector<std::string> example;
  std::string written_at;
  std::string written_value;

  std::string Path() const { return table.empty() ? key : table + "." + key; }

  // ParseSchemaRange(range), for a row whose type is "integer" or "whole number" a whole number.
  std::optional<SchemaRange> Bounds() const;

  // The default as a YAML value when `default_text` is one literal in backticks, optionally
  // followed by a remark in parentheses ("`1e-8`", "`0` (elastic)", "`[x, y, z]`"); "" when it is
  // prose ("**required**", "none", "the method's", "disc − 1 cm", "`out/<name>`" a pattern).
  std::string DefaultLiteral() const;
};

// Every row, table by table in the reference's order.
const std::vector<SchemaRow>& SceneSchema();

// The reference tables, in order ("" the top level).
std::vector<std::string> SchemaTables();

// The keys the map `table` accepts (each once, in the rows' order); with `kind`, only those the
// kind takes. Rows whose key is a placeholder (`<method>`) are not listed.
std::vector<std::string> SchemaKeys(const std::string& table, const std::string& kind = "");

// The rows of `table`.
std::vector<const SchemaRow*> SchemaRows(const std::string& table);

// The unit of the value at `path` in a written scene ("fixed[0].move",
// "obstacles[1].sphere.radius", "regions[0].nodes.within.radius"): its row's, else its nearest
// ancestor row's; "" for none.
std::string SchemaUnit(const std::string& path);

// docs/reference.md's table of `table`, in markdown (ending with a newline).
std::string SchemaMarkdown(const std::string& table);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_SCHEMA_H_
