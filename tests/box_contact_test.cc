#include "costs/box_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/term_checks.h"

namespace drape {
namespace {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

BoxContact Obstacle() {
  return BoxContact::Create(std::vector<double>{-0.5, -0.4, -1.0}.data(),
                            std::vector<double>{0.5, 0.4, 0.0}.data(), kClearance, kStiffness);
}

struct Probe {
  std::vector<double> x;
  double distance;  // expected signed distance to the surface, m
};

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<Probe> kProbes = {
    {{0.1, 0.2, 0.001}, 0.001},                           // on the table top
    {{0.5012, 0.1, -0.3}, 0.0012},                        // beside a side face
    {{0.5009, 0.1, 0.0012}, std::hypot(0.0009, 0.0012)},  // beyond an edge
    {{-0.5008, 0.4009, 0.0011}, std::sqrt(0.0008 * 0.0008 + 0.0009 * 0.0009 + 0.0011 * 0.0011)},
    {{0.1, 0.2, -0.01}, -0.01},  // inside, nearest the top
    {{0.1, 0.2, 0.3}, 0.3}};

TEST(BoxContact, DistanceToTheSurface) {
  for (const Probe& probe : kProbes) {
    EXPECT_NEAR(Obstacle().Distance(probe.x.data()), probe.distance, 1e-14);
  }
}

TEST(BoxContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  const auto term = MakeTerm("box_contact", {0}, Obstacle());
  for (const Probe& probe : kProbes) {
    double energy;
    ASSERT_TRUE(term->Energy(probe.x.data(), &energy));
    const double gap = std::max(0.0, kClearance - probe.distance);
    EXPECT_NEAR(energy, kStiffness / 3.0 * gap * gap * gap, 1e-12 * (1.0 + energy));
  }
}

TEST(BoxContact, DerivativesMatchDifferences) {
  const auto term = MakeTerm("box_contact", {0}, Obstacle());
  for (const Probe& probe : kProbes) {
    SCOPED_TRACE(probe.distance);
    testing::ExpectDerivativesMatchDifferences(*term, probe.x);
  }
}

// The force pushes the node out, along the distance's gradient, with magnitude k g².
TEST(BoxContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  const auto term = MakeTerm("box_contact", {0}, Obstacle());
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
