// solver.levels solved end to end: the refinement study of a case with a known order and limit.
#include "src/run/run_levels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/test_scenes.h"

namespace drape {
namespace run_levels_test {

// The refinement study on a case with a known answer. A weightless strip, clamped, with a small
// tip load P (deflection 7 % of its length: linear theory holds to ~1e-3): its equilibrium
// energy is −P² ℓ³/(6 EI) with ℓ the free length. The discrete clamp sits at h/2
// (tests/cantilever_test.cc), so ℓ = L − h/2 and the energy's error is first order in h:
// E(h) = −P² L³/(6 EI) (1 − 3h/(2L) + O(h²)). Three levels (41, 21, 11 nodes) must give an
// observed order near 1 and an extrapolated energy near −P² L³/(6 EI), closer than the finest
// level's own; each level starts from the previous one and all converge to stable minima.
TEST(Levels, CantileverRefinementHasTheKnownOrderAndLimit) {
  Scene scene = testing::LoadConfig("configs/fv/cantilever_tip.yaml",
                                    {"mesh.nodes=[41, 1]", "solver.levels=3"});
  const double load = 1.6e-5;  // N
  scene.loads.forces.at(0).value = Eigen::Vector3d(0.0, 0.0, -load);
  const double length = scene.mesh.size.x();
  const double ei = scene.material.finite_volume.D_warp * scene.mesh.size.y();
  const double exact = -load * load * std::pow(length, 3) / (6.0 * ei);
  Model model = BuildModel(scene);
  LevelsReport report;
  const RunResult result = RunLevels(scene, model, "newton", {}, &report);
  ASSERT_TRUE(result.converged) << result.summary.termination;
  ASSERT_EQ(report.levels.size(), 3u);
  EXPECT_EQ(report.levels[0].nodes, 11);
  EXPECT_EQ(report.levels[2].nodes, 41);
  for (const LevelRecord& level : report.levels) {
    EXPECT_TRUE(level.converged && level.stable);
    EXPECT_FALSE(level.drape_coefficient.has_value());
    std::printf("h %.5f m: %d iterations, energy %.6e J (exact limit %.6e)\n", level.spacing,
                level.iterations, level.energy, exact);
  }
  ASSERT_EQ(report.extrapolations.size(), 1u);  // no drape coefficient here: the energy
  const Extrapolation& e = report.extrapolations[0];
  ASSERT_TRUE(e.available) << e.reason;
  std::printf("extrapolated %.6e ± %.2e, order %.3f\n", e.value, e.error_estimate,
              e.observed_order);
  EXPECT_NEAR(e.observed_order, 1.0, 0.2);
  const double finest_error = std::abs(report.levels[2].energy - exact);
  EXPECT_LT(std::abs(e.value - exact), 0.2 * finest_error);
  EXPECT_NEAR(e.error_estimate, finest_error, 0.3 * finest_error);
}

}  // namespace run_levels_test
}  // namespace drape
