// The shared stopping rule (IterationMonitor) and the registry.
#include "src/solvers/solver.h"

#include <gtest/gtest.h>

#include "src/scene/solver_methods.h"

namespace drape {
namespace {

TEST(IterationMonitor, ConvergesOnTheRelativeResidual) {
  Model model;
  SolverOptions options;
  options.tolerance = 1e-6;
  SolverSummary summary;
  IterationMonitor monitor(model, options, &summary);
  EXPECT_FALSE(monitor.Record(0, 1.0, 1.0));
  EXPECT_FALSE(monitor.Record(1, 0.5, 1e-3));
  EXPECT_TRUE(monitor.Record(2, 0.4, 1e-7));
  EXPECT_TRUE(summary.converged);
  EXPECT_EQ(summary.iterations, 2);
  ASSERT_EQ(summary.history.size(), 3u);
  EXPECT_EQ(summary.history[1].relative_residual, 1e-3);
  EXPECT_NE(summary.termination.find("tolerance"), std::string::npos);
}

TEST(IterationMonitor, StopsAtTheIterationLimitWithoutConverging) {
  Model model;
  SolverOptions options;
  options.max_iterations = 2;
  SolverSummary summary;
  IterationMonitor monitor(model, options, &summary);
  EXPECT_FALSE(monitor.Record(0, 1.0, 1.0));
  EXPECT_FALSE(monitor.Record(1, 1.0, 1.0));
  EXPECT_TRUE(monitor.Record(2, 1.0, 1.0));
  EXPECT_FALSE(summary.converged);
  EXPECT_NE(summary.termination.find("iteration limit"), std::string::npos);
}

TEST(IterationMonitor, StopsWhenTheTimeIsUpOrTheCallerSaysSo) {
  Model model;
  SolverOptions options;
  options.time_limit = 0.0;
  SolverSummary summary;
  IterationMonitor timed(model, options, &summary);
  EXPECT_TRUE(timed.Record(0, 1.0, 1.0));
  EXPECT_NE(summary.termination.find("time limit"), std::string::npos);

  options.time_limit = 600.0;
  int calls = 0;
  options.on_iteration = [&calls](const IterationRecord& record) { return ++calls < 2; };
  IterationMonitor called(model, options, &summary);
  EXPECT_FALSE(called.Record(0, 1.0, 1.0));
  EXPECT_TRUE(called.Record(1, 1.0, 1.0));
  EXPECT_FALSE(summary.converged);
  EXPECT_EQ(summary.termination, "stopped by caller");
}

TEST(SolverRegistry, EveryRegisteredMethodIsInTheCatalogueAndBuilds) {
  ASSERT_FALSE(AllSolvers().empty());
  for (const auto& info : AllSolvers()) {
    EXPECT_NE(FindSolverMethod(info.name), nullptr) << info.name;
    EXPECT_NE(info.make(), nullptr) << info.name;
    EXPECT_EQ(FindSolver(info.name), &info);
  }
  EXPECT_EQ(FindSolver("no-such-method"), nullptr);
}

TEST(SolverRegistry, EveryMethodOfTheCatalogueHasCode) {
  for (const auto& method : SolverMethods()) {
    EXPECT_NE(FindSolver(method.name), nullptr) << method.name;
  }
  EXPECT_EQ(SolverMethods().size(), AllSolvers().size());
}

}  // namespace
}  // namespace drape
