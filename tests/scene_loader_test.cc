// Scene loading: every key of docs/reference.md's scene reference, the defaults, `--set` overrides,
// and every bad input rejected with "file:line:column: key.path: what is wrong".
#include "src/scene/scene_loader.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "src/scene/fabric_parameters.h"
#include "src/scene/solver_methods.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test holding the scene text as scene.yaml.
class SceneLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("scene_loader");
    folder_ = scratch_->path();
  }
  void TearDown() override { scratch_.reset(); }

  std::string Write(const std::string& text, const std::string& file = "scene.yaml") {
    const fs::path path = folder_ / file;
    std::ofstream(path) << text;
    return path.string();
  }

  Scene Load(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return LoadScene(Write(text), overrides);
  }

  // The message of the InputError that loading throws ("" if it loads).
  std::string Error(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
      LoadScene(Write(text), overrides);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  std::string ScenePath() const { return (folder_ / "scene.yaml").string(); }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path folder_;
};

// A valid scene to start from; line numbers below refer to it.
constexpr char kMinimal[] = R"(mesh:
  kind: grid
  nodes: [3, 3]
material:
  density: 0.2
  springs:
    structural: 100
)";

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ------------------------------------------------------------------------------- valid scenes

// kMinimal with its `nodes:` line (line 3) replaced.
std::string MinimalWithNodes(const std::string& lines) {
  std::string text = kMinimal;
  const std::string nodes = "  nodes: [3, 3]";
  return text.replace(text.find(nodes), nodes.size(), lines);
}

TEST_F(SceneLoaderTest, MinimalSceneGetsTheDefaults) {
  const Scene scene = Load(kMinimal);
  EXPECT_EQ(scene.file, ScenePath());
  EXPECT_EQ(scene.directory, folder_.string());
  EXPECT_EQ(scene.name, "scene");
  EXPECT_EQ(scene.dimension, 3);
  EXPECT_EQ(scene.mesh.kind, MeshSpec::Kind::kGrid);
  EXPECT_EQ(scene.mesh.nodes[0], 3);
  EXPECT_EQ(scene.mesh.size, Eigen::Vector2d(1.0, 1.0));
  EXPECT_TRUE(scene.mesh.u.empty());
  EXPECT_EQ(scene.mesh.plane, "xy");
  EXPECT_EQ(scene.mesh.origin, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.material.model, MaterialModel::kSprings);
  EXPECT_EQ(scene.material.mass_kind, MaterialSpec::MassKind::kDensity);
  EXPECT_DOUBLE_EQ(scene.material.mass_value, 0.2);
  const SpringsSpec& springs = scene.material.springs;
  EXPECT_TRUE(springs.structural.present);
  EXPECT_DOUBLE_EQ(springs.structural.warp, 100.0);
  EXPECT_DOUBLE_EQ(springs.structural.weft, 100.0);
  EXPECT_FALSE(springs.shear.present);
  EXPECT_FALSE(springs.flexion.present);
  EXPECT_EQ(springs.rest_length, SpringsSpec::RestLength::kInitial);
  EXPECT_FALSE(springs.tension_only);
  EXPECT_FALSE(springs.stretch_limit.has_value());
  EXPECT_FALSE(scene.material.finite_volume.present);
  EXPECT_TRUE(scene.fixed.empty());
  EXPECT_FALSE(scene.loads.gravity.has_value());
  EXPECT_TRUE(scene.loads.forces.empty());
  EXPECT_TRUE(scene.obstacles.empty());
  EXPECT_DOUBLE_EQ(scene.contact.thickness, ContactSpec().thickness);
  const SolverSpec defaults;
  EXPECT_EQ(scene.solver.method, "newton");
  EXPECT_DOUBLE_EQ(scene.solver.tolerance, defaults.tolerance);
  EXPECT_FALSE(scene.solver.max_iterations.has_value());  // the method's default applies
  EXPECT_FALSE(scene.solver.time_limit.has_value());
  EXPECT_TRUE(scene.solver.method_options.empty());
  EXPECT_EQ(scene.output.directory, (folder_ / "out" / "scene").string());
  EXPECT_EQ(scene.output.write, OutputSpec().write);
  EXPECT_EQ(scene.output.obj_up, "z");
}

