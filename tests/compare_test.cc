// drape compare: the error measures against a reference, and a report that keeps failing runs.
#include "src/compare/compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "src/analysis/drape_analysis.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/version.h"
#include "src/scene/scene_loader.h"
#include "tests/run_program.h"
#include "tests/scratch_folder.h"
#include "tests/test_meshes.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;

std::string SourcePath(const std::string& relative) {
  return (fs::path(drape_tests::kSourceDir) / relative).string();
}

TEST(MeasurePositionError, IdenticalPositionsGiveZero) {
  const std::vector<double> positions = {0.0, 1.0, 2.0, -3.0, 0.5, 7.0};
  const PositionError error = MeasurePositionError(positions, positions);
  EXPECT_EQ(error.max_m, 0.0);
  EXPECT_EQ(error.rms_m, 0.0);
}

TEST(MeasurePositionError, MatchesDirectComputation) {
  const std::vector<double> reference = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  // Node 0 moved by (3, 4, 0): distance 5; node 1 unmoved; node 2 moved by (0, 0, 1).
  const std::vector<double> positions = {3, 4, 0, 1, 0, 0, 2, 0, 1};
  const PositionError error = MeasurePositionError(positions, reference);
  EXPECT_DOUBLE_EQ(error.max_m, 5.0);
  EXPECT_DOUBLE_EQ(error.rms_m, std::sqrt((25.0 + 0.0 + 1.0) / 3.0));
}

CompareOptions ChainOptions(const std::vector<std::string>& solvers,
                            const std::vector<std::string>& overrides = {}) {
  CompareOptions options;
  options.scenes = {SourcePath("configs/validation/funicular_chain.yaml")};
  options.solvers = solvers;
  options.overrides = overrides;
  options.time_limit = 30.0;
  options.plots = false;
  return options;
}

TEST(CompareScene, NewtonAgainstItsOwnReferenceHasNoError) {
  std::ostringstream log;
  const SceneComparison comparison = CompareScene(
      SourcePath("configs/validation/funicular_chain.yaml"), ChainOptions({"newton"}), log);
  ASSERT_TRUE(comparison.error.empty()) << comparison.error;
  EXPECT_TRUE(comparison.reference.converged) << comparison.reference.termination;
  EXPECT_LE(comparison.reference.relative_residual, 1e-12);
  ASSERT_EQ(comparison.runs.size(), 1u);
  const RunRecord& run = comparison.runs[0];
  EXPECT_EQ(run.status, RunStatus::kConverged) << run.reason;
  // Same start, same method, a tolerance of 1e-9 instead of 1e-12: the same equilibrium.
  EXPECT_LT(run.error.rms_m / comparison.size, 1e-6);
  EXPECT_LE(std::abs(run.energy_gap), comparison.reference.energy_tolerance);
  ASSERT_FALSE(run.curve.empty());
  EXPECT_GE(TimeToReach(run, 1e-2), 0.0);
}

// A run whose converged state passes through itself is no answer: its status says so, and its
// reason is the certificate's words (the crossed squares of tests/test_meshes.h).
TEST(CompareScene, ARunThroughItselfPassesThroughWhateverItsSolverSays) {
  const testing::ScratchFolder folder("compare_crossed");
  std::ofstream(folder / "crossed.obj") << testing::CrossedSquaresObj();
  std::ofstream(folder / "crossed.yaml") << testing::CrossedSquaresScene("crossed.obj");
  CompareOptions options;
  options.scenes = {(folder / "crossed.yaml").string()};
  options.solvers = {"newton"};
  options.time_limit = 30.0;
  options.plots = false;
  std::ostringstream log;
  const SceneComparison comparison = CompareScene(options.scenes[0], options, log);
  ASSERT_TRUE(comparison.error.empty()) << comparison.error;
  ASSERT_EQ(comparison.runs.size(), 1u);
  const RunRecord& run = comparison.runs[0];
  EXPECT_EQ(run.status, RunStatus::kPassesThrough) << run.reason;
  EXPECT_STREQ(RunStatusName(run.status), "passes through");
  EXPECT_NE(run.reason.find("fabric through itself ("), std::string::npos) << run.reason;
  EXPECT_EQ(TimeToReach(run, 1e-2), -1.0);  // never reached, not unknown (kTimeUnknown)
}

TEST(CompareScene, RunStoppedEarlyHasTheDirectlyComputedError) {
  std::ostringstream log;
  const SceneComparison comparison =
      CompareScene(SourcePath("configs/validation/funicular_chain.yaml"),
                   ChainOptions({"ceres-lbfgs"}, {"solver.max_iterations=2"}), log);
  ASSERT_TRUE(comparison.error.empty()) << comparison.error;
  // The reference is not held to the scene's iteration limit.
  EXPECT_TRUE(comparison.reference.converged) << comparison.reference.termination;
  ASSERT_EQ(comparison.runs.size(), 1u);
  const RunRecord& run = comparison.runs[0];
  EXPECT_EQ(run.status, RunStatus::kNotConverged) << run.reason;
  ASSERT_EQ(run.positions.size(), comparison.reference.positions.size());
  double largest = 0.0, sum_squares = 0.0;
  const size_t nodes = run.positions.size() / 3;
  for (size_t node = 0; node < nodes; ++node) {
    const double dx = run.positions[3 * node] - comparison.reference.positions[3 * node];
    const double dy = run.positions[3 * node + 1] - comparison.reference.positions[3 * node + 1];
    const double dz = run.positions[3 * node + 2] - comparison.reference.positions[3 * node + 2];
    const double squared = dx * dx + dy * dy + dz * dz;
    largest = std::max(largest, std::sqrt(squared));
    sum_squares += squared;
  }
  EXPECT_GT(run.error.max_m, 0.0);
  EXPECT_DOUBLE_EQ(run.error.max_m, largest);
  EXPECT_DOUBLE_EQ(run.error.rms_m, std::sqrt(sum_squares / nodes));
  EXPECT_GT(run.energy_gap, 0.0);  // the reference is the minimum
  // Stopped after two iterations, it never reaches the finest level.
  EXPECT_LT(TimeToReach(run, 1e-8), 0.0);
}

