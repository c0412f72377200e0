#include "src/parallel/shared_work.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/parallel/task_farm.h"

namespace drape {
namespace {

// In a process alone (the test binary), every unit is computed once, on some thread, and the
// results come back in unit order, whatever the number of threads. (Under MPI: FitMpi.*.)
class SharedWorkThreads : public ::testing::TestWithParam<int> {};

TEST_P(SharedWorkThreads, ComputesEveryUnitOnceAndReturnsTheResultsInUnitOrder) {
  std::mutex mutex;
  std::map<int, int> computed;
  const std::vector<std::string> results = ComputeOnOwners(
      {3, 1, 4, 1, 5, 9, 2},
      [&](int unit) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          ++computed[unit];
        }
        return std::string(static_cast<size_t>(unit), 'x') + std::to_string(unit);
      },
      GetParam());
  ASSERT_EQ(results.size(), 7u);
  for (int unit = 0; unit < 7; ++unit) {
    EXPECT_EQ(computed[unit], 1) << unit;
    EXPECT_EQ(results[unit], std::string(static_cast<size_t>(unit), 'x') + std::to_string(unit));
  }
}

TEST_P(SharedWorkThreads, TheLowestFailingUnitsExceptionComesOutAsItWas) {
  // Alone, the exception keeps its type (the command reports an input error or out of memory as
  // such); units 1 and 3 fail, unit 1's comes out whatever the threads did first.
  try {
    ComputeOnOwners(
        {1, 1, 1, 5},
        [](int unit) {
          if (unit == 1) throw std::invalid_argument("unit 1");
          if (unit == 3) throw std::out_of_range("unit 3");
          return std::string("fine");
        },
        GetParam());
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "unit 1");
  }
}

INSTANTIATE_TEST_SUITE_P(Threads, SharedWorkThreads, ::testing::Values(1, 2, 4));

TEST(SharedWork, NoUnitsGiveNoResults) {
  const std::vector<double> no_costs;
  EXPECT_TRUE(ComputeOnOwners(
                  no_costs, [](int) { return std::string("x"); }, 2)
                  .empty());
}

TEST(SharedWork, AloneAFlagIsItsOwnAgreement) {
  EXPECT_TRUE(AnyProcess(true));
  EXPECT_FALSE(AnyProcess(false));
}

TEST(SharedWork, OwnersAreBalancedByCostTheCostliestFirst) {
  const std::vector<double> costs = {3, 1, 4, 1, 5, 9, 2};
  EXPECT_EQ(CostliestFirst(costs), (std::vector<int>{5, 4, 2, 0, 6, 1, 3}));
  const std::vector<int> owners = BalancedOwners(costs, 2);
  // Each unit, costliest first, goes to the less loaded rank (the lower one on a tie):
  std::vector<double> load(2, 0.0);
  for (const int unit : CostliestFirst(costs)) {
    const int lighter = load[1] < load[0] ? 1 : 0;
    EXPECT_EQ(owners[unit], lighter) << "unit " << unit;
    load[owners[unit]] += costs[unit];
  }
  EXPECT_LE(std::abs(load[0] - load[1]), 1.0);
  // Equal costs: dealt in turn, and one rank takes everything.
  EXPECT_EQ(BalancedOwners({1, 1, 1, 1, 1}, 3), (std::vector<int>{0, 1, 2, 0, 1}));
  EXPECT_EQ(BalancedOwners({7, 2, 5}, 1), (std::vector<int>{0, 0, 0}));
}

}  // namespace
}  // namespace drape