TEST_F(SceneLoaderTest, EveryKeyOfAGridScene) {
  const Scene scene = Load(R"(name: every-key
dimension: 3
mesh:
  kind: grid
  size: [2.0, 1.5]
  nodes: [5, 4]
  plane: xz
  origin: [0.1, 0.2, 0.3]
material:
  model: springs
  total_mass: 0.5
  springs:
    structural: {warp: 1000, weft: 800}
    shear: 500
    flexion: 10
    rest_length: 0.05
    tension_only: true
    stretch_limit: 1.1
fixed:
  - nodes: {edge: top}
    dofs: [x, z]
    move: [0, 0.01, -0.02]
loads:
  gravity: [0, 0, -9.81]
  forces:
    - nodes: {edge: bottom}
      total: [0, 0, -3.0]
    - nodes: {ids: [7]}
      each: [1.0, 0, 0]
obstacles:
  - sphere: {center: [0, 0, -0.2], radius: 0.15, friction: 0.3}
  - disk: {center: [0, 0, 0], radius: 0.09}
  - cylinder: {center: [1, 0, 0], radius: 0.08, height: 0.3}
  - box: {min: [-0.5, -0.5, -1], max: [0.5, 0.5, 0]}
  - plane: {point: [0, 0, -1], normal: [0, 0, 2]}
  - pin: {position: [0.2, 0.3, 0.4]}
contact:
  thickness: 0.002
solver:
  method: ceres-lbfgs
  tolerance: 1.0e-9
  max_iterations: 500
  time_limit: 30
  ceres-lbfgs: {memory: 12}
output:
  directory: results/here
  write: [summary, nodes, history, vtk, obj, png, kinetic, profile, shadow]
  obj_up: y
)");
  EXPECT_EQ(scene.name, "every-key");
  EXPECT_EQ(scene.mesh.size, Eigen::Vector2d(2.0, 1.5));
  EXPECT_EQ(scene.mesh.nodes[0], 5);
  EXPECT_EQ(scene.mesh.nodes[1], 4);
  EXPECT_EQ(scene.mesh.plane, "xz");
  EXPECT_EQ(scene.mesh.origin, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(scene.material.mass_kind, MaterialSpec::MassKind::kTotalMass);
  EXPECT_DOUBLE_EQ(scene.material.mass_value, 0.5);
  const SpringsSpec& springs = scene.material.springs;
  EXPECT_DOUBLE_EQ(springs.structural.warp, 1000.0);
  EXPECT_DOUBLE_EQ(springs.structural.weft, 800.0);
  EXPECT_DOUBLE_EQ(springs.shear.warp, 500.0);
  EXPECT_DOUBLE_EQ(springs.flexion.weft, 10.0);
  EXPECT_EQ(springs.rest_length, SpringsSpec::RestLength::kGiven);
  EXPECT_DOUBLE_EQ(springs.rest_length_value, 0.05);
  EXPECT_TRUE(springs.tension_only);
  EXPECT_DOUBLE_EQ(springs.stretch_limit.value_or(0.0), 1.1);
  ASSERT_EQ(scene.fixed.size(), 1u);
  EXPECT_EQ(scene.fixed[0].nodes.kind, NodeSelector::Kind::kEdge);
  EXPECT_EQ(scene.fixed[0].nodes.name, "top");
  EXPECT_EQ(scene.fixed[0].dofs, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(scene.fixed[0].move, Eigen::Vector3d(0, 0.01, -0.02));
  ASSERT_TRUE(scene.loads.gravity.has_value());
  EXPECT_EQ(*scene.loads.gravity, Eigen::Vector3d(0, 0, -9.81));
  ASSERT_EQ(scene.loads.forces.size(), 2u);
  EXPECT_EQ(scene.loads.forces[0].kind, ForceSpec::Kind::kTotal);
  EXPECT_EQ(scene.loads.forces[0].value, Eigen::Vector3d(0, 0, -3.0));
  EXPECT_EQ(scene.loads.forces[1].kind, ForceSpec::Kind::kEach);
  EXPECT_EQ(scene.loads.forces[1].nodes.ids, std::vector<int>{7});
  ASSERT_EQ(scene.obstacles.size(), 6u);
  EXPECT_EQ(scene.obstacles[0].kind, "sphere");
  EXPECT_DOUBLE_EQ(scene.obstacles[0].radius, 0.15);
  EXPECT_DOUBLE_EQ(scene.obstacles[0].friction, 0.3);
  EXPECT_EQ(scene.obstacles[1].kind, "disk");
  EXPECT_DOUBLE_EQ(scene.obstacles[1].friction, 0.0);
  EXPECT_EQ(scene.obstacles[2].kind, "cylinder");
  EXPECT_DOUBLE_EQ(scene.obstacles[2].height, 0.3);
  EXPECT_EQ(scene.obstacles[2].center, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(scene.obstacles[3].kind, "box");
  EXPECT_EQ(scene.obstacles[3].min, Eigen::Vector3d(-0.5, -0.5, -1));
  EXPECT_EQ(scene.obstacles[3].max, Eigen::Vector3d(0.5, 0.5, 0));
  EXPECT_EQ(scene.obstacles[4].kind, "plane");
  EXPECT_EQ(scene.obstacles[4].center, Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(scene.obstacles[4].normal, Eigen::Vector3d(0, 0, 1));  // normalised
  EXPECT_EQ(scene.obstacles[5].kind, "pin");
  EXPECT_EQ(scene.obstacles[5].center, Eigen::Vector3d(0.2, 0.3, 0.4));
  EXPECT_DOUBLE_EQ(scene.contact.thickness, 0.002);
  EXPECT_EQ(scene.solver.method, "ceres-lbfgs");
  EXPECT_DOUBLE_EQ(scene.solver.tolerance, 1e-9);
  EXPECT_EQ(scene.solver.max_iterations, 500);
  EXPECT_DOUBLE_EQ(scene.solver.time_limit.value_or(0.0), 30.0);
  EXPECT_DOUBLE_EQ(scene.solver.method_options.at("ceres-lbfgs").at("memory"), 12.0);
  EXPECT_EQ(scene.output.directory, (folder_ / "results" / "here").string());
  EXPECT_EQ(scene.output.write.size(), 9u);
  EXPECT_EQ(scene.output.write.back(), "shadow");
  EXPECT_EQ(scene.output.obj_up, "y");
}

TEST_F(SceneLoaderTest, ExplicitGridCoordinatesSetNodesAndSize) {
  const Scene scene = Load(R"(mesh:
  u: [0.0, 0.1, 0.3, 0.6]
  v: [-0.5, 0.5]
material: {node_mass: 0.01, springs: {structural: 1}}
)");
  EXPECT_EQ(scene.mesh.u, (std::vector<double>{0.0, 0.1, 0.3, 0.6}));
  EXPECT_EQ(scene.mesh.v, (std::vector<double>{-0.5, 0.5}));
  EXPECT_EQ(scene.mesh.nodes[0], 4);
  EXPECT_EQ(scene.mesh.nodes[1], 2);
  EXPECT_DOUBLE_EQ(scene.mesh.size[0], 0.6);
  EXPECT_DOUBLE_EQ(scene.mesh.size[1], 1.0);
  EXPECT_EQ(scene.material.mass_kind, MaterialSpec::MassKind::kNodeMass);
}

TEST_F(SceneLoaderTest, ARowOfNodesMayHaveZeroWidth) {
  const Scene scene = Load(MinimalWithNodes("  nodes: [5, 1]\n  size: [2, 0]"));
  EXPECT_EQ(scene.mesh.nodes[1], 1);
  EXPECT_DOUBLE_EQ(scene.mesh.size[0], 2.0);
  EXPECT_DOUBLE_EQ(scene.mesh.size[1], 0.0);
}

TEST_F(SceneLoaderTest, CircleArcChainAndFileMeshes) {
  const std::string material = "material: {density: 0.2, springs: {structural: 1}}\n";
  const Scene circle =
      Load("mesh: {kind: circle, radius: 0.2, spacing: 0.02, origin: [0, 0, 1]}\n" + material);
  EXPECT_EQ(circle.mesh.kind, MeshSpec::Kind::kCircle);
  EXPECT_DOUBLE_EQ(circle.mesh.radius, 0.2);
  EXPECT_DOUBLE_EQ(circle.mesh.spacing, 0.02);
  EXPECT_EQ(circle.mesh.origin, Eigen::Vector3d(0, 0, 1));

  const Scene arc = Load("mesh: {kind: arc, radius: 0.15, rings: 7, spokes: 32}\n" + material);
  EXPECT_EQ(arc.mesh.kind, MeshSpec::Kind::kArc);
  EXPECT_EQ(arc.mesh.rings, 7);
  EXPECT_EQ(arc.mesh.spokes, 32);

  const Scene chain = Load(
      "dimension: 2\nmesh: {kind: chain, length: 2, nodes: 21, "
      "direction: [0, 0, -3]}\n" +
      material);
  EXPECT_EQ(chain.dimension, 2);
  EXPECT_EQ(chain.mesh.kind, MeshSpec::Kind::kChain);
  EXPECT_DOUBLE_EQ(chain.mesh.length, 2.0);
  EXPECT_EQ(chain.mesh.chain_nodes, 21);
  EXPECT_EQ(chain.mesh.direction, Eigen::Vector3d(0, 0, -1));  // normalised

  const Scene file = Load("mesh: {kind: file, path: meshes/skirt.obj}\n" + material);
  EXPECT_EQ(file.mesh.kind, MeshSpec::Kind::kFile);
  EXPECT_EQ(file.mesh.path, (folder_ / "meshes" / "skirt.obj").string());
  const Scene absolute = Load("mesh: {kind: file, path: /data/skirt.obj}\n" + material);
  EXPECT_EQ(absolute.mesh.path, "/data/skirt.obj");
}

TEST_F(SceneLoaderTest, RestLengthWordsAndFiniteVolume) {
  const Scene zero = Load(std::string(kMinimal) + "    rest_length: zero\n");
  EXPECT_EQ(zero.material.springs.rest_length, SpringsSpec::RestLength::kZero);
  const Scene initial = Load(std::string(kMinimal) + "    rest_length: initial\n");
  EXPECT_EQ(initial.material.springs.rest_length, SpringsSpec::RestLength::kInitial);

  const Scene fv = Load(R"(mesh: {nodes: [3, 3]}
material:
  model: finite_volume
  density: 0.2
  finite_volume:
    E_warp: 500
    E_weft: 300
    nu_warp: 0.2
    nu_weft: 0.1
    G: 5
    D_warp: 1.0e-5
    D_weft: 2.0e-5
    D_12: 1.0e-6
)");
  const FiniteVolumeSpec& spec = fv.material.finite_volume;
  EXPECT_EQ(fv.material.model, MaterialModel::kFiniteVolume);
  EXPECT_TRUE(spec.present);
  EXPECT_DOUBLE_EQ(spec.E_warp, 500.0);
  EXPECT_DOUBLE_EQ(spec.E_weft, 300.0);
  EXPECT_DOUBLE_EQ(spec.nu_warp, 0.2);
  EXPECT_DOUBLE_EQ(spec.nu_weft, 0.1);
  EXPECT_DOUBLE_EQ(spec.G, 5.0);
  EXPECT_DOUBLE_EQ(spec.D_warp, 1e-5);
  EXPECT_DOUBLE_EQ(spec.D_weft, 2e-5);
  EXPECT_DOUBLE_EQ(spec.D_12, 1e-6);
  EXPECT_FALSE(fv.material.springs.structural.present);
}

TEST_F(SceneLoaderTest, EverySelectorKindIsReadAndLocated) {
  const Scene scene = Load(std::string(kMinimal) + R"(fixed:
  - nodes: {edge: left}
  - nodes: {corner: top-right}
  - nodes: {ids: [0, 4]}
  - nodes: {ij: [[0, 0], [2, 1]]}
  - nodes: {box: {min: [0, 0, 0], max: [1, 0.5, 0]}}
  - nodes: {within: {center: [0.5, 0.5, 0], radius: 0.2}}
  - nodes: {all: true}
)");
  ASSERT_EQ(scene.fixed.size(), 7u);
  const auto& f = scene.fixed;
  EXPECT_EQ(f[0].nodes.kind, NodeSelector::Kind::kEdge);
  EXPECT_EQ(f[0].nodes.name, "left");
  EXPECT_EQ(f[1].nodes.kind, NodeSelector::Kind::kCorner);
  EXPECT_EQ(f[1].nodes.name, "top-right");
  EXPECT_EQ(f[2].nodes.kind, NodeSelector::Kind::kIds);
  EXPECT_EQ(f[2].nodes.ids, (std::vector<int>{0, 4}));
  EXPECT_EQ(f[3].nodes.kind, NodeSelector::Kind::kIj);
  ASSERT_EQ(f[3].nodes.ij.size(), 2u);
  EXPECT_EQ(f[3].nodes.ij[1], (std::array<int, 2>{2, 1}));
  EXPECT_EQ(f[4].nodes.kind, NodeSelector::Kind::kBox);
  EXPECT_EQ(f[4].nodes.max, Eigen::Vector3d(1, 0.5, 0));
  EXPECT_EQ(f[5].nodes.kind, NodeSelector::Kind::kWithin);
  EXPECT_EQ(f[5].nodes.center, Eigen::Vector3d(0.5, 0.5, 0));
  EXPECT_DOUBLE_EQ(f[5].nodes.radius, 0.2);
  EXPECT_EQ(f[6].nodes.kind, NodeSelector::Kind::kAll);
  // Each selector is located at its value, so that the selection builder's errors point there:
  // line 11 is "  - nodes: {ids: [0, 4]}", the list starts at column 18.
  const Location& where = f[2].nodes.where;
  EXPECT_EQ(where.file, ScenePath());
  EXPECT_EQ(where.line, 11);
  EXPECT_EQ(where.column, 18);
  EXPECT_EQ(where.key, "fixed[2].nodes.ids");
  EXPECT_EQ(f[2].where.key, "fixed[2]");
  EXPECT_EQ(f[2].where.line, 11);
  EXPECT_EQ(f[2].where.column, 5);
}

// Several terms in one energy: springs beside a finite-volume material, spring lines, regions;
// the row, column and outside selectors.
TEST_F(SceneLoaderTest, SpringsBesideFiniteVolumeLinesAndRegions) {
  const std::string fv = R"(mesh: {nodes: [5, 5]}
material:
  model: finite_volume
  density: 0.2
  finite_volume: {E_warp: 500, E_weft: 300, G: 5, D_warp: 1.0e-5, D_weft: 2.0e-5}
  springs:
    structural: 100
    tension_only: true
  lines:
    - nodes: {row: 2}
      structural: 50
      tension_only: true
    - nodes: {column: 0}
      structural: 70
regions:
  - nodes: {outside: {center: [0.5, 0.5, 0], radius: 0.4}}
    density: 0.4
    D_warp: 4.0e-5
    structural: {warp: 200, weft: 150}
    tension_only: false
)";
  const Scene scene = Load(fv);
  EXPECT_TRUE(scene.material.springs.present);
  EXPECT_TRUE(scene.material.springs.tension_only);
  ASSERT_EQ(scene.material.lines.size(), 2u);
  EXPECT_EQ(scene.material.lines[0].nodes.kind, NodeSelector::Kind::kRow);
  EXPECT_EQ(scene.material.lines[0].nodes.index, 2);
  EXPECT_EQ(scene.material.lines[0].stiffness, 50.0);
  EXPECT_TRUE(scene.material.lines[0].tension_only);
  EXPECT_EQ(scene.material.lines[1].nodes.kind, NodeSelector::Kind::kColumn);
  EXPECT_FALSE(scene.material.lines[1].tension_only);
  ASSERT_EQ(scene.regions.size(), 1u);
  const RegionSpec& region = scene.regions[0];
  EXPECT_EQ(region.nodes.kind, NodeSelector::Kind::kOutside);
  EXPECT_EQ(region.nodes.radius, 0.4);
  EXPECT_EQ(*region.density, 0.4);
  EXPECT_EQ(region.finite_volume.at("D_warp"), 4e-5);
  EXPECT_EQ(region.finite_volume.count("D_weft"), 0u);
  EXPECT_EQ(region.structural.weft, 150.0);
  EXPECT_FALSE(*region.tension_only);
  EXPECT_EQ(region.where.key, "regions[0]");
  EXPECT_EQ(region.given.at("D_warp").line, 18);

  // The message the issue quotes is gone: springs may be set beside a finite_volume material.
  const Scene set = Load(fv, {"material.springs={structural: 100, tension_only: true}"});
  EXPECT_EQ(set.material.springs.structural.warp, 100.0);
  EXPECT_TRUE(Contains(Error(fv, {"material.springs.stretch_limit=1.1"}),
                       "material.springs.stretch_limit: 'stretch_limit' applies only when "
                       "material.model is springs"));
  const std::string node_mass =
      std::string(kMinimal) + "regions:\n  - nodes: {all: true}\n    density: 0.4\n";
  std::string replaced = node_mass;
  replaced.replace(replaced.find("density: 0.2"), 12, "node_mass: 0.2");
  EXPECT_TRUE(Contains(Error(replaced), "10:5: regions[0].density: a region's density needs"));
  EXPECT_TRUE(Contains(Error(std::string(kMinimal) + "regions:\n  - nodes: {all: true}\n"),
                       "9:5: regions[0]: the region overrides nothing"));
}

// A named region is selected by `{region: name}` wherever a selection is written (supports,
// loads, spring lines, later regions): the loader puts the region's own selection there, located
// where the region wrote it. Traction and pressure are read as forces per unit area.
TEST_F(SceneLoaderTest, RegionReferencesBecomeTheRegionsSelection) {
  const Scene scene = Load(std::string(kMinimal) + R"(  lines:
    - nodes: {region: hem}
      structural: 50
regions:
  - name: hem
    nodes: {row: 0}
    density: 0.4
  - nodes: {region: hem}
    density: 0.5
fixed:
  - nodes: {region: hem}
loads:
  forces:
    - nodes: {region: hem}
      traction: [0, 0, -2]
    - nodes: {all: true}
      pressure: 30
)");
  ASSERT_EQ(scene.regions.size(), 2u);
  EXPECT_EQ(scene.regions[0].name, "hem");
  EXPECT_TRUE(scene.regions[1].name.empty());
  for (const NodeSelector* selector : {&scene.material.lines[0].nodes, &scene.regions[1].nodes,
                                       &scene.fixed[0].nodes, &scene.loads.forces[0].nodes}) {
    EXPECT_TRUE(selector->region.empty());
    EXPECT_EQ(selector->kind, NodeSelector::Kind::kRow);
    EXPECT_EQ(selector->index, 0);
    EXPECT_EQ(selector->where.key, "regions[0].nodes.row");  // errors point at the region
  }
  EXPECT_EQ(scene.loads.forces[0].kind, ForceSpec::Kind::kTraction);
  EXPECT_EQ(scene.loads.forces[0].value, Eigen::Vector3d(0, 0, -2));
  EXPECT_EQ(scene.loads.forces[1].kind, ForceSpec::Kind::kPressure);
  EXPECT_EQ(scene.loads.forces[1].pressure, 30.0);

  const std::string regions =
      std::string(kMinimal) + "regions:\n  - name: hem\n    nodes: {row: 0}\n    density: 0.4\n";
  EXPECT_TRUE(Contains(Error(regions + "fixed:\n  - nodes: {region: rim}\n"),
                       "13:21: fixed[0].nodes.region: no region named 'rim' (named regions: hem)"));
  EXPECT_TRUE(Contains(Error(regions + "  - name: hem\n    nodes: {row: 1}\n    density: 0.3\n"),
                       "12:11: regions[1].name: another region is already named 'hem'"));
  EXPECT_TRUE(Contains(
      Error(std::string(kMinimal) + "regions:\n  - nodes: {region: late}\n    density: 0.4\n"
                                    "  - name: late\n    nodes: {row: 1}\n    density: 0.3\n"),
      "9:21: regions[0].nodes.region: no region named 'late' before this one"));
  EXPECT_TRUE(Contains(Error(std::string(kMinimal) + "fixed:\n  - nodes: {region: hem}\n"),
                       "9:21: fixed[0].nodes.region: no region named 'hem' (no region is named"));
  EXPECT_TRUE(Contains(Error(std::string(kMinimal) +
                             "loads:\n  forces:\n    - nodes: {all: true}\n      pressure: [1]\n"),
                       "11:17: loads.forces[0].pressure: expected a number"));
}

TEST_F(SceneLoaderTest, SpecsCarryTheirLocations) {
  const Scene scene = Load(std::string(kMinimal) + R"(loads:
  gravity: [0, 0, -9.81]
obstacles:
  - disk: {center: [0, 0, 0], radius: 0.09}
)");
  EXPECT_EQ(scene.root.file, ScenePath());
  EXPECT_EQ(scene.root.line, 1);
  // A block map is located at its key.
  EXPECT_EQ(scene.mesh.where.line, 1);
  EXPECT_EQ(scene.mesh.where.column, 1);
  EXPECT_EQ(scene.mesh.where.key, "mesh");
  EXPECT_EQ(scene.material.where.line, 4);
  EXPECT_EQ(scene.material.springs.where.line, 6);
  EXPECT_EQ(scene.material.springs.where.column, 3);
  EXPECT_EQ(scene.material.springs.where.key, "material.springs");
  EXPECT_EQ(scene.material.springs.structural.where.line, 7);
  EXPECT_EQ(scene.material.springs.structural.where.column, 17);
  EXPECT_EQ(scene.loads.where.line, 8);
  EXPECT_EQ(scene.obstacles[0].where.line, 11);
  EXPECT_EQ(scene.obstacles[0].where.column, 11);
  EXPECT_EQ(scene.obstacles[0].where.key, "obstacles[0].disk");
}

// A value inside the option's range: its default when that is a finite number, else 1 (or 0,
// "none", where that is accepted).
double ValidValue(const MethodOption& option) {
  if (option.default_value && std::isfinite(*option.default_value)) return *option.default_value;
  return option.zero_means_none ? 0.0 : 1.0;
}

TEST_F(SceneLoaderTest, EveryRegisteredMethodAndItsOptionsAreAccepted) {
  for (const auto& method : SolverMethods()) {
    std::string text = std::string(kMinimal) + "solver:\n  method: " + method.name + "\n";
    if (!method.options.empty()) text += "  " + method.name + ":\n";
    for (const auto& option : method.options) {
      std::ostringstream line;
      line << "    " << option.key << ": " << ValidValue(option) << "\n";
      text += line.str();
    }
    const Scene scene = Load(text);
    EXPECT_EQ(scene.solver.method, method.name);
    for (const auto& option : method.options) {
      EXPECT_DOUBLE_EQ(scene.solver.method_options.at(method.name).at(option.key),
                       ValidValue(option))
          << method.name << "." << option.key;
    }
  }
}

TEST_F(SceneLoaderTest, AbsoluteOutputDirectoryStaysAsGiven) {
  const Scene scene = Load(std::string(kMinimal) + "output: {directory: /tmp/drape-abs}\n");
  EXPECT_EQ(scene.output.directory, "/tmp/drape-abs");
  const Scene named = Load(std::string(kMinimal) + "name: sheet\n");
  EXPECT_EQ(named.output.directory, (folder_ / "out" / "sheet").string());
}

// ---------------------------------------------------------------------------------- --set

TEST_F(SceneLoaderTest, SetOverridesScalarsListsNestedKeysAndListItems) {
  const std::string text = std::string(kMinimal) + "fixed:\n  - nodes: {edge: top}\n";
  const Scene scene =
      Load(text, {"solver.tolerance=1e-6", "mesh.nodes=[4, 5]", "solver.ceres-lbfgs.memory=7",
                  "fixed[0].dofs=[z]", "material.springs.structural={warp: 3, weft: 4}",
                  "fixed[0].nodes={ids: [1, 2]}", "name=renamed"});
  EXPECT_DOUBLE_EQ(scene.solver.tolerance, 1e-6);
  EXPECT_EQ(scene.mesh.nodes[0], 4);
  EXPECT_EQ(scene.mesh.nodes[1], 5);
  EXPECT_DOUBLE_EQ(scene.solver.method_options.at("ceres-lbfgs").at("memory"), 7.0);
  EXPECT_EQ(scene.fixed[0].dofs, (std::array<bool, 3>{false, false, true}));
  EXPECT_DOUBLE_EQ(scene.material.springs.structural.warp, 3.0);
  EXPECT_DOUBLE_EQ(scene.material.springs.structural.weft, 4.0);
  EXPECT_EQ(scene.fixed[0].nodes.ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(scene.name, "renamed");
  EXPECT_EQ(scene.output.directory, (folder_ / "out" / "renamed").string());
  // A value from --set is located in the override: the 6th, its ids list at column 22.
  EXPECT_EQ(scene.fixed[0].nodes.where.file, "--set");
  EXPECT_EQ(scene.fixed[0].nodes.where.line, 6);
  EXPECT_EQ(scene.fixed[0].nodes.where.column, 22);
}

TEST_F(SceneLoaderTest, SetIndexesIntoAList) {
  const Scene scene = Load(kMinimal, {"mesh.nodes[1]=7"});
  EXPECT_EQ(scene.mesh.nodes[0], 3);
  EXPECT_EQ(scene.mesh.nodes[1], 7);
}

TEST_F(SceneLoaderTest, SetCreatesMissingSectionsAndLaterSetsWin) {
  const Scene scene = Load(kMinimal, {"loads.gravity=[0, 0, -1]", "fixed=[{nodes: {all: true}}]",
                                      "solver.max_iterations=5", "solver.max_iterations=9"});
  EXPECT_EQ(*scene.loads.gravity, Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(scene.fixed.size(), 1u);
  EXPECT_EQ(scene.solver.max_iterations, 9);
}

TEST_F(SceneLoaderTest, SetErrorsAreLocatedInTheOverride) {
  EXPECT_TRUE(Contains(Error(kMinimal, {"solver.tolerance"}), "--set:1:1: "));
  EXPECT_TRUE(Contains(Error(kMinimal, {"solver.tolerance"}), "key.path=value"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"ok=1", "mesh..kind=grid"}), "--set:2:6: "));
  EXPECT_TRUE(Contains(Error(kMinimal, {"fixed[x]=1"}), "--set:1:6: "));
  EXPECT_TRUE(Contains(Error(kMinimal, {"mesh.nodes[2]=1"}), "has no item 2"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"mesh.kind.x=1"}), "--set:1:11: "));
  EXPECT_TRUE(Contains(Error(kMinimal, {"mesh.kind.x=1"}), "cannot set 'x' inside 'grid'"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"mesh.nodes.x=1"}), "inside a list"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"fixed[0].dofs=[z]"}), "'fixed' is not a list"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"mesh.nodes=[3, 3"}), "--set:1:"));
  // A bad value is located at its character in the override.
  EXPECT_TRUE(Contains(Error(kMinimal, {"material.density=-1"}),
                       "--set:1:18: material.density: must be positive"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"mesh.nodes=[3, 0x3]"}),
                       "--set:1:16: mesh.nodes[1]: expected a number"));
  EXPECT_TRUE(Contains(Error(kMinimal, {"material.densty=1"}),
                       "--set:1:10: material.densty: unknown key 'densty'; did you mean "
                       "'density'?"));
}

