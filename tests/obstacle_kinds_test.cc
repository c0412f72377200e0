// The obstacle-kind registry (src/model/obstacle_kinds.h): the reference's table
// (docs/reference.md) is its rows, each row's functor sees the scene's geometry, and a kind's keys
// are checked, located, when the model is built.
#include "src/model/obstacle_kinds.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "src/model/model.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// The rows of docs/reference.md's obstacle table: "| `name` | doc |".
std::vector<std::pair<std::string, std::string>> ReadmeObstacleRows() {
  std::ifstream readme(testing::SourcePath("docs/reference.md"));
  std::string line;
  bool in_section = false;
  std::vector<std::pair<std::string, std::string>> rows;
  const std::regex row(R"(^\| `([a-z_]+)` \| (.*) \|$)");
  while (std::getline(readme, line)) {
    if (line.rfind("### `obstacles`", 0) == 0) in_section = true;
    if (!in_section) continue;
    if (line.rfind("Example:", 0) == 0) break;
    std::smatch match;
    if (std::regex_match(line, match, row)) rows.emplace_back(match[1], match[2]);
  }
  return rows;
}

TEST(ObstacleKinds, TheReferenceTableIsTheRegistry) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const ObstacleKind& kind : ObstacleKinds()) rows.emplace_back(kind.name, kind.doc);
  EXPECT_EQ(ReadmeObstacleRows(), rows);
}

// Each row's distance at a point 0.5 m above the top of a body of size ~1 m whose keys the loader
// read: the functor must see the scene's geometry, not a default.
TEST(ObstacleKinds, EachRowMeasuresFromItsOwnGeometry) {
  const std::map<std::string, ObstacleSpec> samples = [] {
    std::map<std::string, ObstacleSpec> specs;
    ObstacleSpec spec;
    spec.center = {1, 2, 3};
    spec.radius = 1.0;
    spec.height = 2.0;
    spec.min = {0, 1, 1};
    spec.max = {2, 3, 3};
    spec.normal = {0, 0, 1};
    for (const char* name : {"sphere", "disk", "cylinder", "box", "plane"}) {
      specs[name] = spec;
      specs[name].kind = name;
    }
    specs["sphere"].center = {1, 2, 2};  // top at z = 3
    specs["pin"] = spec;
    specs["pin"].kind = "pin";
    specs["pin"].radius = 0.0;  // a pin has no radius key
    return specs;
  }();
  const double above[3] = {1, 2, 3.5};
  for (const ObstacleKind& kind : ObstacleKinds()) {
    ASSERT_EQ(samples.count(kind.name), 1u) << "no sample for the new kind " << kind.name;
    const ObstacleSpec& spec = samples.at(kind.name);
    EXPECT_NEAR(kind.distance(spec, above), 0.5, 1e-12) << kind.name;
    const auto term = kind.make_term(spec, 0, 0.001, 1.0, 0.0);
    EXPECT_EQ(term->type(), kind.name + "_contact");
    EXPECT_FALSE(kind.draw(spec, DrawingFrame{}).empty()) << kind.name;
  }
}

class ObstacleKindErrors : public ::testing::Test {
 protected:
  // The message of the InputError that loading and building the model throws ("" if none).
  std::string Error(const std::string& obstacles) {
    const testing::ScratchFolder scratch("obstacle_kinds");
    const fs::path path = scratch / "scene.yaml";
    std::ofstream(path) << "mesh:\n  kind: grid\n  nodes: [3, 3]\nmaterial:\n  density: 0.2\n"
                           "  springs:\n    structural: 100\nfixed:\n  - nodes: {corner: "
                           "top-left}\nobstacles:\n  - "
                        << obstacles << "\n";
    std::string message;
    try {
      BuildModel(LoadScene(path.string()));
    } catch (const InputError& error) {
      message = error.what();
    }
    return message.substr(message.find(':') + 1);  // without the file's path
  }
};

TEST_F(ObstacleKindErrors, AreLocatedAtTheObstacle) {
  EXPECT_EQ(Error("cone: {radius: 1}"),
            "11:11: obstacles[0].cone: unknown obstacle 'cone' (expected one of: sphere, disk, "
            "cylinder, box, plane, pin)");
  EXPECT_EQ(Error("sphere: {center: [0, 0, 0]}"),
            "11:13: obstacles[0].sphere.radius: required key 'radius' is missing");
  EXPECT_EQ(Error("sphere: {center: [0, 0, -1], radius: 0.1, normal: [0, 0, 1]}"),
            "11:55: obstacles[0].sphere.normal: a sphere takes no 'normal' (its keys: center, "
            "radius, friction)");
  EXPECT_EQ(Error("box: {min: [0, 0, -2], max: [1, 1, -3]}"),
            "11:33: obstacles[0].box.max: max must exceed min in every coordinate");
}

}  // namespace
}  // namespace drape
