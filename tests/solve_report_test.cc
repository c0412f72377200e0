// The report of a solve (src/run/solve_report.h): the drape coefficient's error bar every report
// of it gives (ReportedDrapeCoefficientError).
#include "src/run/solve_report.h"

#include <gtest/gtest.h>

#include <optional>

#include "src/analysis/mesh_rule.h"
#include "src/model/model.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// The 24 cm polyester on a 20 cm disc (a short overhang: quick), as in the command-line tests.
Scene SmallTester() {
  return testing::LoadConfig("configs/fv/drape_tester_polyester_24.yaml",
                             {"drape_test.disc_diameter=0.2", "mesh.spacing=0.0125"});
}

// Two levels (the default): the levels' error bar, which is at least the mesh rule's; one level:
// the mesh rule's alone; a scene without a support disc: none.
TEST(SolveReport, TheDrapeCoefficientsErrorBarIsTheLinesOne) {
  const Scene scene = SmallTester();
  Model model = BuildModel(scene);
  ASSERT_EQ(LevelsToSolve(scene, model), 2);
  const SolveReport two = SolveAndReport(scene, model, scene.solver.method);
  ASSERT_TRUE(two.levels && two.levels->drape_error);
  const std::optional<MeshAdvice> advice = AdviseMesh(scene, model);
  ASSERT_TRUE(advice);
  ASSERT_TRUE(two.mesh_advice);
  EXPECT_EQ(two.mesh_advice->expected_error, advice->expected_error);  // the report's own
  const std::optional<double> bar = ReportedDrapeCoefficientError(two);
  ASSERT_TRUE(bar);
  EXPECT_EQ(*bar, two.levels->drape_error->error());
  EXPECT_GE(*bar, advice->expected_error);
  EXPECT_GE(*bar, two.levels->drape_error->levels_error);

  SolveReport one = two;  // the same drape, as a one-level solve reports it
  one.levels.reset();
  EXPECT_EQ(ReportedDrapeCoefficientError(one), advice->expected_error);

  const Scene sheet = testing::LoadConfig("configs/examples/hanging_sheet.yaml", {});
  const Model sheet_model = BuildModel(sheet);
  const SolveReport plain = ReportOf(sheet, sheet_model, RunResult{});
  ASSERT_FALSE(plain.drape);
  EXPECT_FALSE(plain.mesh_advice);
  EXPECT_FALSE(ReportedDrapeCoefficientError(plain));
}

}  // namespace
}  // namespace drape
