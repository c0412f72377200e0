// `drape fabrics` across MPI ranks: `mpirun -np 2` writes the same fabrics.csv as the process
// alone, every column but the solve's time.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

constexpr char kTable[] =
    "name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft,measured_dc\n"
    "a,12,0.12,0.08,0.9,4,7,0.70\n"
    "b,8,0.02,0.02,0.4,4,7,0.40\n"
    "c,10,0.06,0.05,0.6,4,7,0.55\n";

std::vector<std::vector<std::string>> Rows(const fs::path& csv) {
  return testing::CsvRowsWithout(csv, "time_s [s]");
}

TEST(FabricsMpi, RanksWriteTheRowsOfTheProcessAlone) {
  if (!testing::MpiLauncherAvailable()) {
    GTEST_SKIP() << "drape was built without MPI (mpi-default-dev not found): no MPI test";
  }
  testing::ScratchFolder scratch("fabrics_mpi");
  const fs::path& folder = scratch.path();
  std::ofstream(folder / "fabrics.csv") << kTable;
  auto run = [&](int ranks, const std::string& label) {
    const std::string command = std::string(drape_tests::kDrapeBinary) +
                                " fabrics fabrics.csv --set mesh.spacing=0.05 -o out_" + label +
                                (ranks == 0 ? " --threads 1" : "");
    return RunProgram(
        "cd '" + folder.string() + "' && " + (ranks == 0 ? command : MpiRun(ranks) + command),
        folder);
  };
  const ProgramOutcome alone = run(0, "alone");
  ASSERT_EQ(alone.exit_status, 0) << alone.err;
  const ProgramOutcome ranks = run(2, "ranks");
  ASSERT_EQ(ranks.exit_status, 0) << ranks.err;
  const auto expected = Rows(folder / "out_alone/fabrics.csv");
  ASSERT_EQ(expected.size(), 4u);
  EXPECT_EQ(Rows(folder / "out_ranks/fabrics.csv"), expected);
}

}  // namespace
}  // namespace drape
