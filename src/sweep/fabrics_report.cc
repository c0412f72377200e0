#include "src/sweep/fabrics_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "src/output/axis_ticks.h"
#include "src/output/html_text.h"
#include "src/output/json.h"
#include "src/output/svg_chart.h"
#include "src/sweep/drops.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

struct ChartPoint {
  std::string name;
  double measured, measured_sd, predicted, error;
};

std::vector<ChartPoint> ChartPoints(const FabricsSpec& spec,
                                    const std::vector<FabricPrediction>& predictions) {
  std::vector<ChartPoint> points;
  for (size_t f = 0; f < spec.fabrics.size(); ++f) {
    const FabricRow& row = spec.fabrics[f].row;
    const FabricPrediction& p = predictions[f];
    if (!row.measured_dc || !p.drape_coefficient) continue;
    points.push_back({row.name, *row.measured_dc, row.measured_dc_sd.value_or(0.0),
                      *p.drape_coefficient, p.error});
  }
  return points;
}

std::string PlusMinus(const std::optional<double>& value, double bar) {
  if (!value) return "";
  return FixedText(*value, 3) + (bar > 0.0 ? " ± " + FixedText(bar, 3) : "");
}

void WriteTable(const FabricsSpec& spec, const std::vector<FabricPrediction>& predictions,
                std::ostream& html) {
  html << "<table>\n<tr><th>fabric</th><th>measured DC</th><th>predicted DC</th><th>Δ</th>"
          "<th>folds</th><th>drops counted</th><th>state</th><th>files</th></tr>\n";
  for (size_t f = 0; f < spec.fabrics.size(); ++f) {
    const FabricCase& fabric = spec.fabrics[f];
    const FabricPrediction& p = predictions[f];
    const bool compared = fabric.row.measured_dc && p.drape_coefficient;
    const double delta = compared ? *p.drape_coefficient - *fabric.row.measured_dc : 0.0;
    html << "<tr><td>" << HtmlText(fabric.row.name) << "</td><td>"
         << PlusMinus(fabric.row.measured_dc, fabric.row.measured_dc_sd.value_or(0.0))
         << "</td><td>" << PlusMinus(p.drape_coefficient, p.error)
         << (p.standard_deviation ? " (SD " + FixedText(*p.standard_deviation, 3) + ")" : "")
         << "</td><td>" << (compared ? (delta >= 0 ? "+" : "") + FixedText(delta, 3) : "")
         << "</td><td>" << (p.drape_coefficient ? std::to_string(p.folds) : "") << "</td><td>"
         << p.counted << " of " << p.tasks << "</td><td>" << HtmlText(p.state)
         << "</td><td><a href=\"" << HtmlText(fabric.folder) << "/\">" << HtmlText(fabric.folder)
         << "</a></td></tr>\n";
  }
  html << "</table>\n";
}

void WriteShadows(const FabricsSpec& spec, const fs::path& directory, std::ostream& html) {
  html << "<h2>The shadows</h2>\n";
  for (const FabricCase& fabric : spec.fabrics) {
    const fs::path folder = directory / fabric.folder;
    const fs::path png = spec.drops > 1 ? folder / DropFolderName(1, spec.drops) / "shadow.png"
                                        : folder / "shadow.png";
    const std::string caption =
        fabric.row.name + (spec.drops > 1 ? " (drop 1 of " + std::to_string(spec.drops) + ")" : "");
    html << "<figure>" << HtmlPngImage(png, "the shadow of " + caption) << "<figcaption>"
         << HtmlText(caption) << "</figcaption></figure>\n";
  }
}

}  // namespace

