// `drape check --json`: the scene as scene.yaml writes it (src/output/scene_yaml.h: the `--set`
// overrides applied, every default filled in, SI units), as JSON whose every value carries its
// unit from the scene schema (src/scene/scene_schema.h): a map stays an object, a list of maps an
// array, and every other value (a number, a text, a list of numbers) is a leaf
// {"value": ..., "unit": "N/m"} ("unit" is "" where the key has none, "1" for a ratio).
#ifndef DRAPE_SRC_OUTPUT_SCENE_JSON_H_
#define DRAPE_SRC_OUTPUT_SCENE_JSON_H_

#include <yaml-cpp/yaml.h>

#include <string>

#include "src/scene/scene.h"

namespace drape {

std::string SceneJson(const Scene& scene);

// A YAML value as JSON: numbers and true/false as such (a quoted scalar stays a text), lists as
// arrays, maps as objects, on one line.
std::string YamlAsJson(const YAML::Node& node);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_SCENE_JSON_H_
