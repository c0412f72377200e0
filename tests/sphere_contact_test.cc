#include "costs/sphere_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/contact_checks.h"

namespace drape {
namespace sphere_contact_test {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

SphereContact Obstacle() {
  return SphereContact::Create(std::vector<double>{0.1, 0.2, -0.3}.data(), 0.15, kClearance,
                               kStiffness);
}

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<testing::Probe> kProbes = {
    {{0.1, 0.2, -0.149}, 0.001},                            // on top, inside the clearance
    {{0.1 + 0.151 * 0.6, 0.2, -0.3 - 0.151 * 0.8}, 0.001},  // below, to the side
    {{0.1, 0.2 - 0.1515, -0.3}, 0.0015},
    {{0.1, 0.2, -0.14}, 0.01},  // outside the clearance
    {{0.1, 0.2, -0.1505}, -0.0005}};

TEST(SphereContact, DistanceToTheSurface) { testing::ExpectDistances(Obstacle(), kProbes); }

TEST(SphereContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  testing::ExpectCubicPenaltyInsideClearanceOnly(Obstacle(), kProbes, kClearance, kStiffness);
}

TEST(SphereContact, DerivativesMatchDifferences) {
  testing::ExpectDerivativesMatchDifferencesAtProbes(Obstacle(), kProbes);
}

TEST(SphereContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  testing::ExpectForcePushesOutward(Obstacle(), kProbes, kClearance, kStiffness);
}

}  // namespace sphere_contact_test
}  // namespace drape
