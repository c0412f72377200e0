#include "src/scene/scene_size.h"

#include <cmath>

namespace drape {

double EstimatedNodes(const MeshSpec& mesh) {
  switch (mesh.kind) {
    case MeshSpec::Kind::kGrid:
      return static_cast<double>(mesh.nodes[0]) * static_cast<double>(mesh.nodes[1]);
    case MeshSpec::Kind::kCircle: {
      const double side = 2.0 * std::floor(mesh.radius / mesh.spacing * (1.0 + 1e-9)) + 1.0;
      return side * side;
    }
    case MeshSpec::Kind::kArc:
      return 1.0 + static_cast<double>(mesh.rings) * static_cast<double>(mesh.spokes);
    case MeshSpec::Kind::kChain:
      return mesh.points.empty() ? mesh.chain_nodes : static_cast<double>(mesh.points.size());
    case MeshSpec::Kind::kFile:
      return 0.0;
  }
  return 0.0;
}

}  // namespace drape
