#include "src/scene/yaml_overrides.h"

#include <cctype>

namespace drape {
namespace {

// One step of a key path: a name, then list indices (`fixed[0]` → "fixed", {0}).
struct PathStep {
  std::string name;
  int offset = 0;  // 0-based position of the name in the override text
  std::vector<int> indices;
};

// An override being applied: its text and number, for messages.
struct Override {
  const std::string& text;
  int index;

  [[noreturn]] void Fail(int offset, const std::string& what) const {
    throw InputError(Location{"--set", index + 1, offset + 1, ""},
                     "bad --set '" + text + "': " + what);
  }
};

std::vector<PathStep> ParsePath(const Override& override, const std::string& path) {
  std::vector<PathStep> steps;
  size_t at = 0;
  while (true) {
    PathStep step;
    step.offset = static_cast<int>(at);
    while (at < path.size() && path[at] != '.' && path[at] != '[' && path[at] != ']') {
      step.name += path[at++];
    }
    if (step.name.empty()) override.Fail(step.offset, "expected a key name");
    while (at < path.size() && path[at] == '[') {
      const size_t close = path.find(']', at);
      const std::string digits =
          close == std::string::npos ? "" : path.substr(at + 1, close - at - 1);
      if (digits.empty() || digits.size() > 6 ||
          digits.find_first_not_of("0123456789") != std::string::npos) {
        override.Fail(static_cast<int>(at), "expected a list index such as [0]");
      }
      step.indices.push_back(std::stoi(digits));
      at = close + 1;
    }
    steps.push_back(step);
    if (at == path.size()) return steps;
    if (path[at] != '.') override.Fail(static_cast<int>(at), "expected '.' between keys");
    ++at;
  }
}

std::string PathUpTo(const std::string& path, const PathStep& step) {
  return path.substr(0, step.offset + step.name.size());
}

// A new map or list holding the same entries as `node` (each entry shared, with its marks): the
// copy a graft changes, so that the document it came from stays as it was read. It stands in for
// `node` in locations.
YAML::Node ShallowCopy(const YAML::Node& node, YamlOrigins* origins) {
  YAML::Node copy(node.IsSequence() ? YAML::NodeType::Sequence : YAML::NodeType::Map);
  if (node.IsSequence()) {
    // Each item a new node sharing the item's value: assigning to it later leaves the item be
    // (push_back(item) would put the item's own node in both lists).
    for (const YAML::Node& item : node) {
      copy.push_back(YAML::Node(YAML::NodeType::Null));
      copy[copy.size() - 1] = item;
    }
  } else if (node.IsMap()) {
    for (const auto& entry : node) copy[entry.first] = entry.second;
  }
  if (node.IsDefined()) copy.SetStyle(node.Style());
  origins->AddCopy(copy, node);
  return copy;
}

struct Graft {
  const Override& override;
  const std::string& path;
  const std::vector<PathStep>& steps;
  const YAML::Node& value;
  int value_offset;
  YamlOrigins* origins;

  // `map` (a node of the document, or nothing) with the path from step `s` on set to the value:
  // a new node; `map` itself is not changed.
  YAML::Node Into(const YAML::Node& map, size_t s) const {
    const PathStep& step = steps[s];
    const bool last = s + 1 == steps.size();
    if (map.IsDefined() && !map.IsMap() && !map.IsNull()) {
      override.Fail(step.offset, "cannot set '" + step.name + "' inside " + Describe(map));
    }
    YAML::Node copy = ShallowCopy(map, origins);
    if (last && step.indices.empty()) {
      copy[step.name] = value;
      origins->AddOverride(value, override.index, step.offset, value_offset);
      return copy;
    }
    // A const lookup inserts nothing; a missing key gives an undefined node (a zombie that only
    // answers IsDefined: copied, not reset from).
    const YAML::Node found = map.IsMap() ? map[step.name] : YAML::Node();
    YAML::Node child;
    if (found.IsDefined() && !found.IsNull()) {
      child.reset(found);
    } else {
      if (!step.indices.empty()) {
        override.Fail(step.offset, "'" + PathUpTo(path, step) + "' is not a list");
      }
      child.reset(YAML::Node(YAML::NodeType::Map));
      origins->AddOverride(child, override.index, step.offset, step.offset);
    }
    copy[step.name] = Items(child, s, 0);
    return copy;
  }

  // The list `list` (indexed by step `s`'s index `k`) with the rest of the path set.
  YAML::Node Items(const YAML::Node& list, size_t s, size_t k) const {
    const PathStep& step = steps[s];
    if (k == step.indices.size()) {
      return s + 1 == steps.size() ? value : Into(list, s + 1);
    }
    const std::string where = PathUpTo(path, step) + (k ? "[...]" : "");
    const int index = step.indices[k];
    if (!list.IsSequence()) override.Fail(step.offset, "'" + where + "' is not a list");
    if (index >= static_cast<int>(list.size())) {
      override.Fail(step.offset, "'" + where + "' has no item " + std::to_string(index) +
                                     " (it has " + std::to_string(list.size()) + ")");
    }
    YAML::Node copy = ShallowCopy(list, origins);
    const bool leaf = s + 1 == steps.size() && k + 1 == step.indices.size();
    copy[index] = Items(list[index], s, k + 1);
    if (leaf) origins->AddOverride(value, override.index, step.offset, value_offset);
    return copy;
  }
};

// `root` with `value` put at the key path `path` (grafted nodes registered with `origins` as
// override `override.index`).
YAML::Node Grafted(const YAML::Node& root, const Override& override, const std::string& path,
                   const YAML::Node& value, int value_offset, YamlOrigins* origins) {
  const auto steps = ParsePath(override, path);
  return Graft{override, path, steps, value, value_offset, origins}.Into(root, 0);
}

void ApplyOverride(YAML::Node& root, const Override& override, YamlOrigins* origins) {
  const size_t equals = override.text.find('=');
  if (equals == std::string::npos) override.Fail(0, "expected key.path=value");
  const int value_offset = static_cast<int>(equals) + 1;
  YAML::Node value;
  try {
    value.reset(YAML::Load(override.text.substr(equals + 1)));
  } catch (const YAML::Exception& error) {
    override.Fail(value_offset + std::max(0, error.mark.column), error.msg);
  }
  // reset, not operator=: that would write the new root into the document `root` refers to.
  root.reset(
      Grafted(root, override, override.text.substr(0, equals), value, value_offset, origins));
}

}  // namespace

void ApplyOverrides(YAML::Node& root, const std::vector<std::string>& overrides,
                    YamlOrigins* origins) {
  for (size_t k = 0; k < overrides.size(); ++k) {
    ApplyOverride(root, Override{overrides[k], static_cast<int>(k)}, origins);
  }
}

void ApplyValues(YAML::Node& root, const std::vector<SceneValue>& values, int first_index,
                 YamlOrigins* origins) {
  for (size_t k = 0; k < values.size(); ++k) {
    // The text only names the value in a message about its path, as "key=value".
    YAML::Emitter emitter;
    emitter << YAML::Flow << values[k].value;
    const std::string text = values[k].key + "=" + emitter.c_str();
    const int value_offset = static_cast<int>(values[k].key.size()) + 1;
    root.reset(Grafted(root, Override{text, first_index + static_cast<int>(k)}, values[k].key,
                       values[k].value, value_offset, origins));
  }
}

}  // namespace drape
