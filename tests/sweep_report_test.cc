// sweep.html and its charts: each response against each varied key, a heat map for a grid of two
// axes, no NaN anywhere (missing values are skipped).
#include "src/sweep/sweep_report.h"

#include <gtest/gtest.h>

#include <cstdio>
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

// The SVG chart of `html` whose title is `title`, or "".
std::string Chart(const std::string& html, const std::string& title) {
  const size_t at = html.find("<title>" + title + "</title>");
  if (at == std::string::npos) return "";
  const size_t start = html.rfind("<svg ", at);
  return html.substr(start, html.find("</svg>", at) - start);
}

size_t Occurrences(const std::string& text, const std::string& what) {
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// The charts are inline SVG, drawn by drape itself: no gnuplot, no plots folder, nothing linked.
TEST(SweepReport, EveryResponseAgainstEveryKeyAndAHeatMapForTwoAxes) {
  const std::string folder = SweepTempDir("report");
  SweepWithReport(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
grid:
  material.finite_volume.kes.B_warp: [0.06, 0.24]
  material.finite_volume.kes.W: [8.0, 16.0]
)");
  const fs::path out = folder + "/out";
  const std::string html = ReadText((out / "sweep.html").string());
  for (const char* response :
       {"drape coefficient", "energy (J)", "iterations", "solver time (s)"}) {
    for (const char* key : {"material.finite_volume.kes.B_warp", "material.finite_volume.kes.W"}) {
      const std::string chart = Chart(html, std::string(response) + " against " + key);
      EXPECT_EQ(Occurrences(chart, "<circle"), 4u) << response << " against " << key;
    }
  }
  const std::string map = Chart(html, "drape coefficient");
  EXPECT_EQ(Occurrences(map, "<rect x="), 4u) << map;  // a cell per grid point
  EXPECT_NE(map.find(">0.06</text>"), std::string::npos) << map;
  EXPECT_EQ(Occurrences(html, "<svg "), 9u);
  EXPECT_NE(html.find("<figcaption>drape coefficient over the grid</figcaption>"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out / "plots"));
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_NE(html.find("drape " + DrapeVersion()), std::string::npos);  // the provenance line
  EXPECT_NE(html.find("<td>0.24</td>"), std::string::npos);            // the table of rows
  // The drape coefficient's charts carry its error bars, sweep.csv's drape_coefficient_error.
  EXPECT_NE(html.find("drape coefficient against material.finite_volume.kes.W (bars: the "
                      "discretisation error, drape_coefficient_error)"),
            std::string::npos);
  EXPECT_EQ(html.find("energy (J) against material.finite_volume.kes.W (bars"), std::string::npos);
  const auto rows = ReadCsv((out / "sweep.csv").string());
  const int error_column = ColumnOf(rows[0], "drape_coefficient_error");
  const std::string bars = Chart(html, "drape coefficient against material.finite_volume.kes.W");
  for (size_t r = 1; r < rows.size(); ++r) {
    const double value = std::strtod(rows[r][error_column].c_str(), nullptr);
    if (!(value > 0.0)) continue;
    char error[32];
    std::snprintf(error, sizeof error, "%g", value);
    EXPECT_NE(bars.find(std::string(" ± ") + error + "</title>"), std::string::npos) << error;
  }
  ExpectNoNan(out);
}

// sweep.html's table shows each number rounded to 6 significant digits, as drape's other tables
// for people do; sweep.csv holds them exact (the energies to 16 or 17 digits).
TEST(SweepReport, TheTableShowsNumbersRounded) {
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

TEST(SweepReport, MissingValuesAreEmptyCellsAndSkippedByTheCharts) {
  const std::string folder = SweepTempDir("report_missing");
  // puiseux-fixed-point refuses the finite-volume fabric: those tasks have no results.
  SweepWithReport(folder, R"(scene: base.yaml
set: {mesh.spacing: 0.05}
zip:
  solver.method: [newton, puiseux-fixed-point, newton]
  material.finite_volume.kes.W: [8.0, 12.0, 16.0]
)");
  const fs::path out = folder + "/out";
  const std::string html = ReadText((out / "sweep.html").string());
  const std::string chart = Chart(html, "drape coefficient against material.finite_volume.kes.W");
  EXPECT_EQ(Occurrences(chart, "<circle"), 2u) << chart;     // the failed task's row has no point
  EXPECT_EQ(html.find("over the grid"), std::string::npos);  // one axis: no map
  ExpectNoNan(out);
}

}  // namespace
}  // namespace drape::testing
