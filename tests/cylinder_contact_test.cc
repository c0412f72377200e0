#include "costs/cylinder_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/term_checks.h"

namespace drape {
namespace {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

CylinderContact Obstacle() {
  return CylinderContact::Create(std::vector<double>{0, 0, 0}.data(), 0.09, 0.3, kClearance,
                                 kStiffness);
}

struct Probe {
  std::vector<double> x;
  double distance;  // expected signed distance to the surface, m
};

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<Probe> kProbes = {
    {{0.02, -0.03, 0.001}, 0.001},                        // on the top face
    {{0.0915, 0.0, -0.1}, 0.0015},                        // beside the mantle
    {{0.0, 0.0912, 0.0009}, std::hypot(0.0012, 0.0009)},  // beyond the top rim
    {{0.0, 0.0, -0.3012}, 0.0012},                        // under the bottom face
    {{0.05, 0.0, -0.1}, -0.04},                           // inside
    {{0.0, 0.0, 0.02}, 0.02}};

TEST(CylinderContact, DistanceToTheSurface) {
  for (const Probe& probe : kProbes) {
    EXPECT_NEAR(Obstacle().Distance(probe.x.data()), probe.distance, 1e-14);
  }
}

TEST(CylinderContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  const auto term = MakeTerm("cylinder_contact", {0}, Obstacle());
  for (const Probe& probe : kProbes) {
    double energy;
    ASSERT_TRUE(term->Energy(probe.x.data(), &energy));
    const double gap = std::max(0.0, kClearance - probe.distance);
    EXPECT_NEAR(energy, kStiffness / 3.0 * gap * gap * gap, 1e-12 * (1.0 + energy));
  }
}

TEST(CylinderContact, DerivativesMatchDifferences) {
  const auto term = MakeTerm("cylinder_contact", {0}, Obstacle());
  for (const Probe& probe : kProbes) {
    SCOPED_TRACE(probe.distance);
    testing::ExpectDerivativesMatchDifferences(*term, probe.x);
  }
}

// The force pushes the node out, along the distance's gradient, with magnitude k g².
TEST(CylinderContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  const auto term = MakeTerm("cylinder_contact", {0}, Obstacle());
  for (const Probe& probe : kProbes) {
    const double gap = kClearance - probe.distance;
    if (gap <= 0.0) continue;
    std::vector<double> x = probe.x;
    double energy, gradient[3];
    ASSERT_TRUE(term->EnergyGradient(x.data(), &energy, gradient));
    const double force = std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] +
                                   gradient[2] * gradient[2]);
    EXPECT_NEAR(force, kStiffness * gap * gap, 1e-9 * force);
    // Moving along the force increases the distance.
    for (int c = 0; c < 3; ++c) x[c] -= 1e-7 * gradient[c] / force;
    EXPECT_GT(Obstacle().Distance(x.data()), probe.distance);
  }
}

}  // namespace
}  // namespace drape
