#include "src/model/model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>

#include "costs/constant_force_potential.h"
#include "costs/spring_stretch.h"
#include "costs/tension_only_spring.h"
#include "costs/zero_length_spring.h"
#include "src/model/equilibrium.h"

namespace drape {
namespace model_test {

const Eigen::Vector3d kGravity(0.0, 0.0, -9.81);

SpringFamilySpec Family(double warp, double weft) {
  SpringFamilySpec family;
  family.present = true;
  family.warp = warp;
  family.weft = weft;
  return family;
}

NodeSelector Corner(const std::string& name) {
  NodeSelector selector;
  selector.kind = NodeSelector::Kind::kCorner;
  selector.name = name;
  return selector;
}

NodeSelector Edge(const std::string& name) {
  NodeSelector selector;
  selector.kind = NodeSelector::Kind::kEdge;
  selector.name = name;
  return selector;
}

FixedSpec Fixed(const NodeSelector& nodes) {
  FixedSpec fixed;
  fixed.nodes = nodes;
  return fixed;
}

// A nu × nv sheet of the given size with structural springs, density 0.2 kg/m², held by its top
// corners, no loads.
Scene Sheet(int nu, int nv, double width = 0.6, double height = 0.4) {
  Scene scene;
  scene.file = "scene.yaml";
  scene.mesh.kind = MeshSpec::Kind::kGrid;
  scene.mesh.nodes = {nu, nv};
  scene.mesh.size = {width, height};
  scene.material.mass_kind = MaterialSpec::MassKind::kDensity;
  scene.material.mass_value = 0.2;
  scene.material.springs.structural = Family(1000.0, 800.0);
  scene.fixed = {Fixed(Corner("top-left")), Fixed(Corner("top-right"))};
  scene.loads.where = Location{"scene.yaml", 20, 1, "loads"};
  return scene;
}

double Sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

Eigen::Vector3d AppliedSum(const Model& model) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < model.num_nodes; ++k) {
    sum +=
        Eigen::Vector3d(model.applied[3 * k], model.applied[3 * k + 1], model.applied[3 * k + 2]);
  }
  return sum;
}

