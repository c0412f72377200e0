// `drape fabrics` (src/sweep/fabrics.h): each fabric's prediction is the single solve of its scene
// (or its drops' mean), the statistics are those of the differences, a re-run solves only what is
// missing, and the report's chart has a point per compared fabric.
#include "src/sweep/fabrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "src/run/solve_report.h"
#include "src/sweep/fabrics_report.h"
#include "src/sweep/sweep.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// Two fabrics on the standard tester at 5 cm (a fraction of a second each).
constexpr char kTable[] =
    "# two fabrics\n"
    "name,description,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft,measured_dc\n"
    "stiff,\"cotton, shirting\",12,0.12,0.08,0.9,4,7,0.70\n"
    "limp,a limp one,8,0.02,0.02,0.4,4,7,0.40\n";

class FabricsTest : public ::testing::Test {
 protected:
  FabricsOptions Options(const std::string& table, const std::string& out = "out") const {
    const fs::path path = scratch_.path() / "fabrics.csv";
    std::ofstream(path) << table;
    FabricsOptions options;
    options.table = path.string();
    options.overrides = {"mesh.spacing=0.05"};
    options.out = (scratch_.path() / out).string();
    options.threads = 1;
    options.command_line = "drape fabrics fabrics.csv";
    return options;
  }
  std::vector<std::vector<std::string>> Rows(const std::string& out) const {
    std::istringstream in(ReadWholeFile(scratch_.path() / out / "fabrics.csv"));
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) rows.push_back(SplitCsvLine(line));
    return rows;
  }
  static std::string Cell(const std::vector<std::vector<std::string>>& rows, size_t row,
                          const std::string& column) {
    for (size_t k = 0; k < rows[0].size(); ++k) {
      if (rows[0][k] == column) return rows[row][k];
    }
    ADD_FAILURE() << "no column " << column;
    return "";
  }
  testing::ScratchFolder scratch_{"fabrics"};
};

// Known differences: Δ = +0.1, −0.2, +0.05; within: |Δ| ≤ error + SD for the first and third.
TEST(FabricStatistics, AreThoseOfTheDifferences) {
  const FabricStatistics s = ComputeFabricStatistics(
      {{0.6, 0.1, 0.5, 0.0}, {0.3, 0.05, 0.5, 0.1}, {0.45, 0.02, 0.4, 0.03}});
  EXPECT_EQ(s.compared, 3);
  EXPECT_NEAR(s.mean_difference, (0.1 - 0.2 + 0.05) / 3, 1e-15);
  EXPECT_NEAR(s.mean_abs_difference, (0.1 + 0.2 + 0.05) / 3, 1e-15);
  EXPECT_NEAR(s.rms_difference, std::sqrt((0.01 + 0.04 + 0.0025) / 3), 1e-15);
  EXPECT_EQ(s.within, 2);
  EXPECT_EQ(ComputeFabricStatistics({}).compared, 0);
}

// Over drops: the mean and SD of the counted ones, the widest error bar, the most frequent folds.
TEST(FabricPrediction, IsTheCountedDropsMean) {
  std::vector<FabricTaskRecord> records(3);
  const double dcs[] = {0.6, 0.7, 0.1};
  for (int k = 0; k < 3; ++k) {
    records[k].drop = k + 1;
    records[k].drape_coefficient = dcs[k];
    records[k].drape_coefficient_error = 0.05 + 0.01 * k;
    records[k].folds = k == 0 ? 8 : 7;
    records[k].counted = k < 2;
  }
  const FabricPrediction p = PredictFabric(records);
  EXPECT_EQ(p.counted, 2);
  EXPECT_NEAR(*p.drape_coefficient, 0.65, 1e-15);
  EXPECT_NEAR(*p.standard_deviation, std::sqrt(0.005), 1e-15);
  EXPECT_NEAR(p.error, 0.06, 1e-15);
  EXPECT_EQ(p.folds, 7);  // a tie: the smaller count first
  records[0].counted = records[1].counted = false;
  EXPECT_FALSE(PredictFabric(records).drape_coefficient);
}

