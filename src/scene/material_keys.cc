#include "src/scene/material_keys.h"

namespace drape {

const std::vector<FiniteVolumeKey>& FiniteVolumeKeys() {
  using Range = FiniteVolumeKey::Range;
  static const std::vector<FiniteVolumeKey> keys = {
      {"E_warp", &FiniteVolumeSpec::E_warp, Range::kPositive, "N/m"},
      {"E_weft", &FiniteVolumeSpec::E_weft, Range::kPositive, "N/m"},
      {"nu_warp", &FiniteVolumeSpec::nu_warp, Range::kAny, "1"},
      {"nu_weft", &FiniteVolumeSpec::nu_weft, Range::kAny, "1"},
      {"G", &FiniteVolumeSpec::G, Range::kNonNegative, "N/m"},
      {"D_warp", &FiniteVolumeSpec::D_warp, Range::kNonNegative, "N*m"},
      {"D_weft", &FiniteVolumeSpec::D_weft, Range::kNonNegative, "N*m"},
      {"D_12", &FiniteVolumeSpec::D_12, Range::kAny, "N*m"},
      {"D_66", &FiniteVolumeSpec::D_66, Range::kNonNegative, "N*m"},
      {"bending_friction_warp", &FiniteVolumeSpec::bending_friction_warp, Range::kNonNegative, "N",
       false},
      {"bending_friction_weft", &FiniteVolumeSpec::bending_friction_weft, Range::kNonNegative, "N",
       false},
      {"shear_friction", &FiniteVolumeSpec::shear_friction, Range::kNonNegative, "N/m", false}};
  return keys;
}

std::vector<FrictionSetting> FrictionSettings(const FiniteVolumeSpec& fv) {
  std::vector<FrictionSetting> settings;
  const bool bending = fv.bending_friction_warp > 0.0 || fv.bending_friction_weft > 0.0;
  if (bending)
    settings.push_back({"bending_friction_smoothing", fv.bending_friction_smoothing, "1/m"});
  if (fv.shear_friction > 0.0) {
    settings.push_back({"shear_friction_smoothing", fv.shear_friction_smoothing, "rad"});
  }
  if (fv.friction_load_steps > 0) {
    settings.push_back({"friction_load_steps", static_cast<double>(fv.friction_load_steps), "1"});
  }
  return settings;
}

}  // namespace drape