// ---------------------------------------------------------------------- a scene read once

TEST_F(SceneLoaderTest, ADocumentReadOnceTakesValuesAndStaysAsItWasRead) {
  const std::string text = std::string(kMinimal) + "fixed:\n  - nodes: {edge: top}\n";
  const SceneDocument document = SceneDocument::Read(Write(text));
  fs::remove(ScenePath());           // nothing below reads the file
  const double density = 0.1 + 0.2;  // not a short decimal: set exactly, not through text
  const Scene changed =
      document.Load({"solver.tolerance=1e-6"}, {{"material.density", YAML::Node(density)},
                                                {"fixed[0].dofs", YAML::Load("[z]")},
                                                {"mesh.nodes[1]", YAML::Node(5)},
                                                {"loads.gravity", YAML::Load("[0, 0, -1]")}});
  EXPECT_EQ(changed.material.mass_value, density);
  EXPECT_DOUBLE_EQ(changed.solver.tolerance, 1e-6);
  EXPECT_EQ(changed.fixed[0].dofs, (std::array<bool, 3>{false, false, true}));
  EXPECT_EQ(changed.mesh.nodes[1], 5);
  EXPECT_EQ(*changed.loads.gravity, Eigen::Vector3d(0, 0, -1));
  // The document is as it was read: a load without values gives the file's scene.
  const Scene plain = document.Load();
  EXPECT_EQ(plain.material.mass_value, 0.2);
  EXPECT_EQ(plain.mesh.nodes[1], 3);
  EXPECT_EQ(plain.fixed[0].dofs, (std::array<bool, 3>{true, true, true}));
  EXPECT_FALSE(plain.loads.gravity.has_value());
  EXPECT_EQ(plain.solver.tolerance, Load(kMinimal).solver.tolerance);
  EXPECT_EQ(plain.material.where.line, 4);  // still located in the file
}

