// scene.yaml (src/output/scene_yaml.h): the scene as solved, written back as a scene file.
#include "src/output/scene_yaml.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/scene/fabric_parameters.h"
#include "src/scene/scene_loader.h"
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
  const fs::path folder = fs::temp_directory_path() /
                          ("drape_scene_yaml_test_" + std::to_string(::getpid()) + "_" + tag);
  fs::create_directories(folder);
  const fs::path path = folder / "scene.yaml";
  std::ofstream(path) << SceneText(scene);
  Scene loaded = LoadScene(path.string());
  fs::remove_all(folder);
  return loaded;
}

// Every scene of configs/ written and loaded back gives the same text again (nothing lost or
// changed by the writer) and the same model (node count and start positions).
TEST(SceneYaml, EveryConfigRoundTrips) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(testing::SourcePath("configs"))) {
    const fs::path& path = entry.path();
    if (path.extension() != ".yaml" || path.filename().string().rfind("fit", 0) == 0) continue;
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
  const std::string text = SceneText(scene);
  EXPECT_EQ(text.find("kes"), std::string::npos) << text;
  EXPECT_NE(text.find("max_iterations: 2000"), std::string::npos) << text;
  EXPECT_NE(text.find("max_nodes:"), std::string::npos) << text;  // a default, filled in
}

}  // namespace
}  // namespace drape
