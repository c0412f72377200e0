// A mesh obstacle's file (`obstacles: [{mesh: {file: form.obj, scale, rotation, translation}}]`),
// read when the scene is loaded: its errors are the scene's, located at the `file` key.
#ifndef DRAPE_SRC_SCENE_OBSTACLE_MESH_H_
#define DRAPE_SRC_SCENE_OBSTACLE_MESH_H_

#include <string>

#include "src/scene/scene.h"

namespace drape {

// Resolves obstacle->file against the scene's folder, reads it (OBJ, PLY or STL,
// src/scene/mesh_file.h), places its vertices (PlaceVertex), triangulates its polygons as fans
// and sets obstacle->surface. Throws InputError at the `file` key, naming the place in the mesh
// file, for an unreadable or malformed file and for a surface that is not closed and outward
// oriented (src/geometry/triangle_surface.h).
void LoadObstacleMesh(const std::string& scene_directory, ObstacleSpec* obstacle);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_OBSTACLE_MESH_H_
