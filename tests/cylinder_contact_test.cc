#include "costs/cylinder_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/contact_checks.h"

namespace drape {
namespace cylinder_contact_test {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

CylinderContact Obstacle() {
  return CylinderContact::Create(std::vector<double>{0, 0, 0}.data(), 0.09, 0.3, kClearance,
                                 kStiffness);
}

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<testing::Probe> kProbes = {
    {{0.02, -0.03, 0.001}, 0.001},                        // on the top face
    {{0.0915, 0.0, -0.1}, 0.0015},                        // beside the mantle
    {{0.0, 0.0912, 0.0009}, std::hypot(0.0012, 0.0009)},  // beyond the top rim
    {{0.0, 0.0, -0.3012}, 0.0012},                        // under the bottom face
    {{0.05, 0.0, -0.1}, -0.04},                           // inside
    {{0.0, 0.0, 0.02}, 0.02}};

TEST(CylinderContact, DistanceToTheSurface) { testing::ExpectDistances(Obstacle(), kProbes); }

TEST(CylinderContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  testing::ExpectCubicPenaltyInsideClearanceOnly(Obstacle(), kProbes, kClearance, kStiffness);
}

TEST(CylinderContact, DerivativesMatchDifferences) {
  testing::ExpectDerivativesMatchDifferencesAtProbes(Obstacle(), kProbes);
}

TEST(CylinderContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  testing::ExpectForcePushesOutward(Obstacle(), kProbes, kClearance, kStiffness);
}

}  // namespace cylinder_contact_test
}  // namespace drape
