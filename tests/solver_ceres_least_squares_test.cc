// ceres-lm and ceres-dogleg: they converge where least squares suits the energy, and on the
// hanging sheet their outcome — whatever it is — is reported as it is.
#include <gtest/gtest.h>

#include "tests/test_scenes.h"

namespace drape {
namespace {

TEST(CeresLeastSquares, DoglegConvergesOnTheFunicularChain) {
  const auto solved = testing::SolveConfig("configs/validation/funicular_chain.yaml",
                                           "ceres-dogleg", {"solver.max_iterations=2000"});
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_LE(solved.result.certificate.relative_residual, 1e-9);
}

// Whatever ceres-lm does on a taut drape, the result says so honestly: "converged" exactly when
// the recomputed residual meets the tolerance, and a reason in words either way.
TEST(CeresLeastSquares, HangingSheetOutcomeIsReportedAsItIs) {
  for (const char* method : {"ceres-lm", "ceres-dogleg"}) {
    const auto solved = testing::SolveConfig("configs/examples/hanging_sheet.yaml", method,
                                             {"mesh.nodes=[10,10]", "solver.max_iterations=200"});
    const auto& result = solved.result;
    EXPECT_EQ(result.converged, result.certificate.relative_residual <= 1e-8) << method;
    EXPECT_FALSE(result.summary.termination.empty()) << method;
    ASSERT_FALSE(result.summary.history.empty()) << method;
    EXPECT_LE(result.summary.iterations, 200) << method;
    EXPECT_TRUE(result.certificate.evaluable) << method;
  }
}

}  // namespace
}  // namespace drape
