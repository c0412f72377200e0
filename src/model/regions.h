// Regions (the scene's `regions:`): the material of each node. Each region selects nodes (the
// selectors of `fixed`) and overrides, for those nodes, only the values it gives: density,
// finite-volume E/nu/G/D, spring families, tension_only. Regions apply in the order written, so
// where two overlap the later one's values win (key by key: a value only the earlier one gives
// stays). Nodes in no region keep the scene's material.
#ifndef DRAPE_SRC_MODEL_REGIONS_H_
#define DRAPE_SRC_MODEL_REGIONS_H_

#include <vector>

#include "src/model/mesh.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

struct NodeMaterials {
  // [0] the scene's material, then one per distinct set of regions some node lies in. A
  // region's material is located at the region (`where` of the material and of its
  // finite_volume), so that a combination found invalid later is reported there.
  std::vector<MaterialSpec> materials;
  std::vector<int> of_node;                // per node, its index in `materials`
  std::vector<Model::RegionCount> counts;  // per region

  const MaterialSpec& at(int node) const { return materials[of_node[node]]; }
};

// Throws InputError (located at the selection) for a region whose selection is empty or out of
// range.
NodeMaterials AssignMaterials(const Scene& scene, const Mesh& mesh);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_REGIONS_H_
