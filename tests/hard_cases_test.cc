// The hard cases of configs/hard/: newton must reach a relative residual of 1e-8 from the start
// each scene describes, with finite positions, and report a stable equilibrium where the physics
// has one (a sheet turning freely about one support is neutral, not unstable); and the sheet
// lifted by its centre and the strip pooling on the floor rest on themselves with no crossing,
// while without the fabric's contact with itself they pass through themselves and are never
// called stable minima.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "src/run/state_text.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

using testing::SolveConfig;

void ExpectConvergedAndStable(const std::string& file) {
  const auto solved = SolveConfig("configs/hard/" + file, "newton");
  const RunResult& result = solved.result;
  EXPECT_TRUE(result.converged) << file << ": " << result.summary.termination;
  EXPECT_LE(result.certificate.relative_residual, 1e-8) << file;
  for (double x : solved.model.positions) ASSERT_TRUE(std::isfinite(x)) << file;
  for (const auto& record : result.summary.history) {
    ASSERT_TRUE(std::isfinite(record.energy) && std::isfinite(record.relative_residual)) << file;
  }
  EXPECT_TRUE(result.stability.computed) << file;
  EXPECT_TRUE(result.stability.stable)
      << file << ": min eigenvalue " << result.stability.min_eigenvalue;
}

TEST(HardCases, SheetHangingFromTwoCornersFromTheFlatStart) {
  ExpectConvergedAndStable("two_corner_sheet.yaml");
}
TEST(HardCases, NearInextensibleSheet) { ExpectConvergedAndStable("near_inextensible_sheet.yaml"); }
TEST(HardCases, TautCableAtItsRestLength) { ExpectConvergedAndStable("taut_cable.yaml"); }
TEST(HardCases, CompressedStartBetweenCloseSupports) {
  ExpectConvergedAndStable("compressed_chain.yaml");
}
TEST(HardCases, TensionOnlySprings) { ExpectConvergedAndStable("tension_only_sheet.yaml"); }
TEST(HardCases, SheetHungByOneCorner) { ExpectConvergedAndStable("one_corner_sheet.yaml"); }
TEST(HardCases, LargeLoad) { ExpectConvergedAndStable("large_load.yaml"); }
TEST(HardCases, TinyLoad) { ExpectConvergedAndStable("tiny_load.yaml"); }
TEST(HardCases, ThreeByThreeMesh) { ExpectConvergedAndStable("small_mesh.yaml"); }

// A limp square lifted by its centre: the flaps fall into one another. Without the fabric's contact
// with itself the equilibrium passes through itself: the certificate must find it and never call
// it a stable minimum (src/model/self_intersection.h), whatever the Hessian says.
TEST(HardCases, ASheetLiftedByItsCentreIsNoStableMinimumWhileItPassesThroughItself) {
  const auto solved =
      SolveConfig("configs/hard/lifted_by_centre.yaml", "newton", {"contact.self=false"});
  const RunResult& result = solved.result;
  EXPECT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.self_intersections.checked);
  EXPECT_GT(result.self_intersections.crossings, 0);
  EXPECT_TRUE(result.PassesThrough());
  EXPECT_EQ(StateText(result).rfind("fabric through itself (", 0), 0u) << StateText(result);
}

// With it (the default), the flaps press on one another and the drape is a stable minimum that
// never passes through itself (on a 21 × 21 lattice: 4 s where the shipped 31 × 31 takes 12 s).
TEST(HardCases, ASheetLiftedByItsCentreRestsOnItselfWithItsContact) {
  const auto solved =
      SolveConfig("configs/hard/lifted_by_centre.yaml", "newton", {"mesh.nodes=[21, 21]"});
  const RunResult& result = solved.result;
  ASSERT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.stability.stable);
  EXPECT_TRUE(result.self_intersections.checked);
  EXPECT_EQ(result.self_intersections.crossings, 0);
  EXPECT_FALSE(result.PassesThrough());
  EXPECT_GT(result.summary.statistics.at("self_contact_rebuilds"), 0.0);
  EXPECT_EQ(StateText(result), "stable minimum");
}

// A strip standing on the floor sinks and pools in layers (half the shipped strip: 25 cm, 2.6 s).
TEST(HardCases, AStripPoolsOnTheFloorInLayersThatDoNotCross) {
  const auto solved = SolveConfig("configs/hard/strip_pooling.yaml", "newton",
                                  {"mesh.size=[0.04, 0.25]", "mesh.nodes=[5, 26]"});
  const RunResult& result = solved.result;
  ASSERT_TRUE(result.converged) << result.summary.termination;
  EXPECT_TRUE(result.stability.stable);
  EXPECT_EQ(result.self_intersections.crossings, 0);
  EXPECT_FALSE(result.PassesThrough());
  // It lies on the floor: every node within the layers' reach of it, none through it.
  double highest = 0.0;
  for (int k = 0; k < solved.model.num_nodes; ++k) {
    const double z = testing::Position(solved.model, k).z();
    EXPECT_GT(z, 0.0) << "node " << k;
    highest = std::max(highest, z);
  }
  EXPECT_LT(highest, 0.05);  // m: a pile, not a standing strip (25 cm)
  EXPECT_GT(result.summary.statistics.at("self_contact_rebuilds"), 0.0);
}

TEST(HardCases, TautCableSagsOnlyByItsElasticStretch) {
  const auto solved = SolveConfig("configs/hard/taut_cable.yaml", "newton");
  ASSERT_TRUE(solved.result.converged);
  // Mid-span sag of a cable of weight W = 0.981 N, span L = 1 m and axial stiffness EA = 1e5 N
  // that is taut at its rest length: the stretch ΔL = H L / EA must make up the extra length of
  // the parabola, 8 d² / (3 L), with H = W L / (8 d)  ⇒  d³ = 3 W L³ / (64 EA).
  const double expected = std::cbrt(3.0 * 0.981 / (64.0 * 1e5));
  const double sag = -testing::Position(solved.model, 10).z();
  EXPECT_NEAR(sag, expected, 0.05 * expected);
}

TEST(HardCases, MillimetresAndGramsGiveTheSameShapeScaled) {
  const auto si = SolveConfig("configs/hard/units_si.yaml", "newton");
  const auto mm = SolveConfig("configs/hard/units_mm.yaml", "newton");
  ASSERT_TRUE(si.result.converged && mm.result.converged);
  ASSERT_EQ(si.model.positions.size(), mm.model.positions.size());
  double largest = 0.0;
  for (size_t k = 0; k < si.model.positions.size(); ++k) {
    largest = std::max(largest, std::abs(mm.model.positions[k] / 1000.0 - si.model.positions[k]));
  }
  EXPECT_LE(largest / si.model.size, 1e-8);
}

}  // namespace
}  // namespace drape
