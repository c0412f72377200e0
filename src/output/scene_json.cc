#include "src/output/scene_json.h"

#include <yaml-cpp/yaml.h>

#include <sstream>
#include <string>
#include <utility>

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
    std::string text = "{";
    for (const auto& entry : node) {
      text += (text.size() > 1 ? ", " : "") + JsonString(entry.first.Scalar()) + ": " +
              YamlAsJson(entry.second);
    }
    return text + "}";
  }
  if (!node.IsSequence()) return JsonScalar(node);
  std::string text = "[";
  for (const auto& item : node) text += (text.size() > 1 ? ", " : "") + YamlAsJson(item);
  return text + "]";
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

void Write(const YAML::Node& node, const std::string& path, const std::string& indent,
           std::ostream& out) {
  if (IsLeaf(node)) {
    out << "{\"value\": " << YamlAsJson(node)
        << ", \"unit\": " << JsonString(AsciiUnit(SchemaUnit(path))) << "}";
    return;
  }
  const std::string inner = indent + "  ";
  if (node.IsSequence()) {
    out << "[";
    for (size_t k = 0; k < node.size(); ++k) {
      out << (k == 0 ? "\n" : ",\n") << inner;
      Write(node[k], path + "[" + std::to_string(k) + "]", inner, out);
    }
    out << (node.size() == 0 ? "" : "\n" + indent) << "]";
    return;
  }
  out << "{";
  bool first = true;
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    out << (first ? "\n" : ",\n") << inner << JsonString(key) << ": ";
    Write(entry.second, path.empty() ? key : path + "." + key, inner, out);
    first = false;
  }
  out << (first ? "" : "\n" + indent) << "}";
}

}  // namespace

std::string SceneJson(const Scene& scene) {
  std::ostringstream yaml;
  WriteSceneYaml(scene, yaml);
  std::ostringstream json;
  Write(YAML::Load(yaml.str()), "", "", json);
  json << "\n";
  return json.str();
}

}  // namespace drape
