// The node–triangle contact of the fabric with itself (costs/point_triangle_contact.h): its
// distance is the exact distance to the triangle for each part nearest the node, its energy the
// cubic penalty inside the clearance only, its forces push the node away from the triangle and
// balance (an internal force), and it is invariant under rigid motions. (Its derivatives against
// differences and the nested-Jet reference: tests/costs_test.cc.)
#include "costs/point_triangle_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "src/model/term.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

constexpr double kNodeClearance = 0.002, kNodeStiffness = 1e6;

// The triangle (0,0,0) (2,0,0) (0,2,0) cm, and the node at `p` (m).
std::vector<double> NodeState(double x, double y, double z) {
  return {x, y, z, 0, 0, 0, 0.02, 0, 0, 0, 0.02, 0};
}

double NodeDistanceAt(const std::vector<double>& state) {
  const PointTriangleContact contact(kNodeClearance, kNodeStiffness);
  return contact.Distance(state.data(), state.data() + 3, state.data() + 6, state.data() + 9);
}

TEST(PointTriangleContact, DistanceToTheInsideASideAndACorner) {
  EXPECT_NEAR(NodeDistanceAt(NodeState(0.005, 0.004, 0.0015)), 0.0015, 1e-15);
  EXPECT_NEAR(NodeDistanceAt(NodeState(0.005, 0.004, -0.0012)), 0.0012, 1e-15);  // either side
  EXPECT_NEAR(NodeDistanceAt(NodeState(0.01, -0.0009, 0.0012)), 0.0015, 1e-15);  // beyond side a–b
  EXPECT_NEAR(NodeDistanceAt(NodeState(-0.0006, -0.0008, 0.0)), 0.001, 1e-15);   // beyond corner a
}

TEST(PointTriangleContact, CubicPenaltyInsideTheClearanceOnly) {
  const auto term =
      MakeTerm("self_contact", {0, 1, 2, 3}, PointTriangleContact(kNodeClearance, kNodeStiffness));
  for (double height : {0.0005, 0.0015, 0.0025}) {
    const std::vector<double> state = NodeState(0.005, 0.004, height);
    double energy = 0.0;
    ASSERT_TRUE(term->Energy(state.data(), &energy));
    const double gap = std::max(0.0, kNodeClearance - height);
    EXPECT_NEAR(energy, kNodeStiffness / 3.0 * gap * gap * gap, 1e-15);
    EXPECT_EQ(term->Touches(state.data()), height < kNodeClearance);
  }
}

TEST(PointTriangleContact, PushesTheNodeOffTheTriangleAndBalances) {
  const auto term =
      MakeTerm("self_contact", {0, 1, 2, 3}, PointTriangleContact(kNodeClearance, kNodeStiffness));
  const std::vector<double> state = NodeState(0.005, 0.004, 0.0015);
  double energy = 0.0, gradient[12];
  ASSERT_TRUE(term->EnergyGradient(state.data(), &energy, gradient));
  const double gap = kNodeClearance - 0.0015;
  EXPECT_NEAR(-gradient[2], kNodeStiffness * gap * gap, 1e-12);  // up, k g²
  EXPECT_NEAR(gradient[0], 0.0, 1e-15);
  EXPECT_NEAR(gradient[1], 0.0, 1e-15);
  testing::ExpectForcesBalance(*term, state);
  testing::ExpectRigidMotionInvariant(*term, state);
  testing::ExpectRigidMotionInvariant(*term, NodeState(0.01, -0.0009, 0.0012));
}

}  // namespace
}  // namespace drape
