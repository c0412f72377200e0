// A parallel `drape fit` gives the serial fit: the same fitted values, the same evaluations and
// iterations, the same files (fit.json but its wall time, history.csv but its time column,
// sensitivity.csv, fit.png), with `--threads 3`, `mpirun -np 2` and `mpirun -np 3`
// (oversubscribed on 2 cores). The fit: one spring stiffness from the node positions of three
// hammocks of different sizes (three equilibria, so that every rank of -np 3 owns one), measured
// with seeded noise. The first hammock, which fit.png draws, has the fewest nodes, so that another
// rank than 0 owns it and rank 0 draws it from the positions it received.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "tests/fit_test_support.h"
#include "tests/mpi_run.h"
#include "tests/test_paths.h"

namespace drape::testing {
namespace {

namespace fs = std::filesystem;

// The hammock scene with its size and node counts replaced (as in the scene: "[0.3, 0.3]").
void WriteHammock(const std::string& size, const std::string& nodes, const std::string& path) {
  std::ifstream in(SourcePath("configs/fit/sheet_springs.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("size: [0.5, 0.5]"), 16, "size: " + size);
  text.replace(text.find("nodes: [9, 9]"), 13, "nodes: " + nodes);
  WriteTextFile(path, text);
}

// Three hammocks (0.5, 0.4, 0.3 m; 7 × 7, 9 × 9, 8 × 8 nodes) solved at k = 35 N/m, their positions
// with 0.5 mm noise, and the fit file; returns its path.
std::string ThreeHammocksFit(const std::string& folder) {
  const char* sizes[] = {"[0.5, 0.5]", "[0.4, 0.4]", "[0.3, 0.3]"};
  const char* nodes[] = {"[7, 7]", "[9, 9]", "[8, 8]"};
  std::string fit =
      "parameters:\n  - {key: material.springs.structural, initial: 20, bounds: [1, 1000], "
      "log: true}\nmeasurements:\n";
  for (int s = 0; s < 3; ++s) {
    const std::string name = "hammock" + std::to_string(s);
    WriteHammock(sizes[s], nodes[s], folder + "/" + name + ".yaml");
    Scene scene = LoadScene(folder + "/" + name + ".yaml", {"material.springs.structural=35"});
    scene.solver.tolerance = 1e-10;
    Model model = BuildModel(scene);
    RunSolve(scene, model, "newton");
    WriteNodePositions(model, 0.5e-3, 10 + s, folder + "/" + name + ".csv");
    if (s == 0) {
      fit = "scene: " + name + ".yaml\n" + fit + "  - positions: {file: " + name + ".csv}\n";
    } else {
      fit += "  - scene: " + name + ".yaml\n    measurements:\n      - positions: {file: " + name +
             ".csv}\n";
    }
  }
  WriteTextFile(folder + "/fit.yaml", fit);
  return folder + "/fit.yaml";
}

// The output files with what may differ between runs left out: fit.json's wall time and command
// line, history.csv's time column (report.md has the time in its text, and repeats fit.json).
std::string ComparableOutputs(const fs::path& folder) {
  std::string text;
  std::istringstream json(ReadText(folder / "fit.json"));
  for (std::string line; std::getline(json, line);) {
    if (line.find("\"wall_time_s\"") == std::string::npos &&
        line.find("\"command_line\"") == std::string::npos) {
      text += line + "\n";
    }
  }
  std::istringstream history(ReadText(folder / "history.csv"));
  for (std::string line; std::getline(history, line);) {
    const size_t first = line.find(','), second = line.find(',', first + 1);
    text += line.substr(0, first) + line.substr(second) + "\n";
  }
  return text + ReadText(folder / "sensitivity.csv") + ReadText(folder / "fit.png");
}

class FitMpi : public ::testing::TestWithParam<std::string> {};

TEST_P(FitMpi, AParallelFitGivesTheSerialFit) {
  if (!MpiLauncherAvailable()) {
    GTEST_SKIP() << "drape was built without MPI (mpi-default-dev not found): no MPI test";
  }
  const std::string folder = FitTempDir("mpi_" + GetParam());
  const std::string fit = ThreeHammocksFit(folder);
  const std::string drape =
      std::string(drape_tests::kDrapeBinary) + " fit " + fit + " --method " + GetParam();
  const auto run = [&](const std::string& launcher, const std::string& name,
                       const std::string& threads) {
    const ProgramOutcome outcome = RunProgram(
        launcher + drape + " --threads " + threads + " --out " + folder + "/" + name, folder);
    EXPECT_EQ(outcome.exit_status, 0) << name << ": " << outcome.err;
    return outcome;
  };
  const ProgramOutcome serial = run("", "serial", "1");
  const std::string expected = ComparableOutputs(folder + "/serial");
  ASSERT_NE(expected.find("\"converged\": true"), std::string::npos) << expected;
  run("", "threads", "3");
  EXPECT_EQ(ComparableOutputs(folder + "/threads"), expected) << "--threads 3";
  for (const int ranks : {2, 3}) {
    const std::string name = "np" + std::to_string(ranks);
    const ProgramOutcome parallel = run(MpiRun(ranks), name, "1");
    EXPECT_EQ(ComparableOutputs(folder + "/" + name), expected) << "mpirun -np " << ranks;
    // One result line, from the coordinator only.
    std::string line = serial.out;
    line.replace(line.rfind("/serial"), 7, "/" + name);
    EXPECT_EQ(parallel.out, line) << "mpirun -np " << ranks;
  }
  fs::remove_all(folder);
}

INSTANTIATE_TEST_SUITE_P(Methods, FitMpi, ::testing::Values("bobyqa", "implicit-lm"));

}  // namespace
}  // namespace drape::testing