std::string ErrorOf(const Scene& scene) {
  try {
    BuildModel(scene);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Model, DensityMassesSumToDensityTimesArea) {
  const Scene scene = Sheet(5, 4, 0.6, 0.4);
  const Model model = BuildModel(scene);
  EXPECT_NEAR(Sum(model.mass), 0.2 * 0.6 * 0.4, 1e-15);
  // Corner, edge and interior nodes carry 1, 2 and 4 quarter cells.
  const double quarter = 0.25 * 0.2 * (0.6 / 4) * (0.4 / 3);
  EXPECT_NEAR(model.mass[0], quarter, 1e-15);
  EXPECT_NEAR(model.mass[1], 2 * quarter, 1e-15);
  EXPECT_NEAR(model.mass[5 + 1], 4 * quarter, 1e-15);
}

// The run's time limit bounds the build of the model: past it, the build stops with a message
// located at the solver section (before, only mesh.max_nodes bounded it: 695k nodes with
// time_limit 5 took 114 s).
TEST(Model, TheBuildStopsAtTheTimeLimit) {
  Scene scene = Sheet(30, 30);
  scene.solver.where = Location{"scene.yaml", 30, 1, "solver"};
  scene.solver.time_limit = 1e-9;
  const std::string error = ErrorOf(scene);
  EXPECT_EQ(error.rfind("scene.yaml:30:1: solver: building the model took ", 0), 0u) << error;
  EXPECT_NE(error.find("more than the time limit 1e-09 s"), std::string::npos) << error;
  scene.solver.time_limit = 60.0;
  EXPECT_EQ(BuildModel(scene).num_nodes, 900);
}

TEST(Model, ChainDensityIsPerMetre) {
  Scene scene;
  scene.mesh.kind = MeshSpec::Kind::kChain;
  scene.mesh.chain_nodes = 6;
  scene.mesh.length = 1.5;
  scene.material.mass_value = 0.1;  // kg/m
  scene.material.springs.structural = Family(50.0, 50.0);
  scene.fixed = {Fixed(Edge("left"))};
  const Model model = BuildModel(scene);
  EXPECT_NEAR(Sum(model.mass), 0.1 * 1.5, 1e-15);
  EXPECT_NEAR(model.mass[0], 0.1 * 0.5 * 1.5 / 5, 1e-15);
}

TEST(Model, NodeMassAndTotalMass) {
  Scene scene = Sheet(4, 3);
  scene.material.mass_kind = MaterialSpec::MassKind::kNodeMass;
  scene.material.mass_value = 0.01;
  Model model = BuildModel(scene);
  for (double m : model.mass) EXPECT_EQ(m, 0.01);

  scene.material.mass_kind = MaterialSpec::MassKind::kTotalMass;
  scene.material.mass_value = 0.3;
  model = BuildModel(scene);
  EXPECT_NEAR(Sum(model.mass), 0.3, 1e-15);
  EXPECT_NEAR(model.mass[1], 2 * model.mass[0], 1e-15);      // edge vs corner
  EXPECT_NEAR(model.mass[4 + 1], 4 * model.mass[0], 1e-15);  // interior vs corner
}

TEST(Model, FixedDofsAndMove) {
  Scene scene = Sheet(4, 3);
  FixedSpec left = Fixed(Edge("left"));
  left.dofs = {true, false, true};
  left.move = {0.1, 0.0, -0.05};
  scene.fixed = {left, Fixed(Corner("bottom-left"))};  // overlapping specs are allowed
  const Model model = BuildModel(scene);
  for (int j = 0; j < 3; ++j) {
    const int id = j * 4;
    EXPECT_TRUE(model.fixed[3 * id]);
    EXPECT_EQ(static_cast<bool>(model.fixed[3 * id + 1]), j == 0) << "node " << id;
    EXPECT_TRUE(model.fixed[3 * id + 2]);
    EXPECT_NEAR(model.positions[3 * id], 0.1, 1e-15);
    EXPECT_NEAR(model.positions[3 * id + 2], -0.05, 1e-15);
  }
  // Left edge: x and z of 3 nodes; the corner adds its y.
  EXPECT_EQ(model.num_free_dofs(), 3 * 12 - (2 * 3 + 1));
  EXPECT_EQ(model.initial, model.positions);
  EXPECT_EQ(model.positions[3 * 1], 0.6 / 3);  // node (1, 0) is not moved
}

TEST(Model, TwoDimensionalScenesFixEveryY) {
  Scene scene = Sheet(5, 1);
  scene.dimension = 2;
  scene.mesh.size = {1.0, 0.1};
  scene.fixed = {Fixed(Edge("left"))};
  scene.fixed[0].dofs = {true, false, true};
  const Model model = BuildModel(scene);
  for (int k = 0; k < model.num_nodes; ++k) EXPECT_TRUE(model.fixed[3 * k + 1]) << "node " << k;
  EXPECT_EQ(model.num_free_dofs(), 2 * (5 - 1));

  Scene flat = Sheet(3, 3);
  flat.dimension = 2;
  EXPECT_NE(ErrorOf(flat).find("x-z plane"), std::string::npos);
}

TEST(Model, TermCountsPerTypeForASmallGridWithEveryFamily) {
  const int n = 3;
  Scene scene = Sheet(n, n);
  scene.material.springs.shear = Family(500.0, 500.0);
  scene.material.springs.flexion = Family(10.0, 10.0);
  const Model model = BuildModel(scene);
  const auto counts = model.TermCounts();
  EXPECT_EQ(counts.at("structural"), 2 * n * (n - 1));
  EXPECT_EQ(counts.at("shear"), 2 * (n - 1) * (n - 1));
  EXPECT_EQ(counts.at("flexion"), 2 * n * (n - 2));
  EXPECT_EQ(counts.count("gravity"), 0u);
  EXPECT_EQ(counts.count("load"), 0u);
  EXPECT_EQ(model.triangles.size(), static_cast<size_t>(2 * (n - 1) * (n - 1)));
  EXPECT_NEAR(model.size, std::hypot(0.6, 0.4), 1e-15);

  scene.material.springs.flexion.present = false;
  EXPECT_EQ(BuildModel(scene).TermCounts().count("flexion"), 0u);
}

TEST(Model, ElasticForcesVanishAtTheStart) {
  Scene scene = Sheet(4, 4);
  scene.material.springs.shear = Family(500.0, 300.0);
  scene.material.springs.flexion = Family(10.0, 20.0);
  const Model model = BuildModel(scene);
  double energy = 1.0;
  std::vector<double> gradient;
  ASSERT_TRUE(EvaluateEnergy(model, model.positions.data(), &energy, &gradient));
  EXPECT_NEAR(energy, 0.0, 1e-20);
  for (double g : gradient) EXPECT_NEAR(g, 0.0, 1e-12);
}

TEST(Model, GivenRestLengthScalesStructuralSpringsToIt) {
  Scene scene = Sheet(3, 3, 0.4, 0.4);  // spacing 0.2 both ways
  scene.material.springs.rest_length = SpringsSpec::RestLength::kGiven;
  scene.material.springs.rest_length_value = 0.15;
  const Model model = BuildModel(scene);
  for (const auto& term : model.terms) {
    const auto* spring = FunctorOf<SpringStretch>(*term);
    ASSERT_NE(spring, nullptr);
    EXPECT_NEAR(spring->rest_length, 0.15, 1e-15);
  }
}

TEST(Model, RestLengthZeroAndTensionOnlyPickTheirFunctors) {
  Scene scene = Sheet(3, 3);
  scene.material.springs.tension_only = true;
  Model model = BuildModel(scene);
  for (const auto& term : model.terms) {
    EXPECT_NE(FunctorOf<TensionOnlySpring>(*term), nullptr);
  }
  scene.material.springs.rest_length = SpringsSpec::RestLength::kZero;
  model = BuildModel(scene);
  for (const auto& term : model.terms) {
    EXPECT_NE(FunctorOf<ZeroLengthSpring>(*term), nullptr);
  }
}

TEST(Model, AppliedForcesAreWeightPlusLoads) {
  Scene scene = Sheet(4, 3);
  scene.loads.gravity = kGravity;
  ForceSpec total;
  total.nodes = Edge("bottom");
  total.kind = ForceSpec::Kind::kTotal;
  total.value = {0.0, 0.0, -3.0};
  ForceSpec each;
  each.nodes.kind = NodeSelector::Kind::kIds;
  each.nodes.ids = {5, 6};
  each.kind = ForceSpec::Kind::kEach;
  each.value = {1.0, 0.0, 0.0};
  scene.loads.forces = {total, each};
  const Model model = BuildModel(scene);

  const double mass = Sum(model.mass);
  const Eigen::Vector3d expected = mass * kGravity + total.value + 2 * each.value;
  EXPECT_NEAR((AppliedSum(model) - expected).norm(), 0.0, 1e-14);
  const auto counts = model.TermCounts();
  EXPECT_EQ(counts.at("gravity"), model.num_nodes);
  EXPECT_EQ(counts.at("load"), 4 + 2);
  // The bottom-edge load is shared equally: node 1 carries its weight and a quarter of 3 N.
  EXPECT_NEAR(model.applied[3 * 1 + 2], model.mass[1] * kGravity.z() - 3.0 / 4, 1e-15);

  // The potentials' forces are the applied forces.
  double energy = 0.0;
  std::vector<double> gradient;
  ASSERT_TRUE(EvaluateEnergy(model, model.positions.data(), &energy, &gradient));
  EXPECT_NEAR(energy, 0.0, 1e-15);
  for (int k = 0; k < model.num_dofs(); ++k) EXPECT_NEAR(-gradient[k], model.applied[k], 1e-12);
}

// `traction` and `pressure` are forces per unit area: each selected node gets its lumped area
// (the area its mass is lumped from) times the traction, or times p along the initial normal.
// On a flat sheet in the x-y plane the normal is +z (the grid's triangles run counterclockwise
// seen from +z), so a pressure p is the traction [0, 0, p]; on the whole sheet their sum is
// p × the sheet's area. A pressure needs a surface: on a chain it is refused where written.
TEST(Model, TractionAndPressureAreLumpedByArea) {
  Scene scene = Sheet(5, 4);
  ForceSpec traction;
  traction.nodes.kind = NodeSelector::Kind::kAll;
  traction.kind = ForceSpec::Kind::kTraction;
  traction.value = {2.0, 0.0, -3.0};
  scene.loads.forces = {traction};
  const Model by_traction = BuildModel(scene);
  const double area = 0.6 * 0.4;
  EXPECT_NEAR((AppliedSum(by_traction) - area * traction.value).norm(), 0.0, 1e-14);
  // A corner node carries a quarter of one cell, an inner node a whole cell.
  const double cell = (0.6 / 4) * (0.4 / 3);
  EXPECT_NEAR(by_traction.applied[3 * 0 + 2], -3.0 * cell / 4, 1e-15);
  EXPECT_NEAR(by_traction.applied[3 * 6 + 2], -3.0 * cell, 1e-15);

  ForceSpec pressure;
  pressure.nodes.kind = NodeSelector::Kind::kIds;
  pressure.nodes.ids = {6, 7, 8, 11, 12, 13};  // the inner nodes
  pressure.kind = ForceSpec::Kind::kPressure;
  pressure.pressure = 40.0;
  ForceSpec as_traction = pressure;
  as_traction.kind = ForceSpec::Kind::kTraction;
  as_traction.value = {0.0, 0.0, 40.0};
  scene.loads.forces = {pressure};
  const Model by_pressure = BuildModel(scene);
  scene.loads.forces = {as_traction};
  const Model by_vertical_traction = BuildModel(scene);
  for (int k = 0; k < by_pressure.num_dofs(); ++k) {
    EXPECT_NEAR(by_pressure.applied[k], by_vertical_traction.applied[k], 1e-14) << k;
  }
  EXPECT_NEAR(AppliedSum(by_pressure).z(), 40.0 * 6 * cell, 1e-13);

  Scene chain;
  chain.file = "scene.yaml";
  chain.mesh.kind = MeshSpec::Kind::kChain;
  chain.mesh.nodes = {5, 1};
  chain.mesh.length = 1.0;
  chain.material = scene.material;
  NodeSelector first;
  first.kind = NodeSelector::Kind::kIds;
  first.ids = {0};
  chain.fixed = {Fixed(first)};
  pressure.where = Location{"scene.yaml", 12, 7, "loads.forces[0]"};
  pressure.nodes.ids = {1, 2};
  chain.loads.forces = {pressure};
  const std::string message = ErrorOf(chain);
  EXPECT_EQ(message.rfind("scene.yaml:12:7: loads.forces[0]: ", 0), 0u) << message;
  EXPECT_NE(message.find("needs a surface mesh"), std::string::npos) << message;
}

TEST(Model, LoadsWithNothingFixedAlongThemHaveNoMinimum) {
  Scene scene = Sheet(3, 3);
  scene.loads.gravity = kGravity;
  scene.fixed.clear();
  std::string message = ErrorOf(scene);
  EXPECT_EQ(message.rfind("scene.yaml:20:1: loads: ", 0), 0u) << message;
  EXPECT_NE(message.find("along z but no node is fixed along z"), std::string::npos) << message;
  EXPECT_NE(message.find("no minimum"), std::string::npos) << message;

  scene.fixed = {Fixed(Corner("top-left"))};
  scene.fixed[0].dofs = {true, true, false};  // fixed in x and y only: still free to fall
  EXPECT_NE(ErrorOf(scene).find("no minimum"), std::string::npos);

  scene.fixed[0].dofs = {false, false, true};  // held in z, free to slide in x, y: no load there
  EXPECT_EQ(ErrorOf(scene), "");
}

TEST(Model, EverythingFixedIsFine) {
  Scene scene = Sheet(3, 3);
  scene.loads.gravity = kGravity;
  NodeSelector all;
  all.kind = NodeSelector::Kind::kAll;
  scene.fixed = {Fixed(all)};
  const Model model = BuildModel(scene);
  EXPECT_EQ(model.num_free_dofs(), 0);
}

TEST(Model, MaterialAndObstacleErrorsAreRejectedWhereWritten) {
  Scene scene = Sheet(3, 3);
  scene.material.model = MaterialModel::kFiniteVolume;
  scene.material.finite_volume.present = true;
  scene.material.finite_volume.where = Location{"scene.yaml", 9, 3, "material.finite_volume"};
  const std::string message = ErrorOf(scene);  // every rigidity left at zero
  EXPECT_EQ(message.rfind("scene.yaml:9:3: material.finite_volume: ", 0), 0u) << message;

  scene = Sheet(3, 3);
  scene.obstacles.resize(1);
  scene.obstacles[0].friction = 0.3;
  scene.obstacles[0].where = Location{"scene.yaml", 30, 5, "obstacles[0]"};
  EXPECT_EQ(ErrorOf(scene).rfind("scene.yaml:30:5: obstacles[0]", 0), 0u) << ErrorOf(scene);
}

TEST(Model, SelectionErrorsSurfaceFromTheBuild) {
  Scene scene = Sheet(3, 3);
  scene.fixed[0].nodes.kind = NodeSelector::Kind::kIds;
  scene.fixed[0].nodes.ids = {9};
  scene.fixed[0].nodes.where = Location{"scene.yaml", 12, 14, "fixed[0].nodes"};
  const std::string message = ErrorOf(scene);
  EXPECT_EQ(message.rfind("scene.yaml:12:14: fixed[0].nodes: ", 0), 0u) << message;
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
}

}  // namespace model_test
}  // namespace drape
