// sweep.html and its plots: each response against each varied key, a heat map for a grid of two
// axes, no NaN anywhere (missing values are skipped).
#include "src/sweep/sweep_report.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "src/output/json.h"
#include "src/output/version.h"
#include "src/scene/number_text.h"
#include "tests/sweep_test_support.h"

namespace drape::testing {
namespace {

namespace fs = std::filesystem;

bool HaveGnuplot() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

// Runs the sweep with its report into `folder`/out.
void SweepWithReport(const std::string& folder, const std::string& text) {
  const SweepSpec spec = LoadSweepFile(WriteSweep(folder, text));
  SweepOptions options;
  options.out = folder + "/out";
  options.threads = 1;
  std::ostringstream log;
  RunSweep(spec, options, log);
  EXPECT_EQ(log.str().find("could not draw"), std::string::npos) << log.str();
}

// `html` without its embedded pictures' base64 text (which may spell anything).
std::string WithoutDataUris(std::string html) {
  const std::string data = "data:image/png;base64,";
  for (size_t at = html.find(data); at != std::string::npos; at = html.find(data, at)) {
    html.erase(at, html.find('"', at) - at);
  }
  return html;
}

void ExpectNoNan(const fs::path& folder) {
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const auto extension = entry.path().extension();
    if (extension != ".csv" && extension != ".dat" && extension != ".html") continue;
    const std::string text = WithoutDataUris(ReadText(entry.path().string()));
    EXPECT_EQ(text.find("nan"), std::string::npos) << entry.path();
    EXPECT_EQ(text.find("inf"), std::string::npos) << entry.path();
  }
}

TEST(SweepReport, EveryResponseAgainstEveryKeyAndAHeatMapForTwoAxes) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string folder = SweepTempDir("report");
  SweepWithReport(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.B_warp: [0.06, 0.24]
  material.finite_volume.kes.W: [8.0, 16.0]
)");
  const fs::path out = folder + "/out";
  const std::string html = ReadText((out / "sweep.html").string());
  int images = 0;
  for (const char* response : {"drape_coefficient", "energy_J", "iterations", "time_s"}) {
    for (const char* key : {"material_finite_volume_kes_B_warp", "material_finite_volume_kes_W"}) {
      const std::string png = std::string("plots/") + response + "__" + key + ".png";
      EXPECT_TRUE(fs::exists(out / png)) << png;
      ++images;
    }
  }
  EXPECT_EQ(images, 8);
  EXPECT_TRUE(fs::exists(out / "plots/drape_coefficient__map.png"));
  // The page stands alone: its nine pictures are in it, none is linked.
  size_t embedded = 0;
  for (size_t at = html.find("src=\"data:image/png;base64,iVBOR"); at != std::string::npos;
       at = html.find("src=\"data:image/png;base64,iVBOR", at + 1)) {
    ++embedded;
  }
  EXPECT_EQ(embedded, 9u);
  EXPECT_EQ(html.find("src=\"plots/"), std::string::npos);
  EXPECT_NE(html.find("alt=\"drape coefficient over the grid\""), std::string::npos);
  EXPECT_NE(html.find("drape " + DrapeVersion()), std::string::npos);  // the provenance line
  EXPECT_NE(html.find("<td>0.24</td>"), std::string::npos);            // the table of rows
  // The drape coefficient's plots carry its error bars: the data's last column (after the two
  // keys and four responses) is sweep.csv's drape_coefficient_error.
  EXPECT_NE(html.find("drape coefficient against material.finite_volume.kes.W (bars: the "
                      "discretisation error, drape_coefficient_error)"),
            std::string::npos);
  EXPECT_EQ(html.find("energy (J) against material.finite_volume.kes.W (bars"), std::string::npos);
  std::istringstream data(ReadText((out / "plots/data/rows.dat").string()));
  const auto rows = ReadCsv((out / "sweep.csv").string());
  const int error_column = ColumnOf(rows[0], "drape_coefficient_error");
  std::string line;
  for (size_t r = 1; std::getline(data, line); ++r) {
    std::istringstream cells(line);
    std::vector<std::string> values;
    for (std::string cell; cells >> cell;) values.push_back(cell);
    ASSERT_EQ(values.size(), 7u) << line;
    ASSERT_LT(r, rows.size());
    EXPECT_EQ(std::strtod(values[6].c_str(), nullptr),
              std::strtod(rows[r][error_column].c_str(), nullptr));
  }
  ExpectNoNan(out);
}

// sweep.html's table shows each number rounded to 6 significant digits, as drape's other tables
// for people do; sweep.csv holds them exact (the energies to 16 or 17 digits).
TEST(SweepReport, TheTableShowsNumbersRounded) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string folder = SweepTempDir("report_rounded");
  SweepWithReport(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.W: [8.0, 16.0]
)");
  const fs::path out = folder + "/out";
  bool exact_is_longer = false;
  for (const auto& row : ReadCsv((out / "sweep.csv").string())) {
    for (const std::string& cell : row) {
      const auto number = WholeNumber(cell);
      exact_is_longer = exact_is_longer || (number && RoundedNumber(*number, 6) != cell);
    }
  }
  EXPECT_TRUE(exact_is_longer) << "no number of sweep.csv needs rounding: the test shows nothing";
  const std::string html = WithoutDataUris(ReadText((out / "sweep.html").string()));
  static const std::regex cell("<td>([^<]*)</td>");
  int numbers = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), cell); it != std::sregex_iterator();
       ++it) {
    const std::string text = (*it)[1];
    const auto number = WholeNumber(text);
    if (!number) continue;
    ++numbers;
    EXPECT_EQ(text, RoundedNumber(*number, 6));
  }
  EXPECT_GT(numbers, 10);
}

TEST(SweepReport, MissingValuesAreEmptyCellsAndSkippedByThePlots) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string folder = SweepTempDir("report_missing");
  // puiseux-fixed-point refuses the finite-volume fabric: those tasks have no results.
  SweepWithReport(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
zip:
  solver.method: [newton, puiseux-fixed-point, newton]
  material.finite_volume.kes.W: [8.0, 12.0, 16.0]
)");
  const fs::path out = folder + "/out";
  EXPECT_TRUE(fs::exists(out / "plots/drape_coefficient__material_finite_volume_kes_W.png"));
  EXPECT_FALSE(fs::exists(out / "plots/drape_coefficient__map.png"));  // one axis: no map
  const std::string data = ReadText((out / "plots/data/rows.dat").string());
  EXPECT_NE(data.find('?'), std::string::npos) << data;
  ExpectNoNan(out);
}

}  // namespace
}  // namespace drape::testing
