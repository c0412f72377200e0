#include "costs/fv_bending.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "src/model/finite_volume.h"
#include "src/model/mesh.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

// The five nodes W, P, E, S, N of an internal control volume with arms h1 (warp) and h2 (weft),
// flat in the xy plane, stored as nodes 0..4 in that order.
std::vector<double> FlatStencil(double h1, double h2) {
  return {-h1, 0, 0, 0, 0, 0, h1, 0, 0, 0, -h2, 0, 0, h2, 0};
}

std::unique_ptr<Term> InternalVolume(double d12 = 0.4e-5) {
  return MakeTerm("fv_bending", {0, 1, 2, 3, 4},
                  FvBending::Create(1.0e-5, 0.6e-5, d12, 0.02, 0.03, 0.02 * 0.03));
}

std::unique_ptr<Term> EdgeVolume() {
  return MakeTerm("fv_bending", {0, 1, 2}, FvBendingEdge::Create(1.0e-5, 0.02, 0.01));
}

TEST(FvBending, DerivativesMatchDifferencesAtRandomStates) {
  const auto term = InternalVolume();
  for (unsigned seed = 1; seed <= 20; ++seed) {
    testing::ExpectDerivativesMatchDifferences(
        *term, testing::Perturbed(FlatStencil(0.02, 0.03), 0.012, seed));
  }
}

TEST(FvBending, DerivativesMatchDifferencesAtFlatRestState) {
  testing::ExpectDerivativesMatchDifferences(*InternalVolume(), FlatStencil(0.02, 0.03));
  testing::ExpectDerivativesMatchDifferences(*InternalVolume(0.0), FlatStencil(0.02, 0.03));
}

TEST(FvBending, ZeroForceAtRestInAnyOrientation) {
  const auto term = InternalVolume();
  testing::ExpectZeroForce(*term, FlatStencil(0.02, 0.03), 1e-15);
  // The same flat stencil rotated and moved, stretched and sheared in its plane: still no bending.
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, 1.0, -0.4).normalized()).toRotationMatrix();
  std::vector<double> moved = FlatStencil(0.025, 0.028);
  moved[9] += 0.004;  // the weft line S-P-N sheared (turned in the plane), still straight
  moved[12] -= 0.004;
  for (int node = 0; node < 5; ++node) {
    const Eigen::Vector3d q =
        rotation * Eigen::Vector3d(moved[3 * node], moved[3 * node + 1], moved[3 * node + 2]);
    for (int c = 0; c < 3; ++c) moved[3 * node + c] = q[c] + 0.5;
  }
  testing::ExpectZeroForce(*term, moved, 1e-15);
}

TEST(FvBending, InvariantUnderRigidMotionAndBalanced) {
  for (const auto& term : {InternalVolume(), EdgeVolume()}) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
      auto positions = testing::Perturbed(FlatStencil(0.02, 0.03), 0.01, seed);
      positions.resize(3 * static_cast<size_t>(testing::NodesSpanned(*term)));
      testing::ExpectRigidMotionInvariant(*term, positions);
      testing::ExpectForcesBalance(*term, positions);
    }
  }
}

TEST(FvBendingEdge, DerivativesMatchDifferencesAtRandomAndFlatStates) {
  const auto term = EdgeVolume();
  for (unsigned seed = 1; seed <= 20; ++seed) {
    testing::ExpectDerivativesMatchDifferences(
        *term, testing::Perturbed({-0.02, 0, 0, 0, 0, 0, 0.02, 0, 0}, 0.012, seed));
  }
  testing::ExpectDerivativesMatchDifferences(*term, {-0.02, 0, 0, 0, 0, 0, 0.02, 0, 0});
  testing::ExpectZeroForce(*term, {-0.02, 0, 0, 0, 0, 0, 0.03, 0, 0}, 1e-15);
}

// The staged projection (src/derivatives/fast_hessian.h) at states where the exact Hessian is
// indefinite: semidefinite, Ceres's Jᵀ J for the internal volume and above H for the edge one,
// H₊ = H where H is semidefinite (the shared check); and it does change something at some of
// these states (the check is not vacuous) but not at rest.
TEST(FvBending, StagedProjectionIsSemidefiniteItsStandInAndExactWhereItCan) {
  const auto internal = InternalVolume();
  const auto edge = EdgeVolume();
  int changed = 0, changed_edge = 0;
  for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute}) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
      changed += testing::ExpectStagedProjectionValid(
          *internal, testing::Perturbed(FlatStencil(0.02, 0.03), 0.012, seed), filter);
      changed_edge += testing::ExpectStagedProjectionValid(
          *edge, testing::Perturbed({-0.02, 0, 0, 0, 0, 0, 0.02, 0, 0}, 0.012, seed), filter);
    }
    EXPECT_FALSE(testing::ExpectStagedProjectionValid(*internal, FlatStencil(0.02, 0.03), filter));
    EXPECT_FALSE(
        testing::ExpectStagedProjectionValid(*edge, {-0.02, 0, 0, 0, 0, 0, 0.02, 0, 0}, filter));
  }
  EXPECT_GT(changed, 0);
  EXPECT_GT(changed_edge, 0);
}

