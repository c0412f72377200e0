// The contact of a node with a mesh obstacle (costs/mesh_contact.h): a cube given as 12 triangles
// is the box of costs/box_contact.h, so its signed distance and contact energy are the box's, face,
// edge and corner alike; and the shared checks of every contact functor.
#include "costs/mesh_contact.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "costs/box_contact.h"
#include "costs/edge_contact.h"
#include "src/geometry/triangle_surface.h"
#include "tests/contact_checks.h"
#include "tests/test_meshes.h"

namespace drape {
namespace mesh_contact_test {

constexpr double kClearance = 0.002, kStiffness = 4.0e6, kSide = 0.1;

// The cube [0, 0.1]³, each face split along a diagonal, normals outward.
std::shared_ptr<const TriangleSurface> Cube() {
  return testing::Cuboid(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(kSide));
}

MeshContact<TriangleSurface> Obstacle(double clearance = kClearance) {
  return MeshContact<TriangleSurface>(Cube(), clearance, kStiffness);
}

BoxContact Box(double clearance = kClearance) {
  const double low[3] = {0, 0, 0}, high[3] = {kSide, kSide, kSide};
  return BoxContact::Create(low, high, clearance, kStiffness);
}

// Beside a face (away from its diagonal), an edge and a corner; inside; beyond the clearance.
const std::vector<testing::Probe> kProbes = {
    {{0.03, 0.06, 0.101}, 0.001},                                          // above the top face
    {{-0.0012, 0.07, 0.02}, 0.0012},                                       // beside the face x = 0
    {{0.1009, 0.04, -0.0012}, std::hypot(0.0009, 0.0012)},                 // beyond an edge
    {{-0.0005, -0.0007, 0.1008}, std::sqrt(0.25e-6 + 0.49e-6 + 0.64e-6)},  // beyond a corner
    {{0.02, 0.07, 0.0995}, -0.0005},  // inside, under the top face
    {{0.05, 0.03, 0.13}, 0.004}};     // beyond 2t: the bound, 2t

TEST(MeshContact, DistanceToTheSurfaceAndTheBoundBeyondTwiceTheClearance) {
  testing::ExpectDistances(Obstacle(), kProbes);
  const double far[3] = {0.05, 0.03, 0.13};
  EXPECT_NEAR(Cube()->SignedDistance(far), 0.03, 1e-15);
}

TEST(MeshContact, IsTheBoxsContactForACubeEverywhereNearIt) {
  // A clearance of 0.05 m takes in every point the test draws (the bound is 0.1 m).
  const MeshContact<TriangleSurface> cube = Obstacle(0.05);
  const auto mesh = MakeTerm("mesh_contact", {0}, cube);
  const auto box = MakeTerm("box_contact", {0}, Box(0.05));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.04, 0.14);
  for (int k = 0; k < 3000; ++k) {
    const double x[3] = {coordinate(random), coordinate(random), coordinate(random)};
    EXPECT_NEAR(cube.Distance(x), Box(0.05).Distance(x), 1e-15);
    double mesh_energy, box_energy, mesh_gradient[3], box_gradient[3];
    ASSERT_TRUE(mesh->EnergyGradient(x, &mesh_energy, mesh_gradient));
    ASSERT_TRUE(box->EnergyGradient(x, &box_energy, box_gradient));
    EXPECT_NEAR(mesh_energy, box_energy, 1e-12 * (1.0 + box_energy));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(mesh_gradient[c], box_gradient[c], 1e-9 * (1.0 + std::abs(box_gradient[c])));
    }
  }
}

TEST(MeshContact, EnergyIsTheCubicPenaltyInsideTheClearanceOnly) {
  testing::ExpectCubicPenaltyInsideClearanceOnly(Obstacle(), kProbes, kClearance, kStiffness);
}

TEST(MeshContact, DerivativesMatchDifferences) {
  testing::ExpectDerivativesMatchDifferencesAtProbes(Obstacle(), kProbes);
}

TEST(MeshContact, ForcePushesOutwardWithMagnitudeKGapSquared) {
  testing::ExpectForcePushesOutward(Obstacle(), kProbes, kClearance, kStiffness);
}

// An edge's term over a mesh asks once whether the edge can reach the body (Reaches): the same
// energy as the box's edge term where it can, none where it cannot.
TEST(MeshContact, AnEdgesTermIsTheBoxsEdgeTerm) {
  const auto mesh = MakeTerm("mesh_edge_contact", {0, 1}, EdgeContact(Obstacle(), 7));
  const auto box = MakeTerm("box_edge_contact", {0, 1}, EdgeContact(Box(), 7));
  for (const std::vector<double>& ends :
       {std::vector<double>{0.095, 0.05, 0.1015, 0.11, 0.05, 0.096},  // across the top edge
        std::vector<double>{0.02, 0.02, 0.1012, 0.06, 0.03, 0.1009},  // along the top face
        std::vector<double>{0.02, 0.02, 0.2, 0.06, 0.03, 0.3}}) {     // far above
    double mesh_energy, box_energy;
    ASSERT_TRUE(mesh->Energy(ends.data(), &mesh_energy));
    ASSERT_TRUE(box->Energy(ends.data(), &box_energy));
    EXPECT_NEAR(mesh_energy, box_energy, 1e-12 * (1.0 + box_energy));
    EXPECT_EQ(mesh->Touches(ends.data()), box->Touches(ends.data()));
    testing::ExpectDerivativesMatchDifferences(*mesh, ends);
  }
}

}  // namespace mesh_contact_test
}  // namespace drape
