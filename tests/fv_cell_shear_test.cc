#include "costs/fv_cell_shear.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <vector>

#include "src/model/finite_volume.h"
#include "src/model/mesh.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

// The corners P, E, N, C of a flat h1 × h2 cell, nodes 0..3.
std::vector<double> FlatCell(double h1, double h2) {
  return {0, 0, 0, h1, 0, 0, 0, h2, 0, h1, h2, 0};
}

constexpr double kShear = 50.0;  // G, N/m

std::unique_ptr<Term> Cell() {
  return MakeTerm("fv_cell_shear", {0, 1, 2, 3}, FvCellShear::Create(kShear, 0.02 * 0.03));
}

TEST(FvCellShear, DerivativesMatchDifferencesAtRandomStates) {
  const auto term = Cell();
  for (unsigned seed = 1; seed <= 20; ++seed) {
    testing::ExpectDerivativesMatchDifferences(
        *term, testing::Perturbed(FlatCell(0.02, 0.03), 0.01, seed));
  }
}

TEST(FvCellShear, DerivativesMatchDifferencesAtTheFlatRestState) {
  testing::ExpectDerivativesMatchDifferences(*Cell(), FlatCell(0.02, 0.03));
}

// Forces to round-off of the term's scale, G h ≈ 1 N: 1e-14 N.
TEST(FvCellShear, ZeroForceAtRestInAnyOrientation) {
  testing::ExpectZeroForceInAnyOrientation(*Cell(), FlatCell(0.02, 0.03), 1e-14);
}

TEST(FvCellShear, InvariantUnderRigidMotionAndBalanced) {
  const auto term = Cell();
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const std::vector<double> positions = testing::Perturbed(FlatCell(0.02, 0.03), 0.008, seed);
    testing::ExpectRigidMotionInvariant(*term, positions);
    testing::ExpectForcesBalance(*term, positions);
  }
}

TEST(FvCellShear, StagedProjectionIsSemidefiniteAboveTheHessianAndExactWhereItCan) {
  const auto term = Cell();
  for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute}) {
    int changed = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
      changed += testing::ExpectStagedProjectionValid(
          *term, testing::Perturbed(FlatCell(0.02, 0.03), 0.01, seed), filter);
    }
    EXPECT_FALSE(testing::ExpectStagedProjectionValid(*term, FlatCell(0.02, 0.03), filter));
    EXPECT_GT(changed, 0);  // the indefinite case is exercised
  }
}

// The cell turned into a parallelogram whose sides keep their lengths and close the angle at P by
// γ: the centre tangents are its sides, so U = ½ G γ² A exactly.
TEST(FvCellShear, ParallelogramCostsItsShearAngle) {
  const double h1 = 0.02, h2 = 0.03, gamma = 0.2;
  const Eigen::Vector3d e(h1, 0, 0), n(h2 * std::sin(gamma), h2 * std::cos(gamma), 0);
  const Eigen::Vector3d c = e + n;
  const std::vector<double> x = {0,     0,     0,     e.x(), e.y(), e.z(),
                                 n.x(), n.y(), n.z(), c.x(), c.y(), c.z()};
  double energy = 0.0;
  ASSERT_TRUE(Cell()->Energy(x.data(), &energy));
  EXPECT_NEAR(energy / (0.5 * kShear * gamma * gamma * h1 * h2), 1.0, 1e-12);
}

// ------------------------------------------------------------ the lattice: corners against cells

// An n × n grid of side `side`, membrane only (E 1000 N/m, G 50 N/m, no bending), with the shear
// at the corners or at the cells' centres.
Model Membrane(int n, double side, bool cell_shear, Mesh* mesh) {
  MeshSpec spec;
  spec.size = {side, side};
  spec.nodes = {n, n};
  *mesh = BuildMesh(spec);
  FiniteVolumeSpec material;
  material.E_warp = material.E_weft = 1000.0;
  material.G = kShear;
  material.cell_shear = cell_shear;
  Model model;
  model.num_nodes = static_cast<int>(mesh->nodes.size());
  AddFiniteVolumeTerms(material, *mesh, &model);
  return model;
}

double TotalEnergy(const Model& model, const std::vector<double>& x) {
  double sum = 0.0;
  for (const auto& term : model.terms) {
    double energy = 0.0;
    EXPECT_TRUE(term->Energy(x.data(), &energy));
    sum += energy;
  }
  return sum;
}

