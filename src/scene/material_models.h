// The material models a scene's `material.model` may name: one row each, the single owner of what
// drape asks a model beyond its own terms: its name in the scene file, the reference's
// description, how `solver.levels` rescales its parameters between lattice spacings, and whether
// the virtual Peirce test and the frictions apply to it. The loader reads the name by it,
// scene.yaml and summary.json write it, src/analysis/levels.cc rescales by it, the fit and the
// solve's friction continuation ask it.
//
// Adding a model: a value in MaterialModel, one row in MaterialModels()
// (src/scene/material_models.cc) with its rescaling rule, its reading in the scene loader
// (src/scene/scene_loader.cc, ReadMaterial), its terms in BuildModel (src/model/model.cc), its
// writing in scene.yaml (src/output/scene_yaml.cc), its case in every other switch over
// MaterialModel, and its row in docs/reference.md's table of material models. The code asks the
// model by a switch with no default, never by ==, so -Wswitch lists every place it is missing.
// tests/material_models_test.cc fails until the row, its rule and its documentation are there,
// and where the model is compared instead of switched on.
#ifndef DRAPE_SRC_SCENE_MATERIAL_MODELS_H_
#define DRAPE_SRC_SCENE_MATERIAL_MODELS_H_

#include <string>
#include <vector>

namespace drape {

struct MaterialSpec;

enum class MaterialModel { kSprings, kFiniteVolume };

struct MaterialModelRow {
  MaterialModel model;
  std::string name;  // `material.model`
  std::string doc;   // docs/reference.md's table of material models
  // `solver.levels`: the model's parameters on a lattice of `ratio` times the scene's spacing, so
  // that the coarser level is the same fabric per unit area; and what that does, in words.
  void (*rescale_for_spacing)(double ratio, MaterialSpec* material) = nullptr;
  std::string rescaling_doc;
  bool peirce_test = false;  // a fit's virtual Peirce test (bending_length) can bend it
  bool friction = false;     // takes the frictions in bending and shear
};

// Every model, in the order of the reference's table; the first is the default.
const std::vector<MaterialModelRow>& MaterialModels();
const MaterialModelRow& MaterialModelOf(MaterialModel model);
const std::string& MaterialModelName(MaterialModel model);
std::vector<std::string> MaterialModelNames();
// The model named `name`, which must be one (asserted: the loader checks it first).
MaterialModel MaterialModelNamed(const std::string& name);
// The names of the models that have `flag`, joined by " or ": "finite_volume".
std::string MaterialModelsWith(bool MaterialModelRow::*flag);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_MATERIAL_MODELS_H_