TEST_F(SceneLoaderTest, ADocumentLoadsOnSeveralThreadsAtOnce) {
  // A sweep's tasks and a fit's equilibria load from one document on their threads.
  const SceneDocument document = SceneDocument::Read(Write(kMinimal));
  std::vector<double> densities(8);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < densities.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int k = 0; k < 50; ++k) {
        const double density = 0.1 * static_cast<double>(t + 1);
        densities[t] =
            document.Load({}, {{"material.density", YAML::Node(density)}}).material.mass_value;
      }
    });
  }
  for (auto& thread : threads) thread.join();
  for (size_t t = 0; t < densities.size(); ++t) {
    EXPECT_EQ(densities[t], 0.1 * static_cast<double>(t + 1));
  }
  EXPECT_EQ(document.Load().material.mass_value, 0.2);
}

TEST_F(SceneLoaderTest, ADocumentsErrorsAreLocatedAsTheLoadersAre) {
  // A value is located as the override after the text ones, where "key=value" has its value.
  const SceneDocument document = SceneDocument::Read(Write(kMinimal));
  try {
    document.Load({"solver.tolerance=1e-6"}, {{"material.density", YAML::Node(-1.0)}});
    ADD_FAILURE() << "a negative density loaded";
  } catch (const InputError& error) {
    EXPECT_TRUE(Contains(error.what(), "--set:2:18: material.density: must be positive"))
        << error.what();
  }
  // A bad key of the file in a map that a value changes is still located in the file.
  std::string bad = kMinimal;
  bad.replace(bad.find("density: 0.2"), 12, "density: -0.2");
  const SceneDocument bad_document = SceneDocument::Read(Write(bad));
  for (const std::vector<SceneValue>& values :
       {std::vector<SceneValue>{}, {{"material.springs.shear", YAML::Node(5.0)}}}) {
    try {
      bad_document.Load({}, values);
      ADD_FAILURE() << "a negative density loaded";
    } catch (const InputError& error) {
      EXPECT_TRUE(Contains(error.what(), "scene.yaml:5:12: material.density: must be positive"))
          << error.what();
    }
  }
}

