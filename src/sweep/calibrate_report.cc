#include "src/sweep/calibrate_report.h"

#include <algorithm>
#include <cmath>

#include "src/output/axis_ticks.h"
#include "src/output/report_page.h"
#include "src/output/svg_chart.h"

namespace drape {
namespace {

std::string Signed(double value) { return (value >= 0 ? "+" : "") + FixedText(value, 3); }

std::string WithDifference(const std::optional<double>& value,
                           const std::optional<double>& measured) {
  if (!value) return "";
  return FixedText(*value, 3) + (measured ? " (" + Signed(*value - *measured) + ")" : "");
}

// The chart's window: the drape coefficients shown (with `grid`, every grid point's too), out to
// tenths.
std::pair<double, double> Window(const CalibrateSummary& s, bool grid = false) {
  double low = 1.0, high = 0.0;
  auto widen = [&](const std::optional<double>& value) {
    if (value) low = std::min(low, *value), high = std::max(high, *value);
  };
  for (size_t f = 0; f < s.fabric_names.size(); ++f) {
    if (!s.measured[f]) continue;
    widen(s.measured[f]);
    widen(s.uncalibrated[f]);
    widen(s.calibrated[f]);
    if (s.left_out[f]) widen(s.left_out[f]->predicted);
    if (grid) {
      for (const auto& dc : s.grid.dc[f]) widen(dc);
    }
  }
  if (low > high) return {0.0, 1.0};
  low = std::max(0.0, std::floor(low * 10.0) / 10.0);
  high = std::min(1.0, std::ceil(high * 10.0) / 10.0);
  if (high - low < 0.1) high = std::min(1.0, low + 0.1), low = high - 0.1;
  return {low, high};
}

ReportBlock CalibratedFabricsTable(const CalibrateSummary& s) {
  std::vector<std::string> header = {"fabric", "measured DC", "uncalibrated (Δ)", "calibrated (Δ)",
                                     "left out (Δ)"};
  for (const std::string& name : s.constants) header.push_back(name + " without it");
  ReportBlock table = TableBlock({header});
  for (size_t f = 0; f < s.fabric_names.size(); ++f) {
    const std::optional<LeftOut>& left = s.left_out[f];
    std::vector<std::string> row = {s.fabric_names[f],
                                    s.measured[f] ? FixedText(*s.measured[f], 3) : "",
                                    WithDifference(s.uncalibrated[f], s.measured[f]),
                                    WithDifference(s.calibrated[f], s.measured[f]),
                                    left ? WithDifference(left->predicted, s.measured[f]) : ""};
    for (size_t c = 0; c < s.constants.size(); ++c) {
      row.push_back(left ? FixedText(left->fit.values[c], 3) : "");
    }
    table.rows.push_back(row);
  }
  return table;
}

std::string StatisticsText(const CalibrateSummary& s) {
  return "Mean |Δ| over the " + std::to_string(s.fitted_fabrics) +
         " fitted fabrics: " + FixedText(s.before.mean_abs_difference, 3) + " uncalibrated, " +
         FixedText(s.after.mean_abs_difference, 3) + " calibrated (solved at the fitted " +
         "constants), " + FixedText(s.leave_one_out.mean_abs_difference, 3) +
         " left out (each fabric predicted by the constants fitted to the others, read from the "
         "grid's interpolant): the last is the error to expect on a fabric the calibration did "
         "not see.";
}

// One constant: each fabric's solved DC at the grid's points, its measured DC dashed, the fitted
// value a vertical line. x is the grid's index (the fit interpolates linearly in it).
std::string AlongTheGridChart(const CalibrateSummary& s) {
  const std::vector<double>& axis = s.grid.axes.front();
  const auto [low, high] = Window(s, /*grid=*/true);
  ChartAxes a{0.0, static_cast<double>(axis.size() - 1), low, high};
  a.width = 480;
  a.height = 300;
  a.left = 70;
  SvgPicture svg(640, 400, "Each fabric's drape coefficient along " + s.constants.front());
  LabelledTicks x_ticks;
  for (size_t k = 0; k < axis.size(); ++k) x_ticks.emplace_back(k, FixedText(axis[k], 3));
  LabelledTicks y_ticks;
  for (const double y : AxisTicks(low, high, 6)) y_ticks.emplace_back(y, TickText(y));
  DrawChartAxes(&svg, a, s.constants.front(), "drape coefficient", x_ticks, y_ticks);
  int series = 0;
  for (size_t f = 0; f < s.fabric_names.size(); ++f) {
    if (!s.measured[f]) continue;
    const std::string colour = SeriesColour(series++);
    std::vector<std::array<double, 2>> points;
    for (size_t k = 0; k < axis.size(); ++k) {
      const auto& dc = s.grid.dc[f][k];
      if (dc && *dc >= low && *dc <= high) points.push_back({a.X(k), a.Y(*dc)});
    }
    if (points.size() > 1) svg.Polyline(points, false, "fill:none;stroke:" + colour);
    for (const auto& p : points) svg.Circle(p[0], p[1], 2.5, "fill:" + colour);
    if (*s.measured[f] >= low && *s.measured[f] <= high) {
      svg.Line(a.X(0), a.Y(*s.measured[f]), a.X(axis.size() - 1), a.Y(*s.measured[f]),
               "stroke:" + colour + ";stroke-dasharray:4 3");
    }
    if (!points.empty())
      svg.Text(points.back()[0] + 5, points.back()[1], s.fabric_names[f], "start", 10);
  }
  if (!s.fit.coordinates.empty()) {
    const double x = a.X(s.fit.coordinates.front());
    svg.Line(x, a.Y(low), x, a.Y(high), "stroke:#000;stroke-width:1.5");
  }
  return svg.Close();
}

// Two constants: the RMS of predicted − measured over the fitted fabrics at each grid point.
std::string RmsOverGridChart(const CalibrateSummary& s) {
  const std::vector<int> fabrics = FittableFabrics(s.grid);
  std::vector<HeatCell> cells;
  for (int point = 0; point < s.grid.Points(); ++point) {
    double squares = 0.0;
    for (const int f : fabrics) {
      const double delta = *s.grid.dc[f][point] - *s.measured[f];
      squares += delta * delta;
    }
    const std::vector<int> indices = s.grid.Indices(point);
    cells.push_back(
        {indices[0], indices[1], std::sqrt(squares / std::max<size_t>(1, fabrics.size()))});
  }
  std::vector<std::string> columns, rows;
  for (const double v : s.grid.axes[0]) columns.push_back(FixedText(v, 3));
  for (const double v : s.grid.axes[1]) rows.push_back(FixedText(v, 3));
  return HeatMapChart("RMS of predicted − measured over the grid", s.constants[0], columns,
                      s.constants[1], rows, cells);
}

}  // namespace

std::string CalibrationChart(const CalibrateSummary& s) {
  const std::pair<double, double> window = Window(s);
  const double low = window.first, high = window.second;
  ChartAxes a{low, high, low, high};
  a.width = a.height = 360;
  a.left = 70;
  SvgPicture svg(480, 460, "Predicted against measured, before and after the calibration");
  const std::vector<double> ticks = AxisTicks(low, high, 6);
  DrawChartAxes(&svg, a, "measured drape coefficient", "predicted drape coefficient", ticks, ticks);
  svg.Line(a.X(low), a.Y(low), a.X(high), a.Y(high), "stroke:#888;stroke-dasharray:4 3");
  auto inside = [&](double v) { return v >= low && v <= high; };
  for (size_t f = 0; f < s.fabric_names.size(); ++f) {
    if (!s.measured[f] || !inside(*s.measured[f])) continue;
    const double x = a.X(*s.measured[f]);
    const std::string& name = s.fabric_names[f];
    if (s.uncalibrated[f] && inside(*s.uncalibrated[f])) {
      svg.TitledCircle(x, a.Y(*s.uncalibrated[f]), 4, "fill:none;stroke:#888;stroke-width:1.5",
                       name + ": uncalibrated " + FixedText(*s.uncalibrated[f], 3));
    }
    if (s.left_out[f] && inside(s.left_out[f]->predicted)) {
      const double y = a.Y(s.left_out[f]->predicted);
      svg.Line(x - 4, y - 4, x + 4, y + 4, "stroke:#d62728;stroke-width:1.5");
      svg.Line(x - 4, y + 4, x + 4, y - 4, "stroke:#d62728;stroke-width:1.5");
    }
    if (s.calibrated[f] && inside(*s.calibrated[f])) {
      svg.TitledCircle(x, a.Y(*s.calibrated[f]), 4, "fill:#1f77b4",
                       name + ": measured " + FixedText(*s.measured[f], 3) + ", calibrated " +
                           FixedText(*s.calibrated[f], 3));
      svg.Text(x + 7, a.Y(*s.calibrated[f]) - 5, name, "start", 11);
    }
  }
  return svg.Close();
}

std::string CalibrationGridChart(const CalibrateSummary& s) {
  return s.grid.axes.size() == 1 ? AlongTheGridChart(s) : RmsOverGridChart(s);
}

void WriteCalibrateReport(const CalibrateSummary& s, const Provenance& provenance,
                          std::ostream& html) {
  std::vector<ReportBlock> blocks = {
      HeadingBlock("Calibration: " + s.fitted.Text()),
      TextBlock(CalibrateLine(s)),
      TextBlock(StatisticsText(s)),
      ChartBlock(CalibrationChart(s),
                 "Grey rings: uncalibrated; blue dots: solved at the fitted constants; red "
                 "crosses: left out (the constants fitted without the fabric); dashed y = x"),
      ChartBlock(CalibrationGridChart(s),
                 s.grid.axes.size() == 1
                     ? "Each measured fabric's solved DC at the grid's points (its measured DC "
                       "dashed in its colour); the fitted value the black line"
                     : "The fit's RMS difference at each grid point"),
      HeadingBlock("The fabrics"),
      CalibratedFabricsTable(s),
      HeadingBlock("Using it"),
      TextBlock("`calibration.yaml` is the calibration: `drape solve SCENE --calibration "
                "calibration.yaml` and `drape fabrics TABLE --calibration calibration.yaml` apply "
                "it to their fabrics and record it in every result's provenance. `grid/` holds "
                "the table solved at each grid point, `calibrated/` at the fitted constants, each "
                "a complete `drape fabrics` result.")};
  if (s.fit.at_edge) {
    blocks.insert(blocks.begin() + 2,
                  TextBlock("The fit lies at the end of a constant's grid: the best value may lie "
                            "beyond the searched range, and the calibration is that end's."));
  }
  blocks.push_back(TextBlock(ProvenanceLine(provenance) + "."));
  WriteHtmlReport(blocks, s.directory, html);
}

}  // namespace drape
