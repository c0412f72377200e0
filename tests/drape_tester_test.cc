// The scene's drape_test block (src/scene/drape_tester.h): it builds the model of the hand-written
// tester scene it stands for, fills its defaults, refuses what would contradict it, and says
// what it expands to.
#include "src/scene/drape_tester.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/scene/drape_mesh_rule.h"
#include "src/scene/scene_loader.h"
#include "src/scene/scene_size.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

constexpr char kFabric[] = R"(material:
  model: finite_volume
  density: 0.08
  finite_volume: {E_warp: 9000, E_weft: 8000, G: 20, D_warp: 2.6e-6, D_weft: 1.7e-6}
)";

// The 24 cm polyester test at 2 cm, written out by hand as configs/fv/ wrote it before the block.
constexpr char kByHand[] = R"(name: by-hand
mesh: {kind: circle, radius: 0.12, spacing: 0.02, origin: [0, 0, 0.001]}
fixed:
  - nodes: {within: {center: [0.0013, 0.0007, 0.001], radius: 0.085}}
loads: {gravity: [0, 0, -9.81]}
obstacles:
  - disk: {center: [0.0013, 0.0007, 0], radius: 0.09}
contact: {thickness: 0.001}
)";

constexpr char kBlock[] = R"(name: block
drape_test: {specimen_diameter: 0.24}
mesh: {spacing: 0.02}
)";

