// The scene schema (src/scene/scene_schema.h) for machines: `drape schema --json` prints its rows
// with numbers as numbers, `drape schema --json-schema` a JSON Schema (draft 2020-12) of a scene
// file, which an editor's YAML extension uses for completion and checking (yaml-language-server:
// `# yaml-language-server: $schema=scene.schema.json` on a scene's first line).
// tests/scene_json_schema_test.py validates every shipped scene against it.
#ifndef DRAPE_SRC_OUTPUT_SCENE_JSON_SCHEMA_H_
#define DRAPE_SRC_OUTPUT_SCENE_JSON_SCHEMA_H_

#include <string>

namespace drape {

// Every row: table, key, kinds, type, unit, range (as text and as numbers: minimum, maximum,
// exclusive or not, integer), default (as text and, where it is one literal, as a value), doc.
std::string SceneSchemaRowsJson();

// A JSON Schema of a scene file: each map's keys (no others), their types, units (in the
// descriptions), bounds, choices and defaults; lists of supports, loads, regions and obstacles;
// node selections; each solver method's options with their ranges.
std::string SceneJsonSchema();

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_SCENE_JSON_SCHEMA_H_
