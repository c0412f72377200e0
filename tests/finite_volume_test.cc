#include "src/finite_volume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "costs/constant_force_potential.h"
#include "src/equilibrium.h"
#include "src/mesh.h"
#include "src/run.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

FiniteVolumeSpec Cotton() {
  FiniteVolumeSpec spec;
  spec.E_warp = 500;
  spec.E_weft = 300;
  spec.nu_warp = 0.3;
  spec.nu_weft = 0.18;  // ν_warp E_weft / E_warp: a symmetric compliance
  spec.G = 5;
  spec.D_warp = 1e-5;
  spec.D_weft = 0.6e-5;
  spec.D_12 = 0.2e-5;
  return spec;
}

Mesh Grid(int nu, int nv, double width = 0.3, double height = 0.2) {
  MeshSpec spec;
  spec.size = {width, height};
  spec.nodes = {nu, nv};
  return BuildMesh(spec);
}

Model EmptyModel(const Mesh& mesh) {
  Model model;
  model.num_nodes = static_cast<int>(mesh.nodes.size());
  for (const auto& p : mesh.nodes)
    model.positions.insert(model.positions.end(), {p.x(), p.y(), p.z()});
  model.initial = model.positions;
  model.mass = mesh.area;
  for (double& m : model.mass) m *= 0.12;
  model.fixed.assign(model.num_dofs(), 0);
  model.applied.assign(model.num_dofs(), 0.0);
  model.grid_index = mesh.grid_index;
  return model;
}

// Terms by type and node count.
std::map<std::string, int> Census(const Model& model) {
  std::map<std::string, int> census;
  for (const auto& term : model.terms) {
    ++census[term->type() + "/" + std::to_string(term->nodes().size())];
  }
  return census;
}

// 4 × 3 grid: internal volumes (2) bend both ways, edge volumes (4 along the bottom and top, 2 on
// the left and right) one way, corners not at all; every cell holds 4 quarter sections.
TEST(FiniteVolume, BuildsOneBendingTermPerVolumeAndOneMembraneTermPerQuarter) {
  const Mesh mesh = Grid(4, 3);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  const auto census = Census(model);
  EXPECT_EQ(census.at("fv_bending/5"), 2);
  EXPECT_EQ(census.at("fv_bending/3"), 6);
  EXPECT_EQ(census.at("fv_membrane/3"), 3 * 2 * 4);
  EXPECT_EQ(census.size(), 3u);
  ValidateModel(model);
}

TEST(FiniteVolume, StripHasBendingAtInnerNodesAndMembraneOnLinks) {
  const Mesh mesh = Grid(6, 1, 0.1, 0.02);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  const auto census = Census(model);
  EXPECT_EQ(census.at("fv_bending/3"), 4);
  EXPECT_EQ(census.at("fv_membrane/2"), 5);
  // The membrane link is ½ E_warp ε² (l w): stretch the strip uniformly by ε.
  std::vector<double> x = model.positions;
  const double strain = 1e-3;
  for (int k = 0; k < model.num_nodes; ++k) x[3 * k] *= 1 + strain;
  double energy;
  ASSERT_TRUE(EvaluateEnergy(model, x.data(), &energy));
  EXPECT_NEAR(energy, 0.5 * 500 * strain * strain * 0.1 * 0.02, 1e-12 * energy);
}

TEST(FiniteVolume, RestStateHasNoEnergyAndNoForce) {
  const Mesh mesh = Grid(5, 4);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  double energy;
  std::vector<double> gradient;
  ASSERT_TRUE(EvaluateEnergy(model, model.positions.data(), &energy, &gradient));
  EXPECT_NEAR(energy, 0.0, 1e-20);
  for (double g : gradient) EXPECT_NEAR(g, 0.0, 1e-12);
}

TEST(FiniteVolume, RejectsMeshesWithoutGridOrArea) {
  MeshSpec chain;
  chain.kind = MeshSpec::Kind::kChain;
  const Mesh line = BuildMesh(chain);
  Model model = EmptyModel(line);
  EXPECT_THROW(AddFiniteVolumeTerms(Cotton(), line, &model), InputError);
  MeshSpec circle;
  circle.kind = MeshSpec::Kind::kCircle;
  circle.radius = 0.05;
  const Mesh disc = BuildMesh(circle);
  Model disc_model = EmptyModel(disc);
  EXPECT_THROW(AddFiniteVolumeTerms(Cotton(), disc, &disc_model), InputError);
}

