// The material-model registry (src/scene/material_models.h): a row for every model, each with its
// rule for `solver.levels`, the reference's table (docs/reference.md) its rows, the scene's name
// read and written by it, and levels' coarser scenes rescaled by the row's rule.
#include "src/scene/material_models.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "src/analysis/levels.h"
#include "src/output/scene_yaml.h"
#include "src/scene/scene_loader.h"
#include "tests/source_lines.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// A 9 × 9 sheet of `model` held along its top edge, with springs (beside the finite volumes).
Scene MaterialModelSheet(const MaterialModelRow& row) {
  const std::string fv =
      row.model == MaterialModel::kFiniteVolume
          ? "  finite_volume: {E_warp: 500, E_weft: 500, nu_warp: 0, nu_weft: 0, G: 5, "
            "D_warp: 1.0e-5, D_weft: 1.0e-5, D_12: 0}\n"
          : "";
  return LoadSceneText("mesh: {kind: grid, size: [0.4, 0.4], nodes: [9, 9]}\nmaterial:\n  model: " +
                           row.name + "\n  density: 0.2\n" + fv +
                           "  springs: {structural: 100, shear: 50, flexion: 2}\n"
                           "fixed:\n  - nodes: {edge: top}\nloads: {gravity: [0, 0, -9.81]}\n",
                       "<string>", ".");
}

// The program asks a material model what to do by a switch over MaterialModel without a default,
// never by == or !=, so that the compiler (-Wswitch, in -Wall) names every place a new model has
// to be handled.
TEST(MaterialModels, EveryDispatchOnTheModelIsASwitch) {
  testing::ExpectEveryDispatchIsASwitch("MaterialModel");
}

TEST(MaterialModels, EveryModelHasItsRowAndItsRescalingRule) {
  std::set<std::string> names;
  for (const MaterialModelRow& row : MaterialModels()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name << " is listed twice";
    EXPECT_EQ(&MaterialModelOf(row.model), &row) << row.name;
    EXPECT_EQ(MaterialModelNamed(row.name), row.model) << row.name;
    EXPECT_FALSE(row.doc.empty()) << row.name;
    EXPECT_NE(row.rescale_for_spacing, nullptr)
        << row.name << " has no rule for solver.levels' coarser lattices";
    EXPECT_FALSE(row.rescaling_doc.empty()) << row.name;
  }
  EXPECT_EQ(MaterialModels().size(), static_cast<size_t>(MaterialModel::kFiniteVolume) + 1)
      << "a MaterialModel without its row (kFiniteVolume is the last value)";
  EXPECT_EQ(MaterialModels().front().model, MaterialSpec{}.model) << "the first row is the default";
  EXPECT_EQ(MaterialModelsWith(&MaterialModelRow::peirce_test), "finite_volume");
}

std::string MaterialModelsTable() {
  std::ostringstream table;
  table << "| model | what | on `solver.levels`' coarser lattices | Peirce test | frictions |\n"
        << "|---|---|---|---|---|\n";
  for (const MaterialModelRow& row : MaterialModels()) {
    table << "| `" << row.name << "` | " << row.doc << " | " << row.rescaling_doc << " | "
          << (row.peirce_test ? "yes" : "no") << " | " << (row.friction ? "yes" : "no") << " |\n";
  }
  return table.str();
}

std::string MaterialModelsReferenceTable() {
  std::ifstream file(testing::SourcePath("docs/reference.md"));
  std::stringstream text;
  text << file.rdbuf();
  const std::string reference = text.str();
  const size_t from = reference.find("<!-- material-models:begin");
  const size_t to = reference.find("<!-- material-models:end");
  if (from == std::string::npos || to == std::string::npos || to < from) return "";
  const size_t start = reference.find('\n', from) + 1;
  return reference.substr(start, to - start);
}

TEST(MaterialModels, TheReferenceTableIsTheRegistry) {
  EXPECT_EQ(MaterialModelsReferenceTable(), MaterialModelsTable())
      << "docs/reference.md's table between the material-models markers should read:\n"
      << MaterialModelsTable();
}

// The coarser scene of solver.levels is the fine one with the model's rule applied, and the rule
// keeps what is per unit area (structural springs, the finite-volume rigidities, the density).
TEST(MaterialModels, LevelsRescaleByTheModelsRule) {
  for (const MaterialModelRow& row : MaterialModels()) {
    ASSERT_NE(row.rescale_for_spacing, nullptr) << row.name;
    const Scene fine = MaterialModelSheet(row);
    const Scene coarse = CoarsenedScene(fine, 2);
    MaterialSpec expected = fine.material;
    row.rescale_for_spacing(2.0, &expected);
    EXPECT_EQ(coarse.material.springs.flexion.warp, expected.springs.flexion.warp) << row.name;
    EXPECT_EQ(coarse.material.springs.structural.warp, fine.material.springs.structural.warp);
    EXPECT_EQ(coarse.material.finite_volume.D_warp, fine.material.finite_volume.D_warp);
    EXPECT_EQ(coarse.material.mass_value, fine.material.mass_value);
  }
}

// scene.yaml writes the model's name, and reading it back gives the same model.
TEST(MaterialModels, TheSceneRoundTripsTheModel) {
  for (const MaterialModelRow& row : MaterialModels()) {
    std::ostringstream yaml;
    WriteSceneYaml(MaterialModelSheet(row), yaml);
    EXPECT_NE(yaml.str().find("model: " + row.name), std::string::npos) << yaml.str();
    EXPECT_EQ(LoadSceneText(yaml.str(), "<scene.yaml>", ".").material.model, row.model);
  }
}

}  // namespace
}  // namespace drape
