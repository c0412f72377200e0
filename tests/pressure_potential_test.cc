#include "costs/pressure_potential.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "tests/term_checks.h"

namespace drape {
namespace {

// A regular polygon of `count` nodes and circumradius `radius` in the x–z plane, counter-clockwise
// (x to the right, z up), centred at (cx, cz); one pressure term per side.
struct Polygon {
  std::vector<double> positions;
  std::vector<std::unique_ptr<Term>> terms;
};

Polygon MakePolygon(int count, double radius, double pressure, double cx = 0.3, double cz = -0.2) {
  Polygon polygon;
  for (int k = 0; k < count; ++k) {
    const double angle = 2.0 * M_PI * k / count;
    polygon.positions.insert(polygon.positions.end(), {cx + radius * std::cos(angle), 0.1 * k,
                                                       cz + radius * std::sin(angle)});
  }
  for (int k = 0; k < count; ++k) {
    polygon.terms.push_back(
        MakeTerm("pressure", {k, (k + 1) % count}, PressurePotential::Create(pressure, 0.0, 0.0)));
  }
  return polygon;
}

TEST(PressurePotential, DerivativesMatchDifferences) {
  const auto term = MakeTerm("pressure", {0, 1}, PressurePotential::Create(50.0, 0.1, -0.2));
  testing::ExpectDerivativesMatchDifferences(*term, testing::RandomPositions(2, 1.0, 3));
  testing::ExpectDerivativesMatchDifferences(*term, {0.0, 0.0, 0.0, 1.0, 0.0, 0.0});
}

TEST(PressurePotential, LoopEnergyIsMinusPressureTimesEnclosedArea) {
  const int count = 12;
  const double radius = 0.4, pressure = 7.0;
  const Polygon polygon = MakePolygon(count, radius, pressure);
  double total = 0.0;
  for (const auto& term : polygon.terms) {
    double energy;
    ASSERT_TRUE(term->Energy(polygon.positions.data(), &energy));
    total += energy;
  }
  const double area = 0.5 * count * radius * radius * std::sin(2.0 * M_PI / count);
  EXPECT_NEAR(total, -pressure * area, 1e-12);
}

// The force on each node of a regular polygon points outwards (positive p inflates), with
// magnitude p × (side length) (half of each adjacent side, each side's force normal to it), and
// the forces on the loop balance.
TEST(PressurePotential, PositivePressurePushesEveryNodeOutwardsAndTheLoopIsBalanced) {
  const int count = 9;
  const double radius = 0.5, pressure = 3.0, cx = 0.3, cz = -0.2;
  const Polygon polygon = MakePolygon(count, radius, pressure, cx, cz);
  std::vector<double> force(3 * count, 0.0);
  for (const auto& term : polygon.terms) {
    double energy, gradient[6];
    ASSERT_TRUE(term->EnergyGradient(polygon.positions.data(), &energy, gradient));
    for (int a = 0; a < 2; ++a) {
      for (int c = 0; c < 3; ++c) force[3 * term->nodes()[a] + c] -= gradient[3 * a + c];
    }
  }
  const double side = 2.0 * radius * std::sin(M_PI / count);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d f(force[3 * k], force[3 * k + 1], force[3 * k + 2]);
    const Eigen::Vector3d outward(polygon.positions[3 * k] - cx, 0.0,
                                  polygon.positions[3 * k + 2] - cz);
    EXPECT_NEAR(f.y(), 0.0, 1e-15);
    EXPECT_NEAR(f.normalized().dot(outward.normalized()), 1.0, 1e-12) << "node " << k;
    EXPECT_NEAR(f.norm(), pressure * side * std::cos(M_PI / count), 1e-12) << "node " << k;
    sum += f;
  }
  EXPECT_LT(sum.norm(), 1e-12);
}

TEST(PressurePotential, ALoopIsInvariantUnderTranslationAndRotationInItsPlane) {
  const Polygon polygon = MakePolygon(7, 0.3, 2.0);
  std::vector<double> moved = polygon.positions;
  const double angle = 0.8, c = std::cos(angle), s = std::sin(angle);
  for (int k = 0; k < 7; ++k) {
    const double x = polygon.positions[3 * k], z = polygon.positions[3 * k + 2];
    moved[3 * k] = c * x - s * z + 1.5;
    moved[3 * k + 1] += 4.0;  // y is ignored
    moved[3 * k + 2] = s * x + c * z - 0.7;
  }
  double before = 0.0, after = 0.0;
  for (const auto& term : polygon.terms) {
    double e0, e1;
    ASSERT_TRUE(term->Energy(polygon.positions.data(), &e0));
    ASSERT_TRUE(term->Energy(moved.data(), &e1));
    before += e0;
    after += e1;
  }
  EXPECT_NEAR(before, after, 1e-12);
}

}  // namespace
}  // namespace drape
