// Surface mesh files: Wavefront OBJ, PLY (ASCII, binary little- and big-endian) and STL (ASCII
// and binary). The one reader of mesh files: `mesh: {kind: file}` (src/model/mesh.cc) and the
// point clouds of `drape fit` (src/fit/fit_file.cc) both read through it.
#ifndef DRAPE_SRC_SCENE_MESH_FILE_H_
#define DRAPE_SRC_SCENE_MESH_FILE_H_

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

namespace drape {

// Where in a mesh file something is: a line (text files, from 1) or a byte offset (binary files,
// from 0); neither when the whole file is meant.
struct FilePlace {
  int line = 0;         // > 0 for a text file's line
  long long byte = -1;  // >= 0 for a binary file's byte offset
};

// "path", "path:12" or "path: byte 84".
std::string PlaceText(const std::string& path, const FilePlace& place);

// A malformed mesh file: the message is "path:line: what" or "path: byte N: what".
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MeshFileData {
  std::vector<Eigen::Vector3d> vertices;  // finite, in file order (STL: coincident ones merged)
  std::vector<std::vector<int>> faces;    // 0-based vertex ids, not yet range-checked
  std::vector<FilePlace> face_places;     // where each face is in the file, for errors
};

// Reads `path` by its extension (.obj, .ply or .stl, any case). OBJ: `v` and `f` statements
// (`f a/t/n`, negative = relative). PLY: the header's elements in order, any of char/uchar/
// short/ushort/int/uint/float/double (and the int8 … float64 names), the `vertex` element's x, y,
// z and the `face` element's first list. STL: every facet a triangle; vertices that are exactly
// equal once read are merged, so the triangles share them. Throws MeshFileError for an unreadable
// file, an unknown extension or malformed contents (a non-finite coordinate, a truncated body, a
// bad index), never anything else.
MeshFileData ReadMeshFile(const std::string& path);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_MESH_FILE_H_