class DrapeTestBlock : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("test_block");
    folder_ = scratch_->path();
  }
  void TearDown() override { scratch_.reset(); }

  Scene Load(const std::string& text, const std::vector<std::string>& overrides = {}) const {
    const fs::path path = folder_ / "scene.yaml";
    std::ofstream(path) << text;
    return LoadScene(path.string(), overrides);
  }
  std::string Error(const std::string& text) const {
    try {
      Load(text);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path folder_;
};

TEST_F(DrapeTestBlock, BuildsTheModelOfTheHandWrittenScene) {
  const Scene block_scene = Load(std::string(kBlock) + kFabric);
  const Scene hand_scene = Load(std::string(kByHand) + kFabric);
  const Model block = BuildModel(block_scene);
  const Model hand = BuildModel(hand_scene);
  ASSERT_GT(block.num_nodes, 100);
  EXPECT_EQ(block.num_nodes, hand.num_nodes);
  EXPECT_EQ(block.positions, hand.positions);
  EXPECT_EQ(block.fixed, hand.fixed);
  EXPECT_EQ(block.TermCounts(), hand.TermCounts());
  EXPECT_GT(block.TermCounts().at("disk_contact"), 0);
  EXPECT_EQ(block.applied, hand.applied);
  EXPECT_EQ(block.mass, hand.mass);
  ASSERT_EQ(block.obstacles.size(), 1u);
  EXPECT_EQ(block.obstacles[0].center, hand.obstacles[0].center);
  EXPECT_EQ(block.obstacles[0].radius, hand.obstacles[0].radius);
  EXPECT_EQ(block_scene.loads.gravity, hand_scene.loads.gravity);
}

TEST_F(DrapeTestBlock, DefaultsAreTheStandardTest) {
  const Scene scene = Load(std::string("drape_test: {}\n") + kFabric);
  ASSERT_TRUE(scene.drape_test);
  EXPECT_EQ(scene.mesh.kind, MeshSpec::Kind::kCircle);
  EXPECT_DOUBLE_EQ(scene.mesh.radius, 0.15);
  // No mesh.spacing: the spacing the default accuracy needs (the next test).
  EXPECT_TRUE(scene.drape_test->spacing_chosen);
  EXPECT_DOUBLE_EQ(scene.mesh.spacing,
                   SpacingForDrapeError(kDefaultDrapeAccuracy, *LimperBendingLength(scene),
                                        DrapeErrorPerSpacing(scene)));
  EXPECT_DOUBLE_EQ(scene.mesh.origin.z(), scene.contact.thickness);
  ASSERT_EQ(scene.obstacles.size(), 1u);
  EXPECT_EQ(scene.obstacles[0].kind, "disk");
  EXPECT_DOUBLE_EQ(scene.obstacles[0].radius, 0.09);
  EXPECT_DOUBLE_EQ(scene.obstacles[0].center.x(), 0.0013);
  ASSERT_EQ(scene.fixed.size(), 1u);
  EXPECT_DOUBLE_EQ(scene.fixed[0].nodes.radius, 0.085);
  EXPECT_EQ(scene.drape_test->drops, 1);
  // A drape test writes its figures by default.
  for (const std::string kind : {"summary", "profile", "shadow"}) {
    EXPECT_NE(std::find(scene.output.write.begin(), scene.output.write.end(), kind),
              scene.output.write.end())
        << kind;
  }
}

TEST_F(DrapeTestBlock, SetOverridesReachTheBlockAndTheSpacing) {
  const Scene scene = Load(std::string("drape_test: {}\n") + kFabric,
                           {"drape_test.disc_diameter=0.2", "mesh.spacing=0.02"});
  EXPECT_DOUBLE_EQ(scene.obstacles[0].radius, 0.1);
  EXPECT_DOUBLE_EQ(scene.fixed[0].nodes.radius, 0.095);
  EXPECT_DOUBLE_EQ(scene.mesh.spacing, 0.02);
}

TEST_F(DrapeTestBlock, RefusesWhatItSetsItself) {
  EXPECT_NE(Error(std::string(kBlock) + kFabric +
                  "fixed:\n  - nodes: {within: {center: [0, 0, 0], radius: 0.05}}\n")
                .find("scene.yaml:8:1: fixed: 'fixed' is set by drape_test"),
            std::string::npos)
      << Error(std::string(kBlock) + kFabric + "fixed: []\n");
  const std::string radius =
      Error(std::string("drape_test: {}\nmesh: {spacing: 0.02, radius: 0.2}\n") + kFabric);
  EXPECT_NE(radius.find("scene.yaml:2:23: mesh.radius"), std::string::npos) << radius;
  EXPECT_NE(radius.find("'radius' is set by drape_test"), std::string::npos) << radius;
  EXPECT_NE(Error(std::string("drape_test: {}\nobstacles: []\n") + kFabric)
                .find("'obstacles' is set by drape_test"),
            std::string::npos);
}

TEST_F(DrapeTestBlock, RefusesAnImpossibleGeometryAtItsKey) {
  const std::string disc = Error(std::string("drape_test: {disc_diameter: 0.4}\n") + kFabric);
  EXPECT_NE(disc.find("scene.yaml:1:29: drape_test.disc_diameter: the disc (40 cm) must be "
                      "smaller than the specimen (30 cm)"),
            std::string::npos)
      << disc;
  const std::string clamp = Error(std::string("drape_test: {clamp_diameter: 0.2}\n") + kFabric);
  EXPECT_NE(clamp.find("drape_test.clamp_diameter: the clamp (20 cm)"), std::string::npos) << clamp;
  const std::string offset = Error(std::string("drape_test: {offset: [0.07, 0]}\n") + kFabric);
  EXPECT_NE(offset.find("drape_test.offset: the disc, moved by the offset"), std::string::npos)
      << offset;
  EXPECT_NE(Error(std::string("drape_test: {drops: 0}\n") + kFabric).find("drape_test.drops"),
            std::string::npos);
  EXPECT_NE(Error(std::string("drape_test: {specimen_diamter: 0.3}\n") + kFabric)
                .find("did you mean 'specimen_diameter'?"),
            std::string::npos);
}

// The fabric's bending length in its limper (weft) direction, c = (D_weft / (ρ g))^(1/3).
double FabricBendingLength() { return std::cbrt(1.7e-6 / (0.08 * 9.81)); }

// Without mesh.spacing, the lattice is the largest spacing of two digits whose expected error K h
// / c is within the accuracy asked (src/scene/drape_mesh_rule.h), no coarser than 1 cm: a coarse
// request a coarse lattice, a fine one a finer lattice; a given spacing is kept.
TEST_F(DrapeTestBlock, TheAccuracyChoosesTheLattice) {
  const double c = FabricBendingLength();  // 12.9 mm
  ASSERT_NEAR(*LimperBendingLength(Load(std::string("drape_test: {}\n") + kFabric)), c, 1e-15);
  double coarser = 1.0;
  for (const double accuracy : {0.5, 0.2, 0.1, 0.05, 0.03, 0.02}) {
    const Scene scene =
        Load(std::string("drape_test: {accuracy: ") + std::to_string(accuracy) + "}\n" + kFabric);
    const double h = scene.mesh.spacing;
    EXPECT_TRUE(scene.drape_test->spacing_chosen);
    EXPECT_LE(h, kCoarsestChosenSpacing);
    const double k = DrapeErrorPerSpacing(scene);
    EXPECT_LE(k * h / c, accuracy * (1 + 1e-12)) << accuracy;
    // The largest such spacing of two digits, unless the 1 cm cap holds it.
    const double unit = std::pow(10.0, std::floor(std::log10(h)) - 1.0);
    if (h < kCoarsestChosenSpacing) {
      EXPECT_GT(k * (h + unit) / c, accuracy) << accuracy;
    }
    EXPECT_LE(h, coarser) << accuracy;
    coarser = h;
  }
  EXPECT_DOUBLE_EQ(Load(std::string("drape_test: {accuracy: 0.5}\n") + kFabric).mesh.spacing,
                   kCoarsestChosenSpacing);
  EXPECT_LT(coarser, 0.0015);  // 0.02: 1.2 mm
  const Scene given =
      Load(std::string("drape_test: {accuracy: 0.02}\nmesh: {spacing: 0.02}\n") + kFabric);
  EXPECT_FALSE(given.drape_test->spacing_chosen);
  EXPECT_DOUBLE_EQ(given.mesh.spacing, 0.02);
  // A fabric the rule does not cover (springs) keeps the mesh's own default, and an accuracy,
  // which nothing could hold it to, is refused at its key, with or without a spacing.
  const std::string springs = "material: {density: 0.1, springs: {structural: 100}}\n";
  const Scene plain = Load("drape_test: {}\n" + springs);
  EXPECT_FALSE(plain.drape_test->spacing_chosen);
  EXPECT_DOUBLE_EQ(plain.mesh.spacing, MeshSpec().spacing);
  for (const std::string mesh : {"", "mesh: {spacing: 0.02}\n"}) {
    const std::string error = Error("drape_test: {accuracy: 0.02}\n" + mesh + springs);
    EXPECT_NE(error.find("scene.yaml:1:24: drape_test.accuracy: the mesh rule, by which a run is "
                         "held to an accuracy, covers a finite_volume fabric"),
              std::string::npos)
        << error;
  }
}

// An accuracy whose lattice would exceed mesh.max_nodes is refused at the accuracy, saying what
// it needs and the finest accuracy within the limit; that accuracy loads.
TEST_F(DrapeTestBlock, AnUnreachableAccuracyIsRefusedAtItsKey) {
  const std::string text =
      std::string("drape_test: {accuracy: 0.01}\nmesh: {max_nodes: 20000}\n") + kFabric;
  const std::string error = Error(text);
  EXPECT_NE(error.find("scene.yaml:1:24: drape_test.accuracy: an accuracy of 0.01 needs a "),
            std::string::npos)
      << error;
  std::smatch suggested;
  ASSERT_TRUE(std::regex_search(
      error, suggested, std::regex("above mesh.max_nodes 20000: ask for ([0-9.]+) or more")))
      << error;
  const std::string reachable_text = suggested[1];
  const Scene reachable =
      Load("drape_test: {accuracy: " + reachable_text + "}\nmesh: {max_nodes: 20000}\n" + kFabric);
  EXPECT_LE(EstimatedNodes(reachable.mesh), 20000);
  EXPECT_NE(DrapeTestText(reachable).find("chosen for an accuracy of " + reachable_text),
            std::string::npos)
      << DrapeTestText(reachable);
  // One hundredth finer is refused: the suggestion is the finest within the limit.
  const std::string finer = std::to_string(std::stod(reachable_text) - 0.01);
  EXPECT_NE(Error("drape_test: {accuracy: " + finer + "}\nmesh: {max_nodes: 20000}\n" + kFabric)
                .find("above mesh.max_nodes 20000"),
            std::string::npos);
}

TEST_F(DrapeTestBlock, SaysWhatItExpandsTo) {
  const Scene scene = Load(std::string(kBlock) + kFabric);
  const std::string text = DrapeTestText(scene);
  EXPECT_NE(text.find("specimen 24 cm, disc 18 cm, clamp 17 cm"), std::string::npos) << text;
  EXPECT_NE(text.find("mesh {kind: circle, radius: 0.12, spacing: 0.02, origin: [0, 0, 0.001]}"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("obstacles: [{disk: {center: [0.0013, 0.0007, 0], radius: 0.09}}]"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace drape
