#include "costs/fv_membrane.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "src/model/finite_volume.h"
#include "src/model/mesh.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

// Quarter section P, A = E, B = N with arms 0.02 (warp) and 0.03 (weft), flat in xy.
const std::vector<double> kRest = {0, 0, 0, 0.02, 0, 0, 0, 0.03, 0};

FvMembrane Quarter(double e1 = 600.0, double e2 = 350.0, double e12 = 90.0, double g = 5.0) {
  return FvMembrane::Create(e1, e2, e12, g, 0.02, 0.03);
}

TEST(FvMembrane, DerivativesMatchDifferencesAtRandomStates) {
  const auto term = MakeTerm("fv_membrane", {0, 1, 2}, Quarter());
  for (unsigned seed = 1; seed <= 20; ++seed) {
    testing::ExpectDerivativesMatchDifferences(*term, testing::Perturbed(kRest, 0.008, seed));
  }
}

// At rest the gradient is exactly zero, so the shared checker's relative gradient test compares
// round-off (1e-13) with zero; there the gradient is checked to vanish (tolerance 1: within 1e-12
// absolute) and the Hessian against differences of the gradient, relative to its largest entry.
TEST(FvMembrane, DerivativesMatchDifferencesAtFlatRestState) {
  const auto term = MakeTerm("fv_membrane", {0, 1, 2}, Quarter());
  testing::ExpectDerivativesMatchDifferences(*term, kRest, 1.0);
  std::vector<double> x = kRest, gradient(9), hessian(81), plus(9), minus(9);
  double energy;
  ASSERT_TRUE(term->EnergyHessian(x.data(), &energy, gradient.data(), hessian.data()));
  double scale = 0.0;
  for (double h : hessian) scale = std::max(scale, std::abs(h));
  const double step = 1e-7;
  for (int k = 0; k < 9; ++k) {
    x[k] = kRest[k] + step;
    ASSERT_TRUE(term->EnergyGradient(x.data(), &energy, plus.data()));
    x[k] = kRest[k] - step;
    ASSERT_TRUE(term->EnergyGradient(x.data(), &energy, minus.data()));
    x[k] = kRest[k];
    for (int r = 0; r < 9; ++r) {
      EXPECT_NEAR(hessian[r * 9 + k], (plus[r] - minus[r]) / (2 * step), 1e-6 * scale);
    }
  }
}

// The staged projection over the arms' Gram entries (src/derivatives/fast_hessian.h): semidefinite,
// above H, H₊ = H where H is semidefinite (the shared check). Compressed arms make H indefinite
// (negative sideways curvature): then H₊ ≠ H; at rest and stretched, H₊ = H.
TEST(FvMembrane, StagedProjectionIsSemidefiniteAboveTheHessianAndExactWhereItCan) {
  const auto term = MakeTerm("fv_membrane", {0, 1, 2}, Quarter());
  const std::vector<double> compressed = {0, 0, 0, 0.016, 0, 0.001, 0, 0.025, 0};
  const std::vector<double> stretched = {0, 0, 0, 0.022, 0, 0, 0, 0.033, 0};
  int changed = 0;
  for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute}) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
      changed += testing::ExpectStagedProjectionValid(*term, testing::Perturbed(kRest, 0.008, seed),
                                                      filter);
    }
    EXPECT_TRUE(testing::ExpectStagedProjectionValid(*term, compressed, filter));
    EXPECT_FALSE(testing::ExpectStagedProjectionValid(*term, stretched, filter));
    EXPECT_FALSE(testing::ExpectStagedProjectionValid(*term, kRest, filter));
  }
  EXPECT_GT(changed, 0);
}

TEST(FvMembrane, ZeroForceAtRestInAnyOrientation) {
  const auto term = MakeTerm("fv_membrane", {0, 1, 2}, Quarter());
  testing::ExpectZeroForce(*term, kRest, 1e-14);
  // Rest arms, rotated out of the plane: still at rest.
  testing::ExpectZeroForce(*term, {1, 1, 1, 1, 1.02, 1, 1, 1, 1.03}, 1e-12);
}

TEST(FvMembrane, InvariantUnderRigidMotionAndBalanced) {
  const auto term = MakeTerm("fv_membrane", {0, 1, 2}, Quarter());
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto positions = testing::Perturbed(kRest, 0.008, seed);
    testing::ExpectRigidMotionInvariant(*term, positions);
    testing::ExpectForcesBalance(*term, positions);
  }
}

