// scene.yaml of a result folder: the scene as it was solved, written back as a scene file. The
// `--set` overrides are applied, every default is filled in (mesh, contact, solver limits and the
// chosen method's options), material parameters given as KES or Peirce measurements are written
// as the SI values they were converted to (material.finite_volume.E_warp ..., material.density),
// and paths are absolute. Loading it with `drape solve` gives the same model.
#ifndef DRAPE_SRC_OUTPUT_SCENE_YAML_H_
#define DRAPE_SRC_OUTPUT_SCENE_YAML_H_

#include <ostream>

#include "src/scene/scene.h"

namespace drape {

void WriteSceneYaml(const Scene& scene, std::ostream& out);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_SCENE_YAML_H_