// ------------------------------------------------------------------------------ bad input

// One bad scene: its text, the expected "line:column: key.path: " and a fragment of the message.
struct BadScene {
  const char* name;
  std::string text;
  std::string where;  // "line:column: key.path"
  std::string what;
};

// kMinimal with one line replaced (1-based `line`).
std::string MinimalWith(int line, const std::string& replacement) {
  std::string text = kMinimal;
  size_t start = 0;
  for (int k = 1; k < line; ++k) start = text.find('\n', start) + 1;
  const size_t end = text.find('\n', start);
  return text.replace(start, end - start, replacement);
}

const std::vector<BadScene>& BadScenes() {
  static const std::vector<BadScene> scenes = {
      {"UnknownKeySuggestsTheNearest", MinimalWith(5, "  densty: 0.2"), "5:3: material.densty",
       "unknown key 'densty'; did you mean 'density'?"},
      {"UnknownTopLevelKey", std::string(kMinimal) + "solvr: {method: newton}\n", "8:1: solvr",
       "did you mean 'solver'?"},
      {"UnknownKeyWithoutNearOneListsTheKeys", std::string(kMinimal) + "colour: red\n",
       "8:1: colour", "expected one of: name, dimension, mesh"},
      {"KeyOfAnotherMeshKind", MinimalWith(3, "  radius: 0.1"), "3:3: mesh.radius",
       "'radius' does not apply to a grid mesh"},
      {"StringWhereANumberIsExpected", MinimalWith(5, "  density: heavy"), "5:12: material.density",
       "expected a number, got 'heavy'"},
      {"QuotedNumber", MinimalWith(5, "  density: \"0.2\""), "5:12: material.density",
       "quoted text"},
      {"MapWhereAListIsExpected", std::string(kMinimal) + "fixed: {nodes: {edge: top}}\n",
       "8:8: fixed", "expected a list"},
      {"ListWhereANumberIsExpected", MinimalWith(7, "    structural: [1, 2]"),
       "7:17: material.springs.structural", "expected a stiffness in N/m"},
      {"MissingMesh", "material: {density: 1, springs: {structural: 1}}\n", "1:1: mesh",
       "required key 'mesh' is missing"},
      {"MissingMaterial", "mesh: {nodes: [2, 2]}\n", "1:1: material",
       "required key 'material' is missing"},
      {"MissingMass", MinimalWith(5, "  model: springs"), "4:1: material", "the mass is missing"},
      {"TwoMasses", MinimalWith(5, "  density: 1\n  node_mass: 2"), "6:3: material.node_mass",
       "give only one of density, node_mass and total_mass"},
      {"MissingSprings", "mesh: {nodes: [2, 2]}\nmaterial: {density: 1}\n",
       "2:11: material.springs", "required key 'springs' is missing"},
      {"NoSpringFamily", MinimalWith(7, "    tension_only: true"), "6:3: material.springs",
       "no spring family"},
      {"MissingWeft", MinimalWith(7, "    structural: {warp: 1}"),
       "7:17: material.springs.structural.weft", "required key 'weft' is missing"},
      {"NegativeStiffness", MinimalWith(7, "    structural: -100"),
       "7:17: material.springs.structural", "must be positive, got -100"},
      {"ZeroWeftStiffness", MinimalWith(7, "    shear: {warp: 1, weft: 0}"),
       "7:28: material.springs.shear.weft", "must be positive, got 0"},
      {"ZeroMass", MinimalWith(5, "  density: 0"), "5:12: material.density",
       "must be positive, got 0"},
      {"NegativeSize", MinimalWith(3, "  size: [1, -2]"), "3:13: mesh.size[1]",
       "must be positive, got -2"},
      {"ZeroSpacing",
       "mesh:\n  kind: circle\n  spacing: 0\nmaterial: {density: 1, springs: {structural: 1}}\n",
       "3:12: mesh.spacing", "must be positive, got 0"},
      {"NegativeRadius",
       "mesh: {kind: arc, radius: -0.1}\nmaterial: {density: 1, springs: {structural: 1}}\n",
       "1:27: mesh.radius", "must be positive, got -0.1"},
      {"ZeroTolerance", std::string(kMinimal) + "solver: {tolerance: 0}\n",
       "8:21: solver.tolerance", "must be positive, got 0"},
      {"NegativeTimeLimit", std::string(kMinimal) + "solver: {time_limit: -1}\n",
       "8:22: solver.time_limit", "must be positive, got -1"},
      {"ZeroMaxIterations", std::string(kMinimal) + "solver: {max_iterations: 0}\n",
       "8:26: solver.max_iterations", "must be at least 1"},
      {"ZeroLevels", std::string(kMinimal) + "solver: {levels: 0}\n", "8:18: solver.levels",
       "must be at least 1"},
      {"TooManyLevels", std::string(kMinimal) + "solver: {levels: 9}\n", "8:18: solver.levels",
       "must be at most 8, got 9"},
      {"FractionalLevels", std::string(kMinimal) + "solver: {levels: 2.5}\n", "8:18: solver.levels",
       "expected a whole number"},
      {"DotNan", MinimalWith(5, "  density: .nan"), "5:12: material.density",
       "NaN and infinity are not allowed"},
      {"PlainNan", MinimalWith(5, "  density: nan"), "5:12: material.density",
       "NaN and infinity are not allowed"},
      {"DotInf", MinimalWith(7, "    structural: .inf"), "7:17: material.springs.structural",
       "NaN and infinity are not allowed"},
      {"MinusInfInGravity", std::string(kMinimal) + "loads: {gravity: [0, 0, -.inf]}\n",
       "8:25: loads.gravity[2]", "NaN and infinity are not allowed"},
      {"HugeNumberOverflows", MinimalWith(5, "  density: 1e999"), "5:12: material.density",
       "out of range"},
      {"DuplicateTopLevelKey", std::string(kMinimal) + "mesh: {nodes: [4, 4]}\n", "8:1: mesh",
       "duplicate key 'mesh' (first given at line 1)"},
      {"DuplicateNestedKey", MinimalWith(6, "  density: 0.3\n  springs:"), "6:3: material.density",
       "duplicate key 'density'"},
      {"DuplicateKeyInAFlowMap",
       MinimalWith(3,
                   "  nodes: [3, 3]\n  origin: [0, 0, 0]\n"
                   "  plane: xy\n  plane: xz"),
       "6:3: mesh.plane", "duplicate key 'plane'"},
      {"DuplicateKeyInASelector",
       std::string(kMinimal) + "fixed:\n  - nodes: {ids: [0], ids: [1]}\n",
       "9:23: fixed[0].nodes.ids", "duplicate key 'ids'"},
      {"OctalLookingNumber", MinimalWith(3, "  nodes: [010, 3]"), "3:11: mesh.nodes[0]",
       "write 10 or 8 explicitly"},
      {"NegativeOctalLookingNumber", std::string(kMinimal) + "loads: {gravity: [0, 0, -07]}\n",
       "8:25: loads.gravity[2]", "write -7 explicitly"},
      {"NumberWithTwoPoints", MinimalWith(5, "  density: 1.0.0"), "5:12: material.density",
       "'1.0.0' is not a number"},
      {"NumberWithUnit", MinimalWith(7, "    structural: 3 N"), "7:17: material.springs.structural",
       "expected a number, got '3 N'"},
      {"NodeCountZero", MinimalWith(3, "  nodes: [0, 3]"), "3:11: mesh.nodes[0]",
       "must be at least 1, got 0"},
      {"GridOfOneNode", MinimalWith(3, "  nodes: [1, 1]"), "3:10: mesh.nodes",
       "a grid needs at least 2 nodes, got 1"},
      {"ChainOfOneNode",
       "mesh: {kind: chain, nodes: 1}\nmaterial: {density: 1, springs: {structural: 1}}\n",
       "1:28: mesh.nodes", "must be at least 2, got 1"},
      {"NonIncreasingCoordinates", MinimalWith(3, "  u: [0, 0.5, 0.5]"), "3:15: mesh.u[2]",
       "coordinates must increase strictly"},
      {"CoordinatesDisagreeWithNodes", MinimalWith(2, "  u: [0, 0.5, 1, 2]"), "2:6: mesh.u",
       "has 4 coordinates but mesh.nodes[0] is 3"},
      {"CoordinatesDisagreeWithSize", MinimalWith(3, "  u: [0, 0.5, 2]\n  size: [1, 1]"),
       "3:6: mesh.u", "spans 2 m but mesh.size[0] is 1"},
      {"DimensionFour", std::string(kMinimal) + "dimension: 4\n", "8:12: dimension",
       "must be 2 or 3, got 4"},
      {"DofsUnknownName",
       std::string(kMinimal) + "fixed:\n  - nodes: {all: true}\n"
                               "    dofs: [x, w]\n",
       "10:15: fixed[0].dofs[1]", "unknown value 'w'"},
      {"DofsRepeated",
       std::string(kMinimal) + "fixed:\n  - nodes: {all: true}\n"
                               "    dofs: [z, x, z]\n",
       "10:18: fixed[0].dofs[2]", "'z' is listed twice"},
      {"TwoSelectorKinds", std::string(kMinimal) + "fixed:\n  - nodes: {edge: top, ids: [1]}\n",
       "9:24: fixed[0].nodes.ids", "select nodes in one way only"},
      {"NoSelectorKind", std::string(kMinimal) + "fixed:\n  - nodes: {}\n", "9:12: fixed[0].nodes",
       "no selection given"},
      {"UnknownEdge", std::string(kMinimal) + "fixed:\n  - nodes: {edge: up}\n",
       "9:19: fixed[0].nodes.edge", "unknown value 'up'"},
      {"AllFalse", std::string(kMinimal) + "fixed:\n  - nodes: {all: false}\n",
       "9:18: fixed[0].nodes.all", "selects nothing"},
      {"MissingSelection", std::string(kMinimal) + "fixed:\n  - dofs: [z]\n", "9:5: fixed[0].nodes",
       "required key 'nodes' is missing"},
      {"ForceWithoutValue", std::string(kMinimal) + "loads:\n  forces:\n    - nodes: {all: true}\n",
       "10:7: loads.forces[0].total", "the force is missing"},
      {"ForceTotalAndEach",
       std::string(kMinimal) + "loads:\n  forces:\n    - {nodes: {all: true}, total: [0, 0, 1], "
                               "each: [0, 0, 1]}\n",
       "10:46: loads.forces[0].each", "not both"},
      {"ZeroPlaneNormal",
       std::string(kMinimal) + "obstacles:\n  - plane: {point: [0, 0, 0], normal: [0, 0, 0]}\n",
       "9:39: obstacles[0].plane.normal", "must not be the zero vector"},
      {"NegativeFriction",
       std::string(kMinimal) + "obstacles:\n  - pin: {position: [0, 0, 0], friction: -0.1}\n",
       "9:42: obstacles[0].pin.friction", "must not be negative"},
      {"UnknownMethod", std::string(kMinimal) + "solver: {method: ceres-lbfgz}\n",
       "8:18: solver.method", "did you mean 'ceres-lbfgs'?"},
      {"UnknownMethodOption",
       std::string(kMinimal) + "solver:\n  method: ceres-lbfgs\n  ceres-lbfgs: {memroy: 5}\n",
       "10:17: solver.ceres-lbfgs.memroy", "did you mean 'memory'?"},
      {"OptionsForAMethodThatTakesNone", std::string(kMinimal) + "solver: {ceres-lm: {x: 1}}\n",
       "8:21: solver.ceres-lm.x", "unknown key 'x'"},
      {"StretchLimitBelowOne", MinimalWith(7, "    structural: 1\n    stretch_limit: 0.9"),
       "8:20: material.springs.stretch_limit", "must be greater than 1"},
      {"RestLengthTypo", MinimalWith(7, "    structural: 1\n    rest_length: inital"),
       "8:18: material.springs.rest_length", "did you mean 'initial'?"},
      {"RestLengthWord", MinimalWith(7, "    structural: 1\n    rest_length: long"),
       "8:18: material.springs.rest_length", "expected initial, zero or a length in m"},
      {"TensionOnlyNotABool", MinimalWith(7, "    structural: 1\n    tension_only: yes"),
       "8:19: material.springs.tension_only", "expected true or false"},
      {"UnknownMaterialModel", MinimalWith(5, "  model: spring\n  density: 1"),
       "5:10: material.model", "did you mean 'springs'?"},
      {"FiniteVolumeBlockWithSprings", std::string(kMinimal) + "  finite_volume: {E_warp: 1}\n",
       "8:3: material.finite_volume", "applies only when material.model is finite_volume"},
      {"UnknownOutput", std::string(kMinimal) + "output: {write: [summary, pdf]}\n",
       "8:27: output.write[1]", "unknown value 'pdf'"},
      {"ObjUpX", std::string(kMinimal) + "output: {obj_up: x}\n", "8:18: output.obj_up",
       "unknown value 'x'"},
      {"RepeatedOutput", std::string(kMinimal) + "output: {write: [vtk, vtk]}\n",
       "8:23: output.write[1]", "'vtk' is listed twice"},
      {"NameWithSlash", std::string(kMinimal) + "name: a/b\n", "8:7: name", "plain name"},
      {"SecondDocument", std::string(kMinimal) + "---\nname: x\n", "9:1: ", "one YAML document"},
      {"SyntaxError", MinimalWith(3, "  nodes: [3, 3"), "4:9: ", "YAML syntax error"},
      {"TabIndentation", MinimalWith(3, "\tnodes: [3, 3]"), "3:1: ", "YAML syntax error"},
      {"NotAMap", "- mesh\n- material\n", "1:1: ", "expected a map of keys, got a list"},
  };
  return scenes;
}