std::vector<double> Mapped(const Mesh& mesh,
                           const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map) {
  std::vector<double> x;
  for (const auto& p : mesh.nodes) {
    const Eigen::Vector3d q = map(p);
    x.insert(x.end(), {q.x(), q.y(), q.z()});
  }
  return x;
}

// Every cell whole: the shear's terms replace the corners' and nothing else changes.
TEST(FvCellShear, ReplacesTheCornersShearInEveryWholeCell) {
  Mesh mesh;
  const Model corners = Membrane(4, 0.03, false, &mesh);
  const Model cells = Membrane(4, 0.03, true, &mesh);
  int cell_terms = 0;
  for (const auto& term : cells.terms) cell_terms += term->type() == "fv_cell_shear";
  EXPECT_EQ(cell_terms, 9);
  EXPECT_EQ(cells.terms.size(), corners.terms.size() + 9);
}

// A homogeneous in-plane shear (the lattice's angles closed by γ, its lines kept in length) costs
// ½ G γ² A over the whole fabric either way: the corners and the centres read the same γ.
TEST(FvCellShear, HomogeneousShearCostsTheSameAsAtTheCorners) {
  const double side = 0.03, gamma = 0.1;
  Mesh mesh;
  const Model corners = Membrane(4, side, false, &mesh);
  const Model cells = Membrane(4, side, true, &mesh);
  const auto x = Mapped(mesh, [gamma](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(p.x() + p.y() * std::sin(gamma), p.y() * std::cos(gamma), 0.0);
  });
  const double exact = 0.5 * kShear * gamma * gamma * side * side;
  EXPECT_NEAR(TotalEnergy(corners, x) / exact, 1.0, 1e-12);
  EXPECT_NEAR(TotalEnergy(cells, x) / exact, 1.0, 1e-12);
}

// One cell folded by α about its diagonal E–N: an isometry of its two triangles (its four sides
// keep their lengths), so only the shear measures anything. The corners E and N each read
// Δ = asin((1 − cos α)/2) over a quarter of the cell, ¼ G Δ² A in all; the centre reads about
// Δ/2 over the whole cell, ⅛ G Δ² A: half the energy the corners charge the fold, to O(α²).
TEST(FvCellShear, HalvesTheShearAFoldAcrossTheCellIsCharged) {
  const double side = 0.01, alpha = 0.3;
  Mesh mesh;
  const Model corners = Membrane(2, side, false, &mesh);
  const Model cells = Membrane(2, side, true, &mesh);
  // Nodes P (0, 0), E (h, 0), N (0, h), C (h, h): C turned by α about the line E–N.
  const Eigen::Vector3d e(side, 0, 0), axis = Eigen::Vector3d(-1, 1, 0).normalized();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(alpha, axis).toRotationMatrix();
  const auto x = Mapped(mesh, [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    if (p.x() + p.y() < 1.5 * side) return p;
    return e + turn * (p - e);
  });
  const double delta = std::asin((1.0 - std::cos(alpha)) / 2.0);
  const double corner = 0.25 * kShear * delta * delta * side * side;
  EXPECT_NEAR(TotalEnergy(corners, x) / corner, 1.0, 1e-9);
  EXPECT_NEAR(TotalEnergy(cells, x) / corner, 0.5, alpha * alpha);
}

// A fold along the lattice (w = f(y)) bends no cell out of its plane: no shear either way.
TEST(FvCellShear, AFoldAlongTheLatticeCostsNoShear) {
  const double side = 0.03;
  Mesh mesh;
  const Model cells = Membrane(5, side, true, &mesh);
  const double radius = 0.01;
  const auto x = Mapped(mesh, [radius](const Eigen::Vector3d& p) {  // rolled about the x axis
    const double angle = p.y() / radius;
    return Eigen::Vector3d(p.x(), radius * std::sin(angle), radius * (1.0 - std::cos(angle)));
  });
  double shear = 0.0;
  for (const auto& term : cells.terms) {
    if (term->type() != "fv_cell_shear") continue;
    double energy = 0.0;
    ASSERT_TRUE(term->Energy(x.data(), &energy));
    shear += energy;
  }
  EXPECT_LT(shear, 1e-24);
}

}  // namespace
}  // namespace drape
