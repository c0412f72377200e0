#include "costs/edge_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>
#include <vector>

#include "costs/disk_contact.h"
#include "costs/sphere_contact.h"
#include "src/model/contact.h"
#include "src/model/term.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

constexpr double kClearance = 0.001, kStiffness = 4.0e6;
constexpr double kRimRadius = 0.09;

DiskContact Disc() {
  return DiskContact::Create(std::vector<double>{0, 0, 0}.data(), kRimRadius, kClearance,
                             kStiffness);
}

// The edge of a lattice over the disc's rim: one node 0.1 mm above the disc's clearance layer,
// 4 mm inside the rim, the other 6.5 mm beyond the rim and 1.5 mm below the disc's plane. The
// straight edge between them crosses the plane 0.44 mm beyond the rim, passing 0.11 mm from the
// rim's circle: it cuts the rim's corner, though both nodes are clear of the disc's contact.
// (No point of the edges below sits on the rim's circle ρ = R, where the distance's second
// derivative jumps and differences do not give it.)
const std::vector<double> kCornerCut = {kRimRadius - 0.004,  0.0, 0.0011,
                                        kRimRadius + 0.0065, 0.0, -0.0015};

double NodeEnergy(const DiskContact& disc, const double* x) {
  double energy = 0.0;
  disc(x, &energy);
  return energy;
}

TEST(EdgeContact, EnergyIsTheNodePenaltyAtItsPointsInsideTheEdge) {
  const DiskContact disc = Disc();
  for (int points : {1, 3, 9}) {
    const EdgeContact<DiskContact> edge(disc, points);
    double expected = 0.0;
    for (int j = 1; j <= points; ++j) {
      const double s = static_cast<double>(j) / (points + 1);
      double x[3];
      for (int c = 0; c < 3; ++c) x[c] = kCornerCut[c] + s * (kCornerCut[3 + c] - kCornerCut[c]);
      expected += NodeEnergy(disc, x);
    }
    double energy = 0.0;
    ASSERT_TRUE(edge(kCornerCut.data(), kCornerCut.data() + 3, &energy));
    EXPECT_DOUBLE_EQ(energy, expected) << points << " points";
  }
}

TEST(EdgeContact, CatchesAnEdgeThroughTheRimWhoseNodesAreClear) {
  const DiskContact disc = Disc();
  EXPECT_EQ(NodeEnergy(disc, kCornerCut.data()), 0.0);
  EXPECT_EQ(NodeEnergy(disc, kCornerCut.data() + 3), 0.0);
  const Eigen::Vector3d a(kCornerCut.data()), b(kCornerCut.data() + 3);
  ContactSpec contact;
  contact.thickness = kClearance;
  const int points = EdgeContactPoints(a, b, contact);
  const auto term = MakeTerm("disk_edge_contact", {0, 1}, EdgeContact(disc, points));
  double energy = 0.0;
  ASSERT_TRUE(term->Energy(kCornerCut.data(), &energy));
  EXPECT_GT(energy, 0.0);
  // The force pushes the edge off the rim's corner, away from the rim's circle: its total is
  // up and outward, in the vertical plane through the edge.
  double gradient[6];
  ASSERT_TRUE(term->EnergyGradient(kCornerCut.data(), &energy, gradient));
  EXPECT_LT(gradient[0] + gradient[3], 0.0);  // force +x: outward
  EXPECT_EQ(gradient[1] + gradient[4], 0.0);
  EXPECT_LT(gradient[2] + gradient[5], 0.0);  // force +z: up
}

TEST(EdgeContact, NothingWhereNoPointIsInTheClearanceLayer) {
  const auto term = MakeTerm("disk_edge_contact", {0, 1}, EdgeContact(Disc(), 9));
  const std::vector<double> above = {0.01, 0.0, 0.003, 0.02, 0.0, 0.004};
  double energy = 1.0, gradient[6], hessian[36];
  ASSERT_TRUE(term->EnergyHessian(above.data(), &energy, gradient, hessian));
  EXPECT_EQ(energy, 0.0);
  for (double g : gradient) EXPECT_EQ(g, 0.0);
  for (double h : hessian) EXPECT_EQ(h, 0.0);
}