// Exact energies: stretches of the arms (eq. 9.6 with the strains of eq. 9.3) and a shear by an
// exact angle γ (the arms kept at rest length).
TEST(FvMembrane, EnergyOfStretchAndShear) {
  const double e1 = 600, e2 = 350, e12 = 90, g = 5, area = 0.02 * 0.03 / 4;
  const auto term = MakeTerm("fv_membrane", {0, 1, 2}, Quarter(e1, e2, e12, g));
  const double s1 = 0.05, s2 = -0.03;
  std::vector<double> stretched = {0, 0, 0, 0.02 * (1 + s1), 0, 0, 0, 0.03 * (1 + s2), 0};
  double energy;
  ASSERT_TRUE(term->Energy(stretched.data(), &energy));
  EXPECT_NEAR(energy, 0.5 * (e1 * s1 * s1 + 2 * e12 * s1 * s2 + e2 * s2 * s2) * area, 1e-15);
  const double gamma = 0.3;  // the arms close from 90° to 90° − γ
  std::vector<double> sheared = {
      0, 0, 0, 0.02, 0, 0, 0.03 * std::sin(gamma), 0.03 * std::cos(gamma), 0};
  ASSERT_TRUE(term->Energy(sheared.data(), &energy));
  EXPECT_NEAR(energy, 0.5 * g * gamma * gamma * area, 1e-15);
}

// Off-axis uniaxial stiffness of an orthotropic patch (classical laminate theory, e.g. Jones,
// "Mechanics of Composite Materials", eq. 2.97):
//   1/E(φ) = cos⁴φ/E_warp + (1/G − 2ν12/E_warp) sin²φ cos²φ + sin⁴φ/E_weft,   ν12 = ν_warp.
// The patch's stiffness for homogeneous strain (ε11, ε22, γ12) is read off the assembled Hessian
// of its membrane terms at rest: K = Uᵀ H U / A for the nodal displacements U of unit strains.
// Then 1/E(φ) = aᵀ K⁻¹ a with a = (cos²φ, sin²φ, sinφ cosφ) (the strain along φ under a uniaxial
// stress along φ). Non-uniform spacing on purpose.
TEST(FvMembrane, OrthotropicPatchHasOffAxisModulusOfClassicalTheory) {
  FiniteVolumeSpec material;
  material.E_warp = 500;
  material.E_weft = 300;
  material.nu_warp = 0.3;
  material.nu_weft = 0.3 * 300.0 / 500.0;  // symmetric compliance: ν_warp/E_warp = ν_weft/E_weft
  material.G = 20;
  MeshSpec spec;
  spec.u = {0.0, 0.01, 0.025, 0.03, 0.05};
  spec.v = {0.0, 0.02, 0.03, 0.045};
  const Mesh mesh = BuildMesh(spec);
  Model model;
  model.num_nodes = static_cast<int>(mesh.nodes.size());
  AddFiniteVolumeTerms(material, mesh, &model);
  std::vector<double> rest;
  double area = 0.0;
  for (int k = 0; k < model.num_nodes; ++k) {
    rest.insert(rest.end(), {mesh.nodes[k].x(), mesh.nodes[k].y(), mesh.nodes[k].z()});
    area += mesh.area[k];
  }
  const int n = model.num_dofs();
  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(n, n);
  for (const auto& term : model.terms) {
    const int m = term->num_coordinates();
    std::vector<double> gradient(m), local(m * m);
    double energy;
    ASSERT_TRUE(term->EnergyHessian(rest.data(), &energy, gradient.data(), local.data()));
    for (int r = 0; r < m; ++r) {
      for (int c = 0; c < m; ++c) {
        hessian(3 * term->nodes()[r / 3] + r % 3, 3 * term->nodes()[c / 3] + c % 3) +=
            local[r * m + c];
      }
    }
  }
  Eigen::MatrixXd modes(n, 3);  // u = ε11 x e_x, ε22 y e_y, γ12 (y e_x + x e_y)/2
  for (int k = 0; k < model.num_nodes; ++k) {
    const double x = rest[3 * k], y = rest[3 * k + 1];
    modes.row(3 * k) << x, 0, 0.5 * y;
    modes.row(3 * k + 1) << 0, y, 0.5 * x;
    modes.row(3 * k + 2) << 0, 0, 0;
  }
  const Eigen::Matrix3d stiffness = modes.transpose() * hessian * modes / area;
  const Eigen::Matrix3d compliance = stiffness.inverse();
  for (double degrees = 0; degrees <= 90; degrees += 15) {
    const double phi = degrees * M_PI / 180, c = std::cos(phi), s = std::sin(phi);
    const Eigen::Vector3d a(c * c, s * s, s * c);
    const double expected =
        std::pow(c, 4) / material.E_warp +
        (1 / material.G - 2 * material.nu_warp / material.E_warp) * s * s * c * c +
        std::pow(s, 4) / material.E_weft;
    EXPECT_NEAR(a.dot(compliance * a), expected, 1e-10 * expected) << degrees << "°";
  }
}

}  // namespace
}  // namespace drape
