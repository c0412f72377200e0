#include "src/scene/drape_mesh_rule.h"

#include <algorithm>
#include <cmath>

namespace drape {

std::optional<double> LimperBendingLength(const Scene& scene) {
  const MaterialSpec& material = scene.material;
  switch (material.model) {
    case MaterialModel::kSprings:
      return std::nullopt;  // the rule is the finite-volume fabric's refinement study's
    case MaterialModel::kFiniteVolume:
      break;
  }
  if (material.mass_kind != MaterialSpec::MassKind::kDensity || !scene.loads.gravity) {
    return std::nullopt;
  }
  const double rigidity = std::min(material.finite_volume.D_warp, material.finite_volume.D_weft);
  const double weight = material.mass_value * scene.loads.gravity->norm();  // N/m²
  if (!(rigidity > 0.0) || !(weight > 0.0)) return std::nullopt;
  return std::cbrt(rigidity / weight);
}

double DrapeErrorPerSpacing(const Scene& scene) {
  return scene.material.finite_volume.cell_shear ? kCellShearErrorPerSpacing
                                                 : kCornerShearErrorPerSpacing;
}

double ExpectedDrapeError(double spacing, double bending_length, double error_per_spacing) {
  return std::min(error_per_spacing * spacing / bending_length, kMostDrapeError);
}

double SpacingForDrapeError(double error, double bending_length, double error_per_spacing) {
  const double spacing = error * bending_length / error_per_spacing;
  const double unit = std::pow(10.0, std::floor(std::log10(spacing)) - 1.0);
  return std::floor(spacing / unit) * unit;
}

double AskedDrapeAccuracy(const Scene& scene) {
  if (scene.drape_test && scene.drape_test->accuracy) return *scene.drape_test->accuracy;
  return kDefaultDrapeAccuracy;
}

}  // namespace drape