void PrintTo(const BadScene& bad, std::ostream* out) { *out << bad.name; }

class BadSceneTest : public SceneLoaderTest, public ::testing::WithParamInterface<BadScene> {};

TEST_P(BadSceneTest, IsRejectedWithALocatedMessage) {
  const BadScene& bad = GetParam();
  const std::string message = Error(bad.text);
  ASSERT_FALSE(message.empty()) << "loaded without error:\n" << bad.text;
  const std::string where = ScenePath() + ":" + bad.where + (bad.where.back() == ' ' ? "" : ": ");
  EXPECT_EQ(message.rfind(where, 0), 0u)
      << "expected the message to start with '" << where << "'\ngot: " << message << "\nscene:\n"
      << bad.text;
  EXPECT_TRUE(Contains(message, bad.what)) << "expected '" << bad.what << "' in: " << message;
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, BadSceneTest, ::testing::ValuesIn(BadScenes()),
                         [](const auto& test) { return std::string(test.param.name); });

TEST_F(SceneLoaderTest, UnreadableSceneFileSaysSo) {
  const std::string missing = (folder_ / "missing.yaml").string();
  try {
    LoadScene(missing);
    FAIL() << "loaded a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(missing + ": cannot read", 0), 0u) << error.what();
  }
  try {
    LoadScene(folder_.string());
    FAIL() << "loaded a folder";
  } catch (const InputError& error) {
    EXPECT_TRUE(Contains(error.what(), "cannot read")) << error.what();
  }
}

