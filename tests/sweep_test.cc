// `drape sweep`'s runs: each row is the same solve as `drape solve --set ...`; a restart keeps the
// finished tasks and solves only the rest; a changed variant is solved again; warm starts follow
// their chain whatever is restarted; a failed task is a row.
#include "src/sweep/sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "src/analysis/mesh_rule.h"
#include "src/cli/cli.h"
#include "src/output/json.h"
#include "src/output/version.h"
#include "src/scene/scene_loader.h"
#include "src/solvers/solver.h"
#include "tests/sweep_test_support.h"

namespace drape::testing {
namespace {

namespace fs = std::filesystem;

constexpr char kSmall[] = R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.B_warp: [0.06, 0.24]
  material.finite_volume.kes.W: [8.0, 16.0]
)";

// `log`: where the sweep's messages go (null: dropped).
SweepSummary SweepInto(const SweepSpec& spec, const std::string& out, std::optional<int> only = {},
                       std::ostream* log = nullptr) {
  SweepOptions options;
  options.out = out;
  options.only = only;
  options.threads = 1;
  options.plots = false;
  std::ostringstream dropped;
  return RunSweep(spec, options, log ? *log : dropped);
}

// The number after `"key": ` in a summary.json.
double JsonField(const std::string& json, const std::string& key) {
  const size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return NAN;
  return std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

double Number(const std::string& cell) { return std::strtod(cell.c_str(), nullptr); }

TEST(Sweep, RowsAreTheScenesSolvedOneByOneWithSet) {
  const std::string folder = SweepTempDir("one_by_one");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kSmall));
  const SweepSummary summary = SweepInto(spec, folder + "/out");
  EXPECT_EQ(summary.solved, 4);
  EXPECT_EQ(summary.rows, 4);
  const auto rows = ReadCsv(folder + "/out/sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  const auto& header = rows[0];
  for (int task = 0; task < 4; ++task) {
    SCOPED_TRACE(task);
    const auto& row = rows[task + 1];
    EXPECT_EQ(row[0], std::to_string(task));
    std::vector<std::string> args = {"solve", folder + "/base.yaml", "--out",
                                     folder + "/one/" + std::to_string(task)};
    for (const std::string& set : TaskOverrides(spec, task)) {
      args.insert(args.end(), {"--set", set});
    }
    std::ostringstream out, err;
    // 3: the coarse tester's fabric passes through the disc (the certificate says so below).
    const int status = RunCommand(args, out, err);
    ASSERT_TRUE(status == 0 || status == 3) << status << err.str();
    const std::string json = ReadText(folder + "/one/" + std::to_string(task) + "/summary.json");
    EXPECT_EQ(row[ColumnOf(header, "converged")], "true");
    EXPECT_EQ(Number(row[ColumnOf(header, "iterations")]), JsonField(json, "iterations"));
    EXPECT_EQ(Number(row[ColumnOf(header, "energy_J")]), JsonField(json, "total"));
    EXPECT_EQ(Number(row[ColumnOf(header, "relative_residual")]), JsonField(json, "relative"));
    EXPECT_EQ(Number(row[ColumnOf(header, "drape_coefficient")]), JsonField(json, "cusick"));
    EXPECT_EQ(Number(row[ColumnOf(header, "folds")]), JsonField(json, "folds"));
    // The drape coefficient's error: the levels' error bar, else the mesh rule's (this lattice).
    const double levels_bar = JsonField(json, "estimate");
    EXPECT_EQ(
        Number(row[ColumnOf(header, "drape_coefficient_error")]),
        std::isnan(levels_bar) ? JsonField(json, "expected_drape_coefficient_error") : levels_bar);
    EXPECT_GT(Number(row[ColumnOf(header, "drape_coefficient_error")]), 0.0);
    EXPECT_EQ(row[ColumnOf(header, "stable")], "true");
    const size_t state = json.find("\"state\": \"");
    ASSERT_NE(state, std::string::npos);
    const std::string state_text = json.substr(state + 10, json.find('"', state + 10) - state - 10);
    EXPECT_EQ(row[ColumnOf(header, "certificate")], state_text);
    EXPECT_EQ(status == 3, state_text != "stable minimum") << state_text;
    // The task's own folder: the same result files, and its row.
    const std::string task_folder = TaskFolder(folder + "/out", spec, task);
    EXPECT_EQ(JsonField(ReadText(task_folder + "/summary.json"), "total"),
              JsonField(json, "total"));
    const auto own = ReadCsv(task_folder + "/row.csv");
    ASSERT_EQ(own.size(), 2u);
    EXPECT_EQ(own[1], row);
  }
  // sweep.json beside sweep.csv: what the sweep is and how it was made.
  const std::string sweep_json = ReadText(folder + "/out/sweep.json");
  EXPECT_NE(sweep_json.find("\"rows\": 4"), std::string::npos) << sweep_json;
  EXPECT_NE(sweep_json.find("\"drape_version\": " + JsonString(DrapeVersion())), std::string::npos)
      << sweep_json;
  // No NaN or infinity anywhere.
  const std::string csv = ReadText(folder + "/out/sweep.csv");
  EXPECT_EQ(csv.find("nan"), std::string::npos);
  EXPECT_EQ(csv.find("inf"), std::string::npos);
}

TEST(Sweep, TasksAreLoadedFromTheBaseSceneReadOnce) {
  // LoadSweepFile reads the base scene once: the tasks solve with the file gone.
  const std::string folder = SweepTempDir("read_once");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kSmall));
  fs::remove(folder + "/base.yaml");
  EXPECT_EQ(SweepInto(spec, folder + "/out", 3).solved, 1);
  double weight = 0;
  for (const auto& given : TaskScene(spec, 3).material.finite_volume.measured) {
    if (given.key == "kes.W") weight = given.value;
  }
  EXPECT_EQ(weight, 16.0);  // task 3: the second value of each key
}

