#include "src/output/scene_json.h"

#include <yaml-cpp/yaml.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "src/output/json.h"
#include "src/output/scene_yaml.h"
#include "src/scene/number_text.h"
#include "src/scene/scene_schema.h"

namespace drape {
namespace {

// A value without maps inside: a number, a text, a list of numbers or of [3] lists.
bool IsLeaf(const YAML::Node& node) {
  if (node.IsMap()) return false;
  if (!node.IsSequence()) return true;
  for (const auto& item : node) {
    if (!IsLeaf(item)) return false;
  }
  return true;
}

// scene.yaml's scalars: numbers, true/false, texts (quoted ones always texts).
std::string JsonScalar(const YAML::Node& node) {
  if (node.IsNull()) return "null";
  const std::string& text = node.Scalar();
  if (node.Tag() != "!") {
    if (text == "true" || text == "false") return text;
    if (WholeNumber(text)) return text;
  }
  return JsonString(text);
}

}  // namespace

std::string YamlAsJson(const YAML::Node& node) {
  if (node.IsMap()) {
    std::vector<std::pair<std::string, std::string>> members;
    for (const auto& entry : node) {
      members.emplace_back(entry.first.Scalar(), YamlAsJson(entry.second));
    }
    return JsonInlineObject(members);
  }
  if (!node.IsSequence()) return JsonScalar(node);
  std::vector<std::string> items;
  for (const auto& item : node) items.push_back(YamlAsJson(item));
  return JsonList(items);
}

namespace {

// The schema's unit as summary.json writes units: ASCII ("kg/m^2", "N*m"), not the reference's
// typography ("kg/m²", "N·m").
std::string AsciiUnit(std::string unit) {
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"²", "^2"}, {"³", "^3"}, {"·", "*"}}) {
    for (size_t at = unit.find(from); at != std::string::npos; at = unit.find(from, at)) {
      unit.replace(at, from.size(), to);
    }
  }
  return unit;
}

// The scene's node at `path` as JSON at `depth`: maps and lists one member a line, each leaf
// {"value": ..., "unit": ...}.
std::string SceneNodeJson(const YAML::Node& node, const std::string& path, int depth) {
  if (IsLeaf(node)) {
    return JsonInlineObject(
        {{"value", YamlAsJson(node)}, {"unit", JsonString(AsciiUnit(SchemaUnit(path)))}});
  }
  if (node.IsSequence()) {
    std::vector<std::string> items;
    for (size_t k = 0; k < node.size(); ++k) {
      items.push_back(SceneNodeJson(node[k], path + "[" + std::to_string(k) + "]", depth + 1));
    }
    return JsonListLines(items, depth);
  }
  std::vector<std::pair<std::string, std::string>> members;
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    members.emplace_back(
        key, SceneNodeJson(entry.second, path.empty() ? key : path + "." + key, depth + 1));
  }
  return JsonObject(members, depth);
}

}  // namespace

std::string SceneJson(const Scene& scene) {
  std::ostringstream yaml;
  WriteSceneYaml(scene, yaml);
  return SceneNodeJson(YAML::Load(yaml.str()), "", 0) + "\n";
}

}  // namespace drape
