#include "src/output/scene_json_schema.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/output/json.h"
#include "src/output/scene_json.h"
#include "src/scene/output_kinds.h"
#include "src/scene/scene_schema.h"
#include "src/scene/solver_methods.h"

namespace drape {
namespace {

using Members = std::vector<std::pair<std::string, std::string>>;

// The names in backticks of a type's text: "`top` \| `bottom`" → top, bottom.
std::vector<std::string> Backticked(const std::string& text) {
  std::vector<std::string> names;
  for (size_t open = text.find('`'); open != std::string::npos;) {
    const size_t close = text.find('`', open + 1);
    if (close == std::string::npos) break;
    names.push_back(text.substr(open + 1, close - open - 1));
    open = text.find('`', close + 1);
  }
  return names;
}

// A choice among words.
Members Choice(const std::vector<std::string>& names) {
  return {{"enum", JsonList(JsonStrings(names))}};
}

// The JSON Schema keywords of a range: minimum/exclusiveMinimum, maximum/exclusiveMaximum.
Members BoundMembers(const std::optional<SchemaRange>& range) {
  Members members;
  if (!range) return members;
  if (std::isfinite(range->lower)) {
    members.emplace_back(range->lower_inclusive ? "minimum" : "exclusiveMinimum",
                         JsonNumber(range->lower));
  }
  if (std::isfinite(range->upper)) {
    members.emplace_back(range->upper_inclusive ? "maximum" : "exclusiveMaximum",
                         JsonNumber(range->upper));
  }
  return members;
}

Members Number(const std::optional<SchemaRange>& range, bool integer) {
  Members members = {{"type", integer ? "\"integer\"" : "\"number\""}};
  for (auto& member : BoundMembers(range)) members.push_back(std::move(member));
  return members;
}

Members Text() { return {{"type", "\"string\""}}; }

// A list of `items` (exactly `count` of them when count > 0).
Members ListOf(const Members& items, int count, int depth) {
  Members members = {{"type", "\"array\""}, {"items", JsonObject(items, depth + 1)}};
  if (count > 0) {
    members.emplace_back("minItems", std::to_string(count));
    members.emplace_back("maxItems", std::to_string(count));
  }
  return members;
}

Members UniqueListOf(const Members& items, int depth) {
  Members members = ListOf(items, 0, depth);
  members.emplace_back("uniqueItems", "true");
  return members;
}

Members Point(int depth) { return ListOf(Number(std::nullopt, false), 3, depth); }

Members ObjectOf(const Members& properties, const std::vector<std::string>& required, int depth) {
  Members members = {{"type", "\"object\""}, {"properties", JsonObject(properties, depth + 1)}};
  if (!required.empty()) members.emplace_back("required", JsonList(JsonStrings(required)));
  members.emplace_back("additionalProperties", "false");
  return members;
}

// One of several schemas.
Members AnyOf(const std::vector<Members>& choices, int depth) {
  std::vector<std::string> texts;
  texts.reserve(choices.size());
  for (const Members& choice : choices) texts.push_back(JsonObject(choice, depth + 1));
  return {{"anyOf", JsonList(texts)}};
}

bool IsTable(const std::string& path) {
  const auto tables = SchemaTables();
  return std::find(tables.begin(), tables.end(), path) != tables.end();
}

Members TableSchema(const std::string& table, int depth);

// A plain row's value by its type; none for a composite (kOther).
std::optional<Members> PlainSchema(const SchemaRow& row, int depth) {
  switch (row.value) {
    case ValueType::kNumber:
      return Number(row.bounds, false);
    case ValueType::kInteger:
      return Number(row.bounds, true);
    case ValueType::kBool:
      return Members{{"type", "\"boolean\""}};
    case ValueType::kWord:
      return Choice(row.words);
    case ValueType::kText:
      return Text();
    case ValueType::kPoint:
      return Point(depth);
    case ValueType::kPair:
      return ListOf(Number(std::nullopt, false), 2, depth);
    case ValueType::kOther:
      break;
  }
  return std::nullopt;
}

// A composite row's value by its type (the reference's type column): the rows say such a value's
// type in the words the reference prints; this is where those words become JSON Schema types.
Members ValueSchema(const SchemaRow& row, int depth) {
  if (auto plain = PlainSchema(row, depth)) return *plain;
  const std::string& type = row.type;
  const auto& range = row.bounds;
  if (IsTable(row.Path())) {  // a map of its own table's keys, or a list of them
    return type == "list" ? ListOf(TableSchema(row.Path(), depth + 1), 0, depth)
                          : TableSchema(row.Path(), depth);
  }
  if (type == "path") return Text();
  if (type == "a node selection") return {{"$ref", JsonString("#/$defs/nodes")}};
  if (type == "[2]") return ListOf(Number(std::nullopt, false), 2, depth);
  if (type == "[2] integers") return ListOf(Number(range, true), 2, depth);
  if (type == "list of [3]") return ListOf(Point(depth + 1), 0, depth);
  if (type == "list") return ListOf(Number(std::nullopt, false), 0, depth);  // mesh.u, mesh.v
  if (type == "list, no repeats") return UniqueListOf(Choice(OutputKindNames()), depth);
  if (type.rfind("list of `x`", 0) == 0) return UniqueListOf(Choice({"x", "y", "z"}), depth);
  const SchemaRange index = Whole(AtLeast(0));
  if (type == "list of integers ≥ 0") return ListOf(Number(index, true), 0, depth);
  if (type == "integer ≥ 0") return Number(index, true);
  if (type == "list of [i, j]") {
    return ListOf(ListOf(Number(index, true), 2, depth + 1), 0, depth);
  }
  if (type == "number or `{warp: …, weft: …}`") {
    const Members number = Number(range, false);
    const std::string one = JsonObject(number, depth + 3);
    return AnyOf({number, ObjectOf({{"warp", one}, {"weft", one}}, {"warp", "weft"}, depth + 1)},
                 depth);
  }
  if (type == "`initial` \\| `zero` \\| a length") {
    return AnyOf({Choice({"initial", "zero"}), Number(range, false)}, depth);
  }
  if (type == "`{from: [3], to: [3]}`") {
    const std::string point = JsonObject(Point(depth + 3), depth + 3);
    return ObjectOf({{"from", point}, {"to", point}}, {"from", "to"}, depth);
  }
  if (type == "`{min: [3], max: [3]}`") {
    const std::string point = JsonObject(Point(depth + 3), depth + 3);
    return ObjectOf({{"min", point}, {"max", point}}, {"min", "max"}, depth);
  }
  if (type == "`{center: [3], radius: > 0}`") {
    return ObjectOf({{"center", JsonObject(Point(depth + 3), depth + 3)},
                     {"radius", JsonObject(Number(Above(0), false), depth + 3)}},
                    {"center", "radius"}, depth);
  }
  if (type == "`true`") return {{"const", "true"}};
  if (type == "map" || type == "map of numbers") return {{"type", "\"object\""}};
  return Choice(Backticked(type));  // `a` \| `b`
}

// The description of a row: its doc, with its unit.
std::string Description(const SchemaRow& row) {
  std::string text = row.doc;
  if (!row.unit.empty() && row.unit != "1")
    text += (text.empty() ? "" : " ") + ("[" + row.unit + "]");
  if (!row.kinds.empty()) {
    std::string kinds;
    for (const auto& kind : row.kinds) kinds += (kinds.empty() ? "" : ", ") + kind;
    text += (text.empty() ? "" : " ") + ("(for " + kinds + ")");
  }
  return text;
}

// The default as JSON; "" for none (a default in words).
std::string DefaultJson(const SchemaRow& row) {
  return row.default_yaml.empty() ? "" : YamlAsJson(YAML::Load(row.default_yaml));
}

// The schema of a row: its value's, with a description and a default.
std::string RowSchema(const SchemaRow& row, int depth) {
  Members members = ValueSchema(row, depth);
  const std::string description = Description(row);
  if (!description.empty()) members.emplace_back("description", JsonString(description));
  const std::string fallback = DefaultJson(row);
  if (!fallback.empty()) members.emplace_back("default", fallback);
  return JsonObject(members, depth);
}

// A key whose rows differ by kind: any of the rows' values, each with its own description.
std::string KindsSchema(const SchemaRow* first, const std::vector<const SchemaRow*>& others,
                        int depth) {
  std::vector<std::string> choices = {RowSchema(*first, depth + 1)};
  for (const SchemaRow* row : others) choices.push_back(RowSchema(*row, depth + 1));
  return JsonObject({{"anyOf", JsonList(choices)}}, depth);
}

// The solver's methods: each an object of its options, with their ranges.
Members MethodProperties(int depth) {
  Members methods;
  for (const SolverMethod& method : SolverMethods()) {
    Members options;
    for (const MethodOption& option : method.options) {
      SchemaRange range;
      range.lower = option.min;
      range.upper = option.max;
      range.lower_inclusive = !option.min_exclusive;
      range.upper_inclusive = !option.max_exclusive;
      Members members = Number(range, option.integer);
      if (option.zero_means_none) members = Number(std::nullopt, option.integer);
      members.emplace_back("description", JsonString(option.doc));
      if (option.default_value) members.emplace_back("default", JsonNumber(*option.default_value));
      options.emplace_back(option.key, JsonObject(members, depth + 2));
    }
    Members object = ObjectOf(options, {}, depth);
    object.emplace_back("description", JsonString(method.description));
    methods.emplace_back(method.name, JsonObject(object, depth));
  }
  return methods;
}

bool Takes(const SchemaRow& row, const std::string& kind) {
  return row.kinds.empty() ||
         std::find(row.kinds.begin(), row.kinds.end(), kind) != row.kinds.end();
}

// An obstacle: one kind, {sphere: {center: …, radius: …}}.
Members ObstacleSchema(int depth) {
  std::vector<std::string> kinds;
  for (const SchemaRow* row : SchemaRows("obstacles")) {
    for (const auto& kind : row->kinds) {
      if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
    }
  }
  Members properties;
  for (const std::string& kind : kinds) {
    Members keys;
    std::vector<std::string> required;
    for (const SchemaRow* row : SchemaRows("obstacles")) {
      if (!Takes(*row, kind)) continue;
      keys.emplace_back(row->key, RowSchema(*row, depth + 4));
      if (row->default_text == "**required**") required.push_back(row->key);
    }
    properties.emplace_back(kind, JsonObject(ObjectOf(keys, required, depth + 2), depth + 2));
  }
  return {{"type", "\"object\""},
          {"properties", JsonObject(properties, depth + 1)},
          {"additionalProperties", "false"},
          {"minProperties", "1"},
          {"maxProperties", "1"}};
}

// A map's keys (each row of `table` once: a key of two kinds, mesh.nodes, takes the first row's
// schema); the solver's also takes each method's options.
Members TableSchema(const std::string& table, int depth) {
  if (table == "obstacles") return ObstacleSchema(depth);
  Members properties;
  std::vector<std::string> required;
  const auto rows = SchemaRows(table);
  for (size_t k = 0; k < rows.size(); ++k) {
    const SchemaRow* row = rows[k];
    if (row->key.front() == '<') continue;  // solver.<method>: below
    const bool seen = std::any_of(properties.begin(), properties.end(),
                                  [&](const auto& property) { return property.first == row->key; });
    if (seen) continue;
    std::vector<const SchemaRow*> same;  // a key of two kinds: mesh.nodes of a grid and a chain
    for (size_t j = k + 1; j < rows.size(); ++j) {
      if (rows[j]->key == row->key) same.push_back(rows[j]);
    }
    properties.emplace_back(
        row->key, same.empty() ? RowSchema(*row, depth + 2) : KindsSchema(row, same, depth + 2));
    const bool made_by_drape_test = table.empty() && row->key == "mesh";
    if (row->default_text == "**required**" && row->kinds.empty() && !made_by_drape_test) {
      required.push_back(row->key);
    }
  }
  if (table == "solver") {
    for (auto& method : MethodProperties(depth + 2)) properties.push_back(std::move(method));
  }
  Members object = ObjectOf(properties, required, depth);
  if (table.empty()) {  // a cross-key rule of the loader's: a drape test makes the mesh
    auto required_key = [](const char* key) {
      return JsonInlineObject({{"required", JsonList(JsonStrings({key}))}});
    };
    object.emplace_back("anyOf", JsonList({required_key("mesh"), required_key("drape_test")}));
  }
  return object;
}

}  // namespace

std::string SceneSchemaRowsJson() {
  std::vector<std::string> rows;
  for (const SchemaRow& row : SceneSchema()) {
    Members members = {
        {"table", JsonString(row.table)}, {"key", JsonString(row.key)},
        {"path", JsonString(row.Path())}, {"kinds", JsonList(JsonStrings(row.kinds))},
        {"type", JsonString(row.type)},   {"unit", JsonString(row.unit)},
        {"range", JsonString(row.range)}};
    if (const auto& range = row.bounds) {
      for (auto& member : BoundMembers(range)) members.push_back(std::move(member));
      members.emplace_back("integer", JsonBool(range->integer));
    }
    members.emplace_back("default_text", JsonString(row.default_text));
    const std::string fallback = DefaultJson(row);
    if (!fallback.empty()) members.emplace_back("default", fallback);
    members.emplace_back("doc", JsonString(row.doc));
    rows.push_back(JsonObject(members, 2));
  }
  return JsonObject({{"rows", JsonListLines(rows, 1)}}, 0) + "\n";
}

std::string SceneJsonSchema() {
  Members schema = {{"$schema", JsonString("https://json-schema.org/draft/2020-12/schema")},
                    {"$id", JsonString("urn:drape:scene")},
                    {"title", JsonString("drape scene")},
                    {"description", JsonString("A scene file of drape (docs/reference.md, "
                                               "\"Scene reference\"), generated by `drape schema "
                                               "--json-schema` from the scene schema.")},
                    {"$defs", JsonObject({{"nodes", JsonObject(TableSchema("nodes", 2), 2)}}, 1)}};
  for (auto& member : TableSchema("", 0)) schema.push_back(std::move(member));
  return JsonObject(schema, 0) + "\n";
}

}  // namespace drape
