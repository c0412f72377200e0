#include "src/sweep/sweep_report.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <vector>

#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "src/output/json.h"
#include "src/output/report_page.h"
#include "src/output/svg_chart.h"
#include "src/scene/number_text.h"
#include "src/sweep/sweep.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

// The responses plotted against each key: column of sweep.csv and axis label.
struct Response {
  std::string column;
  std::string label;
};
const std::vector<Response> kResponses = {{"drape_coefficient", "drape coefficient"},
                                          {"energy_J", "energy (J)"},
                                          {"iterations", "iterations"},
                                          {"time_s", "solver time (s)"}};

constexpr const char* kDrapeErrorColumn = "drape_coefficient_error";

// sweep.csv as cells: the header, then the rows.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  int Column(const std::string& name) const {
    for (size_t k = 0; k < header.size(); ++k) {
      if (header[k] == name) return static_cast<int>(k);
    }
    return -1;
  }
  // The number in row `r`, column `c`, if there is one.
  bool Number(size_t r, int c, double* value) const {
    const std::string& text = rows[r][c];
    const auto number = WholeNumber(text);
    if (!number || !std::isfinite(*number)) return false;
    *value = *number;
    return true;
  }
};

Table ReadTable(const fs::path& csv) {
  Table table;
  std::ifstream in(csv);
  std::string line;
  if (std::getline(in, line)) table.header = SplitCsvLine(line);
  while (std::getline(in, line)) {
    auto cells = SplitCsvLine(line);
    if (cells.size() == table.header.size()) table.rows.push_back(std::move(cells));
  }
  return table;
}

// The varied keys with at least two distinct numbers in the table (the x axes of the plots).
std::vector<int> NumericKeyColumns(const SweepSpec& spec, const Table& table) {
  std::vector<int> columns;
  for (const SweepKey& key : spec.keys) {
    const int c = table.Column(key.key);
    std::set<double> distinct;
    double value = 0.0;
    for (size_t r = 0; r < table.rows.size(); ++r) {
      if (table.Number(r, c, &value)) distinct.insert(value);
    }
    if (distinct.size() >= 2) columns.push_back(c);
  }
  return columns;
}

bool WideAndPositive(const Table& table, int c) {
  double lo = INFINITY, hi = 0.0, value = 0.0;
  for (size_t r = 0; r < table.rows.size(); ++r) {
    if (!table.Number(r, c, &value)) continue;
    if (value <= 0.0) return false;
    lo = std::min(lo, value);
    hi = std::max(hi, value);
  }
  return hi >= 20.0 * lo;
}

// Each response against each varied numeric key, a point per row that has both (the drape
// coefficient with its error bars where sweep.csv has them).
std::vector<ReportBlock> ScalarCharts(const SweepSpec& spec, const Table& table) {
  std::vector<ReportBlock> charts;
  const int error_column = table.Column(kDrapeErrorColumn);
  for (const Response& response : kResponses) {
    const int y = table.Column(response.column);
    for (const int x : NumericKeyColumns(spec, table)) {
      const std::string& key = table.header[x];
      std::vector<ScatterPoint> points;
      bool bars = false;
      for (size_t r = 0; r < table.rows.size(); ++r) {
        ScatterPoint point;
        if (!table.Number(r, x, &point.x) || !table.Number(r, y, &point.y)) continue;
        if (response.column == "drape_coefficient" && error_column >= 0 &&
            table.Number(r, error_column, &point.error)) {
          bars = true;
        }
        points.push_back(point);
      }
      if (points.empty()) continue;
      const std::string title = response.label + " against " + key;
      charts.push_back(ChartBlock(
          ScatterChart(title, key, response.label, points, WideAndPositive(table, x),
                       bars ? 0.0 : -INFINITY, bars ? 1.0 : INFINITY),
          title + (bars
                       ? " (bars: the discretisation error, " + std::string(kDrapeErrorColumn) + ")"
                       : "")));
    }
  }
  return charts;
}

// The labels of one axis's positions: each its first key's value.
std::vector<std::string> AxisLabels(const SweepSpec& spec, int axis) {
  int key = 0;
  while (spec.keys[key].axis != axis) ++key;
  std::vector<std::string> labels(spec.axis_sizes[axis]);
  for (const SweepTask& task : spec.tasks) labels[task.axis_index[axis]] = task.values[key].text;
  return labels;
}

std::string AxisName(const SweepSpec& spec, int axis) {
  std::string name;
  for (const SweepKey& key : spec.keys) {
    if (key.axis == axis) name += (name.empty() ? "" : " & ") + key.key;
  }
  return name;
}

