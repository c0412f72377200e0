#include "src/parallel/task_farm.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "src/parallel/process_group.h"

namespace drape {
namespace {

// What a farm's run did: the results collected, how often each task ran, on which threads, and
// whether `collect` was ever called from two threads at once or from another thread than the
// caller's.
struct FarmRecord {
  std::map<int, std::string> collected;
  std::map<int, int> collections, runs;
  std::set<std::thread::id> run_threads;
  bool collect_overlapped = false, collect_off_caller = false;
  TaskFarmSummary summary;
};

std::string ResultOf(int task) { return "result " + std::to_string(task * task + 3); }

FarmRecord Farm(const std::vector<int>& tasks, int threads,
                const std::function<std::string(int)>& run = ResultOf) {
  FarmRecord record;
  std::mutex mutex;
  std::atomic<int> collecting{0};
  const auto caller = std::this_thread::get_id();
  record.summary = RunTaskFarm(
      tasks,
      [&](int task) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          ++record.runs[task];
          record.run_threads.insert(std::this_thread::get_id());
        }
        return run(task);
      },
      [&](int task, const std::string& result) {
        if (collecting.fetch_add(1) != 0) record.collect_overlapped = true;
        if (std::this_thread::get_id() != caller) record.collect_off_caller = true;
        record.collected[task] = result;
        ++record.collections[task];
        collecting.fetch_sub(1);
      },
      TaskFarmOptions{threads});
  return record;
}

std::vector<int> SomeTasks() { return {4, 0, 7, 2, 11, 5, 9, 1, 3, 8, 6}; }

class TaskFarmThreads : public ::testing::TestWithParam<int> {};

TEST_P(TaskFarmThreads, RunsEveryTaskOnceAndCollectsItsResultOnTheCallingThread) {
  const std::vector<int> tasks = SomeTasks();
  const FarmRecord record = Farm(tasks, GetParam());
  EXPECT_EQ(record.summary.tasks, static_cast<int>(tasks.size()));
  EXPECT_TRUE(record.summary.coordinator);
  EXPECT_EQ(record.summary.workers, GetParam());
  ASSERT_EQ(record.collected.size(), tasks.size());
  for (const int task : tasks) {
    EXPECT_EQ(record.runs.at(task), 1) << task;
    EXPECT_EQ(record.collections.at(task), 1) << task;
    EXPECT_EQ(record.collected.at(task), ResultOf(task));
  }
  EXPECT_FALSE(record.collect_overlapped);
  EXPECT_FALSE(record.collect_off_caller);
  EXPECT_LE(static_cast<int>(record.run_threads.size()), GetParam());
}

TEST_P(TaskFarmThreads, ResultsDoNotDependOnTheNumberOfThreads) {
  // Each task's result is a computation of its own number (a sum long enough that the threads
  // overlap); the collected results must be those of the serial farm.
  const auto work = [](int task) {
    double sum = 0.0;
    for (int k = 1; k <= 20000; ++k) sum += 1.0 / (k + task);
    return std::to_string(task) + ":" + std::to_string(sum);
  };
  const FarmRecord serial = Farm(SomeTasks(), 1, work);
  const FarmRecord parallel = Farm(SomeTasks(), GetParam(), work);
  EXPECT_EQ(parallel.collected, serial.collected);
}

TEST_P(TaskFarmThreads, AThrowingTaskIsReportedAsAFarmErrorThatNamesIt) {
  try {
    Farm(SomeTasks(), GetParam(), [&](int task) {
      if (task == 2) throw std::runtime_error("broken task");
      return ResultOf(task);
    });
    ADD_FAILURE() << "no TaskFarmError";
  } catch (const TaskFarmError& error) {
    EXPECT_NE(std::string(error.what()).find("task 2 failed: broken task"), std::string::npos)
        << error.what();
  }
}

TEST_P(TaskFarmThreads, AnExceptionFromCollectIsReportedAsAFarmError) {
  EXPECT_THROW(RunTaskFarm(
                   SomeTasks(), ResultOf,
                   [](int task, const std::string&) {
                     if (task == 7) throw std::runtime_error("disk full");
                   },
                   TaskFarmOptions{GetParam()}),
               TaskFarmError);
}

INSTANTIATE_TEST_SUITE_P(Threads, TaskFarmThreads, ::testing::Values(1, 2, 5));

TEST(TaskFarm, TasksAfterAFailureAreNotStartedAndNoTaskRunsTwice) {
  // Serially the tasks run in their list's order: those after the failing one never start.
  std::map<int, int> runs;
  std::map<int, std::string> collected;
  EXPECT_THROW(RunTaskFarm(
                   {0, 1, 2, 3, 4},
                   [&](int task) {
                     ++runs[task];
                     if (task == 2) throw std::runtime_error("broken task");
                     return ResultOf(task);
                   },
                   [&](int task, const std::string& result) { collected[task] = result; },
                   TaskFarmOptions{1}),
               TaskFarmError);
  EXPECT_EQ(runs, (std::map<int, int>{{0, 1}, {1, 1}, {2, 1}}));
  EXPECT_EQ(collected.size(), 2u);
}

TEST(TaskFarm, TwoThreadsRunTwoTasksAtOnce) {
  // Each task waits (up to 60 s) for the other to start: with two threads both are running at
  // once; a farm that ran them one after another would record a lone task.
  std::mutex mutex;
  std::condition_variable started;
  int running = 0;
  bool saw_both = true;
  RunTaskFarm(
      {0, 1},
      [&](int task) {
        std::unique_lock<std::mutex> lock(mutex);
        ++running;
        started.notify_all();
        if (!started.wait_for(lock, std::chrono::seconds(60), [&] { return running == 2; })) {
          saw_both = false;
        }
        return ResultOf(task);
      },
      [](int, const std::string&) {}, TaskFarmOptions{2});
  EXPECT_TRUE(saw_both);
}

TEST(TaskFarm, AnEmptyListRunsNothing) {
  const FarmRecord record = Farm({}, 3);
  EXPECT_EQ(record.summary.tasks, 0);
  EXPECT_TRUE(record.collected.empty());
}

TEST(TaskFarm, ZeroThreadsMeansTheMachinesCores) {
  EXPECT_GE(EffectiveLocalThreads(0), 1);
  EXPECT_EQ(EffectiveLocalThreads(3), 3);
}

TEST(TaskFarm, AProcessStartedAloneNeverStartsMpi) {
  // The test binary is not started by mpirun: the farm uses threads and MPI stays untouched
  // (MPI_Init is slow and can fail in containers; LeakSanitizer reports Open MPI's allocations).
  ASSERT_FALSE(StartedByMpiLauncher());
  Farm(SomeTasks(), 2);
  EXPECT_FALSE(Processes().IsDistributed());
  EXPECT_TRUE(Processes().IsCoordinator());
  EXPECT_FALSE(MpiStarted());
}

TEST(TaskFarm, ALauncherIsRecognisedByItsEnvironment) {
  Processes();  // decided once, before the variable is set below
  ASSERT_FALSE(StartedByMpiLauncher());
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    ::setenv(variable, "2", 1);
    EXPECT_TRUE(StartedByMpiLauncher()) << variable;
    ::unsetenv(variable);
  }
  EXPECT_FALSE(StartedByMpiLauncher());
}

}  // namespace
}  // namespace drape
