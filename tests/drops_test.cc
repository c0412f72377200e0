// Repeated drops of a drape test (src/sweep/drops.h): the perturbations are seeded, bounded and
// where they are documented to be; the statistics are those of drops.csv; the rows are the same
// on one thread and two.
#include "src/sweep/drops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/output/json.h"
#include "src/output/writers.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// The 24 cm polyester on the standard disc at 2 cm: about 0.1 s a drop.
constexpr char kScene[] = R"(name: drops
drape_test: {specimen_diameter: 0.24, placement: 0.002, waviness: 0.003, seed: 7}
mesh: {spacing: 0.02}
material:
  model: finite_volume
  density: 0.08
  finite_volume: {E_warp: 9000, E_weft: 8000, G: 20, D_warp: 2.6e-6, D_weft: 1.7e-6}
solver: {method: newton, tolerance: 1.0e-8, max_iterations: 500}
output: {write: [summary]}
)";

class Drops : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("drops");
    folder_ = scratch_->path();
    std::ofstream(folder_ / "scene.yaml") << kScene;
    scene_ = LoadScene((folder_ / "scene.yaml").string());
  }
  void TearDown() override { scratch_.reset(); }

  std::string ReadText(const fs::path& path) const {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path folder_;
  Scene scene_;
};

TEST_F(Drops, PlacementIsSeededAndWithinItsRadius) {
  const DrapeTestSpec& test = *scene_.drape_test;
  std::vector<Eigen::Vector2d> offsets;
  for (int drop = 1; drop <= 20; ++drop) {
    Eigen::Vector2d offset;
    const Scene drop_scene = DropScene(scene_, drop, &offset);
    EXPECT_LE((offset - test.offset).norm(), test.placement);
    // The expansion follows the drop's placement: the disc and the clamp move together.
    EXPECT_EQ(drop_scene.obstacles[0].center.head<2>(), offset);
    EXPECT_EQ(drop_scene.fixed[0].nodes.center.head<2>(), offset);
    EXPECT_EQ(drop_scene.solver.levels, 1);
    Eigen::Vector2d again;
    DropScene(scene_, drop, &again);
    EXPECT_EQ(again, offset);
    for (const auto& earlier : offsets) EXPECT_NE(earlier, offset);
    offsets.push_back(offset);
  }
  Scene other_seed = scene_;
  other_seed.drape_test->seed = 8;
  Eigen::Vector2d other;
  DropScene(other_seed, 1, &other);
  EXPECT_NE(other, offsets[0]);
}

TEST_F(Drops, WavinessMovesOnlyTheOverhangVerticallyWithinItsAmplitude) {
  const Scene drop_scene = DropScene(scene_, 3);
  Model model = BuildModel(drop_scene);
  const std::vector<double> flat = model.positions;
  AddDropWaviness(drop_scene, 3, &model);
  const DrapeTestSpec& test = *drop_scene.drape_test;
  double largest = 0.0;
  for (int node = 0; node < model.num_nodes; ++node) {
    EXPECT_EQ(model.positions[3 * node], flat[3 * node]);
    EXPECT_EQ(model.positions[3 * node + 1], flat[3 * node + 1]);
    const double dz = model.positions[3 * node + 2] - flat[3 * node + 2];
    const double r = (Eigen::Vector2d(flat[3 * node], flat[3 * node + 1]) - test.offset).norm();
    if (r <= test.disc_diameter / 2) {
      EXPECT_EQ(dz, 0.0) << node;
    }
    EXPECT_LE(std::abs(dz), test.waviness * (1 + 1e-12));
    largest = std::max(largest, std::abs(dz));
  }
  EXPECT_GT(largest, 0.3 * test.waviness);
  EXPECT_EQ(model.initial, flat);  // the flat shape the drape coefficient is measured against
}

TEST_F(Drops, StatisticsOfHandMadeRecords) {
  std::vector<DropRecord> drops(5);
  const double dc[] = {0.60, 0.64, 0.62, 0.70, 0.10};
  const int folds[] = {7, 8, 7, 8, 9};
  for (int k = 0; k < 5; ++k) {
    drops[k].drop = k + 1;
    drops[k].drape_coefficient = dc[k];
    drops[k].folds = folds[k];
    drops[k].counted = k < 4;  // the fifth did not reach a stable minimum
  }
  const DropStatistics s = ComputeDropStatistics(drops);
  EXPECT_EQ(s.drops, 5);
  EXPECT_EQ(s.counted, 4);
  EXPECT_DOUBLE_EQ(s.mean, 0.64);
  EXPECT_NEAR(s.standard_deviation, std::sqrt((0.0016 + 0.0 + 0.0004 + 0.0036) / 3), 1e-15);
  EXPECT_EQ(s.folds_histogram, (std::map<int, int>{{7, 2}, {8, 2}}));
  EXPECT_EQ(s.modal_folds, (std::vector<int>{7, 8}));  // a tie: both
  EXPECT_EQ(s.modal_drops, 4);
  EXPECT_DOUBLE_EQ(s.modal_mean, 0.64);
  drops[3].folds = 7;
  const DropStatistics one_mode = ComputeDropStatistics(drops);
  EXPECT_EQ(one_mode.modal_folds, std::vector<int>{7});
  EXPECT_DOUBLE_EQ(one_mode.modal_mean, (0.60 + 0.62 + 0.70) / 3);
  EXPECT_NE(DropsLine(one_mode).find("5 drops (4 at a stable minimum, counted): drape "
                                     "coefficient 0.640 ± 0.043"),
            std::string::npos)
      << DropsLine(one_mode);
}