TEST_F(SceneLoaderTest, EmptyFileMissesTheMesh) {
  EXPECT_EQ(Error(""), ScenePath() + ":1:1: mesh: required key 'mesh' is missing");
}

// ------------------------------------------------------- fabric measurements (kes, Peirce)

// A finite-volume scene: lines 9 and 10 hold D_warp and D_weft.
constexpr char kFiniteVolume[] = R"(mesh: {nodes: [3, 3]}
material:
  model: finite_volume
  density: 0.12
  finite_volume:
    E_warp: 500
    E_weft: 300
    G: 5
    D_warp: 1.0e-5
    D_weft: 1.0e-5
)";

// kFiniteVolume with lines first..last (1-based) replaced by `replacement` (empty: removed).
std::string FiniteVolumeWith(int first, int last, const std::string& replacement,
                             std::string text = kFiniteVolume) {
  size_t begin = 0;
  for (int line = 1; line < first; ++line) begin = text.find('\n', begin) + 1;
  size_t end = begin;
  for (int line = first; line <= last; ++line) end = text.find('\n', end) + 1;
  return text.replace(begin, end - begin, replacement.empty() ? "" : replacement + "\n");
}

// Each SI value worked out by hand (1 gf = 9.80665e-3 N): W 12 mg/cm² → 0.12 kg/m²;
// B 0.12 gf·cm → 0.12 × 9.80665e-5 = 1.176798e-5 N·m; bending length 2 cm with ρ = 0.12 kg/m² →
// 0.12 × 9.80665 × 0.02³ = 9.414384e-6 N·m; G 0.9 gf/(cm·deg) → 0.9 × 0.980665 × 180/π =
// 50.56916 N/m; EMT 4 %, LT 0.65 at 500 gf/cm = 490.3325 N/m → 0.65 × 490.3325/0.04 =
// 7967.903 N/m; EMT 7 % without LT (secant) → 490.3325/0.07 = 7004.750 N/m.
TEST_F(SceneLoaderTest, KesAndBendingLengthGiveTheSiParameters) {
  const Scene scene = Load(R"(mesh: {kind: circle, radius: 0.1, spacing: 0.02}
material:
  model: finite_volume
  finite_volume:
    kes: {W: 12, B_warp: 0.12, G: 0.9, EMT_warp: 4, LT_warp: 0.65, EMT_weft: 7}
    bending_length: {weft: 2.0}
    nu_warp: 0.1
)");
  const FiniteVolumeSpec& fv = scene.material.finite_volume;
  EXPECT_EQ(scene.material.mass_kind, MaterialSpec::MassKind::kDensity);
  EXPECT_NEAR(scene.material.mass_value, 0.12, 1e-15);
  EXPECT_NEAR(fv.D_warp, 1.176798e-5, 1e-11);
  EXPECT_NEAR(fv.D_weft, 9.414384e-6, 1e-12);
  EXPECT_NEAR(fv.G, 50.56916, 1e-4);
  EXPECT_NEAR(fv.E_warp, 7967.903, 1e-3);
  EXPECT_NEAR(fv.E_weft, 7004.750, 1e-3);
  EXPECT_DOUBLE_EQ(fv.nu_warp, 0.1);
}

// FAST's units by hand: W 150 g/m² → 0.15 kg/m²; B 7.5 µN·m → 7.5e-6 N·m; EB5 2 % → 123/2 =
// 61.5 N/m; E100 2 % → 98.0665/0.02 = 4903.325 N/m. The measurements are kept as given, with the
// schema's units, in the schema's order.
TEST_F(SceneLoaderTest, FastGivesTheSiParametersAndKeepsTheMeasurementsAsGiven) {
  const Scene scene = Load(R"(mesh: {kind: circle, radius: 0.1, spacing: 0.02}
material:
  model: finite_volume
  finite_volume:
    fast: {E100_weft: 4, EB5: 2, B_warp: 7.5, W: 150, E100_warp: 2}
    bending_length: {weft: 2.0}
)");
  const FiniteVolumeSpec& fv = scene.material.finite_volume;
  EXPECT_NEAR(scene.material.mass_value, 0.15, 1e-15);
  EXPECT_NEAR(fv.D_warp, 7.5e-6, 1e-18);
  EXPECT_NEAR(fv.D_weft, PeirceBendingRigidity(2.0, 0.15), 1e-18);
  EXPECT_NEAR(fv.G, 61.5, 1e-12);
  EXPECT_NEAR(fv.E_warp, 4903.325, 1e-9);
  EXPECT_NEAR(fv.E_weft, 2451.6625, 1e-9);
  const std::vector<std::string> keys = {"fast.W",         "fast.B_warp",    "fast.EB5",
                                         "fast.E100_warp", "fast.E100_weft", "bending_length.weft"};
  ASSERT_EQ(fv.measured.size(), keys.size());
  for (size_t k = 0; k < keys.size(); ++k) EXPECT_EQ(fv.measured[k].key, keys[k]);
  EXPECT_EQ(fv.measured[0].unit, "g/m²");
  EXPECT_DOUBLE_EQ(fv.measured[0].value, 150.0);
  EXPECT_EQ(fv.measured[5].unit, "cm");
}

// A bending length uses material.density when there is no kes.W; Fm changes the KES load.
TEST_F(SceneLoaderTest, BendingLengthUsesTheMaterialDensity) {
  const Scene scene =
      Load(FiniteVolumeWith(6, 10,
                            "    kes: {EMT_warp: 4, EMT_weft: 4, Fm: 50}\n    G: 5\n"
                            "    bending_length: {warp: 2.0, weft: 1.0}"));
  const FiniteVolumeSpec& fv = scene.material.finite_volume;
  EXPECT_NEAR(fv.D_warp, 9.414384e-6, 1e-12);
  EXPECT_NEAR(fv.D_weft, 9.414384e-6 / 8, 1e-12);
  EXPECT_NEAR(fv.E_warp, 1225.831, 1e-3);  // 50 gf/cm = 49.03325 N/m over 0.04
}

// The twist (docs/reference.md, "Twist"). Without a bias measurement, D_66 = √(D_warp D_weft)/3
// = 1e-5/3 N·m. A bias bending length of 2 cm at ρ = 0.12 kg/m² is B45 = 9.414384e-6 N·m (as
// above), and kes.B_bias = 9.414384e-6 / 9.80665e-5 = 0.096 gf·cm²/cm is the same rigidity; with
// D_warp = D_weft = 1e-5 N·m both give D_66 = 1/(4/B45 − 2/1e-5) = 1/(424881.76 − 200000) =
// 4.446781e-6 N·m.
TEST_F(SceneLoaderTest, TwistIsGivenMeasuredOnTheBiasOrTheDefault) {
  const FiniteVolumeSpec plain = Load(kFiniteVolume).material.finite_volume;
  EXPECT_NEAR(plain.D_66, 1e-5 / 3, 1e-18);
  EXPECT_EQ(plain.twist_source, FiniteVolumeSpec::TwistSource::kDefault);
  const FiniteVolumeSpec given =
      Load(FiniteVolumeWith(10, 10, "    D_weft: 1.0e-5\n    D_66: 2.5e-6")).material.finite_volume;
  EXPECT_DOUBLE_EQ(given.D_66, 2.5e-6);
  EXPECT_EQ(given.twist_source, FiniteVolumeSpec::TwistSource::kGiven);
  for (const char* bias : {"    bending_length: {bias: 2.0}", "    kes: {B_bias: 0.096}"}) {
    const FiniteVolumeSpec measured =
        Load(FiniteVolumeWith(10, 10, std::string("    D_weft: 1.0e-5\n") + bias))
            .material.finite_volume;
    EXPECT_NEAR(measured.D_66, 4.446781e-6, 1e-12) << bias;
    EXPECT_EQ(measured.twist_source, FiniteVolumeSpec::TwistSource::kBias) << bias;
  }
}

