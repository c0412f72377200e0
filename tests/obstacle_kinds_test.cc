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
    specs["mesh"] = spec;
    specs["mesh"].kind = "mesh";
    // The octahedron of circumradius 1 about (1, 2, 2): its top vertex at z = 3.
    std::vector<Eigen::Vector3d> corners = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                            {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (auto& corner : corners) corner += Eigen::Vector3d(1, 2, 2);
    specs["mesh"].surface = TriangleSurface::Make(
        corners,
        {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
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
  std::string Error(const std::string& obstacles, const std::string& obj = "") {
    const testing::ScratchFolder scratch("obstacle_kinds");
    const fs::path path = scratch / "scene.yaml";
    if (!obj.empty()) std::ofstream(scratch / "body.obj") << obj;
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
            "cylinder, box, plane, pin, mesh)");
  EXPECT_EQ(Error("sphere: {center: [0, 0, 0]}"),
            "11:13: obstacles[0].sphere.radius: required key 'radius' is missing");
  EXPECT_EQ(Error("sphere: {center: [0, 0, -1], radius: 0.1, normal: [0, 0, 1]}"),
            "11:55: obstacles[0].sphere.normal: a sphere takes no 'normal' (its keys: center, "
            "radius, friction)");
  EXPECT_EQ(Error("box: {min: [0, 0, -2], max: [1, 1, -3]}"),
            "11:33: obstacles[0].box.max: max must exceed min in every coordinate");
}

// The octahedron of tests/data/meshes/octahedron.obj, its faces from `faces` on.
std::string Octahedron(const std::string& faces, const std::string& top = "0 0 1") {
  return "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv " + top + "\nv 0 0 -1\n" + faces;
}
const std::string kFaces =
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

TEST_F(ObstacleKindErrors, AMeshThatIsNoClosedOutwardSurfaceIsLocatedInItsFile) {
  const std::string mesh = "mesh: {file: body.obj, translation: [0, 0, -2]}";
  EXPECT_EQ(Error(mesh, Octahedron(kFaces)), "");
  const std::string at = "11:18: obstacles[0].mesh.file: ";
  std::string hole = kFaces.substr(0, kFaces.rfind("f "));
  EXPECT_NE(Error(mesh, Octahedron(hole)).find(at), std::string::npos);
  EXPECT_NE(Error(mesh, Octahedron(hole)).find("has a hole"), std::string::npos);
  std::string turned = kFaces;
  turned.replace(turned.find("f 3 1 6"), 7, "f 1 3 6");
  const std::string turned_error = Error(mesh, Octahedron(turned));
  EXPECT_NE(turned_error.find(at), std::string::npos) << turned_error;
  EXPECT_NE(turned_error.find("body.obj:11: "), std::string::npos) << turned_error;
  EXPECT_NE(turned_error.find("the same way as face"), std::string::npos) << turned_error;
  std::string inverted = "f 1 5 3\nf 3 5 2\nf 2 5 4\nf 4 5 1\nf 3 6 1\nf 2 6 3\nf 4 6 2\nf 1 6 4\n";
  EXPECT_NE(Error(mesh, Octahedron(inverted)).find("inside out"), std::string::npos);
  const std::string nan_error = Error(mesh, Octahedron(kFaces, "0 nan 1"));
  EXPECT_NE(nan_error.find(at), std::string::npos) << nan_error;
  EXPECT_NE(nan_error.find("body.obj:5: "), std::string::npos) << nan_error;
  EXPECT_NE(Error("mesh: {file: missing.obj}").find("missing.obj"), std::string::npos);
  EXPECT_EQ(Error("mesh: {scale: 2}"),
            "11:11: obstacles[0].mesh.file: required key 'file' is missing");
  EXPECT_EQ(Error("sphere: {center: [0, 0, -1], radius: 0.1, scale: 2}"),
            "11:54: obstacles[0].sphere.scale: a sphere takes no 'scale' (its keys: center, "
            "radius, friction)");
}

}  // namespace
}  // namespace drape