TEST(Sweep, ARestartSolvesOnlyTheUnfinishedTasks) {
  const std::string folder = SweepTempDir("restart");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kSmall));
  const std::string out = folder + "/out";
  // A "killed" sweep: only tasks 1 and 2 finished (run one by one, as a job array would).
  EXPECT_EQ(SweepInto(spec, out, 1).solved, 1);
  EXPECT_EQ(SweepInto(spec, out, 2).solved, 1);
  EXPECT_EQ(ReadCsv(out + "/sweep.csv").size(), 3u);  // header and the two finished rows
  const auto kept = fs::last_write_time(TaskFolder(out, spec, 1) + "/summary.json");
  const SweepSummary rest = SweepInto(spec, out);
  EXPECT_EQ(rest.solved, 2);
  EXPECT_EQ(rest.skipped, 2);
  EXPECT_EQ(rest.rows, 4);
  EXPECT_EQ(fs::last_write_time(TaskFolder(out, spec, 1) + "/summary.json"), kept);
  const auto restarted = ReadCsv(out + "/sweep.csv");
  // The same as one uninterrupted sweep, but for the times.
  const std::string fresh = folder + "/fresh";
  SweepInto(spec, fresh);
  EXPECT_EQ(WithoutTime(restarted), WithoutTime(ReadCsv(fresh + "/sweep.csv")));
  // A task folder removed (a kill while it was written): only that task again.
  fs::remove_all(TaskFolder(out, spec, 3));
  const SweepSummary again = SweepInto(spec, out);
  EXPECT_EQ(again.solved, 1);
  EXPECT_EQ(again.skipped, 3);
  EXPECT_EQ(SweepInto(spec, out).solved, 0);
}

// sweep.csv's drape_version: the drape that solved each row. A restart by another drape keeps
// the finished rows (the physics of a row is its variant's) with their own version, and says so.
TEST(Sweep, EachRowNamesTheDrapeThatSolvedItAndARestartSaysWhatItKept) {
  const std::string folder = SweepTempDir("versions");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kSmall));
  const std::string out = folder + "/out";
  SweepInto(spec, out, 1);
  const auto first = ReadCsv(out + "/sweep.csv");
  ASSERT_EQ(first.size(), 2u);
  const int version = ColumnOf(first[0], "drape_version");
  ASSERT_GE(version, 0);
  EXPECT_EQ(first[1][version], DrapeVersion());
  // As if an older drape had solved task 1.
  const std::string row_file = TaskFolder(out, spec, 1) + "/row.csv";
  std::string row = ReadText(row_file);
  const size_t at = row.rfind(DrapeVersion());
  ASSERT_NE(at, std::string::npos);
  row.replace(at, DrapeVersion().size(), "v0.1-older");
  WriteText(row_file, row);

  std::ostringstream log;
  const SweepSummary summary = SweepInto(spec, out, {}, &log);
  EXPECT_EQ(summary.solved, 3);
  EXPECT_EQ(summary.skipped, 1);
  EXPECT_NE(log.str().find("sweep: 1 finished task kept from drape v0.1-older (this is " +
                           DrapeVersion()),
            std::string::npos)
      << log.str();
  const auto rows = ReadCsv(out + "/sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  for (size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][version], rows[r][0] == "1" ? "v0.1-older" : DrapeVersion()) << r;
  }
}

