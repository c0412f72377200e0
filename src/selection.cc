#include "src/selection.h"

namespace drape {
std::vector<int> SelectNodes(const NodeSelector& selector, const Mesh& mesh) {
  throw InputError(selector.where, "selections are not implemented yet");
}
}  // namespace drape
