// Reading a scene file: YAML → Scene, with every key checked and every error located
// ("file:line:column: key.path: what is wrong"). Nothing is solved or written here.
#ifndef DRAPE_SRC_SCENE_SCENE_LOADER_H_
#define DRAPE_SRC_SCENE_SCENE_LOADER_H_

#include <string>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

// Loads and validates `path`. `overrides` are "key.path=value" strings (`--set`), applied to the
// document before validation; a value is parsed as YAML (`--set mesh.nodes=[30,30]`).
// Throws InputError on any bad input.
// The value an obstacle key holds (3 numbers for a point or vector, 1 for a length or friction), as
// the loader read it: what src/output/scene_yaml.cc writes back.
std::vector<double> ObstacleKeyValue(const ObstacleSpec& obstacle, const std::string& key);

Scene LoadScene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for a scene's YAML text (the Python module's drape.loads): errors are located in
// `label` (e.g. "<string>"), relative paths in it (mesh.path, output.directory) are taken from
// `directory`, and the scene's name, where it gives none, is "scene".
Scene LoadSceneText(const std::string& text, const std::string& label, const std::string& directory,
                    const std::vector<std::string>& overrides = {});

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_LOADER_H_