TEST_F(Drops, ACsvRowReadsBackExactly) {
  DropRecord record;
  record.drop = 12;
  record.offset = Eigen::Vector2d(0.1 / 3, -2e-3);
  record.waviness = 0.002;
  record.drape_coefficient = 2.0 / 3;
  record.folds = 8;
  record.energy = -6.1e-5 / 7;
  record.counted = false;
  record.state = "failed: a message, with \"quotes\"";
  const DropRecord back = ParseDropCsvRow(DropCsvRow(record));
  EXPECT_EQ(back.drop, record.drop);
  EXPECT_EQ(back.offset, record.offset);
  EXPECT_EQ(back.waviness, record.waviness);
  EXPECT_EQ(back.drape_coefficient, record.drape_coefficient);
  EXPECT_EQ(back.folds, record.folds);
  EXPECT_EQ(back.energy, record.energy);
  EXPECT_EQ(back.counted, record.counted);
  EXPECT_EQ(back.state, record.state);
}

// docs/reference.md names drops.csv's columns in order: "`OUT/drops.csv` has one row per drop
// (`drop, offset_x_m, …`)"; they are the header drape writes (one list of columns, drops.cc).
TEST(DropsCsv, TheReferenceNamesItsColumnsInOrder) {
  std::ifstream in(std::string(drape_tests::kSourceDir) + "/docs/reference.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string reference = text.str();
  const size_t at = reference.find("`OUT/drops.csv` has one row per");
  ASSERT_NE(at, std::string::npos);
  const size_t open = reference.find("(`", at) + 2;
  const size_t close = reference.find("`)", open);
  ASSERT_NE(close, std::string::npos);
  std::string listed;
  for (char c : reference.substr(open, close - open)) {
    if (c != ' ' && c != '\n') listed += c;
  }
  EXPECT_EQ(listed, DropsCsvHeader());
}

TEST_F(Drops, OneThreadAndTwoWriteTheSameDropsAndTheStatisticsAreThoseOfDropsCsv) {
  std::map<int, std::string> csv;
  for (const int threads : {1, 2}) {
    DropsOptions options;
    options.drops = 4;
    options.threads = threads;
    options.directory = (folder_ / ("out" + std::to_string(threads))).string();
    std::ostringstream log;
    const DropsSummary summary = RunDrops(scene_, options, log);
    ASSERT_TRUE(summary.coordinator);
    csv[threads] = ReadText(fs::path(options.directory) / "drops.csv");
    EXPECT_TRUE(fs::exists(fs::path(options.directory) / "drops/04/summary.json"));
    EXPECT_NE(ReadText(fs::path(options.directory) / "report.html").find("<svg "),
              std::string::npos);
    ASSERT_EQ(summary.outlines.size(), 4u);
    EXPECT_EQ(summary.outlines[3].radius.size(), 360u);

    // The statistics from the file's rows, recomputed here.
    std::istringstream rows(csv[threads]);
    std::string line;
    std::getline(rows, line);
    EXPECT_EQ(line, DropsCsvHeader());
    double sum = 0.0, squares = 0.0;
    std::vector<double> values;
    std::map<int, int> histogram;
    while (std::getline(rows, line)) {
      const DropRecord record = ParseDropCsvRow(line);
      ASSERT_TRUE(record.counted) << line;
      EXPECT_GT(record.drape_coefficient, 0.3);
      values.push_back(record.drape_coefficient);
      sum += record.drape_coefficient;
      ++histogram[record.folds];
    }
    ASSERT_EQ(values.size(), 4u);
    const double mean = sum / 4;
    for (double v : values) squares += (v - mean) * (v - mean);
    EXPECT_DOUBLE_EQ(summary.statistics.mean, mean);
    EXPECT_DOUBLE_EQ(summary.statistics.standard_deviation, std::sqrt(squares / 3));
    EXPECT_EQ(summary.statistics.folds_histogram, histogram);
    EXPECT_GT(summary.statistics.standard_deviation, 0.0);  // the drops do differ
    const std::string json = ReadText(fs::path(options.directory) / "summary.json");
    EXPECT_NE(json.find("\"drape_coefficient_mean\": " + FormatNumber(mean)), std::string::npos)
        << json;
    // The spread over drops and, beside it, each drop's discretisation error (the mesh rule).
    ASSERT_TRUE(summary.mesh_advice);
    const Scene first = DropScene(scene_, 1);
    const std::optional<MeshAdvice> advice = AdviseMesh(first, BuildModel(first));
    ASSERT_TRUE(advice);
    EXPECT_EQ(summary.mesh_advice->expected_error, advice->expected_error);
    EXPECT_NE(json.find("\"mesh_rule\": " + MeshRuleJson(*advice)), std::string::npos) << json;
    const std::string text = DropsLine(summary.statistics, summary.mesh_advice);
    EXPECT_NE(text.find(", discretisation error about "), std::string::npos) << text;
  }
  EXPECT_EQ(csv[1], csv[2]);
}

}  // namespace
}  // namespace drape