TEST(FiniteVolume, RejectsIndefiniteRigidities) {
  const Mesh mesh = Grid(3, 3);
  Model model = EmptyModel(mesh);
  FiniteVolumeSpec coupling = Cotton();
  coupling.D_12 = 1e-5;  // D12² > D1 D2
  EXPECT_THROW(AddFiniteVolumeTerms(coupling, mesh, &model), InputError);
  FiniteVolumeSpec poisson = Cotton();
  poisson.nu_warp = 1.5;  // ν_warp² E_weft > E_warp
  poisson.nu_weft = 0.5;
  EXPECT_THROW(AddFiniteVolumeTerms(poisson, mesh, &model), InputError);
  EXPECT_TRUE(model.terms.empty());
}

// Non-uniform spacing: l_P = (x_E − x_W)/2 makes the discrete curvature of a sheet rolled onto a
// cylinder 1/R again, so each curved volume carries ½ D1 / R² per unit area up to O(h²).
TEST(FiniteVolume, NonUniformGridRolledOntoCylinderHasExactEnergyDensity) {
  MeshSpec spec;
  spec.u = {0.0, 0.01, 0.03, 0.035, 0.05, 0.08, 0.09, 0.1};
  spec.v = {0.0, 0.02, 0.05};
  const Mesh mesh = BuildMesh(spec);
  Model model = EmptyModel(mesh);
  FiniteVolumeSpec material = Cotton();
  material.D_12 = 0.0;
  AddFiniteVolumeTerms(material, mesh, &model);
  const double radius = 0.5;
  std::vector<double> x;
  double curved_area = 0.0;
  for (int k = 0; k < model.num_nodes; ++k) {
    const double s = mesh.nodes[k].x();
    x.insert(x.end(), {radius * std::sin(s / radius), mesh.nodes[k].y(),
                       radius * (1 - std::cos(s / radius))});
    const int i = mesh.grid_index[k][0];
    if (i > 0 && i + 1 < mesh.nu) curved_area += mesh.area[k];
  }
  double bending = 0.0;
  for (const auto& term : model.terms) {
    double energy;
    ASSERT_TRUE(term->Energy(x.data(), &energy));
    if (term->type() == "fv_bending") bending += energy;
  }
  const double expected = 0.5 * material.D_warp / (radius * radius) * curved_area;
  EXPECT_NEAR(bending / expected, 1.0, 0.17 * std::pow(0.03 / radius, 2));
}

// A flat orthotropic patch pulled along the warp by a total force F on its right edge (shared by
// edge length), left edge held along x, one corner along y, z held: the uniform state
// ε_warp = F/(H E_warp), ε_weft = −ν_warp ε_warp is the equilibrium, solved with newton.
TEST(FiniteVolume, UniaxialTensionGivesWarpModulusAndPoissonContraction) {
  const int nu = 6, nv = 5;
  const double width = 0.1, height = 0.08, force = 0.01;
  const Mesh mesh = Grid(nu, nv, width, height);
  Model model = EmptyModel(mesh);
  const FiniteVolumeSpec material = Cotton();
  AddFiniteVolumeTerms(material, mesh, &model);
  for (int j = 0; j < nv; ++j) {
    model.fixed[3 * (j * nu)] = 1;
    const int right = j * nu + nu - 1;
    const double share = (j == 0 || j == nv - 1 ? 0.5 : 1.0) / (nv - 1);
    const double f[3] = {force * share, 0, 0};
    model.terms.push_back(
        MakeTerm("load", {right}, ConstantForcePotential::Create(f, &model.initial[3 * right])));
    model.applied[3 * right] += f[0];
  }
  model.fixed[1] = 1;
  for (int k = 0; k < model.num_nodes; ++k) model.fixed[3 * k + 2] = 1;
  ValidateModel(model);
  Scene scene;
  scene.solver.tolerance = 1e-10;
  const RunResult run = RunSolve(scene, model, "newton");
  ASSERT_TRUE(run.converged) << run.summary.termination;
  const double strain = force / (height * material.E_warp);
  for (int k = 0; k < model.num_nodes; ++k) {
    EXPECT_NEAR(model.positions[3 * k], mesh.nodes[k].x() * (1 + strain), 2e-3 * strain * width);
    EXPECT_NEAR(model.positions[3 * k + 1], mesh.nodes[k].y() * (1 - material.nu_warp * strain),
                2e-3 * strain * height);
  }
}

}  // namespace
}  // namespace drape
