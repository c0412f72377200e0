#include "src/sweep/sweep_report.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <set>
#include <vector>

#include "src/output/atomic_file.h"
#include "src/output/gnuplot_plots.h"
#include "src/output/html_text.h"
#include "src/output/json.h"
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

std::string Slug(const std::string& name) {
  std::string slug;
  for (char c : name) slug += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return slug;
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

// The rows as whitespace-separated numbers, '?' where missing: the columns `columns`, in order.
std::string ScalarData(GnuplotPlots& plotter, const Table& table, const std::vector<int>& columns) {
  return plotter.Data("rows.dat", [&](std::ostream& out) {
    for (size_t r = 0; r < table.rows.size(); ++r) {
      for (size_t k = 0; k < columns.size(); ++k) {
        double value = 0.0;
        out << (k ? " " : "") << (table.Number(r, columns[k], &value) ? FormatNumber(value) : "?");
      }
      out << '\n';
    }
  });
}

struct Figure {
  std::string image;
  std::string caption;
};

std::vector<Figure> ScalarPlots(const SweepSpec& spec, const Table& table, GnuplotPlots& plotter) {
  std::vector<Figure> figures;
  const std::vector<int> keys = NumericKeyColumns(spec, table);
  std::vector<int> columns = keys;
  std::vector<const Response*> responses;
  for (const Response& response : kResponses) {
    const int c = table.Column(response.column);
    double value = 0.0;
    bool any = false;
    for (size_t r = 0; r < table.rows.size() && !any; ++r) any = table.Number(r, c, &value);
    if (!any) continue;
    columns.push_back(c);
    responses.push_back(&response);
  }
  if (keys.empty() || responses.empty()) return figures;
  // The drape coefficient's error bars (sweep.csv's drape_coefficient_error), the last column.
  const int error_column = table.Column(kDrapeErrorColumn);
  bool bars = false;
  for (size_t r = 0; r < table.rows.size() && error_column >= 0 && !bars; ++r) {
    double value = 0.0;
    bars = table.Number(r, error_column, &value);
  }
  if (bars) columns.push_back(error_column);
  const std::string data = ScalarData(plotter, table, columns);
  for (size_t y = 0; y < responses.size(); ++y) {
    const bool with_bars = bars && responses[y]->column == "drape_coefficient";
    for (size_t x = 0; x < keys.size(); ++x) {
      const std::string& key = table.header[keys[x]];
      const std::string png = responses[y]->column + "__" + Slug(key) + ".png";
      std::vector<std::pair<std::string, std::string>> variables = {
          {"input", data},
          {"xcol", std::to_string(x + 1)},
          {"ycol", std::to_string(keys.size() + y + 1)},
          {"xlabel", key},
          {"ylabel", responses[y]->label},
          {"title", responses[y]->label + " against " + key},
          {"logx", WideAndPositive(table, keys[x]) ? "1" : "0"}};
      if (with_bars) variables.emplace_back("errcol", std::to_string(columns.size()));
      const std::string image = plotter.Draw("sweep_scalar.gp", png, variables);
      const std::string caption =
          responses[y]->label + " against " + key +
          (with_bars ? " (bars: the discretisation error, " + std::string(kDrapeErrorColumn) + ")"
                     : "");
      if (!image.empty()) figures.push_back({image, caption});
    }
  }
  return figures;
}

// The tic list of one axis: each position labelled with its first key's value.
std::string Tics(const SweepSpec& spec, int axis) {
  int key = 0;
  while (spec.keys[key].axis != axis) ++key;
  std::vector<std::string> labels(spec.axis_sizes[axis]);
  for (const SweepTask& task : spec.tasks) labels[task.axis_index[axis]] = task.values[key].text;
  std::string tics = "(";
  for (size_t k = 0; k < labels.size(); ++k) {
    std::string label;
    for (char c : labels[k]) label += c == '"' ? '\'' : c;
    tics += (k ? ", \"" : "\"") + label + "\" " + std::to_string(k);
  }
  return tics + ")";
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

std::vector<Figure> HeatMap(const SweepSpec& spec, const Table& table, GnuplotPlots& plotter) {
  const std::vector<int> axes = VaryingAxes(spec);
  if (axes.size() != 2) return {};
  const int x_axis = axes[1], y_axis = axes[0];
  for (const char* response : {"drape_coefficient", "energy_J"}) {
    const int c = table.Column(response);
    std::string cells;
    double value = 0.0;
    for (size_t r = 0; r < table.rows.size(); ++r) {
      const int task = std::atoi(table.rows[r][0].c_str());
      if (task < 0 || task >= static_cast<int>(spec.tasks.size()) || !table.Number(r, c, &value)) {
        continue;
      }
      if (spec.tasks[task].repeat != 0) continue;
      const auto& index = spec.tasks[task].axis_index;
      cells += std::to_string(index[x_axis]) + " " + std::to_string(index[y_axis]) + " " +
               FormatNumber(value) + "\n";
    }
    if (cells.empty()) continue;
    const std::string data = plotter.Data("heatmap.dat", [&](std::ostream& out) { out << cells; });
    const std::string label =
        response == std::string("energy_J") ? "energy (J)" : "drape coefficient";
    const std::string image = plotter.Draw("sweep_heatmap.gp", std::string(response) + "__map.png",
                                           {{"input", data},
                                            {"xtics", Tics(spec, x_axis)},
                                            {"ytics", Tics(spec, y_axis)},
                                            {"xlabel", AxisName(spec, x_axis)},
                                            {"ylabel", AxisName(spec, y_axis)},
                                            {"cblabel", label},
                                            {"title", label}});
    if (image.empty()) return {};
    return {{image, label + " over the grid"}};
  }
  return {};
}

void WriteHtml(const SweepSpec& spec, const Table& table, const std::vector<Figure>& figures,
               const Provenance& provenance, const fs::path& directory, std::ostream& out) {
  out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>drape sweep "
      << HtmlText(fs::path(spec.file).filename().string())
      << "</title>\n<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;"
         "font-size:90%}td,th{border:1px solid #ccc;padding:2px 6px}figure{display:inline-block;"
         "margin:0.5em}img{max-width:800px}</style></head><body>\n";
  out << "<h1>drape sweep: " << HtmlText(spec.file) << "</h1>\n<p>base scene "
      << HtmlText(spec.scene_file) << "; design " << HtmlText(spec.design) << ", "
      << spec.tasks.size() << " tasks, " << table.rows.size()
      << " finished (sweep.csv); an empty cell is a value the task does not have.</p>\n<p>"
      << HtmlText(ProvenanceLine(provenance)) << " (sweep.json)</p>\n";
  for (const Figure& figure : figures) {
    out << "<figure>" << HtmlPngImage(directory / figure.image, figure.caption) << "<figcaption>"
        << HtmlText(figure.caption) << "</figcaption></figure>\n";
  }
  out << "<h2>Tasks</h2>\n<table><tr>";
  for (const std::string& name : table.header) out << "<th>" << HtmlText(name) << "</th>";
  out << "</tr>\n";
  for (const auto& row : table.rows) {
    out << "<tr>";
    for (const std::string& cell : row) {
      // A number rounded for people, as drape's other tables show it (sweep.csv keeps it exact).
      const std::optional<double> number = WholeNumber(cell);
      const bool shown = number && std::isfinite(*number);
      out << "<td>" << HtmlText(shown ? RoundedNumber(*number, 6) : cell) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</table>\n</body></html>\n";
}

}  // namespace

void WriteSweepReport(const SweepSpec& spec, const std::string& directory,
                      const Provenance& provenance, std::ostream& log) {
  const Table table = ReadTable(fs::path(directory) / "sweep.csv");
  GnuplotPlots plotter(directory, "", log);
  std::vector<Figure> figures = HeatMap(spec, table, plotter);
  for (Figure& figure : ScalarPlots(spec, table, plotter)) figures.push_back(std::move(figure));
  WriteAtomically(fs::path(directory) / "sweep.html", [&](std::ostream& out) {
    WriteHtml(spec, table, figures, provenance, directory, out);
  });
}

}  // namespace drape
