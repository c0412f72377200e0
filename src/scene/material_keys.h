// The finite-volume material's SI values by key (E_warp, E_weft, nu_warp, nu_weft, G, D_warp,
// D_weft, D_12, D_66, bending_friction_warp, bending_friction_weft): one list for the loader
// (material.finite_volume and regions), the scene.yaml writer and the regions' overrides
// (src/model/regions.h).
#ifndef DRAPE_SRC_SCENE_MATERIAL_KEYS_H_
#define DRAPE_SRC_SCENE_MATERIAL_KEYS_H_

#include <string>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

struct FiniteVolumeKey {
  std::string key;
  double FiniteVolumeSpec::*member;
  enum class Range { kPositive, kNonNegative, kAny };
  Range range;  // what a region may give (the material's own keys are read as before)
  std::string unit;
  // Reported (drape check, summary.json, scene.yaml) when 0 too; the friction is reported only
  // where a fabric has it.
  bool reported_when_zero = true;
};

// In the order scene.yaml writes them.
const std::vector<FiniteVolumeKey>& FiniteVolumeKeys();

// The frictions' settings, material-wide (no region gives them), that drape check, summary.json
// and scene.yaml report: each friction's smoothing where the fabric has that friction, and
// friction_load_steps where the incremental form is chosen.
struct FrictionSetting {
  std::string key;
  double value;
  std::string unit;
};
std::vector<FrictionSetting> FrictionSettings(const FiniteVolumeSpec& fv);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_MATERIAL_KEYS_H_
