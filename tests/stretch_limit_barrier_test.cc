#include "costs/stretch_limit_barrier.h"

#include <gtest/gtest.h>

#include "src/model/stretch_limit.h"
#include "src/run/run.h"
#include "tests/term_checks.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

using testing::RandomPositions;

// κ = 1000 N/m, limit length 1.1 × 0.1 m.
std::unique_ptr<Term> Barrier() {
  return MakeTerm("stretch_limit", {0, 1}, StretchLimitBarrier::Create(1000.0, 0.11));
}

TEST(StretchLimitBarrier, DerivativesMatchDifferencesAtRandomStates) {
  const auto term = Barrier();
  int stretched = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const auto positions = RandomPositions(2, 0.3, seed);
    const Eigen::Vector3d d(positions[3] - positions[0], positions[4] - positions[1],
                            positions[5] - positions[2]);
    if (std::abs(d.norm() - 0.11) < 1e-4) continue;  // the kink of the C¹ energy
    stretched += d.norm() > 0.11;
    testing::ExpectDerivativesMatchDifferences(*term, positions);
  }
  EXPECT_GT(stretched, 5);  // both sides of the limit were checked
}

TEST(StretchLimitBarrier, DerivativesMatchDifferencesAtFlatRestState) {
  testing::ExpectDerivativesMatchDifferences(*Barrier(), {0, 0, 0, 0.1, 0, 0});
  testing::ExpectZeroForce(*Barrier(), {0, 0, 0, 0.1, 0, 0});
}

TEST(StretchLimitBarrier, NoForceUpToTheLimitThenHookesLawBeyond) {
  const auto term = Barrier();
  testing::ExpectZeroForce(*term, {0, 0, 0, 0.0, 0.0, 0.1099});
  const std::vector<double> positions = {0, 0, 0, 0, 0, 0.12};  // 0.01 m beyond the limit
  double energy, gradient[6];
  ASSERT_TRUE(term->EnergyGradient(positions.data(), &energy, gradient));
  EXPECT_NEAR(energy, 0.5 * 1000.0 * 0.01 * 0.01, 1e-12);
  EXPECT_NEAR(gradient[5], 1000.0 * 0.01, 1e-9);  // pulls node 1 back towards node 0
}

TEST(StretchLimitBarrier, InvariantUnderRigidMotionAndBalanced) {
  const auto term = Barrier();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto positions = RandomPositions(2, 0.5, seed);
    testing::ExpectRigidMotionInvariant(*term, positions);
    testing::ExpectForcesBalance(*term, positions);
  }
}

TEST(StretchLimitTerms, OnePenaltyPerSpringAndTheModelKnowsItsLimit) {
  Model model = BuildModel(testing::LoadConfig("configs/netlogo/yarn_limit.yaml"));
  EXPECT_DOUBLE_EQ(model.stretch_limit, 1.1);
  const auto counts = model.TermCounts();
  EXPECT_EQ(counts.at("stretch_limit"), counts.at("structural"));
  EXPECT_EQ(ModelSprings(model).size(), 4u);
}

// The stated tolerance: a spring that would reach λ_free without the limit ends at
// λ + (λ_free − λ) / (1 + kStretchLimitPenaltyRatio). The yarn's springs at the pin reach about
// 1.4 without the limit, so at most 1.1 + 0.3 / 1001 with it.
TEST(StretchLimitTerms, NewtonKeepsEverySpringWithinTheStatedTolerance) {
  const Scene scene = testing::LoadConfig("configs/netlogo/yarn_limit.yaml");
  Model free_model = BuildModel(testing::LoadConfig("configs/netlogo/yarn.yaml"));
  const RunResult free_result = RunSolve(scene, free_model, "newton");
  ASSERT_TRUE(free_result.converged);
  const double free_stretch = MaxStretchRatio(free_model, free_model.positions.data());
  ASSERT_GT(free_stretch, 1.2);  // without the limit, it is exceeded by far

  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  ASSERT_TRUE(result.converged) << result.summary.termination;
  const double allowed = 1.1 + (free_stretch - 1.1) / (1.0 + kStretchLimitPenaltyRatio);
  const double stretch = MaxStretchRatio(model, model.positions.data());
  EXPECT_LE(stretch, allowed * (1.0 + 1e-6));
  EXPECT_GT(stretch, 1.1);  // the penalty acts only beyond the limit
}

}  // namespace
}  // namespace drape
