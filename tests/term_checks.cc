#include "tests/term_checks.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <random>

namespace drape::testing {

void ExpectHessianMatchesReference(const Term& term, const std::vector<double>& positions,
                                   double tolerance) {
  const int n = term.num_coordinates();
  std::vector<double> gradient(n), hessian(n * n), reference_gradient(n), reference(n * n);
  double energy = 0.0, reference_energy = 0.0;
  ASSERT_TRUE(term.EnergyHessian(positions.data(), &energy, gradient.data(), hessian.data()));
  ASSERT_TRUE(term.ReferenceHessian(positions.data(), &reference_energy, reference_gradient.data(),
                                    reference.data()));
  EXPECT_NEAR(energy, reference_energy, tolerance * std::abs(reference_energy) + 1e-300);
  double g_scale = 0.0, h_scale = 0.0;
  for (double g : reference_gradient) g_scale = std::max(g_scale, std::abs(g));
  for (double h : reference) h_scale = std::max(h_scale, std::abs(h));
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(gradient[k], reference_gradient[k], tolerance * g_scale) << "gradient entry " << k;
  }
  for (int k = 0; k < n * n; ++k) {
    EXPECT_NEAR(hessian[k], reference[k], tolerance * h_scale) << "Hessian entry " << k;
  }
}

Eigen::MatrixXd GaussNewtonByCeres(const Term& term, const std::vector<double>& positions) {
  const std::unique_ptr<ceres::CostFunction> cost(term.NewCostFunction());
  const int nodes = static_cast<int>(term.nodes().size());
  const int outputs = cost->num_residuals();
  std::vector<const double*> parameters;
  for (int node : term.nodes()) parameters.push_back(positions.data() + 3 * node);
  std::vector<double> residuals(outputs), blocks(nodes * outputs * 3);
  std::vector<double*> jacobians;
  jacobians.reserve(nodes);
  for (int a = 0; a < nodes; ++a) jacobians.push_back(blocks.data() + a * outputs * 3);
  EXPECT_TRUE(cost->Evaluate(parameters.data(), residuals.data(), jacobians.data()));
  Eigen::MatrixXd jacobian(outputs, 3 * nodes);
  for (int a = 0; a < nodes; ++a) {
    jacobian.middleCols(3 * a, 3) =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(jacobians[a],
                                                                                    outputs, 3);
  }
  return jacobian.transpose() * jacobian;
}

bool ExpectStagedProjectionValid(const Term& term, const std::vector<double>& positions,
                                 EigenvalueFilter filter) {
  const int n = term.num_coordinates();
  std::vector<double> gradient(n), hessian(n * n), g(n), h(n * n), projected(n * n);
  double energy = 0.0, e = 0.0;
  bool changed = false;
  EXPECT_TRUE(term.HasStagedProjection());
  EXPECT_TRUE(term.EnergyHessian(positions.data(), &energy, gradient.data(), hessian.data()));
  EXPECT_TRUE(term.EnergyHessianProjected(positions.data(), filter, &e, g.data(), h.data(),
                                          projected.data(), &changed));
  EXPECT_EQ(e, energy);
  EXPECT_TRUE(g == gradient);
  EXPECT_TRUE(h == hessian);
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const Matrix exact = Eigen::Map<const Matrix>(hessian.data(), n, n);
  const Matrix stand_in = Eigen::Map<const Matrix>(projected.data(), n, n);
  const double scale = exact.cwiseAbs().maxCoeff() + 1e-300;
  EXPECT_LT((stand_in - stand_in.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  auto smallest = [](const Matrix& m) {
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (m + m.transpose()))
        .eigenvalues()
        .minCoeff();
  };
  EXPECT_GT(smallest(stand_in), -1e-10 * scale);
  if (changed && term.StagedStandIn() == StandIn::kGaussNewton) {
    const Eigen::MatrixXd gauss_newton = GaussNewtonByCeres(term, positions);
    EXPECT_LT((stand_in - gauss_newton).cwiseAbs().maxCoeff(),
              1e-10 * gauss_newton.cwiseAbs().maxCoeff());
  } else {
    EXPECT_GT(smallest(stand_in - exact), -1e-10 * scale);
  }
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(n);
    for (int k = c; k < n; k += 3) translation[k] = 1.0;
    EXPECT_LT((stand_in * translation).cwiseAbs().maxCoeff(), 1e-10 * scale);
  }
  const double least = smallest(exact);
  if (least >= -1e-14 * scale) {
    EXPECT_FALSE(changed);
    EXPECT_TRUE(projected == hessian);
  }
  if (least < -1e-9 * scale) {
    EXPECT_TRUE(changed);
  }
  return changed;
}

