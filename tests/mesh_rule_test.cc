#include "src/analysis/mesh_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "src/model/model.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// The cotton of configs/fv/ (KES B_weft 0.08 gf·cm²/cm, W 12 mg/cm²): its bending length in the
// weft, c = (D_weft / (ρ g))^(1/3), the expected error K h / c at 1 cm, and the
// spacing that keeps the error at 0.05 (two digits, rounded down: a scene at it is not coarse);
// coarse at 1 cm, not at 3 mm.
TEST(MeshRule, AdviceForTheCottonFollowsFromItsBendingLength) {
  const Scene scene =
      testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml", {"mesh.spacing=0.01"});
  const Model model = BuildModel(scene);
  const auto advice = AdviseMesh(scene, model);
  ASSERT_TRUE(advice);
  const double d_weft = scene.material.finite_volume.D_weft;
  const double c = std::cbrt(d_weft / (0.12 * 9.81));
  EXPECT_NEAR(advice->bending_length, c, 1e-12);
  EXPECT_NEAR(advice->spacing, 0.01, 1e-15);
  EXPECT_EQ(advice->error_per_spacing, kCellShearErrorPerSpacing);  // the default cell_shear
  EXPECT_NEAR(advice->expected_error, kCellShearErrorPerSpacing * 0.01 / c, 1e-12);
  const double needed = kDefaultDrapeAccuracy * c / kCellShearErrorPerSpacing;  // 4.70 mm
  EXPECT_LE(advice->spacing_needed, needed);
  EXPECT_GE(advice->spacing_needed, 0.9 * needed);
  EXPECT_NEAR(advice->spacing_needed, 0.0047, 1e-15);
  EXPECT_TRUE(advice->coarse);
  const std::string warning = CoarseMeshWarning(*advice);
  EXPECT_NE(warning.find("mesh.spacing 1 cm is coarse"), std::string::npos) << warning;
  EXPECT_NE(warning.find("bending length 1.9 cm"), std::string::npos) << warning;

  const Scene fine =
      testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml",
                          {"mesh.spacing=0.003", "drape_test.specimen_diameter=0.2"});
  const auto fine_advice = AdviseMesh(fine, BuildModel(fine));
  ASSERT_TRUE(fine_advice);
  EXPECT_FALSE(fine_advice->coarse);
}

// The rule's K follows the scene's shear (finite_volume.cell_shear): the shear at the corners
// charges oblique folds and converges more slowly, so the same lattice expects a larger error and
// the same accuracy needs a finer one.
TEST(MeshRule, TheShearAtTheCornersHasTheLargerK) {
  const std::string file = "configs/fv/drape_tester_cotton_30.yaml";
  const Scene cells = testing::LoadConfig(file, {"mesh.spacing=0.005"});
  const Scene corners =
      testing::LoadConfig(file, {"mesh.spacing=0.005", "material.finite_volume.cell_shear=false"});
  const auto at_cells = AdviseMeshOfScene(cells);
  const auto at_corners = AdviseMeshOfScene(corners);
  ASSERT_TRUE(at_cells && at_corners);
  EXPECT_EQ(at_cells->error_per_spacing, kCellShearErrorPerSpacing);
  EXPECT_EQ(at_corners->error_per_spacing, kCornerShearErrorPerSpacing);
  EXPECT_GT(at_corners->expected_error, at_cells->expected_error);
  EXPECT_LT(at_corners->spacing_needed, at_cells->spacing_needed);
}

// The error bar takes the rule's K h / c where the levels' estimate is smaller (two levels
// outside the asymptotic range), naming both; where the levels' is larger it stays theirs.
TEST(MeshRule, WidensAnErrorBarSmallerThanItsExpectedError) {
  DrapeErrorBar bar;
  bar.value = 0.481;
  bar.levels_error = 0.018;
  bar.levels_basis = "change from the 2 cm level";
  MeshAdvice advice;
  advice.bending_length = 0.0096;
  advice.spacing = 0.01;
  advice.expected_error = kCellShearErrorPerSpacing * advice.spacing / advice.bending_length;
  WidenToMeshRule(advice, &bar);
  EXPECT_DOUBLE_EQ(bar.error(), advice.expected_error);
  EXPECT_EQ(bar.basis(), "mesh rule for a 9.6 mm bending length; change from the 2 cm level 0.018");
  EXPECT_DOUBLE_EQ(bar.levels_error, 0.018);
  ASSERT_TRUE(bar.mesh_rule_error);
  EXPECT_DOUBLE_EQ(*bar.mesh_rule_error, advice.expected_error);

  bar.levels_error = 0.5;
  WidenToMeshRule(advice, &bar);
  EXPECT_DOUBLE_EQ(bar.error(), 0.5);
  EXPECT_EQ(bar.basis(), "change from the 2 cm level");
  EXPECT_DOUBLE_EQ(*bar.mesh_rule_error, advice.expected_error);
}

