#include "src/scene/obstacle_mesh.h"

#include <array>
#include <utility>
#include <vector>

#include "src/geometry/triangle_surface.h"
#include "src/scene/file_paths.h"
#include "src/scene/mesh_file.h"

namespace drape {

void LoadObstacleMesh(const std::string& scene_directory, ObstacleSpec* obstacle) {
  const auto key = obstacle->given.find("file");
  if (key == obstacle->given.end()) return;  // the model build reports the missing key
  const Location where = key->second;
  if (obstacle->file.empty())
    throw InputError(where, "expected the path of an OBJ, PLY or STL file");
  obstacle->file = ResolvePath(scene_directory, obstacle->file);
  MeshFileData data;
  try {
    data = ReadMeshFile(obstacle->file);
  } catch (const MeshFileError& error) {
    throw InputError(where, error.what());
  }
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(data.vertices.size());
  for (const Eigen::Vector3d& v : data.vertices) {
    vertices.push_back(PlaceVertex(v, obstacle->scale, obstacle->rotation, obstacle->translation));
  }
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> face_of_triangle;
  for (size_t f = 0; f < data.faces.size(); ++f) {
    const std::vector<int>& face = data.faces[f];
    if (face.size() < 3) {
      throw InputError(where, PlaceText(obstacle->file, data.face_places[f]) +
                                  ": a face needs at least 3 vertices");
    }
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      triangles.push_back({face[0], face[k], face[k + 1]});
      face_of_triangle.push_back(static_cast<int>(f));
    }
  }
  try {
    obstacle->surface = TriangleSurface::Make(std::move(vertices), std::move(triangles));
  } catch (const SurfaceError& error) {
    const FilePlace place =
        error.face >= 0 ? data.face_places[face_of_triangle[error.face]] : FilePlace{};
    throw InputError(where, PlaceText(obstacle->file, place) + ": " + error.what());
  }
}

}  // namespace drape
