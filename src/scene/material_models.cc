// The material models (see material_models.h).
#include "src/scene/material_models.h"

#include <cassert>
#include <cmath>

#include "src/scene/registry_row.h"
#include "src/scene/scene.h"

namespace drape {
namespace {

// A square lattice of springs k has membrane rigidity k whatever its spacing, so structural and
// shear springs stay; a skip-one spring of a sheet bent to curvature κ shortens by κ²h³/3, so its
// energy per unit area, k_f κ⁴ h⁴/18, stays the same when k_f scales as h⁻⁴. A given rest length
// is a length of the lattice.
void RescaleSprings(double ratio, MaterialSpec* material) {
  SpringsSpec& springs = material->springs;
  springs.flexion.warp *= std::pow(ratio, -4.0);
  springs.flexion.weft *= std::pow(ratio, -4.0);
  if (springs.rest_length == SpringsSpec::RestLength::kGiven) springs.rest_length_value *= ratio;
}

// The finite-volume rigidities and the areal density are per unit area already; springs beside
// them scale as springs.
void RescaleFiniteVolume(double ratio, MaterialSpec* material) { RescaleSprings(ratio, material); }

}  // namespace

const std::vector<MaterialModelRow>& MaterialModels() {
  static const std::vector<MaterialModelRow> models = {
      {MaterialModel::kSprings, "springs",
       "a lattice of springs (`springs`): structural, shear and flexion families", RescaleSprings,
       "`flexion` scales as h⁻⁴, a given `rest_length` as h; the rest unchanged", false, false},
      {MaterialModel::kFiniteVolume, "finite_volume",
       "the finite-volume membrane and bending (`finite_volume`), with springs beside it if "
       "`springs` is given",
       RescaleFiniteVolume,
       "unchanged (rigidities per unit area); springs beside it as the `springs` model's", true,
       true},
  };
  return models;
}

const MaterialModelRow& MaterialModelOf(MaterialModel model) {
  return RegistryRow(MaterialModels(), &MaterialModelRow::model, model);
}

const std::string& MaterialModelName(MaterialModel model) { return MaterialModelOf(model).name; }

std::vector<std::string> MaterialModelNames() {
  std::vector<std::string> names;
  for (const MaterialModelRow& row : MaterialModels()) names.push_back(row.name);
  return names;
}

MaterialModel MaterialModelNamed(const std::string& name) {
  for (const MaterialModelRow& row : MaterialModels()) {
    if (row.name == name) return row.model;
  }
  assert(false && "a material model name the loader did not check");
  return MaterialModels().front().model;
}

std::string MaterialModelsWith(bool MaterialModelRow::*flag) {
  std::string names;
  for (const MaterialModelRow& row : MaterialModels()) {
    if (row.*flag) names += (names.empty() ? "" : " or ") + row.name;
  }
  return names;
}

}  // namespace drape
