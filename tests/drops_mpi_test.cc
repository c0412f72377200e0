// `drape solve --drops` across MPI ranks: `mpirun -np 2` writes the same drops.csv as the process
// alone on one thread, and the same statistics line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/mpi_run.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using testing::MpiRun;
using testing::ProgramOutcome;
using testing::ReadText;
using testing::RunProgram;

constexpr char kScene[] = R"(name: drops
drape_test: {specimen_diameter: 0.24, drops: 4, seed: 3}
mesh: {spacing: 0.02}
material:
  model: finite_volume
  density: 0.08
  finite_volume: {E_warp: 9000, E_weft: 8000, G: 20, D_warp: 2.6e-6, D_weft: 1.7e-6}
output: {write: [summary]}
)";

TEST(DropsMpi, TheSameDropsCsvAloneAndOnTwoRanks) {
  if (!testing::MpiLauncherAvailable()) {
    GTEST_SKIP() << "drape was built without MPI (mpi-default-dev not found): no MPI test";
  }
  // Made here, in the test process: every rank of mpirun works in it (cd below).
  const testing::ScratchFolder scratch("drops_mpi");
  const fs::path& folder = scratch.path();
  std::ofstream(folder / "scene.yaml") << kScene;
  const std::string drape = std::string(drape_tests::kDrapeBinary) + " solve scene.yaml --out ";
  const std::string cd = "cd '" + folder.string() + "' && ";
  const ProgramOutcome alone = RunProgram(cd + drape + "alone --threads 1", folder);
  ASSERT_EQ(alone.exit_status, 0) << alone.err;
  const ProgramOutcome ranks = RunProgram(cd + MpiRun(2) + drape + "np2", folder);
  ASSERT_EQ(ranks.exit_status, 0) << ranks.err;
  const std::string expected = ReadText(folder / "alone/drops.csv");
  EXPECT_NE(expected.find("\n4,"), std::string::npos) << expected;
  EXPECT_EQ(ReadText(folder / "np2/drops.csv"), expected);
  // One statistics line, rank 0's, the same as alone.
  EXPECT_EQ(ranks.out.substr(0, ranks.out.find("; results in")),
            alone.out.substr(0, alone.out.find("; results in")));
  EXPECT_EQ(ranks.out.find("4 drops"), ranks.out.rfind("4 drops")) << ranks.out;
}

}  // namespace
}  // namespace drape
