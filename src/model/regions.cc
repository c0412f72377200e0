#include "src/model/regions.h"

#include <map>

#include "src/model/selection.h"
#include "src/scene/fabric_parameters.h"
#include "src/scene/material_keys.h"

namespace drape {

namespace {

void ApplyRegion(const RegionSpec& region, MaterialSpec* material) {
  material->where = region.where;
  if (region.density) material->mass_value = *region.density;
  if (!region.finite_volume.empty()) material->finite_volume.where = region.where;
  FiniteVolumeSpec& fv = material->finite_volume;
  for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
    const auto given = region.finite_volume.find(key.key);
    if (given != region.finite_volume.end()) fv.*key.member = given->second;
  }
  // A fabric whose twist follows the default rule keeps following it in a region that changes its
  // bending rigidities (src/scene/fabric_parameters.h); a region's own D_66 is given.
  if (region.finite_volume.count("D_66") > 0) {
    fv.twist_source = FiniteVolumeSpec::TwistSource::kGiven;
  } else if (fv.twist_source == FiniteVolumeSpec::TwistSource::kDefault) {
    fv.D_66 = DefaultTorsionalRigidity(fv.D_warp, fv.D_weft);
  }
  SpringsSpec& springs = material->springs;
  if (region.structural.present) springs.structural = region.structural;
  if (region.shear.present) springs.shear = region.shear;
  if (region.flexion.present) springs.flexion = region.flexion;
  if (region.tension_only) springs.tension_only = *region.tension_only;
}

}  // namespace

NodeMaterials AssignMaterials(const Scene& scene, const Mesh& mesh) {
  const int n = static_cast<int>(mesh.nodes.size());
  const int num_regions = static_cast<int>(scene.regions.size());
  std::vector<std::vector<int>> regions_of(n);  // the regions each node lies in, in order
  NodeMaterials result;
  result.counts.resize(num_regions);
  for (int r = 0; r < num_regions; ++r) {
    for (int node : SelectNodes(scene.regions[r].nodes, mesh)) regions_of[node].push_back(r);
  }
  result.materials.push_back(scene.material);
  result.of_node.assign(n, 0);
  std::map<std::vector<int>, int> index_of{{{}, 0}};
  for (int k = 0; k < n; ++k) {
    const std::vector<int>& in = regions_of[k];
    for (int r : in) ++result.counts[r].selected;
    if (in.empty()) continue;
    ++result.counts[in.back()].last;
    const auto [found, added] = index_of.emplace(in, static_cast<int>(result.materials.size()));
    if (added) {
      MaterialSpec material = scene.material;
      for (int r : in) ApplyRegion(scene.regions[r], &material);
      result.materials.push_back(material);
    }
    result.of_node[k] = found->second;
  }
  return result;
}

}  // namespace drape
