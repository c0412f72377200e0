// Mesh generation: node positions and the topology the spring families follow.
#ifndef DRAPE_SRC_MODEL_MESH_H_
#define DRAPE_SRC_MODEL_MESH_H_

#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

using Link = std::array<int, 2>;

// The part of a specimen its triangles leave out: on a circle mesh, the strip between the
// lattice's staircase outline and the circle. Each point is an affine combination of node
// positions, x = Σ w_k x_k with Σ w_k = 1, fitted so that an affine map of the flat specimen moves
// it with the nodes: in the flat state the outer points lie on the circle, and on a draped specimen
// they follow the deformation gradient of the boundary they extend (least squares over the
// boundary node's triangle neighbours). Triangles index nodes (< node count) and then these points
// (node count + k); the drape coefficient's shadow and flat area include them.
struct Fringe {
  std::vector<std::vector<std::pair<int, double>>> points;
  std::vector<std::array<int, 3>> triangles;
};

// `positions` (3 doubles per node) followed by the fringe's points at those positions.
std::vector<double> WithFringePoints(const Fringe& fringe, const std::vector<double>& positions);

struct Mesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 2>> grid_index;  // (i, j) per node; (-1, -1) where not a grid
  int nu = 0, nv = 0;                          // grid: node counts along u and v (else 0)
  // Spring topology, by family. Grid and circle: warp along u (x), weft along v; arc: warp along
  // the spokes, weft around the rings; chain: warp along the line; file: warp = the mesh edges.
  std::vector<Link> warp, weft;
  std::vector<Link> shear;                       // diagonals of each quad
  std::vector<Link> flexion_warp, flexion_weft;  // skip-one neighbours
  std::vector<std::array<int, 3>> triangles;     // surface, for output and areas
  std::vector<Link> lines;                       // line elements (chains), for output
  std::vector<double> area;                      // lumped area per node, m² (0 for a chain)
  std::vector<double> length;                    // lumped length per node, m (chains)
  std::vector<Link> loop;  // closed chain: its links in order around the loop (else empty)
  Fringe fringe;           // circle: the specimen beyond the triangles (else empty)
};

// Builds the mesh of `spec`. Throws InputError (at spec.where) for fewer than 2 nodes, an
// unreadable or malformed mesh file, or coincident nodes.
Mesh BuildMesh(const MeshSpec& spec);

// The diagonal of the axis-aligned box around `points` (3 × n, one node per column), m; 0 for no
// points. Flat xyz storage (Model::positions) maps onto it with Eigen::Map<const Matrix3Xd>.
double BoundingDiagonal(const Eigen::Ref<const Eigen::Matrix3Xd>& points);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_MESH_H_