void ExpectDerivativesMatchDifferences(const Term& term, std::vector<double> positions,
                                       double tolerance) {
  ExpectHessianMatchesReference(term, positions);
  if (term.HasStagedProjection()) {
    for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute})
      ExpectStagedProjectionValid(term, positions, filter);
  }
  const int n = term.num_coordinates();
  std::vector<double> gradient(n), hessian(n * n), g_plus(n), g_minus(n);
  double energy = 0.0, energy_h = 0.0;
  ASSERT_TRUE(term.EnergyGradient(positions.data(), &energy, gradient.data()));
  ASSERT_TRUE(term.EnergyHessian(positions.data(), &energy_h, g_plus.data(), hessian.data()));
  double plain = 0.0;
  ASSERT_TRUE(term.Energy(positions.data(), &plain));
  EXPECT_NEAR(energy, plain, 1e-12 * (1.0 + std::abs(plain)));
  EXPECT_NEAR(energy_h, plain, 1e-12 * (1.0 + std::abs(plain)));

  double scale = 0.0;
  for (double p : positions) scale = std::max(scale, std::abs(p));
  const double h = 1e-6 * std::max(scale, 1e-3);
  std::vector<double> numeric_gradient(n), numeric_hessian(n * n);
  for (int k = 0; k < n; ++k) {
    const int global = 3 * term.nodes()[k / 3] + k % 3;
    const double saved = positions[global];
    double e_plus, e_minus, unused;
    positions[global] = saved + h;
    ASSERT_TRUE(term.Energy(positions.data(), &e_plus));
    ASSERT_TRUE(term.EnergyGradient(positions.data(), &unused, g_plus.data()));
    positions[global] = saved - h;
    ASSERT_TRUE(term.Energy(positions.data(), &e_minus));
    ASSERT_TRUE(term.EnergyGradient(positions.data(), &unused, g_minus.data()));
    positions[global] = saved;
    numeric_gradient[k] = (e_plus - e_minus) / (2 * h);
    for (int r = 0; r < n; ++r) numeric_hessian[r * n + k] = (g_plus[r] - g_minus[r]) / (2 * h);
  }
  // The gradient's scale: its largest entry, but at least the change the step h makes in it (at
  // a rest state the gradient is 0 and the differences are round-off of the energy).
  double g_scale = 1e-12, h_scale = 1e-12;
  for (int k = 0; k < n * n; ++k) h_scale = std::max(h_scale, std::abs(hessian[k]));
  g_scale = std::max(g_scale, h_scale * h);
  for (int k = 0; k < n; ++k) g_scale = std::max(g_scale, std::abs(gradient[k]));
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(gradient[k], numeric_gradient[k], tolerance * g_scale) << "gradient entry " << k;
  }
  for (int k = 0; k < n * n; ++k) {
    EXPECT_NEAR(hessian[k], numeric_hessian[k], tolerance * h_scale) << "Hessian entry " << k;
    EXPECT_NEAR(hessian[k], hessian[(k % n) * n + k / n], 1e-9 * h_scale) << "symmetry " << k;
  }
}

void ExpectRigidMotionInvariant(const Term& term, const std::vector<double>& positions) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(0.3, -1.1, 2.0);
  std::vector<double> moved = positions;
  for (int node : term.nodes()) {
    const Eigen::Vector3d p(positions[3 * node], positions[3 * node + 1], positions[3 * node + 2]);
    const Eigen::Vector3d q = rotation * p + shift;
    for (int c = 0; c < 3; ++c) moved[3 * node + c] = q[c];
  }
  double before, after;
  ASSERT_TRUE(term.Energy(positions.data(), &before));
  ASSERT_TRUE(term.Energy(moved.data(), &after));
  EXPECT_NEAR(before, after, 1e-10 * (1.0 + std::abs(before)));
}

void ExpectForcesBalance(const Term& term, const std::vector<double>& positions) {
  const int n = term.num_coordinates();
  std::vector<double> gradient(n);
  double energy;
  ASSERT_TRUE(term.EnergyGradient(positions.data(), &energy, gradient.data()));
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double scale = 1e-12;
  for (size_t a = 0; a < term.nodes().size(); ++a) {
    const Eigen::Vector3d f(-gradient[3 * a], -gradient[3 * a + 1], -gradient[3 * a + 2]);
    const int node = term.nodes()[a];
    const Eigen::Vector3d p(positions[3 * node], positions[3 * node + 1], positions[3 * node + 2]);
    force += f;
    moment += p.cross(f);
    scale = std::max(scale, f.norm() * (1.0 + p.norm()));
  }
  EXPECT_LT(force.norm(), 1e-10 * scale);
  EXPECT_LT(moment.norm(), 1e-10 * scale);
}

void ExpectZeroForce(const Term& term, const std::vector<double>& positions, double tolerance) {
  std::vector<double> gradient(term.num_coordinates());
  double energy;
  ASSERT_TRUE(term.EnergyGradient(positions.data(), &energy, gradient.data()));
  for (double g : gradient) EXPECT_NEAR(g, 0.0, tolerance);
}

void ExpectZeroForceInAnyOrientation(const Term& term, const std::vector<double>& positions,
                                     double tolerance) {
  ExpectZeroForce(term, positions, tolerance);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  std::vector<double> moved = positions;
  for (size_t a = 0; a + 2 < moved.size(); a += 3) {
    Eigen::Map<Eigen::Vector3d> x(moved.data() + a);
    x = turn * x + Eigen::Vector3d(0.3, -0.1, 2.0);
  }
  ExpectZeroForce(term, moved, tolerance);
}

std::vector<double> RandomPositions(int count, double size, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-0.5 * size, 0.5 * size);
  std::vector<double> positions(3 * count);
  for (double& p : positions) p = uniform(generator);
  return positions;
}

std::vector<double> Perturbed(std::vector<double> positions, double amplitude, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  for (double& p : positions) p += uniform(generator);
  return positions;
}

}  // namespace drape::testing