// Three nodes on a polyline turning by φ: U = ½ D (2 tan(φ/2) / l)² A exactly (eq. 9.1: the
// circle tangent to both arms), whatever the arm lengths.
TEST(FvBendingEdge, EnergyIsThePapersCurvatureSquared) {
  const double d = 2.0e-5, l = 0.02, area = 0.02 * 0.05;
  const auto term = MakeTerm("fv_bending", {0, 1, 2}, FvBendingEdge::Create(d, l, area));
  for (double phi : {0.01, 0.3, 1.2, 2.5}) {
    const std::vector<double> x = {
        -0.015, 0, 0, 0, 0, 0, 0.025 * std::cos(phi), 0, 0.025 * std::sin(phi)};
    double energy;
    ASSERT_TRUE(term->Energy(x.data(), &energy));
    const double kappa = 2.0 * std::tan(phi / 2.0) / l;
    EXPECT_NEAR(energy, 0.5 * d * kappa * kappa * area, 1e-12 * energy) << phi;
  }
}

// The surface z = (a x² + b y²)/2 through an internal volume: κ1 ≈ a, κ2 ≈ b. The coupling term
// takes the sign of a b: positive on a bowl (synclastic), negative on a saddle (anticlastic).
TEST(FvBending, CouplingFollowsThePapersSignRule) {
  const double d1 = 1.0e-5, d2 = 0.6e-5, d12 = 0.5e-5, h = 1e-3, a = 2.0;
  const double area = h * h;
  const auto term =
      MakeTerm("fv_bending", {0, 1, 2, 3, 4}, FvBending::Create(d1, d2, d12, h, h, area));
  for (double b : {2.0, -2.0, 1.0, -0.5}) {
    std::vector<double> x = FlatStencil(h, h);
    for (int node = 0; node < 5; ++node) {
      const double px = x[3 * node], py = x[3 * node + 1];
      x[3 * node + 2] = 0.5 * (a * px * px + b * py * py);
    }
    double energy;
    ASSERT_TRUE(term->Energy(x.data(), &energy));
    const double expected = 0.5 * (d1 * a * a + 2 * d12 * a * b + d2 * b * b) * area;
    EXPECT_NEAR(energy, expected, 1e-5 * expected) << "b = " << b;
  }
}

// A grid rolled onto a cylinder of radius R about the weft (y) axis bends in the warp direction
// only: every volume with a warp curvature carries ½ D1 / R² per unit area, up to O(h²) from
// 2 tan(φ/2)/l ≈ φ/l. The two edge columns (no warp curvature at a free edge) are missing from
// the whole sheet's ½ D1 A / R², an O(h/L) share.
TEST(FvBending, SheetRolledOntoCylinderHasEnergyHalfDOverRSquared) {
  const double radius = 0.2, width = 0.3, height = 0.2, d1 = 1.0e-5;
  double previous_error = 0.0;
  for (int nodes : {11, 21, 41}) {
    MeshSpec spec;
    spec.size = {width, height};
    spec.nodes = {nodes, 7};
    const Mesh mesh = BuildMesh(spec);
    Model model;
    model.num_nodes = static_cast<int>(mesh.nodes.size());
    FiniteVolumeSpec material;
    material.E_warp = material.E_weft = 500.0;
    material.G = 5.0;
    material.D_warp = d1;
    material.D_weft = 2.0e-5;
    AddFiniteVolumeTerms(material, mesh, &model);
    std::vector<double> x;
    double curved_area = 0.0, total_area = 0.0;
    for (int k = 0; k < model.num_nodes; ++k) {
      const double s = mesh.nodes[k].x(), y = mesh.nodes[k].y();
      x.insert(x.end(), {radius * std::sin(s / radius), y, radius * (1 - std::cos(s / radius))});
      total_area += mesh.area[k];
      const int i = mesh.grid_index[k][0];
      if (i > 0 && i + 1 < mesh.nu) curved_area += mesh.area[k];
    }
    double bending = 0.0;
    for (const auto& term : model.terms) {
      if (term->type() != "fv_bending") continue;
      double energy;
      ASSERT_TRUE(term->Energy(x.data(), &energy));
      bending += energy;
    }
    const double h = width / (nodes - 1);
    const double exact_curved = 0.5 * d1 / (radius * radius) * curved_area;
    const double error = std::abs(bending / exact_curved - 1.0);
    // (2 tan(φ/2))² = φ² (1 + φ²/6 + ...) for the turning angle φ = h/R.
    EXPECT_LT(error, 0.17 * (h / radius) * (h / radius)) << nodes;
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.2);  // second order
    }
    previous_error = error;
    const double exact_whole = 0.5 * d1 / (radius * radius) * total_area;
    EXPECT_NEAR(bending / exact_whole, 1.0, 1.01 * h / width) << nodes;
  }
}

}  // namespace
}  // namespace drape
