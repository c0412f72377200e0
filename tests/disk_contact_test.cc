#include "costs/disk_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/contact_checks.h"

namespace drape {
namespace disk_contact_test {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

DiskContact Obstacle() {
  return DiskContact::Create(std::vector<double>{0, 0, 0.5}.data(), 0.09, kClearance, kStiffness);
}

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<testing::Probe> kProbes = {
    {{0.02, -0.03, 0.501}, 0.001},                        // over the top
    {{0.02, -0.03, 0.4985}, 0.0015},                      // under the disc
    {{0.0912, 0.0, 0.5009}, std::hypot(0.0012, 0.0009)},  // beside the rim
    {{0.0, -0.0913, 0.4992}, std::hypot(0.0013, 0.0008)},
    {{0.03, 0.04, 0.51}, 0.01}};

TEST(DiskContact, DistanceToTheSurface) { testing::ExpectDistances(Obstacle(), kProbes); }

TEST(DiskContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  testing::ExpectCubicPenaltyInsideClearanceOnly(Obstacle(), kProbes, kClearance, kStiffness);
}

TEST(DiskContact, DerivativesMatchDifferences) {
  testing::ExpectDerivativesMatchDifferencesAtProbes(Obstacle(), kProbes);
}

TEST(DiskContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  testing::ExpectForcePushesOutward(Obstacle(), kProbes, kClearance, kStiffness);
}

}  // namespace disk_contact_test
}  // namespace drape
