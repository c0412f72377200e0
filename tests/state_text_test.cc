// StateText: what drape solve's result line and drape sweep's rows say of the final state. A run
// that stopped short of the tolerance (an iteration or time limit) is not an equilibrium, whatever
// its Hessian: it used to be called a "stable minimum" there. Nor is a state with the fabric
// through a support disk or through itself.
#include "src/run/state_text.h"

#include <gtest/gtest.h>

namespace drape {
namespace {

RunResult Result(bool converged, bool stable, double min_eigenvalue) {
  RunResult result;
  result.converged = converged;
  result.stability.computed = true;
  result.stability.stable = stable;
  result.stability.min_eigenvalue = min_eigenvalue;
  return result;
}

TEST(StateText, AConvergedRunIsAStableMinimumOrASaddle) {
  EXPECT_EQ(StateText(Result(true, true, 0.25)), "stable minimum");
  EXPECT_EQ(StateText(Result(true, false, -0.49)), "saddle: most negative eigenvalue -0.49 N/m");
}

TEST(StateText, ARunThatDidNotConvergeIsNotAnEquilibrium) {
  EXPECT_EQ(StateText(Result(false, true, 0.25)),
            "not an equilibrium (Hessian positive definite there)");
  EXPECT_EQ(StateText(Result(false, false, -0.49)),
            "not an equilibrium (most negative eigenvalue -0.49 N/m)");
}

// A positive definite state with `nodes` hanging under a support disk and `edges` through it,
// `inside` metres inside its rim at the deepest.
RunResult ThroughDisk(bool converged, int nodes, int edges, double inside) {
  RunResult result = Result(converged, true, 0.25);
  result.contact.nodes_under_disk = nodes;
  result.contact.edges_through_disk = edges;
  result.contact.under_disk_inside = inside;
  return result;
}

// A state with the fabric through a support disk is no drape over it: never a stable minimum,
// whatever its Hessian (the counts and depth are MeasureContact's, src/model/contact.h).
TEST(StateText, FabricThroughASupportDiskIsNeverAStableMinimum) {
  EXPECT_EQ(StateText(ThroughDisk(true, 216, 3, 0.0062)),
            "fabric through the support disk (3 edges through it, up to 6.2 mm inside its rim)");
  EXPECT_EQ(StateText(ThroughDisk(false, 0, 1, 0.0003)),
            "fabric through the support disk (1 edge through it, up to 0.3 mm inside its rim), "
            "not an equilibrium");
}

// Nodes hanging under a disk with no edge through it went round its rim (a fold's trough inside
// the rim's radius): the state is what its certificate says.
TEST(StateText, FabricHangingUnderADiskRoundItsRimIsNoFault) {
  EXPECT_EQ(StateText(ThroughDisk(true, 80, 0, 0.0)), "stable minimum");
}

// A state with the fabric through itself (a triangle's side across another triangle:
// src/model/self_intersection.h) is no drape either, whatever its Hessian; the message names the
// first crossing, and both faults are said where both are there.
TEST(StateText, FabricThroughItselfIsNeverAStableMinimum) {
  RunResult result = Result(true, true, 0.25);
  result.self_intersections.checked = true;
  result.self_intersections.crossings = 3;
  result.self_intersections.side = {12, 13};
  result.self_intersections.triangle = {40, 41, 52};
  EXPECT_TRUE(result.PassesThrough());
  EXPECT_EQ(StateText(result),
            "fabric through itself (3 crossings of a triangle's side and a triangle; the first: "
            "side 12–13 through triangle 40 41 52)");
  result.self_intersections.crossings = 1;
  result.contact.edges_through_disk = 2;
  result.contact.under_disk_inside = 0.001;
  result.converged = false;
  EXPECT_EQ(StateText(result),
            "fabric through the support disk (2 edges through it, up to 1 mm inside its rim); "
            "fabric through itself (1 crossing of a triangle's side and a triangle; side 12–13 "
            "through triangle 40 41 52), not an equilibrium");
}

TEST(StateText, NoVerdictWhereTheStateIsUnsoundOrStabilityWasNotComputed) {
  RunResult unsound = Result(true, true, 0.25);
  unsound.certificate.unsound = "a force is not finite";
  EXPECT_EQ(StateText(unsound), "not certified: a force is not finite");
  RunResult not_computed;
  not_computed.converged = true;
  EXPECT_EQ(StateText(not_computed), "stability not computed");
}

}  // namespace
}  // namespace drape
