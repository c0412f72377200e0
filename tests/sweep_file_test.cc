// The sweep file: grid, zip, set, repeat, warm-start chains and samples read into tasks; every
// mistake reported as file:line:column: key: what, before anything is solved.
#include "src/sweep/sweep_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "src/scene/output_kinds.h"
#include "tests/sweep_test_support.h"

namespace drape::testing {
namespace {

constexpr char kGridZip[] = R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.W: [8, 12, 16]
  loads.gravity: [[0, 0, -9.81], [0, 0, -9.0]]
zip:
  material.finite_volume.kes.B_warp: [0.06, 0.12]
  material.finite_volume.kes.B_weft: [0.04, 0.08]
repeat: 2
warm_start: {along: material.finite_volume.kes.W}
keep: [summary, shape]
)";

TEST(SweepFile, GridTimesZipTimesRepeatLastAxisFastest) {
  const std::string folder = SweepTempDir("grid_zip");
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, kGridZip));
  EXPECT_EQ(spec.design, "grid+zip");
  ASSERT_EQ(spec.keys.size(), 4u);
  EXPECT_EQ(spec.axis_sizes, (std::vector<int>{3, 2, 2}));
  ASSERT_EQ(spec.tasks.size(), 3u * 2u * 2u * 2u);
  EXPECT_EQ(spec.keys[2].axis, spec.keys[3].axis);  // a zip is one axis
  // Task 0 and 1: the same variant, repeats 0 and 1; then the zip (last axis) moves.
  EXPECT_EQ(spec.tasks[0].repeat, 0);
  EXPECT_EQ(spec.tasks[1].repeat, 1);
  EXPECT_EQ(spec.tasks[2].values[2].text, "0.12");
  EXPECT_EQ(spec.tasks[2].values[3].text, "0.08");
  EXPECT_EQ(spec.tasks[4].values[1].text, "[0, 0, -9.0]");
  EXPECT_EQ(spec.tasks[8].values[0].text, "12");
  EXPECT_TRUE(spec.tasks[8].values[0].numeric);
  EXPECT_FALSE(spec.tasks[8].values[1].numeric);
  EXPECT_EQ(TaskOverrides(spec, 8),
            (std::vector<std::string>{
                "material.finite_volume.kes.W=12", "loads.gravity=[0, 0, -9.81]",
                "material.finite_volume.kes.B_warp=0.06", "material.finite_volume.kes.B_weft=0.04",
                "mesh.spacing=0.05", "output.write=[summary,nodes,vtk,obj,gltf]"}));
  // Chains along W: 3 tasks each, one per (gravity, zip, repeat): 8 chains.
  ASSERT_EQ(spec.chains.size(), 8u);
  std::set<int> seen;
  for (const auto& chain : spec.chains) {
    ASSERT_EQ(chain.size(), 3u);
    for (size_t k = 0; k < chain.size(); ++k) {
      EXPECT_EQ(spec.tasks[chain[k]].axis_index[0], static_cast<int>(k));
      EXPECT_EQ(WarmStartSource(spec, chain[k]), k == 0 ? -1 : chain[k - 1]);
      seen.insert(chain[k]);
      for (size_t a = 1; a < 3; ++a) {
        EXPECT_EQ(spec.tasks[chain[k]].axis_index[a], spec.tasks[chain[0]].axis_index[a]);
      }
      EXPECT_EQ(spec.tasks[chain[k]].repeat, spec.tasks[chain[0]].repeat);
    }
  }
  EXPECT_EQ(seen.size(), spec.tasks.size());
}

