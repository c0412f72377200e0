// The edge–edge contact of the fabric with itself (costs/edge_edge_contact.h): its distance is the
// exact distance between the segments for each pair of nearest parts, its energy the cubic penalty
// inside the clearance only, its forces push the edges apart and balance, and it is invariant
// under rigid motions. (Its derivatives: tests/costs_test.cc.)
#include "costs/edge_edge_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "src/model/term.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

constexpr double kEdgeClearance = 0.002, kEdgeStiffness = 1e6;

// The edge (0,0,0)–(2,0,0) cm and the edge c–d.
std::vector<double> EdgeState(const std::vector<double>& c, const std::vector<double>& d) {
  std::vector<double> state = {0, 0, 0, 0.02, 0, 0};
  state.insert(state.end(), c.begin(), c.end());
  state.insert(state.end(), d.begin(), d.end());
  return state;
}

double EdgeDistanceAt(const std::vector<double>& s) {
  const EdgeEdgeContact contact(kEdgeClearance, kEdgeStiffness);
  return contact.Distance(s.data(), s.data() + 3, s.data() + 6, s.data() + 9);
}

TEST(EdgeEdgeContact, DistanceBetweenInsidesAnEndAndAnInsideAndTwoEnds) {
  EXPECT_NEAR(EdgeDistanceAt(EdgeState({0.01, -0.01, 0.0015}, {0.01, 0.01, 0.0015})), 0.0015,
              1e-15);
  EXPECT_NEAR(EdgeDistanceAt(EdgeState({0.021, -0.01, 0.0}, {0.021, 0.01, 0.0})), 0.001, 1e-15);
  EXPECT_NEAR(EdgeDistanceAt(EdgeState({0.0206, 0.0008, 0.0}, {0.04, 0.01, 0.0})), 0.001, 1e-15);
}

TEST(EdgeEdgeContact, CubicPenaltyInsideTheClearanceOnly) {
  const auto term =
      MakeTerm("self_edge_contact", {0, 1, 2, 3}, EdgeEdgeContact(kEdgeClearance, kEdgeStiffness));
  for (double height : {0.0005, 0.0015, 0.0025}) {
    const std::vector<double> state = EdgeState({0.01, -0.01, height}, {0.01, 0.01, height});
    double energy = 0.0;
    ASSERT_TRUE(term->Energy(state.data(), &energy));
    const double gap = std::max(0.0, kEdgeClearance - height);
    EXPECT_NEAR(energy, kEdgeStiffness / 3.0 * gap * gap * gap, 1e-15);
    EXPECT_EQ(term->Touches(state.data()), height < kEdgeClearance);
  }
}

TEST(EdgeEdgeContact, PushesTheEdgesApartAndBalances) {
  const auto term =
      MakeTerm("self_edge_contact", {0, 1, 2, 3}, EdgeEdgeContact(kEdgeClearance, kEdgeStiffness));
  const std::vector<double> state = EdgeState({0.01, -0.01, 0.0015}, {0.01, 0.01, 0.0015});
  double energy = 0.0, gradient[12];
  ASSERT_TRUE(term->EnergyGradient(state.data(), &energy, gradient));
  const double gap = kEdgeClearance - 0.0015;
  // The upper edge is pushed up with k g² in all, half on each end (they cross at both middles).
  EXPECT_NEAR(-(gradient[8] + gradient[11]), kEdgeStiffness * gap * gap, 1e-12);
  EXPECT_NEAR(-gradient[8], -gradient[11], 1e-12);
  testing::ExpectForcesBalance(*term, state);
  testing::ExpectRigidMotionInvariant(*term, state);
}

}  // namespace
}  // namespace drape
