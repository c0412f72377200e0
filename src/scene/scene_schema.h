// The scene schema: one row per scene key, the one table of what a scene may say. The loader
// (src/scene/scene_loader.cc) takes each map's allowed keys from it and reads, checks and stores
// every plain value through its row (src/scene/schema_reader.h), scene.yaml writes those from the
// rows (src/output/scene_yaml.cc), `drape schema --json-schema` and docs/reference.md's scene
// tables (between `<!-- schema: TABLE -->` and `<!-- /schema -->`) are generated from them, and
// tests/scene_schema_test.cc loads, writes and re-reads every row's example, a value just inside
// and just outside each range, and each default.
//
// Adding a plain key (a number, whole number, truth value, word, text, point or pair): its member
// in src/scene/scene.h with its default, its row here bound to the member (`.Field(&Spec::key)`),
// and the regenerated reference table (DRAPE_WRITE_SCHEMA_DOCS=1 drape_tests
// --gtest_filter='SceneSchema*'). A composite key (kOther) is read and written by hand; a key left
// out of either fails the round trip of tests/scene_schema_test.cc.
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

#include "src/scene/scene_field.h"

namespace drape {

// A row's numeric range: open or closed at each end; whole numbers only for an integer row.
struct SchemaRange {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_inclusive = false;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_inclusive = false;
  bool integer = false;

  bool Contains(double value) const;
  // "> 0", "≥ 1", "1–8", "in [2, 1e+08]": the reference's text.
  std::string Text() const;
  // "must be positive, got -1", "must be at least 3, got 2", "must be 2 or 3, got 4": the loader's
  // refusal of `value`.
  std::string Refusal(double value) const;
};

// The ranges the rows use.
SchemaRange Above(double bound);                  // > bound
SchemaRange AtLeast(double bound);                // ≥ bound
SchemaRange Between(double lower, double upper);  // [lower, upper]
SchemaRange Whole(SchemaRange range);             // whole numbers in `range`

// A row's value type. The plain types are read, checked and written from the row alone
// (src/scene/schema_reader.h, src/output/scene_yaml.cc); kOther is a composite value (a map, a
// list, a node selection, a family `number or {warp, weft}`) that the loader reads by hand, its
// type in `type`'s words.
enum class ValueType { kNumber, kInteger, kBool, kWord, kText, kPoint, kPair, kOther };

struct SchemaRow {
  // The reference table the row is listed in: "" (the top level), "mesh", "material.springs",
  // "loads.forces" (the keys of each item of a list), "nodes" (a node selection, anywhere).
  std::string table;
  std::string key;                 // within the table's map: "E_warp"
  std::vector<std::string> kinds;  // the kinds (or cases) that take it; empty: all
  ValueType value = ValueType::kOther;
  std::optional<SchemaRange> bounds;  // a number's or a whole number's
  std::vector<std::string> words;     // a word's choices
  // Where the value goes (src/scene/scene_field.h); none for a value the loader converts (a KES
  // measurement) or reads by hand (kOther).
  SceneField field;
  // The default: the bound member's value in a default-constructed owner; else one given in the
  // row (a converted measurement's); none for a default in words (`default_text`).
  FieldValue default_value;
  // The default as YAML: the typed default's text, or a composite value's ("[15, 15]"); "" none.
  std::string default_yaml;
  std::string type;          // "[3]", "integer", "`xy` \| `xz`" (markdown), from `value`
  std::string unit;          // SI: "N/m", "m"; "" none
  std::string range;         // "> 0", "≥ 1" (from `bounds`), or in words; "" any
  std::string default_text;  // markdown: "`0.001`", "**required**", "none"
  std::string doc;           // markdown, one line

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
  bool Takes(const std::string& kind) const;  // the row applies to `kind` ("" any)
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

// The row of `key` in `table` that applies to `kind` (a programmer error if there is none).
const SchemaRow& SchemaRowOf(const std::string& table, const std::string& key,
                             const std::string& kind = "");

// The row of the value at `path` in a scene ("obstacles[1].sphere.radius",
// "regions[0].structural.warp"): its own, else its nearest ancestor's; null for none.
const SchemaRow* SchemaRowAt(const std::string& path);

// The unit of the value at `path` in a written scene ("fixed[0].move",
// "obstacles[1].sphere.radius", "regions[0].nodes.within.radius"): its row's, else its nearest
// ancestor row's; "" for none.
std::string SchemaUnit(const std::string& path);

// docs/reference.md's table of `table`, in markdown (ending with a newline).
std::string SchemaMarkdown(const std::string& table);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_SCHEMA_H_
