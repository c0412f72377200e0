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

// The item `index` of the list `node`, which `where` names.
YAML::Node Item(const Override& override, YAML::Node& node, int index, const std::string& where,
                int offset) {
  const YAML::Node& list = node;
  if (!list.IsSequence()) override.Fail(offset, "'" + where + "' is not a list");
  if (index >= static_cast<int>(list.size())) {
    override.Fail(offset, "'" + where + "' has no item " + std::to_string(index) + " (it has " +
                              std::to_string(list.size()) + ")");
  }
  return node[index];
}

// Sets `value` at the key path `path` of `root`, in place (creating missing maps), registering
// the grafted nodes with `origins` as override `override.index`.
void Graft(YAML::Node& root, const Override& override, const std::string& path,
           const YAML::Node& value, int value_offset, YamlOrigins* origins) {
  const auto steps = ParsePath(override, path);
  YAML::Node current = root;
  for (size_t s = 0; s < steps.size(); ++s) {
    const PathStep& step = steps[s];
    const bool last = s + 1 == steps.size();
    const YAML::Node& map = current;
    if (!map.IsMap() && !map.IsNull()) {
      override.Fail(step.offset, "cannot set '" + step.name + "' inside " + Describe(map));
    }
    if (last && step.indices.empty()) {
      current[step.name] = value;
      origins->AddOverride(value, override.index, step.offset, value_offset);
      return;
    }
    const YAML::Node found = map[step.name];  // const lookup: inserts nothing
    if (!found.IsDefined() || found.IsNull()) {
      if (!step.indices.empty()) {
        override.Fail(step.offset, "'" + PathUpTo(path, step) + "' is not a list");
      }
      YAML::Node made(YAML::NodeType::Map);
      current[step.name] = made;
      origins->AddOverride(made, override.index, step.offset, step.offset);
    }
    YAML::Node child = map[step.name];
    for (size_t k = 0; k < step.indices.size(); ++k) {
      const std::string where = PathUpTo(path, step) + (k ? "[...]" : "");
      YAML::Node item = Item(override, child, step.indices[k], where, step.offset);
      if (last && k + 1 == step.indices.size()) {
        item = value;  // operator= replaces the item inside the document
        origins->AddOverride(value, override.index, step.offset, value_offset);
        return;
      }
      child.reset(item);
    }
    current.reset(child);
  }
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
  Graft(root, override, override.text.substr(0, equals), value, value_offset, origins);
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
    // A clone: the graft puts the node itself into the document, which the caller's value must
    // not become part of (a sweep's value is set on every task's document).
    Graft(root, Override{text, first_index + static_cast<int>(k)}, values[k].key,
          YAML::Clone(values[k].value), value_offset, origins);
  }
}

}  // namespace drape
