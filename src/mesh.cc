#include "src/mesh.h"

namespace drape {
Mesh BuildMesh(const MeshSpec& spec) {
  throw InputError(spec.where, "meshes are not implemented yet");
}
}  // namespace drape
