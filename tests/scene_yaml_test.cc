// scene.yaml (src/output/scene_yaml.h): the scene as solved, written back as a scene file.
#include "src/output/scene_yaml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/scene/fabric_parameters.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

std::string SceneText(const Scene& scene) {
  std::ostringstream text;
  WriteSceneYaml(scene, text);
  return text.str();
}

// Writes `scene` as scene.yaml into a fresh folder and loads it back.
Scene RoundTrip(const Scene& scene, const std::string& tag) {
  const testing::ScratchFile file("scene_yaml_test_" + tag, "scene.yaml", SceneText(scene));
  return LoadScene(file.path().string());
}

// Every scene of configs/ written and loaded back gives the same text again (nothing lost or
// changed by the writer) and the same model (node count and start positions).
TEST(SceneYaml, EveryConfigRoundTrips) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(testing::SourcePath("configs"))) {
    const fs::path& path = entry.path();
    const std::string name = path.filename().string();
    // Fit files (drape fit) and sweep files (drape sweep) are not scenes.
    if (path.extension() != ".yaml" || name.rfind("fit", 0) == 0 || name.rfind("sweep", 0) == 0) {
      continue;
    }
    SCOPED_TRACE(path.string());
    const Scene scene = LoadScene(path.string());
    const Scene again = RoundTrip(scene, std::to_string(count++));
    EXPECT_EQ(SceneText(again), SceneText(scene));
    const Model model = BuildModel(scene), rebuilt = BuildModel(again);
    ASSERT_EQ(rebuilt.num_nodes, model.num_nodes);
    EXPECT_EQ(rebuilt.initial, model.initial);
    EXPECT_EQ(rebuilt.fixed, model.fixed);
    EXPECT_EQ(rebuilt.TermCounts(), model.TermCounts());
  }
  EXPECT_GE(count, 6);
}

// Springs beside a finite-volume fabric, spring lines and regions (every kind of key, the row,
// column and outside selectors, a region's name), loads on a region by name, traction and pressure
// are written back, and the scene they load into builds the same model: the same terms, masses
// and energy at a perturbed configuration.
TEST(SceneYaml, HoldsSpringsLinesAndRegions) {
  const std::string regions =
      "regions=[{nodes: {column: 3}, D_warp: 3.0e-5, nu_warp: 0.1, structural: {warp: 50, weft: "
      "40}, tension_only: false}, {nodes: {outside: {center: [0, 0, 0], radius: 0.15}}, "
      "density: 0.3, name: rim}]";
  const std::string forces =
      "loads.forces=[{nodes: {region: rim}, pressure: -1.5}, {nodes: {all: true}, traction: [0, "
      "0.5, 0]}]";
  const Scene scene = testing::LoadConfig(
      "configs/fv/square_table_seam.yaml",
      {"mesh.nodes=[9, 9]", "material.springs={structural: 100, shear: 20, tension_only: true}",
       "material.lines[0].nodes={row: 4}", regions, forces});
  const Scene again = RoundTrip(scene, "combined");
  EXPECT_EQ(SceneText(again), SceneText(scene));
  ASSERT_EQ(again.regions.size(), 2u);
  EXPECT_EQ(again.regions[0].nodes.kind, NodeSelector::Kind::kColumn);
  EXPECT_EQ(again.regions[0].finite_volume.at("nu_warp"), 0.1);
  EXPECT_FALSE(*again.regions[0].tension_only);
  EXPECT_EQ(again.regions[1].nodes.kind, NodeSelector::Kind::kOutside);
  EXPECT_EQ(again.material.lines[0].nodes.kind, NodeSelector::Kind::kRow);
  EXPECT_TRUE(again.material.springs.present);
  EXPECT_EQ(again.regions[1].name, "rim");
  ASSERT_EQ(again.loads.forces.size(), 2u);
  EXPECT_EQ(again.loads.forces[0].kind, ForceSpec::Kind::kPressure);
  EXPECT_EQ(again.loads.forces[0].pressure, -1.5);
  EXPECT_EQ(again.loads.forces[0].nodes.kind, NodeSelector::Kind::kOutside);
  EXPECT_EQ(again.loads.forces[1].kind, ForceSpec::Kind::kTraction);
  const Model model = BuildModel(scene), rebuilt = BuildModel(again);
  EXPECT_EQ(rebuilt.applied, model.applied);
  EXPECT_EQ(rebuilt.TermCounts(), model.TermCounts());
  EXPECT_EQ(model.TermCounts().at("line"), 8);
  EXPECT_GT(model.TermCounts().at("shear"), 0);
  EXPECT_EQ(rebuilt.mass, model.mass);
  std::vector<double> moved = model.positions;
  for (size_t i = 0; i < moved.size(); ++i) moved[i] += 1e-3 * std::sin(0.3 * i);
  double energy = 0.0, energy_again = 0.0;
  for (size_t t = 0; t < model.terms.size(); ++t) {
    double a = 0.0, b = 0.0;
    ASSERT_TRUE(model.terms[t]->Energy(moved.data(), &a));
    ASSERT_TRUE(rebuilt.terms[t]->Energy(moved.data(), &b));
    energy += a;
    energy_again += b;
  }
  EXPECT_EQ(energy_again, energy);
}