// The assembly's active set asks Touches; an edge it skips must be one whose energy, gradient and
// Hessian are exactly zero, and an edge it keeps one with some point in the layer: the corner cut,
// whose nodes are both clear, among edges thrown at random across the rim.
TEST(EdgeContact, TouchesExactlyWhereSomePointIsInTheClearanceLayer) {
  const EdgeContact<DiskContact> corner(Disc(), 3);
  EXPECT_TRUE(corner.Touches(kCornerCut.data(), kCornerCut.data() + 3));
  std::mt19937 random(5);
  std::uniform_real_distribution<double> radial(kRimRadius - 0.006, kRimRadius + 0.006);
  std::uniform_real_distribution<double> height(-0.003, 0.003);
  int touching = 0, clear = 0;
  for (int sample = 0; sample < 2000; ++sample) {
    const std::vector<double> x = {radial(random), 0.002 * height(random), height(random),
                                   radial(random), 0.002 * height(random), height(random)};
    const auto term = MakeTerm("disk_edge_contact", {0, 1}, EdgeContact(Disc(), 3));
    double energy, gradient[6], hessian[36];
    ASSERT_TRUE(term->ReferenceHessian(x.data(), &energy, gradient, hessian));
    bool any_point_inside = false;
    for (int j = 1; j <= 3; ++j) {
      double point[3];
      for (int c = 0; c < 3; ++c) point[c] = x[c] + 0.25 * j * (x[3 + c] - x[c]);
      any_point_inside = any_point_inside || Disc().Distance(point) < kClearance;
    }
    ASSERT_EQ(term->Touches(x.data()), any_point_inside);
    if (any_point_inside) {
      ++touching;
      continue;
    }
    ++clear;
    EXPECT_EQ(energy, 0.0);
    for (double g : gradient) EXPECT_EQ(g, 0.0);
    for (double h : hessian) EXPECT_EQ(h, 0.0);
  }
  EXPECT_GT(touching, 100);
  EXPECT_GT(clear, 100);
}

TEST(EdgeContact, DerivativesMatchDifferences) {
  const auto disc = MakeTerm("disk_edge_contact", {0, 1}, EdgeContact(Disc(), 9));
  {
    SCOPED_TRACE("the rim's corner");
    testing::ExpectDerivativesMatchDifferences(*disc, kCornerCut);
  }
  SCOPED_TRACE("flat, then the sphere");
  // The flat state: an edge lying on the disc's top, inside its clearance layer.
  testing::ExpectDerivativesMatchDifferences(*disc, {0.01, 0.0, 0.0009, 0.02, 0.0, 0.0009});
  const auto sphere = MakeTerm(
      "sphere_edge_contact", {0, 1},
      EdgeContact(
          SphereContact::Create(std::vector<double>{0, 0, 0}.data(), 0.05, kClearance, kStiffness),
          4));
  testing::ExpectDerivativesMatchDifferences(*sphere, {-0.01, 0.0, 0.0508, 0.01, 0.0, 0.0509});
}

TEST(EdgeContact, PointsLeaveNoGapLongerThanTheClearance) {
  ContactSpec contact;
  contact.thickness = 0.001;
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  EXPECT_EQ(EdgeContactPoints(origin, Eigen::Vector3d(0.0008, 0, 0), contact), 0);
  EXPECT_EQ(EdgeContactPoints(origin, Eigen::Vector3d(0.001, 0, 0), contact), 0);
  EXPECT_EQ(EdgeContactPoints(origin, Eigen::Vector3d(0.0013, 0, 0), contact), 1);
  EXPECT_EQ(EdgeContactPoints(origin, Eigen::Vector3d(0.0026, 0, 0), contact), 2);
  EXPECT_EQ(EdgeContactPoints(origin, Eigen::Vector3d(0.006, 0.008, 0), contact), 9);
}

}  // namespace
}  // namespace drape
