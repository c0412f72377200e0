// Node selections (`nodes:` under `fixed` and `loads.forces`).
#ifndef DRAPE_SRC_MODEL_SELECTION_H_
#define DRAPE_SRC_MODEL_SELECTION_H_

#include <vector>

#include "src/model/mesh.h"
#include "src/scene/scene.h"

namespace drape {

// The ids of the nodes `selector` picks, sorted, without repeats. Throws InputError (at
// selector.where) when the selection is empty, an id or (i, j) is out of range, or an edge or
// corner is asked of a mesh that has none.
std::vector<int> SelectNodes(const NodeSelector& selector, const Mesh& mesh);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_SELECTION_H_