std::string MeasuredAgainstPredictedChart(const FabricsSpec& spec,
                                          const std::vector<FabricPrediction>& predictions) {
  const std::vector<ChartPoint> points = ChartPoints(spec, predictions);
  double low = 1.0, high = 0.0;
  for (const ChartPoint& p : points) {
    low = std::min({low, p.measured - p.measured_sd, p.predicted - p.error});
    high = std::max({high, p.measured + p.measured_sd, p.predicted + p.error});
  }
  if (points.empty()) low = 0.0, high = 1.0;
  low = std::max(0.0, std::floor(low * 10.0) / 10.0);
  high = std::min(1.0, std::ceil(high * 10.0) / 10.0);
  if (high - low < 0.1) high = std::min(1.0, low + 0.1), low = high - 0.1;
  ChartAxes a{low, high, low, high};
  a.width = a.height = 360;
  a.left = 70;
  SvgPicture svg(480, 460,
                 "Predicted against measured drape coefficient, " + std::to_string(points.size()) +
                     (points.size() == 1 ? " fabric" : " fabrics"));
  const std::vector<double> ticks = AxisTicks(low, high, 6);
  DrawChartAxes(&svg, a, "measured drape coefficient", "predicted drape coefficient", ticks, ticks);
  svg.Line(a.X(low), a.Y(low), a.X(high), a.Y(high), "stroke:#888;stroke-dasharray:4 3");
  for (size_t k = 0; k < points.size(); ++k) {
    const ChartPoint& p = points[k];
    const std::string colour = SeriesColour(static_cast<int>(k));
    const std::string bar = "stroke:" + colour + ";stroke-width:1.5";
    svg.Line(a.X(p.measured), a.Y(p.predicted - p.error), a.X(p.measured),
             a.Y(p.predicted + p.error), bar);
    if (p.measured_sd > 0.0) {
      svg.Line(a.X(p.measured - p.measured_sd), a.Y(p.predicted), a.X(p.measured + p.measured_sd),
               a.Y(p.predicted), bar);
    }
    svg.TitledCircle(a.X(p.measured), a.Y(p.predicted), 4, "fill:" + colour,
                     p.name + ": measured " + FixedText(p.measured, 3) + ", predicted " +
                         FixedText(p.predicted, 3) + " ± " + FixedText(p.error, 3));
    svg.Text(a.X(p.measured) + 7, a.Y(p.predicted) - 5, p.name, "start", 11);
  }
  return svg.Close();
}

void WriteFabricsReport(const FabricsSpec& spec, const std::vector<FabricPrediction>& predictions,
                        const FabricsSummary& summary, const Provenance& provenance,
                        std::ostream& html) {
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>drape fabrics: "
       << HtmlText(spec.table.file) << "</title>\n<style>"
       << "body{font-family:sans-serif;max-width:80em;margin:1em auto}"
       << "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px}"
       << "figure{display:inline-block;margin:0.5em}img{width:300px}</style></head><body>\n"
       << "<h1>Fabrics: " << HtmlText(spec.table.file) << "</h1>\n<p><b>"
       << HtmlText(FabricsLine(summary)) << "</b></p>\n<p>Each fabric solved on "
       << HtmlText(spec.scene_label) << " with its row's material"
       << (spec.drops > 1 ? ", " + std::to_string(spec.drops) +
                                " drops each (the prediction is "
                                "their mean)"
                          : "")
       << ". Δ = predicted − measured; a fabric is within its error bars when |Δ| ≤ the "
          "prediction's error bar + the measured standard deviation.</p>\n"
       << "<figure>" << MeasuredAgainstPredictedChart(spec, predictions)
       << "<figcaption>Predicted against measured: the prediction's error bar vertical, the "
          "measured SD horizontal, dashed y = x</figcaption></figure>\n<h2>The fabrics</h2>\n";
  WriteTable(spec, predictions, html);
  html
      << "<h2>Which number to quote</h2>\n<p>A lab quotes the mean drape coefficient of several "
         "specimens, and so should a prediction set beside it: one solve settles on one fold "
         "pattern, and the drape coefficient moves with the fold count (a fabric that folds "
         "into 11 lobes in one solve may fold into 7 or 8 in another). With <code>--drops N</code> "
         "(or <code>drape_test.drops</code> in the base scene) each fabric's predicted DC is "
         "the mean over N drops with its standard deviation; without, the single solve's, with "
         "the error bar of its lattice alone.</p>\n";
  WriteShadows(spec, fs::path(spec.directory), html);
  html
      << "<p>" << HtmlText(ProvenanceLine(provenance))
      << ". fabrics.csv and fabrics.json hold these figures (units in fabrics.csv's headers); each "
         "fabric's folder holds its solve.</p>\n</body></html>\n";
}

}  // namespace drape
