#include "costs/plane_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/contact_checks.h"

namespace drape {
namespace plane_contact_test {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

PlaneContact Obstacle() {
  return PlaneContact::Create(std::vector<double>{0, 0, -1}.data(),
                              std::vector<double>{0.6, 0, 0.8}.data(), kClearance, kStiffness);
}

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<testing::Probe> kProbes = {
    {{0.3, 0.5, -0.999}, 0.6 * 0.3 + 0.8 * 0.001},
    {{-0.3, 0.5, -0.999}, -0.6 * 0.3 + 0.8 * 0.001},  // behind the plane
    {{0.0, 0.2, -1.0 + 0.0015 / 0.8}, 0.0015},
    {{0.0, 0.2, -0.9}, 0.08}};

TEST(PlaneContact, DistanceToTheSurface) { testing::ExpectDistances(Obstacle(), kProbes); }

TEST(PlaneContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  testing::ExpectCubicPenaltyInsideClearanceOnly(Obstacle(), kProbes, kClearance, kStiffness);
}

TEST(PlaneContact, DerivativesMatchDifferences) {
  testing::ExpectDerivativesMatchDifferencesAtProbes(Obstacle(), kProbes);
}

TEST(PlaneContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  testing::ExpectForcePushesOutward(Obstacle(), kProbes, kClearance, kStiffness);
}

}  // namespace plane_contact_test
}  // namespace drape
