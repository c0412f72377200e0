#include "costs/box_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/contact_checks.h"

namespace drape {
namespace box_contact_test {

constexpr double kClearance = 0.002, kStiffness = 4.0e6;

BoxContact Obstacle() {
  return BoxContact::Create(std::vector<double>{-0.5, -0.4, -1.0}.data(),
                            std::vector<double>{0.5, 0.4, 0.0}.data(), kClearance, kStiffness);
}

// Points beside each part of the surface (well inside one region, away from the seams where the
// distance's second derivative jumps), with their distances worked out by hand.
const std::vector<testing::Probe> kProbes = {
    {{0.1, 0.2, 0.001}, 0.001},                           // on the table top
    {{0.5012, 0.1, -0.3}, 0.0012},                        // beside a side face
    {{0.5009, 0.1, 0.0012}, std::hypot(0.0009, 0.0012)},  // beyond an edge
    {{-0.5008, 0.4009, 0.0011}, std::sqrt(0.0008 * 0.0008 + 0.0009 * 0.0009 + 0.0011 * 0.0011)},
    {{0.1, 0.2, -0.01}, -0.01},  // inside, nearest the top
    {{0.1, 0.2, 0.3}, 0.3}};

TEST(BoxContact, DistanceToTheSurface) { testing::ExpectDistances(Obstacle(), kProbes); }

TEST(BoxContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  testing::ExpectCubicPenaltyInsideClearanceOnly(Obstacle(), kProbes, kClearance, kStiffness);
}

TEST(BoxContact, DerivativesMatchDifferences) {
  testing::ExpectDerivativesMatchDifferencesAtProbes(Obstacle(), kProbes);
}

TEST(BoxContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  testing::ExpectForcePushesOutward(Obstacle(), kProbes, kClearance, kStiffness);
}

}  // namespace box_contact_test
}  // namespace drape
