#include "src/model/finite_volume.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "costs/constant_force_potential.h"
#include "src/model/equilibrium.h"
#include "src/model/mesh.h"
#include "src/run/run.h"
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

Mesh Circle(double radius, double spacing) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kCircle;
  spec.radius = radius;
  spec.spacing = spacing;
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
// the left and right) one way, corners not at all; every cell holds 4 quarter sections and, with
// the default cell_shear, one shear at its centre.
TEST(FiniteVolume, BuildsOneBendingTermPerVolumeAndOneMembraneTermPerQuarter) {
  const Mesh mesh = Grid(4, 3);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  const auto census = Census(model);
  EXPECT_EQ(census.at("fv_bending/5"), 2);
  EXPECT_EQ(census.at("fv_bending/3"), 6);
  EXPECT_EQ(census.at("fv_membrane/3"), 3 * 2 * 4);
  EXPECT_EQ(census.at("fv_cell_shear/4"), 3 * 2);
  EXPECT_EQ(census.size(), 4u);
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

// The flat mesh is the rest state: no energy, no force.
void ExpectNoEnergyAndNoForceAtRest(const Mesh& mesh) {
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  double energy;
  std::vector<double> gradient;
  ASSERT_TRUE(EvaluateEnergy(model, model.positions.data(), &energy, &gradient));
  EXPECT_NEAR(energy, 0.0, 1e-20);
  for (double g : gradient) EXPECT_NEAR(g, 0.0, 1e-12);
}

TEST(FiniteVolume, RestStateHasNoEnergyAndNoForce) { ExpectNoEnergyAndNoForceAtRest(Grid(5, 4)); }

TEST(FiniteVolume, RejectsMeshesWithoutGridOrArea) {
  MeshSpec chain;
  chain.kind = MeshSpec::Kind::kChain;
  const Mesh line = BuildMesh(chain);
  Model model = EmptyModel(line);
  EXPECT_THROW(AddFiniteVolumeTerms(Cotton(), line, &model), InputError);
  MeshSpec arc;  // rings × spokes: not a lattice
  arc.kind = MeshSpec::Kind::kArc;
  arc.radius = 0.05;
  arc.rings = 3;
  arc.spokes = 8;
  const Mesh disc = BuildMesh(arc);
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

// Circle of radius 2 lattice steps: the 13 lattice points with i² + j² ≤ 4 (a 3 × 3 block and the
// four tips (±2, 0), (0, ±2)). Counted by hand: both directions continue at the centre and its 4
// neighbours (5 FvBending); at the block's corners (±1, ±1) and the tips neither does (no edge
// bending). Quarter sections (pairs of a warp and a weft arm): 4 at each of the 5 cross nodes,
// 1 at each block corner ((1, 1): W and S), 0 at the tips (one arm only): 24.
TEST(FiniteVolume, CircleOfRadiusTwoStepsHasHandCountedTerms) {
  const Mesh mesh = Circle(2.0, 1.0);
  ASSERT_EQ(mesh.nodes.size(), 13u);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  const auto census = Census(model);
  EXPECT_EQ(census.at("fv_bending/5"), 5);
  EXPECT_EQ(census.at("fv_membrane/3"), 24);
  EXPECT_EQ(census.count("fv_bending/3"), 0u);
  ValidateModel(model);
}

// Lattice neighbours found independently from the node coordinates (x/s, y/s rounded).
struct CoordinateLattice {
  std::map<std::pair<long, long>, int> ids;
  int At(long i, long j) const {
    const auto found = ids.find({i, j});
    return found == ids.end() ? -1 : found->second;
  }
};

CoordinateLattice LatticeOf(const Mesh& mesh, double spacing) {
  CoordinateLattice lattice;
  for (int k = 0; k < static_cast<int>(mesh.nodes.size()); ++k) {
    lattice
        .ids[{std::lround(mesh.nodes[k].x() / spacing), std::lround(mesh.nodes[k].y() / spacing)}] =
        k;
  }
  return lattice;
}

// On a larger circle (with stepped rims where one direction ends), the term counts follow from
// the neighbours found by coordinates: FvBending where all four exist, FvBendingEdge where
// exactly one direction continues, and one quarter per present (warp arm, weft arm) pair.
TEST(FiniteVolume, CircleTermsFollowTheLatticeNeighbours) {
  const double spacing = 0.01;
  const Mesh mesh = Circle(0.073, spacing);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  const CoordinateLattice lattice = LatticeOf(mesh, spacing);
  int full = 0, edge = 0, quarters = 0;
  for (const auto& [ij, id] : lattice.ids) {
    const auto [i, j] = ij;
    const bool w = lattice.At(i - 1, j) >= 0, e = lattice.At(i + 1, j) >= 0;
    const bool s = lattice.At(i, j - 1) >= 0, n = lattice.At(i, j + 1) >= 0;
    const bool warp = w && e, weft = s && n;
    full += warp && weft;
    edge += warp != weft;
    quarters += (w + e) * (s + n);
  }
  ASSERT_GT(edge, 0);
  const auto census = Census(model);
  EXPECT_EQ(census.at("fv_bending/5"), full);
  EXPECT_EQ(census.at("fv_bending/3"), edge);
  EXPECT_EQ(census.at("fv_membrane/3"), quarters);
  ValidateModel(model);
}

TEST(FiniteVolume, FlatCircleAtRestHasNoEnergyAndNoForce) {
  ExpectNoEnergyAndNoForceAtRest(Circle(0.05, 0.007));
}

// Energy is unchanged by a rotation + translation of a deformed circle, and the rest shape moved
// rigidly stays force-free.
TEST(FiniteVolume, CircleEnergyIsInvariantUnderRigidMotion) {
  const Mesh mesh = Circle(0.05, 0.007);
  Model model = EmptyModel(mesh);
  AddFiniteVolumeTerms(Cotton(), mesh, &model);
  std::vector<double> deformed = model.positions;
  for (int k = 0; k < model.num_nodes; ++k) {  // a smooth, non-symmetric deformation
    const double x = deformed[3 * k], y = deformed[3 * k + 1];
    deformed[3 * k] += 0.02 * x * y / 0.05;
    deformed[3 * k + 1] += 0.01 * x;
    deformed[3 * k + 2] += 3.0 * x * x + 1.0 * x * y - 2.0 * y * y * y / 0.05;
  }
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  const Eigen::Vector3d shift(0.3, -0.2, 0.5);
  auto moved = [&](const std::vector<double>& x) {
    std::vector<double> y(x.size());
    for (int k = 0; k < model.num_nodes; ++k) {
      const Eigen::Vector3d p = rotation * Eigen::Vector3d(x[3 * k], x[3 * k + 1], x[3 * k + 2]);
      for (int c = 0; c < 3; ++c) y[3 * k + c] = p[c] + shift[c];
    }
    return y;
  };
  double before, after, rest;
  std::vector<double> gradient;
  ASSERT_TRUE(EvaluateEnergy(model, deformed.data(), &before));
  ASSERT_TRUE(EvaluateEnergy(model, moved(deformed).data(), &after));
  EXPECT_GT(before, 0.0);
  EXPECT_NEAR(after, before, 1e-10 * before);
  ASSERT_TRUE(EvaluateEnergy(model, moved(model.positions).data(), &rest, &gradient));
  EXPECT_NEAR(rest, 0.0, 1e-18);
  for (double g : gradient) EXPECT_NEAR(g, 0.0, 1e-10);
}

// Stretching the circle uniformly by ε along x (the warp) gives each quarter section
// ½ E1 ε² A_q (ε2 = γ = 0), along y ½ E2 ε² A_q, with E1 = E_warp/(1 − ν_warp ν_weft),
// E2 = E_weft/(1 − ν_warp ν_weft) and A_q = s²/4: the warp runs along x, the weft along y.
TEST(FiniteVolume, CircleWarpRunsAlongXAndWeftAlongY) {
  const double spacing = 0.01;
  const Mesh mesh = Circle(0.06, spacing);
  Model model = EmptyModel(mesh);
  const FiniteVolumeSpec material = Cotton();
  AddFiniteVolumeTerms(material, mesh, &model);
  int quarters = 0;
  for (const auto& term : model.terms) quarters += term->type() == "fv_membrane";
  const double quarter_area = spacing * spacing / 4, strain = 1e-3;
  const double factor = 1 - material.nu_warp * material.nu_weft;
  for (int axis : {0, 1}) {
    std::vector<double> x = model.positions;
    for (int k = 0; k < model.num_nodes; ++k) x[3 * k + axis] *= 1 + strain;
    double energy;
    ASSERT_TRUE(EvaluateEnergy(model, x.data(), &energy));
    const double modulus = (axis == 0 ? material.E_warp : material.E_weft) / factor;
    EXPECT_NEAR(energy, 0.5 * modulus * strain * strain * quarters * quarter_area, 1e-9 * energy)
        << "axis " << axis;
  }
}

// Rolling the circle onto a cylinder of radius R about the y axis (the warp bends, κ1 = 1/R,
// κ2 = 0) gives every control volume whose warp continues ½ D_warp κ² per unit area, κ the chord
// curvature 2 tan(φ/2)/s with φ = s/R (= 1/R up to O((s/R)²)); rolled about the x axis, D_weft.
// Against the closed form for the whole disc, ½ D π a² / R², the volumes on the rim where the
// bending direction ends carry none: a strip of about one spacing along the rim, whose share of
// the disc's area decreases like s/a (first order), so the error must shrink with s.
TEST(FiniteVolume, UniformlyBentCircleMatchesTheClosedForm) {
  FiniteVolumeSpec material = Cotton();
  material.D_12 = 0.0;
  const double a = 0.1, radius = 0.4;
  std::vector<double> disc_errors;
  for (double spacing : {0.01, 0.005}) {
    const Mesh mesh = Circle(a, spacing);
    Model model = EmptyModel(mesh);
    AddFiniteVolumeTerms(material, mesh, &model);
    const CoordinateLattice lattice = LatticeOf(mesh, spacing);
    for (int axis : {0, 1}) {
      const double rigidity = axis == 0 ? material.D_warp : material.D_weft;
      std::vector<double> x = model.positions;
      double curved_area = 0.0;
      for (int k = 0; k < model.num_nodes; ++k) {
        const double s = mesh.nodes[k][axis];
        x[3 * k + axis] = radius * std::sin(s / radius);
        x[3 * k + 2] = radius * (1 - std::cos(s / radius));
        const long i = std::lround(mesh.nodes[k].x() / spacing);
        const long j = std::lround(mesh.nodes[k].y() / spacing);
        const bool continues = axis == 0 ? lattice.At(i - 1, j) >= 0 && lattice.At(i + 1, j) >= 0
                                         : lattice.At(i, j - 1) >= 0 && lattice.At(i, j + 1) >= 0;
        if (continues) curved_area += mesh.area[k];
      }
      double bending = 0.0;
      for (const auto& term : model.terms) {
        double energy;
        ASSERT_TRUE(term->Energy(x.data(), &energy));
        if (term->type() == "fv_bending") bending += energy;
      }
      const double density = 0.5 * rigidity / (radius * radius);
      // Nodes s apart along the arc turn by φ = s/R: κ = 2 tan(φ/2)/s, κ² R² = (tan(φ/2)/(φ/2))²
      // = 1 + φ²/6 + O(φ⁴), the discretisation error of the chord curvature.
      const double half_turn = 0.5 * spacing / radius;
      const double chord = std::pow(std::tan(half_turn) / half_turn, 2);
      EXPECT_NEAR(bending / (density * curved_area), chord, 1e-9);
      EXPECT_NEAR(chord, 1.0, 0.17 * std::pow(spacing / radius, 2));
      const double disc_error = std::abs(bending / (density * M_PI * a * a) - 1.0);
      EXPECT_LT(disc_error, 2.0 * spacing / a) << "spacing " << spacing << " axis " << axis;
      disc_errors.push_back(disc_error);
    }
  }
  EXPECT_LT(disc_errors[2], 0.7 * disc_errors[0]);
  EXPECT_LT(disc_errors[3], 0.7 * disc_errors[1]);
}

}  // namespace
}  // namespace drape
