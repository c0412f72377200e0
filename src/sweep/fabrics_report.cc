#include "src/sweep/fabrics_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "src/output/axis_ticks.h"
#include "src/output/json.h"
#include "src/output/report_page.h"
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

ReportBlock FabricsTable(const FabricsSpec& spec,
                         const std::vector<FabricPrediction>& predictions) {
  ReportBlock table = TableBlock(
      {{"fabric", "measured DC", "predicted DC", "Δ", "folds", "drops counted", "state", "files"}});
  for (size_t f = 0; f < spec.fabrics.size(); ++f) {
    const FabricCase& fabric = spec.fabrics[f];
    const FabricPrediction& p = predictions[f];
    const bool compared = fabric.row.measured_dc && p.drape_coefficient;
    const double delta = compared ? *p.drape_coefficient - *fabric.row.measured_dc : 0.0;
    table.rows.push_back(
        {fabric.row.name,
         PlusMinus(fabric.row.measured_dc, fabric.row.measured_dc_sd.value_or(0.0)),
         PlusMinus(p.drape_coefficient, p.error) +
             (p.standard_deviation ? " (SD " + FixedText(*p.standard_deviation, 3) + ")" : ""),
         compared ? (delta >= 0 ? "+" : "") + FixedText(delta, 3) : "",
         (p.drape_coefficient ? std::to_string(p.folds) : "") +
             (fabric.row.measured_folds
                  ? " (measured " + std::to_string(*fabric.row.measured_folds) + ")"
                  : ""),
         std::to_string(p.counted) + " of " + std::to_string(p.tasks), p.state,
         ReportLink(fabric.folder, fabric.folder + "/")});
  }
  return table;
}

// Each fabric's shadow (its first drop's), relative to the report's folder.
std::vector<ReportBlock> Shadows(const FabricsSpec& spec) {
  std::vector<ReportBlock> blocks = {HeadingBlock("The shadows")};
  for (const FabricCase& fabric : spec.fabrics) {
    const fs::path folder = fabric.folder;
    const fs::path png = spec.drops > 1 ? folder / DropFolderName(1, spec.drops) / "shadow.png"
                                        : folder / "shadow.png";
    blocks.push_back(
        ImageBlock(png.string(),
                   "The shadow of " + fabric.row.name +
                       (spec.drops > 1 ? " (drop 1 of " + std::to_string(spec.drops) + ")" : "")));
  }
  std::vector<ViewerShape> shapes;
  for (const FabricCase& fabric : spec.fabrics) {
    const fs::path glb = spec.drops > 1
                             ? fs::path(fabric.folder) / DropFolderName(1, spec.drops) / "drape.glb"
                             : fs::path(fabric.folder) / "drape.glb";
    if (fs::exists(fs::path(spec.directory) / glb))
      shapes.push_back({fabric.row.name, glb.string()});
  }
  if (!shapes.empty()) {
    blocks.push_back(View3dBlock(std::move(shapes),
                                 "The fabrics in 3D (each one's drape.glb" +
                                     std::string(spec.drops > 1 ? ", drop 1" : "") +
                                     "): the fabric, the disc, the shadow and the fold crests in "
                                     "red"));
  }
  return blocks;
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
  std::vector<ReportBlock> blocks = {
      HeadingBlock("Fabrics: " + spec.table.file),
      TextBlock(FabricsLine(summary)),
      TextBlock("Each fabric solved on " + spec.scene_label + " with its row's material" +
                (spec.drops > 1 ? ", " + std::to_string(spec.drops) +
                                      " drops each (the prediction is their mean)"
                                : "") +
                ". Δ = predicted − measured; a fabric is within its error bars when |Δ| ≤ the "
                "prediction's error bar + the measured standard deviation."),
      ChartBlock(MeasuredAgainstPredictedChart(spec, predictions),
                 "Predicted against measured: the prediction's error bar vertical, the measured "
                 "SD horizontal, dashed y = x"),
      HeadingBlock("The fabrics"),
      FabricsTable(spec, predictions),
      HeadingBlock("Which number to quote"),
      TextBlock("A lab quotes the mean drape coefficient of several specimens, and so should a "
                "prediction set beside it: one solve settles on one fold pattern, and the drape "
                "coefficient moves with the fold count (a fabric that folds into 11 lobes in one "
                "solve may fold into 7 or 8 in another). With `--drops N` (or "
                "`drape_test.drops` in the base scene) each fabric's predicted DC is the mean "
                "over N drops with its standard deviation; without, the single solve's, with the "
                "error bar of its lattice alone.")};
  for (ReportBlock& block : Shadows(spec)) blocks.push_back(std::move(block));
  blocks.push_back(TextBlock(ProvenanceLine(provenance) +
                             ". fabrics.csv and fabrics.json hold these figures (units in "
                             "fabrics.csv's headers); each fabric's folder holds its solve."));
  WriteHtmlReport(blocks, spec.directory, html);
}

}  // namespace drape