// KES inputs are written as the SI values they convert to; --set overrides and defaults are in.
TEST(SceneYaml, HoldsTheSiValuesTheOverridesAndTheDefaults) {
  const Scene scene = LoadScene(testing::SourcePath("configs/fv/drape_tester_cotton_24.yaml"),
                                {"mesh.spacing=0.02", "material.finite_volume.kes.B_warp=0.2"});
  const Scene again = RoundTrip(scene, "kes");
  const FiniteVolumeSpec& fv = again.material.finite_volume;
  EXPECT_EQ(fv.D_warp, KesBendingRigidity(0.2));
  EXPECT_EQ(fv.D_weft, KesBendingRigidity(0.08));
  EXPECT_EQ(fv.G, KesShearRigidity(0.9));
  EXPECT_EQ(fv.E_warp, KesTensileRigidity(4.0, 0.65));
  EXPECT_EQ(again.material.mass_kind, MaterialSpec::MassKind::kDensity);
  EXPECT_EQ(again.material.mass_value, KesArealDensity(12.0));
  EXPECT_EQ(again.mesh.spacing, 0.02);
  EXPECT_EQ(again.contact.thickness, 0.001);
  EXPECT_EQ(again.output.obj_up, "z");
  const std::string text = SceneText(scene);
  EXPECT_EQ(text.find("kes"), std::string::npos) << text;
  EXPECT_NE(text.find("max_iterations: 2000"), std::string::npos) << text;
  EXPECT_NE(text.find("max_nodes:"), std::string::npos) << text;  // a default, filled in
}

// A fabric with a bending friction: newton's options as its solve takes them (no step doublings
// unless asked, src/run/run.h, SolveMethodOptions), so that scene.yaml solves the same way again.
TEST(SceneYaml, RecordsTheNewtonOptionsAFrictionSets) {
  const std::string cotton = testing::SourcePath("configs/fv/drape_tester_cotton_30.yaml");
  const Scene scene = LoadScene(cotton, {"material.finite_volume.kes.2HB_warp=0.124"});
  const Scene again = RoundTrip(scene, "friction");
  EXPECT_EQ(again.solver.method_options.at("newton").at("max_expansions"), 0.0);
  const Scene elastic = RoundTrip(LoadScene(cotton), "elastic");
  const MethodOption* doublings = FindMethodOption(*FindSolverMethod("newton"), "max_expansions");
  EXPECT_EQ(elastic.solver.method_options.at("newton").at("max_expansions"),
            doublings->default_value.value());
  EXPECT_NE(doublings->default_value.value(), 0.0);
}

// output.obj_up is recorded as chosen.
TEST(SceneYaml, RecordsTheObjUpAxis) {
  const Scene scene =
      LoadScene(testing::SourcePath("configs/fv/drape_tester_cotton_24.yaml"), {"output.obj_up=y"});
  EXPECT_NE(SceneText(scene).find("obj_up: y"), std::string::npos) << SceneText(scene);
  EXPECT_EQ(RoundTrip(scene, "obj_up").output.obj_up, "y");
}

}  // namespace
}  // namespace drape