TEST(SweepFile, SamplesStayInTheirRangesAndFollowTheirScale) {
  const std::string folder = SweepTempDir("sample");
  for (const std::string method : {"latin-hypercube", "sobol"}) {
    SCOPED_TRACE(method);
    const SweepSpec spec = LoadSweepFile(WriteSweep(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
sample:
  method: )" + method + R"(
  count: 16
  seed: 3
  ranges:
    material.finite_volume.kes.B_warp: {min: 0.01, max: 1.0, scale: log}
    material.finite_volume.kes.W: {min: 8, max: 16}
)"));
    ASSERT_EQ(spec.tasks.size(), 16u);
    EXPECT_EQ(spec.design, method);
    EXPECT_EQ(spec.chains.size(), 16u);
    std::set<int> log_strata, linear_strata;
    for (const SweepTask& task : spec.tasks) {
      const double b = task.values[0].number, w = task.values[1].number;
      EXPECT_GE(b, 0.01);
      EXPECT_LT(b, 1.0);
      EXPECT_GE(w, 8.0);
      EXPECT_LT(w, 16.0);
      // Each sixteenth of the log range of B and of the linear range of W holds one task.
      log_strata.insert(static_cast<int>(std::log(b / 0.01) / std::log(100.0) * 16));
      linear_strata.insert(static_cast<int>((w - 8.0) / 8.0 * 16));
    }
    EXPECT_EQ(log_strata.size(), 16u);
    EXPECT_EQ(linear_strata.size(), 16u);
    // The same file gives the same tasks.
    const SweepSpec again = LoadSweepFile(folder + "/sweep.yaml");
    for (size_t t = 0; t < spec.tasks.size(); ++t) {
      EXPECT_EQ(spec.tasks[t].values[0].text, again.tasks[t].values[0].text);
    }
  }
}

// Loading `text` fails with a message starting "sweep.yaml:LINE:COLUMN: " that contains `what`.
void ExpectError(const std::string& text, int line, int column, const std::string& what) {
  const std::string folder = SweepTempDir("errors");
  const std::string path = WriteSweep(folder, text);
  try {
    LoadSweepFile(path);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& error) {
    const std::string where =
        path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
    EXPECT_EQ(std::string(error.what()).rfind(where, 0), 0u) << error.what();
    EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(folder + "/out"));
}

TEST(SweepFile, EveryMistakeIsLocated) {
  const std::string head = "scene: base.yaml\nset: {mesh.spacing: 0.05}\n";
  ExpectError("scene: base.yaml\ngird: {material.density: [1]}\n", 2, 1, "did you mean 'grid'");
  ExpectError("grid: {material.density: [1]}\n", 1, 1, "'scene' is missing");
  ExpectError("scene: nothere.yaml\ngrid: {material.density: [1]}\n", 1, 8, "no such file");
  ExpectError(head, 1, 1, "expected the variations");
  ExpectError(head + "grid:\n  material.finite_volume.kes.W: []\n", 4, 33, "expected a list");
  ExpectError(head +
                  "zip:\n  material.finite_volume.kes.W: [8, 9]\n"
                  "  material.finite_volume.kes.B_warp: [0.1, 0.2, 0.3]\n",
              5, 38, "has 3 values");
  // A task's bad value: located at the value, with the task named.
  ExpectError(head + "grid:\n  material.finite_volume.kes.W: [8, -2]\n", 4, 37, "task 1");
  ExpectError(head + "grid:\n  material.finite_volume.kes.W: [8, abc]\n", 4, 37,
              "expected a number");
  // A key the scene does not have: located at its value, the scene's suggestion kept.
  ExpectError(head + "grid:\n  material.finite_volume.kes.WW: [8]\n", 4, 35, "did you mean 'W'");
  ExpectError(
      "scene: base.yaml\nset: {mesh.spacng: 0.05}\ngrid:\n  material.finite_volume.kes.W: [8]\n", 2,
      20, "did you mean 'spacing'");
  ExpectError(
      head + "grid:\n  material.finite_volume.kes.W: [8]\n  material.finite_volume.kes.W: [9]\n", 5,
      3, "");
  ExpectError(head + "grid: {material.finite_volume.kes.W: [8]}\nsample: {method: sobol}\n", 4, 1,
              "give one or the other");
  ExpectError(
      head + "sample: {method: sobl, count: 4, ranges: {material.density: {min: 1, max: 2}}}\n", 3,
      18, "did you mean 'sobol'");
  ExpectError(
      head + "sample: {method: sobol, count: 0, ranges: {material.density: {min: 1, max: 2}}}\n", 3,
      32, "at least 1");
  ExpectError(head +
                  "sample:\n  method: sobol\n  count: 4\n  ranges:\n"
                  "    material.finite_volume.kes.W: {min: 9, max: 8}\n",
              7, 49, "max > min");
  ExpectError(head +
                  "sample:\n  method: latin-hypercube\n  count: 4\n  ranges:\n"
                  "    material.finite_volume.kes.W: {min: 0, max: 8, scale: log}\n",
              7, 41, "log scale needs min > 0");
  std::string eleven;
  for (int k = 0; k < 11; ++k) eleven += "    k" + std::to_string(k) + ": {min: 1, max: 2}\n";
  ExpectError(head + "sample:\n  method: sobol\n  count: 4\n  ranges:\n" + eleven, 6, 3,
              "up to 10 keys");
  ExpectError(
      head +
          "grid: {material.finite_volume.kes.W: [8, 9]}\nwarm_start: {along: material.density}\n",
      4, 21, "not a varied key");
  ExpectError(head +
                  "sample: {method: sobol, count: 2, ranges: {material.finite_volume.kes.W: "
                  "{min: 8, max: 9}}}\nwarm_start: {along: material.finite_volume.kes.W}\n",
              4, 21, "a sample has none");
  ExpectError(head + "grid: {material.finite_volume.kes.W: [8]}\nkeep: [summary, pictres]\n", 4, 17,
              "did you mean 'pictures'");
  ExpectError(head + "grid: {material.finite_volume.kes.W: [8]}\nrepeat: 0\n", 4, 9, "");
}

// `keep` stands for output kinds by name: each of its names for at least one, each a row of the
// output-kind registry (a kind renamed there fails here, not in a sweep's first task).
TEST(SweepFile, KeepStandsForRegisteredOutputKinds) {
  for (const std::string& keep : SweepKeepKinds()) {
    const auto kinds = OutputKindsOf({keep});
    EXPECT_FALSE(kinds.empty()) << "keep: " << keep << " stands for nothing";
    for (const std::string& kind : kinds) {
      EXPECT_NE(FindOutputKind(kind), nullptr) << "keep: " << keep << " -> " << kind;
    }
  }
}

TEST(SweepFile, EveryExampleLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourcePath("configs/sweep"))) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("sweep", 0) != 0 || entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(name);
    const SweepSpec spec = LoadSweepFile(entry.path().string());
    EXPECT_FALSE(spec.tasks.empty());
    ++count;
  }
  EXPECT_GE(count, 2);
}

}  // namespace
}  // namespace drape::testing