// Coarser than the study's spacings the error stops growing (docs/drape-tester.md): the limp
// fabric (c = 9.6 mm) on a 5 cm lattice, where K h / c would be 1.6, expects at most
// kMostDrapeError and says the lattice resolves no fold; at 1 cm the rule is linear.
TEST(MeshRule, AnErrorCappedWhereTheLatticeResolvesNoFold) {
  const Scene limp =
      testing::LoadConfig("configs/fv/drape_tester_limp_30.yaml", {"mesh.spacing=0.01"});
  const auto linear = AdviseMesh(limp, BuildModel(limp));
  ASSERT_TRUE(linear);
  EXPECT_FALSE(linear->unresolved);
  EXPECT_NEAR(linear->expected_error, linear->error_per_spacing * 0.01 / linear->bending_length,
              1e-12);
  const Scene coarse =
      testing::LoadConfig("configs/fv/drape_tester_limp_30.yaml", {"mesh.spacing=0.05"});
  const auto capped = AdviseMesh(coarse, BuildModel(coarse));
  ASSERT_TRUE(capped);
  EXPECT_GT(capped->error_per_spacing * 0.05 / capped->bending_length, kMostDrapeError);
  EXPECT_TRUE(capped->unresolved);
  EXPECT_TRUE(capped->coarse);
  EXPECT_DOUBLE_EQ(capped->expected_error, kMostDrapeError);
  const std::string warning = CoarseMeshWarning(*capped);
  EXPECT_NE(warning.find("resolves none of its folds"), std::string::npos) << warning;
  EXPECT_NE(warning.find("off by as much as 0.5"), std::string::npos) << warning;
  EXPECT_EQ(warning.find("first order"), std::string::npos) << warning;
}

// The spacing the warning prints ("… 1.5 mm or finer keeps it within 0.05") is one the rule
// accepts, also where c·0.05/K lies just under a round figure: the limp fabric with D_weft
// 2.667e-6 N·m needs 1.597 mm, which printed to two digits would read "1.6 mm", coarse for it.
TEST(MeshRule, TheSpacingItPrintsIsNotCoarse) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> fabrics = {
      {"cotton_30", {}},
      {"polyester_30", {}},
      {"limp_30", {}},
      {"limp_30", {"material.finite_volume.D_weft=2.667e-6"}}};
  for (const auto& [fabric, overrides] : fabrics) {
    const std::string path = "configs/fv/drape_tester_" + fabric + ".yaml";
    std::vector<std::string> at_1cm = overrides;
    at_1cm.push_back("mesh.spacing=0.01");
    const Scene coarse = testing::LoadConfig(path, at_1cm);
    const auto advice = AdviseMesh(coarse, BuildModel(coarse));
    ASSERT_TRUE(advice) << fabric;
    const std::string warning = CoarseMeshWarning(*advice);
    const std::size_t end = warning.find(" or finer");
    ASSERT_NE(end, std::string::npos) << warning;
    const std::size_t begin = warning.rfind("; ", end) + 2;
    const std::string printed = warning.substr(begin, end - begin);  // "1.5 mm"
    const double value = std::stod(printed);
    const double metres = printed.find(" mm") != std::string::npos ? value / 1000 : value / 100;
    std::vector<std::string> at_printed = overrides;
    at_printed.push_back("mesh.spacing=" + std::to_string(metres));
    at_printed.push_back("drape_test.specimen_diameter=0.2");  // a smaller model, the same rule
    const Scene advised = testing::LoadConfig(path, at_printed);
    const auto at_advised = AdviseMesh(advised, BuildModel(advised));
    ASSERT_TRUE(at_advised) << fabric;
    EXPECT_FALSE(at_advised->coarse) << fabric << " at the printed " << printed << ": " << warning;
  }
}

// Every drape tester scene shipped in configs/fv/ is fine enough for its fabric: drape solve
// warns of none of them (docs/drape-tester.md, "The scenes").
TEST(MeshRule, TheShippedTesterScenesMeetIt) {
  const std::filesystem::path folder = testing::SourcePath("configs/fv");
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("drape_tester_", 0) != 0 || entry.path().extension() != ".yaml") continue;
    const Scene scene = testing::LoadConfig("configs/fv/" + name, {});
    const auto advice = AdviseMesh(scene, BuildModel(scene));
    ASSERT_TRUE(advice) << name;
    EXPECT_FALSE(advice->coarse) << name << ": " << CoarseMeshWarning(*advice);
    ++scenes;
  }
  EXPECT_GE(scenes, 8);
}

// No advice where the rule does not apply: a spring fabric, a scene without a support disc.
TEST(MeshRule, NoAdviceOutsideADrapeTestOfAFiniteVolumeFabric) {
  const Scene springs = testing::LoadConfig("configs/examples/hanging_sheet.yaml", {});
  EXPECT_FALSE(AdviseMesh(springs, BuildModel(springs)));
  const Scene table = testing::LoadConfig("configs/fv/square_table.yaml", {});
  EXPECT_FALSE(AdviseMesh(table, BuildModel(table)));
  EXPECT_FALSE(AdviseMeshOfScene(springs));
  EXPECT_FALSE(AdviseMeshOfScene(table));
}

// The scene alone gives the advice the scene and its model give (a sweep asks it of every task
// before any model is built): the limp fabric and the cotton, coarse and fine.
TEST(MeshRule, TheSceneAloneGivesTheSameAdvice) {
  for (const auto& [file, spacing] : std::vector<std::pair<std::string, std::string>>{
           {"configs/fv/drape_tester_limp_30.yaml", "0.01"},
           {"configs/fv/drape_tester_cotton_30.yaml", "0.01"},
           {"configs/fv/drape_tester_cotton_30.yaml", "0.003"}}) {
    const Scene scene = testing::LoadConfig(file, {"mesh.spacing=" + spacing});
    const auto with_model = AdviseMesh(scene, BuildModel(scene));
    const auto alone = AdviseMeshOfScene(scene);
    ASSERT_TRUE(with_model && alone) << file;
    EXPECT_EQ(alone->spacing, with_model->spacing) << file;
    EXPECT_EQ(alone->bending_length, with_model->bending_length) << file;
    EXPECT_EQ(alone->expected_error, with_model->expected_error) << file;
    EXPECT_EQ(alone->spacing_needed, with_model->spacing_needed) << file;
    EXPECT_EQ(alone->coarse, with_model->coarse) << file;
    EXPECT_EQ(alone->unresolved, with_model->unresolved) << file;
  }
}

}  // namespace
}  // namespace drape
