// `--set key.path=value` overrides, applied to a scene document before it is validated.
#ifndef DRAPE_SRC_SCENE_YAML_OVERRIDES_H_
#define DRAPE_SRC_SCENE_YAML_OVERRIDES_H_

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "src/scene/yaml_reader.h"

namespace drape {

// Sets each "key.path=value" in `root` (a path may index lists: `fixed[0].dofs`); the value is
// parsed as YAML. Missing maps along the path are created; a list index must exist. Every grafted
// node is registered with `origins` so that later errors point at the override. Throws InputError
// (file "--set", line = the override's number, column = the offending character) for a malformed
// override, an index out of range, or a path through something that is not a map.
void ApplyOverrides(YAML::Node& root, const std::vector<std::string>& overrides,
                    YamlOrigins* origins);

// A value set at a key path without text: what a fit, a sweep task or a fabric row gives the
// scene (a number as a double, exactly; a list or a map as YAML nodes).
struct SceneValue {
  std::string key;   // a key path, as an override names it: "material.finite_volume.D_warp"
  YAML::Node value;  // a scalar, list or map; cloned into the document
};

// Sets each value at its key path as ApplyOverrides does, numbering them from `first_index` for
// the messages' locations (file "--set", line = number + 1: after the text overrides).
void ApplyValues(YAML::Node& root, const std::vector<SceneValue>& values, int first_index,
                 YamlOrigins* origins);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_YAML_OVERRIDES_H_
