#include "src/parallel/shared_work.h"

#include <gtest/gtest.h>

#include <map>
#include <mutex>
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
      7,
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

TEST_P(SharedWorkThreads, AUnitThatThrowsIsAFarmErrorNamingIt) {
  try {
    ComputeOnOwners(
        4,
        [](int unit) {
          if (unit == 2) throw std::runtime_error("no equilibrium");
          return std::string("fine");
        },
        GetParam());
    ADD_FAILURE() << "no TaskFarmError";
  } catch (const TaskFarmError& error) {
    EXPECT_NE(std::string(error.what()).find("task 2 failed: no equilibrium"), std::string::npos)
        << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Threads, SharedWorkThreads, ::testing::Values(1, 2, 4));

TEST(SharedWork, NoUnitsGiveNoResults) {
  EXPECT_TRUE(ComputeOnOwners(
                  0, [](int) { return std::string("x"); }, 2)
                  .empty());
}

TEST(SharedWork, AloneEveryUnitIsOwnedHereAndAFlagIsItsOwnAgreement) {
  EXPECT_EQ(OwnerRank(5, Processes()), 0);
  EXPECT_TRUE(AnyProcess(true));
  EXPECT_FALSE(AnyProcess(false));
}

TEST(SharedWork, UnitsAreDealtToRanksInTurn) {
  ProcessGroup group;
  group.size = 3;
  EXPECT_EQ(OwnerRank(0, group), 0);
  EXPECT_EQ(OwnerRank(4, group), 1);
  EXPECT_EQ(OwnerRank(8, group), 2);
}

}  // namespace
}  // namespace drape
