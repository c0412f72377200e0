#include "src/sweep/drops_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "src/output/axis_ticks.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/report_page.h"
#include "src/output/svg_chart.h"
#include "src/output/writers.h"
#include "src/scene/drape_tester.h"
#include "src/scene/material_models.h"

namespace drape {
namespace {

// The standard's thresholds (BS 5058; ISO 9073-9) and its three specimen diameters (m).
constexpr double kLimpBelow = 0.30;
constexpr double kStiffAbove = 0.85;
constexpr double kSmallSpecimen = 0.24;
constexpr double kStandardSpecimen = 0.30;
constexpr double kLargeSpecimen = 0.36;

double TestDiscRadius(const Scene& scene) { return scene.drape_test->disc_diameter / 2; }
double TestSpecimenRadius(const Scene& scene) { return scene.drape_test->specimen_diameter / 2; }

std::vector<std::array<double, 2>> OutlinePoints(const DropOutline& outline) {
  std::vector<std::array<double, 2>> points;
  const int n = static_cast<int>(outline.radius.size());
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * M_PI * k / n;
    points.push_back({outline.centre.x() + outline.radius[k] * std::cos(angle),
                      outline.centre.y() + outline.radius[k] * std::sin(angle)});
  }
  return points;
}

// The top view: the flat specimen (dashed), the disc (grey) and every drop's shadow outline.
std::string OutlinesFigure(const Scene& scene, const DropsSummary& summary) {
  const int size = 480;
  const double reach = 1.05 * TestSpecimenRadius(scene);
  const double scale = size / (2 * reach);
  auto to_pixels = [&](double x, double y) -> std::array<double, 2> {
    return {(x + reach) * scale, (reach - y) * scale};
  };
  SvgPicture svg(size, size,
                 "Shadow outlines of " + std::to_string(summary.drops.size()) +
                     " drops seen from above, over the disc and the flat specimen");
  svg.Circle(size / 2.0, size / 2.0, TestSpecimenRadius(scene) * scale,
             "fill:none;stroke:#888;stroke-dasharray:6,4");
  const Eigen::Vector2d& disc = scene.drape_test->offset;
  const auto disc_centre = to_pixels(disc.x(), disc.y());
  svg.Circle(disc_centre[0], disc_centre[1], TestDiscRadius(scene) * scale,
             "fill:#e6e6e6;stroke:#555");
  for (size_t k = 0; k < summary.outlines.size(); ++k) {
    if (summary.outlines[k].radius.empty()) continue;
    std::vector<std::array<double, 2>> points;
    for (const auto& p : OutlinePoints(summary.outlines[k]))
      points.push_back(to_pixels(p[0], p[1]));
    const bool counted = summary.drops[k].counted;
    svg.Polyline(points, true,
                 "stroke:" + SeriesColour(static_cast<int>(k)) +
                     ";stroke-width:1.5;stroke-opacity:0.8" +
                     (counted ? "" : ";stroke-dasharray:3,3"));
  }
  svg.Text(size / 2.0, disc_centre[1] + 4,
           "disc " + FixedText(200 * TestDiscRadius(scene), 0) + " cm");
  svg.Text(size / 2.0, 14,
           "flat specimen " + FixedText(200 * TestSpecimenRadius(scene), 0) + " cm");
  return svg.Close();
}

// Bars of `counts` at `centres` (width `bar` in data units).
std::string Histogram(const std::string& title, const std::string& x_label,
                      const std::vector<double>& centres, const std::vector<int>& counts,
                      double bar, const std::vector<double>& x_ticks, double mean, double sd) {
  ChartAxes a{centres.front() - bar, centres.back() + bar, 0.0,
              static_cast<double>(*std::max_element(counts.begin(), counts.end())) + 0.5};
  SvgPicture svg(480, 320, title);
  if (sd > 0.0) {
    svg.Rect(a.X(std::max(a.x0, mean - sd)), a.top,
             a.X(std::min(a.x1, mean + sd)) - a.X(std::max(a.x0, mean - sd)), a.height,
             "fill:#fde8c8");
  }
  std::vector<double> y_ticks;
  for (int c = 0; c <= a.y1; ++c) y_ticks.push_back(c);
  DrawChartAxes(&svg, a, x_label, "drops", x_ticks, y_ticks);
  for (size_t k = 0; k < centres.size(); ++k) {
    if (counts[k] == 0) continue;
    svg.Rect(a.X(centres[k] - 0.45 * bar), a.Y(counts[k]),
             a.X(centres[k] + 0.45 * bar) - a.X(centres[k] - 0.45 * bar), a.Y(0) - a.Y(counts[k]),
             "fill:#1f77b4");
  }
  if (sd >= 0.0) svg.Line(a.X(mean), a.top, a.X(mean), a.top + a.height, "stroke:#d62728");
  return svg.Close();
}

std::string DrapeCoefficientHistogram(const DropsSummary& summary) {
  const DropStatistics& s = summary.statistics;
  double low = 1.0, high = 0.0;
  for (const DropRecord& drop : summary.drops) {
    if (!drop.counted) continue;
    low = std::min(low, drop.drape_coefficient);
    high = std::max(high, drop.drape_coefficient);
  }
  double bar = 0.005;
  for (double width : {0.005, 0.01, 0.02, 0.05, 0.1}) {
    bar = width;
    if ((high - low) / width <= 20) break;
  }
  const double first = std::floor(low / bar) * bar;
  std::vector<double> centres;
  std::vector<int> counts;
  for (double edge = first; edge <= high + 1e-12; edge += bar) {
    centres.push_back(edge + bar / 2);
    counts.push_back(0);
  }
  for (const DropRecord& drop : summary.drops) {
    if (!drop.counted) continue;
    const int bin = std::min(static_cast<int>(counts.size()) - 1,
                             static_cast<int>(std::floor((drop.drape_coefficient - first) / bar)));
    ++counts[std::max(0, bin)];
  }
  return Histogram(
      "Drape coefficients of the counted drops; the mean in red, ± one standard "
      "deviation shaded",
      "drape coefficient", centres, counts, bar,
      AxisTicks(centres.front() - bar, centres.back() + bar, 5), s.mean, s.standard_deviation);
}

std::string FoldsHistogram(const DropsSummary& summary) {
  const auto& histogram = summary.statistics.folds_histogram;
  std::vector<double> centres;
  std::vector<int> counts;
  for (int folds = histogram.begin()->first; folds <= histogram.rbegin()->first; ++folds) {
    centres.push_back(folds);
    const auto found = histogram.find(folds);
    counts.push_back(found == histogram.end() ? 0 : found->second);
  }
  std::vector<double> ticks(centres);
  return Histogram("Fold counts of the counted drops", "folds", centres, counts, 1.0, ticks, 0.0,
                   -1.0);
}

// r(θ) of every drop, with the disc's and the specimen's radii.
std::string ProfilesFigure(const Scene& scene, const DropsSummary& summary) {
  ChartAxes a{0.0, 360.0, 100 * TestDiscRadius(scene) * 0.95,
              100 * TestSpecimenRadius(scene) * 1.02};
  a.width = 640;
  SvgPicture svg(740, 320, "Radial profiles r(θ) of the drops' shadows around the disc's centre");
  DrawChartAxes(&svg, a, "θ (degrees from the warp, x)", "r (cm)", AxisTicks(0, 360, 8),
                AxisTicks(a.y0, a.y1, 5));
  svg.Line(a.X(0), a.Y(100 * TestDiscRadius(scene)), a.X(360), a.Y(100 * TestDiscRadius(scene)),
           "stroke:#555;stroke-dasharray:6,4");
  svg.Line(a.X(0), a.Y(100 * TestSpecimenRadius(scene)), a.X(360),
           a.Y(100 * TestSpecimenRadius(scene)), "stroke:#888;stroke-dasharray:6,4");
  for (size_t k = 0; k < summary.outlines.size(); ++k) {
    const auto& radius = summary.outlines[k].radius;
    if (radius.empty()) continue;
    std::vector<std::array<double, 2>> points;
    for (size_t j = 0; j <= radius.size(); ++j) {
      const double r = radius[j % radius.size()];
      points.push_back({a.X(360.0 * j / radius.size()), a.Y(100 * r)});
    }
    svg.Polyline(
        points, false,
        "stroke:" + SeriesColour(static_cast<int>(k)) + ";stroke-width:1.2;stroke-opacity:0.8");
  }
  return svg.Close();
}

ReportBlock DropsTable(const DropsSummary& summary) {
  ReportBlock table = TableBlock({{"drop", "disc centre (mm)", "drape coefficient", "folds",
                                   "energy (J)", "counted", "state", "files"}});
  for (size_t k = 0; k < summary.drops.size(); ++k) {
    const DropRecord& d = summary.drops[k];
    const std::string folder = DropFolderName(d.drop, static_cast<int>(summary.drops.size()));
    table.rows.push_back(
        {std::to_string(d.drop),
         "(" + FixedText(1e3 * d.offset.x(), 2) + ", " + FixedText(1e3 * d.offset.y(), 2) + ")",
         FixedText(d.drape_coefficient, 3), std::to_string(d.folds), RoundedNumber(d.energy, 6),
         d.counted ? "yes" : "no", d.state, ReportLink(folder, folder + "/")});
    table.row_colours.push_back(SeriesColour(static_cast<int>(k)));
  }
  return table;
}

ReportBlock MaterialTable(const Scene& scene) {
  ReportBlock table =
      TableBlock({{"material." + std::string(MaterialModelName(scene.material.model)), "SI"}});
  for (const MaterialValue& value : MaterialSiValues(scene.material)) {
    table.rows.push_back(
        {value.key, RoundedNumber(value.value, 6) + (value.unit == "1" ? "" : " " + value.unit)});
  }
  return table;
}

// The drops whose folders hold a drape.glb (output kind `gltf`, a drape test's default), for the
// 3D view: "drop 3: DC 0.671, 9 folds".
std::vector<ViewerShape> DropShapes(const DropsSummary& summary,
                                    const std::filesystem::path& directory) {
  std::vector<ViewerShape> shapes;
  const int drops = static_cast<int>(summary.drops.size());
  for (const DropRecord& drop : summary.drops) {
    const std::string file = DropFolderName(drop.drop, drops) + "/drape.glb";
    if (!std::filesystem::exists(directory / file)) continue;
    shapes.push_back({"drop " + std::to_string(drop.drop) + ": DC " +
                          FixedText(drop.drape_coefficient, 3) + ", " + std::to_string(drop.folds) +
                          " folds" + (drop.counted ? "" : " (not counted)"),
                      file});
  }
  return shapes;
}

}  // namespace