// The grid's axes with more than one value (a heat map needs exactly two).
std::vector<int> VaryingAxes(const SweepSpec& spec) {
  std::vector<int> axes;
  for (size_t a = 0; a < spec.axis_sizes.size(); ++a) {
    if (spec.axis_sizes[a] > 1) axes.push_back(static_cast<int>(a));
  }
  return axes;
}

// The drape coefficient (else the energy) over a grid of exactly two varying axes.
std::vector<ReportBlock> HeatMap(const SweepSpec& spec, const Table& table) {
  const std::vector<int> axes = VaryingAxes(spec);
  if (axes.size() != 2) return {};
  const int x_axis = axes[1], y_axis = axes[0];
  for (const char* response : {"drape_coefficient", "energy_J"}) {
    const int c = table.Column(response);
    std::vector<HeatCell> cells;
    double value = 0.0;
    for (size_t r = 0; r < table.rows.size(); ++r) {
      const int task = std::atoi(table.rows[r][0].c_str());
      if (task < 0 || task >= static_cast<int>(spec.tasks.size()) || !table.Number(r, c, &value)) {
        continue;
      }
      if (spec.tasks[task].repeat != 0) continue;
      const auto& index = spec.tasks[task].axis_index;
      cells.push_back({index[x_axis], index[y_axis], value});
    }
    if (cells.empty()) continue;
    const std::string label =
        response == std::string("energy_J") ? "energy (J)" : "drape coefficient";
    return {ChartBlock(HeatMapChart(label, AxisName(spec, x_axis), AxisLabels(spec, x_axis),
                                    AxisName(spec, y_axis), AxisLabels(spec, y_axis), cells),
                       label + " over the grid")};
  }
  return {};
}

// The tasks whose folders hold a drape.glb (`keep: [shape]`), for the 3D view: "task 7:
// mesh.spacing=0.005".
std::vector<ViewerShape> TaskShapes(const SweepSpec& spec, const std::string& directory) {
  std::vector<ViewerShape> shapes;
  for (int task = 0; task < static_cast<int>(spec.tasks.size()); ++task) {
    const std::string file =
        fs::relative(fs::path(TaskFolder(directory, spec, task)) / "drape.glb", directory).string();
    if (!fs::exists(fs::path(directory) / file)) continue;
    std::string label = "task " + std::to_string(task);
    for (const std::string& value : TaskOverrides(spec, task)) label += " " + value;
    shapes.push_back({label, file});
  }
  return shapes;
}

std::vector<ReportBlock> Page(const SweepSpec& spec, const Table& table,
                              const Provenance& provenance, const std::string& directory) {
  std::vector<ReportBlock> blocks = {
      HeadingBlock("drape sweep: " + spec.file),
      TextBlock("base scene " + spec.scene_file + "; design " + spec.design + ", " +
                std::to_string(spec.tasks.size()) + " tasks, " + std::to_string(table.rows.size()) +
                " finished (sweep.csv); an empty cell is a value the task does not have."),
      TextBlock(ProvenanceLine(provenance) + " (sweep.json)")};
  for (ReportBlock& chart : HeatMap(spec, table)) blocks.push_back(std::move(chart));
  for (ReportBlock& chart : ScalarCharts(spec, table)) blocks.push_back(std::move(chart));
  if (std::vector<ViewerShape> shapes = TaskShapes(spec, directory); !shapes.empty()) {
    blocks.push_back(
        View3dBlock(std::move(shapes), "The tasks' shapes in 3D (each one's drape.glb)"));
  }
  blocks.push_back(HeadingBlock("Tasks"));
  std::vector<std::vector<std::string>> rows = {table.header};
  for (const auto& row : table.rows) {
    // Numbers rounded for people, as drape's other tables show them (sweep.csv keeps them exact).
    std::vector<std::string> shown;
    for (const std::string& cell : row) {
      const std::optional<double> number = WholeNumber(cell);
      shown.push_back(number && std::isfinite(*number) ? RoundedNumber(*number, 6) : cell);
    }
    rows.push_back(std::move(shown));
  }
  blocks.push_back(TableBlock(std::move(rows)));
  return blocks;
}

}  // namespace

void WriteSweepReport(const SweepSpec& spec, const std::string& directory,
                      const Provenance& provenance) {
  const Table table = ReadTable(fs::path(directory) / "sweep.csv");
  WriteAtomically(fs::path(directory) / "sweep.html", [&](std::ostream& out) {
    WriteHtmlReport(Page(spec, table, provenance, directory), directory, out);
  });
}

}  // namespace drape
