#include "src/parallel/task_farm.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace drape {
namespace {

TEST(TaskFarm, RunsEveryTaskOnceAndCollectsItsResult) {
  const std::vector<int> tasks = {4, 0, 7, 2};
  std::map<int, int> runs;
  std::map<int, std::string> collected;
  const auto summary = RunTaskFarm(
      tasks,
      [&](int task) {
        ++runs[task];
        return "result " + std::to_string(task * task);
      },
      [&](int task, const std::string& result) { collected[task] = result; }, TaskFarmOptions{});
  EXPECT_EQ(summary.tasks, 4);
  EXPECT_TRUE(summary.coordinator);
  ASSERT_EQ(collected.size(), tasks.size());
  for (const int task : tasks) {
    EXPECT_EQ(collected[task], "result " + std::to_string(task * task));
  }
}

}  // namespace
}  // namespace drape
