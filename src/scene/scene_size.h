// The size of the model a scene asks for, known before anything is built: the node count of its
// mesh and a rough memory estimate. The scene loader refuses a mesh above mesh.max_nodes
// (default MeshSpec::max_nodes) with a located message, so that a typo such as
// `nodes: [100000, 100000]` costs nothing instead of gigabytes.
#ifndef DRAPE_SRC_SCENE_SCENE_SIZE_H_
#define DRAPE_SRC_SCENE_SCENE_SIZE_H_

#include "src/scene/scene.h"

namespace drape {

// Memory per node of a solve, a rough upper figure: the model's terms and state, the sparse
// Hessian (27 neighbours × 9 entries) and its Cholesky factor with fill-in.
constexpr double kBytesPerNode = 4096.0;

// The nodes the mesh will have (for a circle, the lattice squares the mesher visits, an upper
// bound); 0 for a mesh file (its size is known once it is read). A double: it may exceed int.
double EstimatedNodes(const MeshSpec& mesh);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_SIZE_H_