TEST(RunCompare, ReportKeepsRefusedAndUnconvergedRuns) {
  const fs::path out = fs::path(::testing::TempDir()) / "drape_compare_test";
  fs::remove_all(out);
  CompareOptions options;
  // 20 x 20 nodes: 1,194 free dofs, above nlopt-slsqp's limit of 1,000.
  options.scenes = {SourcePath("configs/examples/hanging_sheet.yaml")};
  options.overrides = {"mesh.nodes=[20,20]", "solver.max_iterations=3"};
  options.solvers = {"nlopt-slsqp", "ceres-lbfgs"};
  options.out_dir = out.string();
  options.time_limit = 30.0;
  options.tools_dir = SourcePath("tools");
  options.command_line = "drape compare hanging_sheet.yaml";
  std::ostringstream log;
  ASSERT_EQ(RunCompare(options, log), 0) << log.str();
  const std::string report = ReadText(out / "report.md");
  EXPECT_NE(report.find("| nlopt-slsqp | refused |"), std::string::npos) << report;
  EXPECT_NE(report.find("| ceres-lbfgs | not converged |"), std::string::npos) << report;
  EXPECT_NE(report.find("free degrees of freedom"), std::string::npos)
      << "the refusal's reason: " << report;
  const std::string runs = ReadText(out / "runs.csv");
  EXPECT_NE(runs.find(",nlopt-slsqp,refused,"), std::string::npos) << runs;
  const std::string html = ReadText(out / "report.html");
  EXPECT_EQ(html.find('`'), std::string::npos) << "Markdown's backticks leak into the HTML";
  EXPECT_NE(html.find("<code>"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "curves.csv"));
  // How the report was made: compare.json and the pages; pictures inside the page, not linked.
  const std::string json = ReadText(out / "compare.json");
  EXPECT_NE(json.find("\"drape_version\": " + JsonString(DrapeVersion())), std::string::npos)
      << json;
  EXPECT_NE(json.find("\"command_line\": \"drape compare hanging_sheet.yaml\""), std::string::npos)
      << json;
  EXPECT_NE(report.find(ProvenanceLine({options.command_line, options.overrides})),
            std::string::npos);
  EXPECT_EQ(html.find("src=\"plots/"), std::string::npos);
  if (std::system("gnuplot --version >/dev/null 2>&1") == 0) {
    EXPECT_NE(html.find("src=\"data:image/png;base64,"), std::string::npos);
  }
  EXPECT_EQ(runs.find(",yes,"), std::string::npos) << runs;
  // No NaN or infinity in a CSV cell: the sheet has no drape coefficient, so no gap (empty).
  for (const char* csv : {"runs.csv", "curves.csv", "references.csv"}) {
    std::istringstream cells(ReadText(out / csv));
    std::string line;
    while (std::getline(cells, line)) {
      EXPECT_FALSE(std::regex_search(line, std::regex("(^|,)-?(nan|inf)(,|$)")))
          << csv << ": " << line;
    }
  }
}

TEST(RunCompare, UnknownSolverIsBadUsage) {
  CompareOptions options = ChainOptions({"no-such-solver"});
  std::ostringstream log;
  EXPECT_EQ(RunCompare(options, log), 2);
  EXPECT_NE(log.str().find("no-such-solver"), std::string::npos);
}

// A disc over a pin has a drape coefficient: a run stopped early differs from the reference's by
// exactly what the drape analysis gives at the two sets of positions; a chain has none.
TEST(CompareScene, DrapeCoefficientGapWhereTheSceneHasOne) {
  std::ostringstream log;
  const std::string disc = SourcePath("configs/netlogo/disc_quadrangular.yaml");
  const std::vector<std::string> coarse = {"mesh.spacing=0.03", "solver.max_iterations=3"};
  const SceneComparison comparison = CompareScene(disc, ChainOptions({"newton"}, coarse), log);
  ASSERT_TRUE(comparison.error.empty()) << comparison.error;
  ASSERT_EQ(comparison.runs.size(), 1u);
  const RunRecord& run = comparison.runs[0];
  ASSERT_TRUE(std::isfinite(run.drape_coefficient_gap)) << run.reason;
  Model model = BuildModel(LoadScene(disc, coarse));
  const auto ratio_at = [&model](const std::vector<double>& positions) {
    model.positions = positions;
    return ComputeDrapeCoefficient(model).ratio;
  };
  EXPECT_DOUBLE_EQ(run.drape_coefficient_gap,
                   ratio_at(run.positions) - ratio_at(comparison.reference.positions));
  EXPECT_NE(run.drape_coefficient_gap, 0.0);  // three Newton steps from the flat disc

  const SceneComparison chain = CompareScene(SourcePath("configs/validation/funicular_chain.yaml"),
                                             ChainOptions({"newton"}), log);
  ASSERT_EQ(chain.runs.size(), 1u);
  EXPECT_TRUE(std::isnan(chain.runs[0].drape_coefficient_gap));
}

}  // namespace
}  // namespace drape
