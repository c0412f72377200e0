// `drape sweep` across MPI ranks: `mpirun -np 2` and `-np 3` (oversubscribed on 2 cores) write the
// same sweep.csv as the process alone, every column but the solver's time, and every task once.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "src/sweep/sweep.h"
#include "tests/mpi_run.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using testing::MpiRun;
using testing::ProgramOutcome;
using testing::RunProgram;

// 6 tasks on the coarse drape tester (a fraction of a second each): a grid of 3 × 2, and a
// warm-start chain along W (two chains of 3).
constexpr char kSweep[] = R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.B_warp: [0.06, 0.24]
  material.finite_volume.kes.W: [8.0, 12.0, 16.0]
)";

std::vector<std::vector<std::string>> Rows(const fs::path& csv) {
  return testing::CsvRowsWithout(csv, "time_s");
}

class SweepMpi : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::MpiLauncherAvailable()) {
      GTEST_SKIP() << "drape was built without MPI (mpi-default-dev not found): no MPI test";
    }
    // Made here, in the test process: every rank of mpirun works in it (cd in Sweep).
    scratch_.emplace("sweep_mpi");
    folder_ = scratch_->path();
    fs::copy_file(fs::path(drape_tests::kSourceDir) / "configs/fv/drape_tester_cotton_30.yaml",
                  folder_ / "base.yaml");
  }
  void TearDown() override { scratch_.reset(); }

  // `drape sweep` of `text` into out_<label>, under `mpirun -np ranks` (0: alone, one thread).
  ProgramOutcome Sweep(const std::string& text, int ranks, const std::string& label) const {
    std::ofstream(folder_ / "sweep.yaml") << text;
    const std::string command = std::string(drape_tests::kDrapeBinary) +
                                " sweep sweep.yaml --no-plots -o out_" + label +
                                (ranks == 0 ? " --threads 1" : "");
    return RunProgram(
        "cd '" + folder_.string() + "' && " + (ranks == 0 ? command : MpiRun(ranks) + command),
        folder_);
  }

  void ExpectSameRowsOnEveryRankCount(const std::string& text) const {
    const ProgramOutcome alone = Sweep(text, 0, "alone");
    ASSERT_EQ(alone.exit_status, 0) << alone.err;
    const auto expected = Rows(folder_ / "out_alone/sweep.csv");
    ASSERT_EQ(expected.size(), 7u);
    for (const int ranks : {2, 3}) {
      SCOPED_TRACE("mpirun -np " + std::to_string(ranks));
      const std::string label = "np" + std::to_string(ranks);
      const ProgramOutcome run = Sweep(text, ranks, label);
      ASSERT_EQ(run.exit_status, 0) << run.err;
      EXPECT_NE(run.out.find("6 tasks; 6 solved"), std::string::npos) << run.out;
      EXPECT_EQ(Rows(folder_ / ("out_" + label) / "sweep.csv"), expected);
      // One result line (rank 0's) and one progress line per task.
      size_t lines = 0;
      for (size_t at = run.err.find("sweep: task "); at != std::string::npos;
           at = run.err.find("sweep: task ", at + 1)) {
        ++lines;
      }
      EXPECT_EQ(lines, 6u) << run.err;
    }
  }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path folder_;
};

TEST_F(SweepMpi, TheSameSweepCsvOnOneTwoAndThreeRanks) { ExpectSameRowsOnEveryRankCount(kSweep); }

TEST_F(SweepMpi, WarmStartChainsGiveTheSameRowsOnEveryRankCount) {
  ExpectSameRowsOnEveryRankCount(std::string(kSweep) +
                                 "warm_start: {along: material.finite_volume.kes.W}\n");
}

}  // namespace
}  // namespace drape
