#include <gtest/gtest.h>

#include <string>

#include "src/solvers/solvers.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

using testing::Position;
using testing::SolveConfig;

const char* const kNloptSolvers[] = {"nlopt-lbfgs", "nlopt-tnewton", "nlopt-var2", "nlopt-mma",
                                     "nlopt-slsqp"};

class NloptOnChain : public ::testing::TestWithParam<const char*> {};

TEST_P(NloptOnChain, ReachesRelativeResidual1e8AndNewtonsShape) {
  const auto reference = SolveConfig("configs/examples/chain.yaml", "newton");
  ASSERT_TRUE(reference.result.converged);
  const auto solved =
      SolveConfig("configs/examples/chain.yaml", GetParam(), {"solver.tolerance=1e-8"});
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_LE(solved.result.certificate.relative_residual, 1e-8);
  EXPECT_FALSE(solved.result.summary.history.empty());
  for (int node = 0; node < solved.model.num_nodes; ++node) {
    EXPECT_LT((Position(solved.model, node) - Position(reference.model, node)).norm(), 1e-6)
        << "node " << node;
  }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, NloptOnChain, ::testing::ValuesIn(kNloptSolvers),
                         [](const auto& test) {
                           std::string name = test.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

TEST(NloptSolvers, AreListed) {
  for (const char* name : kNloptSolvers) EXPECT_NE(FindSolver(name), nullptr) << name;
  EXPECT_EQ(NewNloptSolver("nlopt-unknown"), nullptr);
}

TEST(NloptSlsqp, RefusedAboveOneThousandFreeDofs) {
  // A 19 × 19 sheet held by two corners: 3 × 359 = 1077 free coordinates.
  const Scene scene =
      testing::LoadConfig("configs/examples/hanging_sheet.yaml", {"mesh.nodes=[19, 19]"});
  Model model = BuildModel(scene);
  ASSERT_GT(model.num_free_dofs(), 1000);
  const std::vector<double> start = model.positions;
  try {
    RunSolve(scene, model, "nlopt-slsqp");
    FAIL() << "nlopt-slsqp accepted " << model.num_free_dofs() << " free dofs";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("nlopt-slsqp"), std::string::npos) << message;
    EXPECT_NE(message.find("1000"), std::string::npos) << message;
    EXPECT_NE(message.find(std::to_string(model.num_free_dofs())), std::string::npos) << message;
  }
  EXPECT_EQ(model.positions, start);  // nothing was moved
}

TEST(NloptSlsqp, AcceptedAtOneThousandFreeDofsOrFewer) {
  // 18 × 18 = 324 nodes, 2 fixed: 966 free coordinates. Without the fabric's contact with itself:
  // its step filter refuses SLSQP's first long steps, which bring parts of the sheet nearer than
  // half their distance (each a penalised evaluation), and the run then ends at its evaluation
  // limit before its third iteration.
  const Scene scene =
      testing::LoadConfig("configs/examples/hanging_sheet.yaml",
                          {"mesh.nodes=[18, 18]", "solver.max_iterations=3", "contact.self=false"});
  Model model = BuildModel(scene);
  ASSERT_LE(model.num_free_dofs(), 1000);
  const RunResult result = RunSolve(scene, model, "nlopt-slsqp");
  EXPECT_GT(result.summary.iterations, 0);
  EXPECT_NE(result.summary.termination.find("iteration limit"), std::string::npos)
      << result.summary.termination;
}

TEST(NloptSolvers, StopAtTheIterationLimitWithTheBestPointKept) {
  const auto solved = SolveConfig("configs/examples/chain.yaml", "nlopt-lbfgs",
                                  {"solver.max_iterations=5", "solver.tolerance=1e-12"});
  EXPECT_FALSE(solved.result.converged);
  EXPECT_NE(solved.result.summary.termination.find("iteration limit"), std::string::npos)
      << solved.result.summary.termination;
  double lowest = INFINITY;
  for (const auto& record : solved.result.summary.history) lowest = std::min(lowest, record.energy);
  EXPECT_NEAR(solved.result.certificate.energy, lowest, 1e-12 * std::abs(lowest));
}

}  // namespace
}  // namespace drape