TEST(Sweep, AChangedVariantIsSolvedAgain) {
  const std::string folder = SweepTempDir("changed");
  const std::string out = folder + "/out";
  SweepInto(LoadSweepFile(WriteSweep(folder, kSmall)), out);
  // W 16 -> 12: tasks 1 and 3 are other variants now; 0 and 2 are unchanged.
  std::string changed = kSmall;
  changed.replace(changed.find("16.0"), 4, "12.0");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, changed));
  const SweepSummary summary = SweepInto(spec, out);
  EXPECT_EQ(summary.solved, 2);
  EXPECT_EQ(summary.skipped, 2);
  const auto rows = ReadCsv(out + "/sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[2][ColumnOf(rows[0], "material.finite_volume.kes.W")], "12.0");
  // A changed base scene changes every task.
  std::string scene = ReadText(folder + "/base.yaml");
  WriteText(folder + "/base.yaml", scene + "\n# edited\n");
  EXPECT_EQ(SweepInto(LoadSweepFile(folder + "/sweep.yaml"), out, 0).solved, 1);
}

TEST(Sweep, WarmStartsFollowTheChainWhateverIsRestarted) {
  const std::string folder = SweepTempDir("warm");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.W: [8.0, 12.0, 16.0]
warm_start: {along: material.finite_volume.kes.W}
)"));
  ASSERT_EQ(spec.chains.size(), 1u);
  const std::string out = folder + "/out";
  // --only 1 runs the chain up to task 1 (task 0 first: its warm start).
  EXPECT_EQ(SweepInto(spec, out, 1).solved, 2);
  const SweepSummary rest = SweepInto(spec, out);
  EXPECT_EQ(rest.solved, 1);
  EXPECT_EQ(rest.skipped, 2);
  const auto rows = ReadCsv(out + "/sweep.csv");
  ASSERT_EQ(rows.size(), 4u);
  const int from = ColumnOf(rows[0], "warm_start_from");
  EXPECT_EQ(rows[1][from], "");
  EXPECT_EQ(rows[2][from], "0");
  EXPECT_EQ(rows[3][from], "1");
  // One uninterrupted run gives the same rows (task 2 started from task 1's saved state).
  SweepInto(spec, folder + "/fresh");
  EXPECT_EQ(WithoutTime(rows), WithoutTime(ReadCsv(folder + "/fresh/sweep.csv")));
  // A warm start is a start: the iterations differ from the cold solve of the same scene.
  const std::string cold = SweepTempDir("warm_cold");
  SweepInto(LoadSweepFile(WriteSweep(cold, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.W: [16.0]
)")),
            cold + "/out");
  const auto cold_rows = ReadCsv(cold + "/out/sweep.csv");
  EXPECT_NE(cold_rows[1][ColumnOf(cold_rows[0], "iterations")],
            rows[3][ColumnOf(rows[0], "iterations")]);
}

TEST(Sweep, AFailedOrUnconvergedTaskIsARowNotAnAbort) {
  const std::string folder = SweepTempDir("failed");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  solver.method: [puiseux-fixed-point, newton]
  solver.max_iterations: [3, 1000]
)"));
  const SweepSummary summary = SweepInto(spec, folder + "/out");
  EXPECT_EQ(summary.rows, 4);
  EXPECT_EQ(summary.converged, 1);
  const auto rows = ReadCsv(folder + "/out/sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  const auto& header = rows[0];
  const int converged = ColumnOf(header, "converged"), reason = ColumnOf(header, "stop_reason");
  // puiseux-fixed-point refuses a finite-volume fabric: a failed row, with empty results.
  EXPECT_EQ(rows[1][converged], "false");
  EXPECT_EQ(rows[1][reason].rfind("failed: ", 0), 0u) << rows[1][reason];
  EXPECT_EQ(rows[1][ColumnOf(header, "energy_J")], "");
  EXPECT_EQ(rows[1][ColumnOf(header, "drape_coefficient")], "");
  // newton stopped after 3 iterations: not converged, with its results.
  EXPECT_EQ(rows[3][converged], "false");
  EXPECT_EQ(rows[3][ColumnOf(header, "iterations")], "3");
  EXPECT_NE(rows[3][ColumnOf(header, "drape_coefficient")], "");
  EXPECT_EQ(rows[4][converged], "true");
  // The failures are finished rows: a rerun keeps them.
  EXPECT_EQ(SweepInto(spec, folder + "/out").solved, 0);
  const std::string csv = ReadText(folder + "/out/sweep.csv");
  EXPECT_EQ(csv.find("nan"), std::string::npos);
}

