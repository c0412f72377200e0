// The fabric's surface as the result files draw it (mesh.vtk, mesh.obj, drape.glb): triangle
// areas, vertex normals, the flat pattern as texture coordinates, and a per-vertex stretch.
#ifndef DRAPE_SRC_OUTPUT_SURFACE_FIELDS_H_
#define DRAPE_SRC_OUTPUT_SURFACE_FIELDS_H_

#include <Eigen/Core>
#include <array>
#include <vector>

#include "src/model/model.h"

namespace drape {

// The area of triangle `t` at `positions` (3 doubles per node), m².
double TriangleArea(const std::vector<double>& positions, const std::array<int, 3>& t);

// Area-weighted vertex normals of the surface at the solved positions (zero where no triangle).
std::vector<Eigen::Vector3d> VertexNormals(const Model& model);

// The flat pattern as texture coordinates: the start positions on their two widest axes, scaled
// by the larger extent into [0, 1] (the aspect ratio kept).
std::vector<std::array<double, 2>> PatternCoordinates(const Model& model);

// Each node's area stretch: the area of its triangles now over their area at the start, minus 1;
// 0 for a node in no triangle, and for every node where the start is not known.
std::vector<double> VertexAreaStretch(const Model& model);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_SURFACE_FIELDS_H_