// The table's prediction is `drape solve`'s: the same scene solved the same way gives the same
// drape coefficient, to the last digit. A re-run solves nothing; a changed row solves that row.
TEST_F(FabricsTest, PredictsWhatASolveGivesAndRerunsOnlyWhatChanged) {
  const FabricsOptions options = Options(kTable);
  const FabricsSpec spec = LoadFabrics(options);
  std::ostringstream log;
  const FabricsSummary first = RunFabrics(spec, options, log);
  EXPECT_EQ(first.solved, 2);
  EXPECT_EQ(first.predicted, 2);
  EXPECT_EQ(first.statistics.compared, 2);
  const auto rows = Rows("out");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(Cell(rows, 1, "description"), "cotton, shirting");
  EXPECT_EQ(Cell(rows, 1, "kes.W [mg/cm²]"), "12");
  EXPECT_EQ(Cell(rows, 1, "si.density [kg/m^2]"), "0.12");

  Scene scene = spec.fabrics[1].scene;
  Model model = BuildModel(scene);
  const SolveReport report = SolveAndReport(scene, model, scene.solver.method, {}, true);
  EXPECT_EQ(Cell(rows, 2, "predicted_dc"), CsvNumber(ReportedDrapeCoefficient(report)));
  const double delta = std::stod(Cell(rows, 2, "difference"));
  EXPECT_NEAR(delta, ReportedDrapeCoefficient(report) - 0.40, 1e-15);
  EXPECT_NE(log.str().find("fabrics: limp (2 of 2 done): DC "), std::string::npos) << log.str();
  // 5 cm is coarse for both: the mesh rule's warning, once, naming them (both at the rule's cap of
  // 0.5, so either is the furthest off).
  EXPECT_NE(log.str().find("drape fabrics: warning: 2 of 2 fabrics on a mesh coarser than their "
                           "fabric's mesh rule (fabrics stiff, limp; each row's predicted_dc_error "
                           "includes the rule's error); the furthest off, fabric "),
            std::string::npos)
      << log.str();

  std::ostringstream again;
  const FabricsSummary second = RunFabrics(LoadFabrics(options), options, again);
  EXPECT_EQ(second.solved, 0);
  EXPECT_EQ(second.skipped, 2);
  EXPECT_EQ(Rows("out"), rows);

  // A record another drape wrote is kept, and its row says which drape solved it.
  const fs::path record = scratch_.path() / "out" / spec.fabrics[0].folder / "record.csv";
  std::string text = ReadWholeFile(record);
  text.replace(text.rfind(',') + 1, std::string::npos, "0.0 (an older drape)\n");
  std::ofstream(record) << text;
  std::ostringstream kept;
  EXPECT_EQ(RunFabrics(LoadFabrics(options), options, kept).skipped, 2);
  EXPECT_EQ(Cell(Rows("out"), 1, "drape_version"), "0.0 (an older drape)");
  EXPECT_NE(kept.str().find("1 finished task kept from drape 0.0 (an older drape)"),
            std::string::npos)
      << kept.str();

  std::string changed = kTable;
  changed.replace(changed.find("8,0.02"), 6, "8,0.03");
  const FabricsOptions edited = Options(changed);
  const FabricsSummary third = RunFabrics(LoadFabrics(edited), edited, again);
  EXPECT_EQ(third.solved, 1);
  EXPECT_EQ(third.skipped, 1);
}

// With --drops, each fabric's DC is the mean over its drops, and its folder holds them.
TEST_F(FabricsTest, DropsMakeTheMean) {
  FabricsOptions options = Options(
      "name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft\n"
      "stiff,12,0.12,0.08,0.9,4,7\n");
  options.drops = 2;
  const FabricsSpec spec = LoadFabrics(options);
  EXPECT_EQ(spec.tasks(), 2);
  std::ostringstream log;
  const FabricsSummary summary = RunFabrics(spec, options, log);
  EXPECT_EQ(summary.solved, 2);
  const auto rows = Rows("out");
  double sum = 0.0;
  for (const char* drop : {"drops/01", "drops/02"}) {
    const std::string record =
        ReadWholeFile(scratch_.path() / "out" / spec.fabrics[0].folder / drop / "record.csv");
    sum += std::stod(SplitCsvLine(record)[4]);
  }
  EXPECT_NEAR(std::stod(Cell(rows, 1, "predicted_dc")), sum / 2, 1e-12);
  EXPECT_EQ(Cell(rows, 1, "drops"), "2");
}

// The chart: one point per fabric with both numbers, the diagonal, both error bars.
TEST_F(FabricsTest, TheChartHasAPointPerComparedFabric) {
  const FabricsSpec spec = LoadFabrics(Options(kTable));
  std::vector<FabricPrediction> predictions(2);
  predictions[0].drape_coefficient = 0.72;
  predictions[0].error = 0.05;
  predictions[1].error = 0.05;  // not predicted: no point
  const std::string svg = MeasuredAgainstPredictedChart(spec, predictions);
  EXPECT_NE(svg.find("<title>Predicted against measured drape coefficient, 1 fabric</title>"),
            std::string::npos);
  EXPECT_NE(svg.find("stiff: measured 0.700, predicted 0.720 ± 0.050"), std::string::npos);
  EXPECT_EQ(svg.find("limp:"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);  // y = x
}

}  // namespace
}  // namespace drape
