// The task farm across MPI ranks: `mpirun -np 2` and `-np 3` (oversubscribed on 2 cores) run the
// probe program tests/task_farm_mpi_probe.cc, whose results must equal the probe's run alone.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "tests/mpi_run.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using testing::MpiRun;
using testing::ProgramOutcome;
using testing::RunProgram;

constexpr int kTasks = 12;

struct ProbeRun {
  ProgramOutcome outcome;
  std::map<int, std::string> values;  // task → value (as printed)
  std::map<int, int> collected;       // task → times collected
  std::set<int> working_ranks;
  int coordinators = 0, workers = 0, mpi_started = 0;
};

ProbeRun ParseProbe(const ProgramOutcome& outcome) {
  ProbeRun run;
  run.outcome = outcome;
  std::istringstream lines(outcome.out);
  std::string word;
  while (lines >> word) {
    if (word == "task") {
      int task = 0, rank = 0;
      std::string value_word, value, rank_word;
      lines >> task >> value_word >> value >> rank_word >> rank;
      run.values[task] = value;
      ++run.collected[task];
      run.working_ranks.insert(rank);
    } else if (word == "summary") {
      std::string key;
      int rank = 0, coordinator = 0, tasks = 0, workers = 0, mpi = 0;
      lines >> key >> rank >> key >> coordinator >> key >> tasks >> key >> workers >> key >> mpi;
      (coordinator ? run.coordinators : run.workers) += 1;
      run.mpi_started += mpi;
    }
  }
  return run;
}

class TaskFarmMpi : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::MpiLauncherAvailable()) {
      GTEST_SKIP() << "drape was built without MPI (mpi-default-dev not found): no MPI test";
    }
    scratch_.emplace("task_farm_mpi");  // in the test process; the ranks never see it
    folder_ = scratch_->path();
  }
  void TearDown() override { scratch_.reset(); }

  ProbeRun Probe(int ranks, const std::string& arguments = "") const {
    const std::string probe =
        std::string(DRAPE_MPI_PROBE) + " " + std::to_string(kTasks) + " " + arguments;
    return ParseProbe(RunProgram(ranks == 0 ? probe : MpiRun(ranks) + probe, folder_));
  }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path folder_;
};

TEST_F(TaskFarmMpi, EveryTaskRunsOnceAndTheResultsEqualTheProcessAlone) {
  const ProbeRun alone = Probe(0);
  ASSERT_EQ(alone.outcome.exit_status, 0) << alone.outcome.err;
  ASSERT_EQ(alone.values.size(), static_cast<size_t>(kTasks));
  EXPECT_EQ(alone.mpi_started, 0) << "a process started alone must not start MPI";
  for (const int ranks : {2, 3}) {
    SCOPED_TRACE("mpirun -np " + std::to_string(ranks));
    const ProbeRun run = Probe(ranks);
    ASSERT_EQ(run.outcome.exit_status, 0) << run.outcome.err;
    EXPECT_EQ(run.values, alone.values);
    for (const auto& [task, times] : run.collected) EXPECT_EQ(times, 1) << "task " << task;
    EXPECT_EQ(run.coordinators, 1);
    EXPECT_EQ(run.workers, ranks - 1);
    EXPECT_EQ(run.mpi_started, ranks) << "every rank initialised MPI";
    // Rank 0 hands every other rank a task before it starts its own.
    for (int rank = 1; rank < ranks; ++rank) EXPECT_EQ(run.working_ranks.count(rank), 1u);
  }
}

TEST_F(TaskFarmMpi, AFailingTaskIsReportedOnTheCoordinatorAndTheJobEnds) {
  const ProbeRun run = Probe(2, "--fail 5");
  EXPECT_NE(run.outcome.exit_status, 124) << "the job hung";
  // The coordinator's error aborts the job as drape's commands do (AbortJobAfterError(3)).
  EXPECT_EQ(run.outcome.exit_status, 3) << run.outcome.err;
  EXPECT_NE(run.outcome.err.find("task 5 failed"), std::string::npos) << run.outcome.err;
  EXPECT_EQ(run.values.count(5), 0u);
  EXPECT_EQ(run.workers, 1) << "the worker rank returned from the farm normally";
}

TEST_F(TaskFarmMpi, ARankWhoseCommandFailsAbortsTheJobInsteadOfLeavingTheOthersWaiting) {
  // Rank 1 throws before the farm while rank 0 waits for its results: AbortJobAfterError ends
  // the job with its status (3) instead of the hang that a plain return would leave.
  const ProbeRun run = Probe(2, "--throw-on-rank 1");
  EXPECT_NE(run.outcome.exit_status, 124) << "the job hung";
  EXPECT_EQ(run.outcome.exit_status, 3) << run.outcome.err;
  EXPECT_NE(run.outcome.err.find("the probe's rank fails"), std::string::npos) << run.outcome.err;
}

TEST_F(TaskFarmMpi, ARankThatDiesEndsTheJobWithAnErrorInsteadOfAHang) {
  const ProbeRun run = Probe(3, "--die 4");
  EXPECT_NE(run.outcome.exit_status, 124) << "the job hung";
  // mpirun ends the job and passes on the dying process's status (the probe's _Exit(7)).
  EXPECT_EQ(run.outcome.exit_status, 7) << run.outcome.err;
  EXPECT_EQ(run.values.count(4), 0u);
}

}  // namespace
}  // namespace drape