std::optional<std::string> SpecimenSizeAdvice(double specimen_diameter, double dc) {
  if (std::abs(specimen_diameter - kStandardSpecimen) > 1e-9) return std::nullopt;
  auto advise = [&](double diameter, const std::string& why) {
    return "the drape coefficient " + FixedText(dc, 3) + " is " + why +
           ": BS 5058 and ISO 9073-9 " + "test such a fabric with a " +
           FixedText(100 * diameter, 0) +
           " cm specimen (--set drape_test.specimen_diameter=" + FixedText(diameter, 2) + ")";
  };
  if (dc < kLimpBelow) return advise(kSmallSpecimen, "below " + FixedText(kLimpBelow, 2));
  if (dc > kStiffAbove) return advise(kLargeSpecimen, "above " + FixedText(kStiffAbove, 2));
  return std::nullopt;
}

void WriteDropsReport(const Scene& scene, const DropsSummary& summary, const Provenance& provenance,
                      std::ostream& html, const std::filesystem::path& directory) {
  const DropStatistics& s = summary.statistics;
  std::vector<ReportBlock> blocks = {HeadingBlock("Drape test: " + scene.name),
                                     TextBlock(DropsLine(s, summary.mesh_advice))};
  if (s.counted > 0) {
    if (const auto advice = SpecimenSizeAdvice(scene.drape_test->specimen_diameter, s.mean)) {
      blocks.push_back(TextBlock("Specimen size: " + *advice + "."));
    }
  }
  blocks.push_back(
      ChartBlock(OutlinesFigure(scene, summary), "Shadows from above (dashed: not counted)"));
  if (s.counted > 0) {
    blocks.push_back(ChartBlock(DrapeCoefficientHistogram(summary), "Drape coefficient"));
    blocks.push_back(ChartBlock(FoldsHistogram(summary), "Fold count"));
  }
  blocks.push_back(ChartBlock(ProfilesFigure(scene, summary), "Radial profiles of the shadows"));
  if (std::vector<ViewerShape> shapes = DropShapes(summary, directory); !shapes.empty()) {
    blocks.push_back(View3dBlock(std::move(shapes),
                                 "The drops in 3D (each drop's drape.glb): the fabric, the disc, "
                                 "the shadow and the fold crests in red"));
  }
  blocks.push_back(HeadingBlock("The drops"));
  blocks.push_back(DropsTable(summary));
  blocks.push_back(HeadingBlock("The test and the fabric"));
  blocks.push_back(PreformattedBlock(DrapeTestText(scene)));
  blocks.push_back(MaterialTable(scene));
  blocks.push_back(TextBlock(ProvenanceLine(provenance) +
                             ". drops.csv and summary.json hold these figures; each drop's folder "
                             "holds its solve."));
  WriteHtmlReport(blocks, directory, html);
}

}  // namespace drape