TEST(Sweep, LocalThreadsGiveTheSameRows) {
  const std::string folder = SweepTempDir("threads");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kSmall));
  SweepInto(spec, folder + "/one");
  SweepOptions options;
  options.out = folder + "/two";
  options.threads = 2;
  options.plots = false;
  std::ostringstream log;
  const SweepSummary summary = RunSweep(spec, options, log);
  EXPECT_EQ(summary.rows, 4);
  EXPECT_EQ(WithoutTime(ReadCsv(folder + "/one/sweep.csv")),
            WithoutTime(ReadCsv(folder + "/two/sweep.csv")));
}

TEST(Sweep, AnInterruptedSweepSavesNothingItDidNotFinish) {
  const std::string folder = SweepTempDir("interrupted");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kSmall));
  RequestInterrupt();  // as a SIGINT or SIGTERM would: the solve stops at its next iteration
  const SweepSummary stopped = SweepInto(spec, folder + "/out");
  ClearInterrupt();
  EXPECT_TRUE(stopped.interrupted);
  EXPECT_EQ(stopped.solved, 0);
  EXPECT_EQ(stopped.rows, 0);
  EXPECT_EQ(ReadCsv(folder + "/out/sweep.csv").size(), 1u);  // the header alone
  const SweepSummary rest = SweepInto(spec, folder + "/out");
  EXPECT_FALSE(rest.interrupted);
  EXPECT_EQ(rest.solved, 4);
  EXPECT_EQ(rest.skipped, 0);
}

// A sweep whose tasks' meshes are coarser than their fabrics' mesh rule says so once, before its
// first solve, naming them and giving `drape solve`'s warning for the one furthest off; with
// --only, for that task alone. The interrupt keeps the tasks unsolved. On the shipped cotton's
// 3 mm lattice, B_weft 0.16 (the warp's 0.12 the limper) needs 3.4 mm or finer, 0.04 needs 2.4 mm.
TEST(Sweep, WarnsOnceOfTheTasksWhoseMeshIsCoarserThanTheirFabricNeeds) {
  const std::string folder = SweepTempDir("coarse_mesh");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, R"(scene: base.yaml
grid:
  material.finite_volume.kes.B_weft: [0.16, 0.04]
)"));
  const auto warnings = [&](std::optional<int> only, const std::string& out) {
    std::ostringstream log;
    RequestInterrupt();
    SweepInto(spec, folder + out, only, &log);
    ClearInterrupt();
    std::vector<std::string> found;
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);) {
      if (line.find("warning") != std::string::npos) found.push_back(line);
    }
    return found;
  };
  const Scene limp = LoadScene(spec.scene_file, TaskOverrides(spec, 1));
  const std::optional<MeshAdvice> advice = AdviseMesh(limp, BuildModel(limp));
  ASSERT_TRUE(advice && advice->coarse);
  const std::vector<std::string> all = warnings(std::nullopt, "/all");
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0],
            "drape sweep: warning: 1 of 2 tasks on a mesh coarser than their fabric's mesh rule "
            "(task 1; each row's drape_coefficient_error includes the rule's error); the furthest "
            "off, task 1: " +
                CoarseMeshWarning(*advice));
  EXPECT_TRUE(warnings(0, "/only0").empty());
  const std::vector<std::string> only = warnings(1, "/only1");
  ASSERT_EQ(only.size(), 1u);
  EXPECT_EQ(only[0].rfind("drape sweep: warning: 1 of 1 task on a mesh coarser", 0), 0u) << only[0];
}

}  // namespace
}  // namespace drape::testing
