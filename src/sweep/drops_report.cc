#include "src/sweep/drops_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "src/output/axis_ticks.h"
#include "src/output/html_text.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/writers.h"
#include "src/scene/drape_test.h"
#include "src/scene/material_models.h"

namespace drape {
namespace {

// The standard's thresholds (BS 5058; ISO 9073-9) and its three specimen diameters (m).
constexpr double kLimpBelow = 0.30;
constexpr double kStiffAbove = 0.85;
constexpr double kSmallSpecimen = 0.24;
constexpr double kStandardSpecimen = 0.30;
constexpr double kLargeSpecimen = 0.36;

std::string Fixed(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// Distinct colours for up to ten drops, then repeated.
std::string Colour(int index) {
  static const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                         "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
  return kColours[index % 10];
}

// An SVG picture written as text: elements in pixel coordinates, the title first (what a screen
// reader and a tooltip say).
class Svg {
 public:
  Svg(int width, int height, const std::string& title) {
    out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\""
         << height << "\" viewBox=\"0 0 " << width << ' ' << height << "\" role=\"img\">"
         << "<title>" << HtmlText(title) << "</title>"
         << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>";
  }
  void Line(double x0, double y0, double x1, double y1, const std::string& style) {
    out_ << "<line x1=\"" << Px(x0) << "\" y1=\"" << Px(y0) << "\" x2=\"" << Px(x1) << "\" y2=\""
         << Px(y1) << "\" style=\"" << style << "\"/>";
  }
  void Circle(double x, double y, double r, const std::string& style) {
    out_ << "<circle cx=\"" << Px(x) << "\" cy=\"" << Px(y) << "\" r=\"" << Px(r) << "\" style=\""
         << style << "\"/>";
  }
  void Rect(double x, double y, double w, double h, const std::string& style) {
    out_ << "<rect x=\"" << Px(x) << "\" y=\"" << Px(y) << "\" width=\"" << Px(w) << "\" height=\""
         << Px(h) << "\" style=\"" << style << "\"/>";
  }
  void Polyline(const std::vector<std::array<double, 2>>& points, bool closed,
                const std::string& style) {
    out_ << (closed ? "<polygon" : "<polyline") << " points=\"";
    for (const auto& p : points) out_ << Px(p[0]) << ',' << Px(p[1]) << ' ';
    out_ << "\" style=\"fill:none;" << style << "\"/>";
  }
  void Text(double x, double y, const std::string& text, const std::string& anchor = "middle",
            int size = 12) {
    out_ << "<text x=\"" << Px(x) << "\" y=\"" << Px(y) << "\" font-family=\"sans-serif\" "
         << "font-size=\"" << size << "\" text-anchor=\"" << anchor << "\">" << HtmlText(text)
         << "</text>";
  }
  std::string Close() { return out_.str() + "</svg>"; }

 private:
  static std::string Px(double v) { return Fixed(v, 1); }
  std::ostringstream out_;
};

// A plot's data window in its pixel frame.
struct Axes {
  double x0, x1, y0, y1;                                  // data
  double left = 60, top = 30, width = 400, height = 240;  // pixels
  double X(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double Y(double y) const { return top + height - (y - y0) / (y1 - y0) * height; }
};

std::string TickText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void DrawAxes(Svg* svg, const Axes& a, const std::string& x_label, const std::string& y_label,
              const std::vector<double>& x_ticks, const std::vector<double>& y_ticks) {
  const std::string axis = "stroke:black;stroke-width:1";
  const std::string grid = "stroke:#ddd;stroke-width:1";
  for (double t : y_ticks) {
    svg->Line(a.left, a.Y(t), a.left + a.width, a.Y(t), grid);
    svg->Text(a.left - 6, a.Y(t) + 4, TickText(t), "end", 11);
  }
  for (double t : x_ticks) svg->Text(a.X(t), a.top + a.height + 16, TickText(t), "middle", 11);
  svg->Line(a.left, a.top + a.height, a.left + a.width, a.top + a.height, axis);
  svg->Line(a.left, a.top, a.left, a.top + a.height, axis);
  svg->Text(a.left + a.width / 2, a.top + a.height + 34, x_label);
  svg->Text(14, a.top - 12, y_label, "start");
}

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
  Svg svg(size, size,
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
                 "stroke:" + Colour(static_cast<int>(k)) + ";stroke-width:1.5;stroke-opacity:0.8" +
                     (counted ? "" : ";stroke-dasharray:3,3"));
  }
  svg.Text(size / 2.0, disc_centre[1] + 4, "disc " + Fixed(200 * TestDiscRadius(scene), 0) + " cm");
  svg.Text(size / 2.0, 14, "flat specimen " + Fixed(200 * TestSpecimenRadius(scene), 0) + " cm");
  return svg.Close();
}

// Bars of `counts` at `centres` (width `bar` in data units).
std::string Histogram(const std::string& title, const std::string& x_label,
                      const std::vector<double>& centres, const std::vector<int>& counts,
                      double bar, const std::vector<double>& x_ticks, double mean, double sd) {
  Axes a{centres.front() - bar, centres.back() + bar, 0.0,
         static_cast<double>(*std::max_element(counts.begin(), counts.end())) + 0.5};
  Svg svg(480, 320, title);
  if (sd > 0.0) {
    svg.Rect(a.X(std::max(a.x0, mean - sd)), a.top,
             a.X(std::min(a.x1, mean + sd)) - a.X(std::max(a.x0, mean - sd)), a.height,
             "fill:#fde8c8");
  }
  std::vector<double> y_ticks;
  for (int c = 0; c <= a.y1; ++c) y_ticks.push_back(c);
  DrawAxes(&svg, a, x_label, "drops", x_ticks, y_ticks);
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
  Axes a{0.0, 360.0, 100 * TestDiscRadius(scene) * 0.95, 100 * TestSpecimenRadius(scene) * 1.02};
  a.width = 640;
  Svg svg(740, 320, "Radial profiles r(θ) of the drops' shadows around the disc's centre");
  DrawAxes(&svg, a, "θ (degrees from the warp, x)", "r (cm)", AxisTicks(0, 360, 8),
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
    svg.Polyline(points, false,
                 "stroke:" + Colour(static_cast<int>(k)) + ";stroke-width:1.2;stroke-opacity:0.8");
  }
  return svg.Close();
}

void WriteDropsTable(const DropsSummary& summary, std::ostream& html) {
  html << "<table>\n<tr><th>drop</th><th>disc centre (mm)</th><th>drape coefficient</th>"
          "<th>folds</th><th>energy (J)</th><th>counted</th><th>state</th><th>files</th></tr>\n";
  for (size_t k = 0; k < summary.drops.size(); ++k) {
    const DropRecord& d = summary.drops[k];
    const std::string folder = DropFolderName(d.drop, static_cast<int>(summary.drops.size()));
    html << "<tr><td><span style=\"color:" << Colour(static_cast<int>(k)) << "\">&#9632;</span> "
         << d.drop << "</td><td>(" << Fixed(1e3 * d.offset.x(), 2) << ", "
         << Fixed(1e3 * d.offset.y(), 2) << ")</td><td>" << Fixed(d.drape_coefficient, 3)
         << "</td><td>" << d.folds << "</td><td>" << RoundedNumber(d.energy, 6) << "</td><td>"
         << (d.counted ? "yes" : "no") << "</td><td>" << HtmlText(d.state) << "</td><td><a href=\""
         << folder << "/\">" << folder << "</a></td></tr>\n";
  }
  html << "</table>\n";
}

void WriteFabric(const Scene& scene, std::ostream& html) {
  html << "<h2>The test and the fabric</h2>\n<pre>" << HtmlText(DrapeTestText(scene))
       << "</pre>\n<table>\n<tr><th>material." << HtmlText(MaterialModelName(scene.material.model))
       << "</th><th>SI</th></tr>\n";
  for (const MaterialValue& value : MaterialSiValues(scene.material)) {
    html << "<tr><td>" << HtmlText(value.key) << "</td><td>" << RoundedNumber(value.value, 6)
         << (value.unit == "1" ? "" : " " + HtmlText(value.unit)) << "</td></tr>\n";
  }
  html << "</table>\n";
}

}  // namespace

std::optional<std::string> SpecimenSizeAdvice(double specimen_diameter, double dc) {
  if (std::abs(specimen_diameter - kStandardSpecimen) > 1e-9) return std::nullopt;
  auto advise = [&](double diameter, const std::string& why) {
    return "the drape coefficient " + Fixed(dc, 3) + " is " + why + ": BS 5058 and ISO 9073-9 " +
           "test such a fabric with a " + Fixed(100 * diameter, 0) +
           " cm specimen (--set drape_test.specimen_diameter=" + Fixed(diameter, 2) + ")";
  };
  if (dc < kLimpBelow) return advise(kSmallSpecimen, "below " + Fixed(kLimpBelow, 2));
  if (dc > kStiffAbove) return advise(kLargeSpecimen, "above " + Fixed(kStiffAbove, 2));
  return std::nullopt;
}

void WriteDropsReport(const Scene& scene, const DropsSummary& summary, const Provenance& provenance,
                      std::ostream& html) {
  const DropStatistics& s = summary.statistics;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>drape: "
       << HtmlText(scene.name) << ", " << s.drops << " drops</title>\n<style>"
       << "body{font-family:sans-serif;max-width:80em;margin:1em auto}"
       << "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px}"
       << "figure{display:inline-block;margin:0.5em}</style></head><body>\n"
       << "<h1>Drape test: " << HtmlText(scene.name) << "</h1>\n<p><b>"
       << HtmlText(DropsLine(s, summary.mesh_advice)) << "</b></p>\n";
  if (s.counted > 0) {
    if (const auto advice = SpecimenSizeAdvice(scene.drape_test->specimen_diameter, s.mean)) {
      html << "<p>Specimen size: " << HtmlText(*advice) << ".</p>\n";
    }
  }
  html << "<figure>" << OutlinesFigure(scene, summary)
       << "<figcaption>Shadows from above (dashed: not counted)</figcaption></figure>\n";
  if (s.counted > 0) {
    html << "<figure>" << DrapeCoefficientHistogram(summary)
         << "<figcaption>Drape coefficient</figcaption></figure>\n<figure>"
         << FoldsHistogram(summary) << "<figcaption>Fold count</figcaption></figure>\n";
  }
  html << "<figure>" << ProfilesFigure(scene, summary)
       << "<figcaption>Radial profiles of the shadows</figcaption></figure>\n"
       << "<h2>The drops</h2>\n";
  WriteDropsTable(summary, html);
  WriteFabric(scene, html);
  html << "<p>" << HtmlText(ProvenanceLine(provenance))
       << ". drops.csv and summary.json hold these "
       << "figures; each drop's folder holds its solve.</p>\n</body></html>\n";
}

}  // namespace drape