std::vector<BadScene> FabricParameterBadScenes() {
  return {
      {"TwistGivenAndMeasured",
       FiniteVolumeWith(10, 10, "    D_weft: 1.0e-5\n    D_66: 1e-6\n    kes: {B_bias: 0.05}"),
       "12:19: material.finite_volume.kes.B_bias",
       "give D_66 in one way only: 'D_66' is given too"},
      {"TwistMeasuredTwice",
       FiniteVolumeWith(10, 10,
                        "    D_weft: 1.0e-5\n    kes: {B_bias: 0.05}\n    bending_length: {bias: "
                        "2}"),
       "12:28: material.finite_volume.bending_length.bias",
       "give D_66 in one way only: 'kes.B_bias' is given too"},
      {"BiasStifferThanAnyTwist",
       FiniteVolumeWith(10, 10, "    D_weft: 1.0e-5\n    kes: {B_bias: 0.3}"),
       "11:19: material.finite_volume.kes.B_bias",
       "is too stiff for the warp's and weft's (1e-05 and 1e-05 N·m): no torsional rigidity gives "
       "it; an orthotropic plate's bias is below 2e-05 N·m"},
      {"NegativeTwist", FiniteVolumeWith(10, 10, "    D_weft: 1.0e-5\n    D_66: -1e-6"),
       "11:11: material.finite_volume.D_66", "must not be negative"},
      {"DirectAndKesBending",
       FiniteVolumeWith(10, 10, "    D_weft: 1.0e-5\n    kes: {B_weft: 0.1}"),
       "11:19: material.finite_volume.kes.B_weft",
       "give D_weft in one way only: 'D_weft' is given too"},
      {"KesAndPeirceBending",
       FiniteVolumeWith(9, 10, "    kes: {B_warp: 0.1}\n    bending_length: {warp: 2, weft: 2}"),
       "10:28: material.finite_volume.bending_length.warp",
       "give D_warp in one way only: 'kes.B_warp' is given too"},
      {"DirectAndKesTensile", FiniteVolumeWith(6, 6, "    E_warp: 500\n    kes: {EMT_warp: 4}"),
       "7:21: material.finite_volume.kes.EMT_warp",
       "give E_warp in one way only: 'E_warp' is given too"},
      {"DirectAndKesShear", FiniteVolumeWith(8, 8, "    G: 5\n    kes: {G: 0.9}"),
       "9:14: material.finite_volume.kes.G", "give G in one way only"},
      {"MissingBending", FiniteVolumeWith(9, 9, ""), "5:3: material.finite_volume.D_warp",
       "required key 'D_warp' is missing: give D_warp (N·m) or kes.B_warp or fast.B_warp or "
       "bending_length.warp"},
      {"MissingTensile", FiniteVolumeWith(7, 7, ""), "5:3: material.finite_volume.E_weft",
       "give E_weft (N/m) or kes.EMT_weft"},
      {"LinearityWithoutStrain", FiniteVolumeWith(6, 6, "    kes: {LT_warp: 0.7}"),
       "6:20: material.finite_volume.kes.LT_warp", "LT_warp needs EMT_warp (%) as well"},
      {"MaximumLoadWithoutStrain", FiniteVolumeWith(8, 8, "    G: 5\n    kes: {Fm: 50}"),
       "9:15: material.finite_volume.kes.Fm", "applies only with EMT_warp or EMT_weft"},
      {"DensityAndKesWeight", FiniteVolumeWith(8, 8, "    G: 5\n    kes: {W: 12}"),
       "4:3: material.density",
       "give the mass in one way only: 'density' and "
       "finite_volume.kes.W are both given"},
      {"KesAndFastWeight",
       FiniteVolumeWith(4, 4, "",
                        FiniteVolumeWith(8, 8, "    G: 5\n    kes: {W: 12}\n    fast: {W: 120}")),
       "9:15: material.finite_volume.fast.W",
       "give the mass in one way only: finite_volume.kes.W and finite_volume.fast.W are both "
       "given"},
      {"KesAndFastBending",
       FiniteVolumeWith(8, 9, "    G: 5\n    kes: {B_warp: 0.1}\n    fast: {B_warp: 9}"),
       "10:20: material.finite_volume.fast.B_warp",
       "give D_warp in one way only: 'kes.B_warp' is given too"},
      {"BendingLengthWithoutArealDensity",
       FiniteVolumeWith(4, 4, "  node_mass: 0.001",
                        FiniteVolumeWith(9, 10, "    bending_length: {warp: 2.0, weft: 1.8}")),
       "9:28: material.finite_volume.bending_length.warp",
       "a bending length needs the areal density: give material.density (kg/m²), "
       "finite_volume.kes.W (mg/cm²) or finite_volume.fast.W (g/m²)"},
      {"BendingLengthNotPerDirection", FiniteVolumeWith(9, 10, "    bending_length: 2.0"),
       "9:21: material.finite_volume.bending_length", "give the bending length per direction"},
      {"KesKeyTypo", FiniteVolumeWith(9, 9, "    kes: {B_wrap: 0.1}"),
       "9:11: material.finite_volume.kes.B_wrap", "did you mean 'B_warp'?"},
      {"NegativeKesBending", FiniteVolumeWith(9, 9, "    kes: {B_warp: -0.1}"),
       "9:19: material.finite_volume.kes.B_warp", "must be positive"},
      {"ZeroKesWeight", FiniteVolumeWith(4, 4, "") + "    kes: {W: 0}\n",
       "10:14: material.finite_volume.kes.W", "must be positive"},
  };
}

class FabricParameterBadSceneTest : public SceneLoaderTest,
                                    public ::testing::WithParamInterface<BadScene> {};

TEST_P(FabricParameterBadSceneTest, IsRejectedWithALocatedMessage) {
  const BadScene& bad = GetParam();
  const std::string message = Error(bad.text);
  ASSERT_FALSE(message.empty()) << "loaded without error:\n" << bad.text;
  const std::string where = ScenePath() + ":" + bad.where + ": ";
  EXPECT_EQ(message.rfind(where, 0), 0u)
      << "expected the message to start with '" << where << "'\ngot: " << message << "\nscene:\n"
      << bad.text;
  EXPECT_TRUE(Contains(message, bad.what)) << "expected '" << bad.what << "' in: " << message;
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, FabricParameterBadSceneTest,
                         ::testing::ValuesIn(FabricParameterBadScenes()),
                         [](const auto& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// A scene's text (the Python module's drape.loads) is the file's scene, its errors located in the
// label, its relative paths taken from the folder given.
TEST(SceneLoaderText, IsTheFilesSceneWithItsErrorsInTheLabel) {
  const std::string path = testing::SourcePath("configs/examples/hanging_sheet.yaml");
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  const Scene from_file = LoadScene(path, {"mesh.nodes=[5,5]"});
  const Scene from_text =
      LoadSceneText(text.str(), "<string>", "/some/folder", {"mesh.nodes=[5,5]"});
  EXPECT_EQ(from_text.name, from_file.name);  // the text's own `name`
  EXPECT_EQ(from_text.mesh.nodes, from_file.mesh.nodes);
  EXPECT_EQ(from_text.directory, "/some/folder");
  EXPECT_EQ(LoadSceneText(kMinimal, "<string>", ".").name, "scene");
  try {
    LoadSceneText("name: x\nmesh: {kind: grid, nodez: 3}\n", "<dict>", ".");
    ADD_FAILURE() << "an unknown key was read";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, "<dict>");
    EXPECT_EQ(error.where().line, 2);
    EXPECT_EQ(error.where().key, "mesh.nodez");
  }
}

}  // namespace
}  // namespace drape
