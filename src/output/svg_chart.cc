#include "src/output/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/output/axis_ticks.h"
#include "src/output/html_text.h"
#include "src/output/json.h"

namespace drape {
namespace {

std::string Px(double v) { return FixedText(v, 1); }

// Ticks labelled with their values (TickText).
LabelledTicks Labelled(const std::vector<double>& ticks) {
  LabelledTicks labelled;
  for (double t : ticks) labelled.emplace_back(t, TickText(t));
  return labelled;
}

// [low, high] widened by `margin` of its width on each side; a single value widened to a unit.
std::pair<double, double> Padded(double low, double high, double margin) {
  if (!(high > low)) {
    const double half = low == 0.0 ? 0.5 : 0.1 * std::abs(low);
    return {low - half, high + half};
  }
  const double pad = margin * (high - low);
  return {low - pad, high + pad};
}

// From blue (0) through pale yellow (0.5) to red (1), each light enough for black text.
std::string RampColour(double share) {
  static const double kStops[3][3] = {{69, 117, 180}, {255, 255, 191}, {215, 48, 39}};
  const double t = std::clamp(share, 0.0, 1.0) * 2.0;
  const int from = t >= 1.0 ? 1 : 0;
  const double f = t - from;
  char text[8];
  std::snprintf(
      text, sizeof text, "#%02x%02x%02x",
      static_cast<int>(std::lround(kStops[from][0] + f * (kStops[from + 1][0] - kStops[from][0]))),
      static_cast<int>(std::lround(kStops[from][1] + f * (kStops[from + 1][1] - kStops[from][1]))),
      static_cast<int>(std::lround(kStops[from][2] + f * (kStops[from + 1][2] - kStops[from][2]))));
  return text;
}

}  // namespace

std::string FixedText(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string SeriesColour(int index) {
  static const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                         "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
  return kColours[index % 10];
}

SvgPicture::SvgPicture(int width, int height, const std::string& title) {
  out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
       << "\" viewBox=\"0 0 " << width << ' ' << height << "\" role=\"img\">"
       << "<title>" << HtmlText(title) << "</title>"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>";
}

void SvgPicture::Line(double x0, double y0, double x1, double y1, const std::string& style) {
  out_ << "<line x1=\"" << Px(x0) << "\" y1=\"" << Px(y0) << "\" x2=\"" << Px(x1) << "\" y2=\""
       << Px(y1) << "\" style=\"" << style << "\"/>";
}

void SvgPicture::Circle(double x, double y, double r, const std::string& style) {
  out_ << "<circle cx=\"" << Px(x) << "\" cy=\"" << Px(y) << "\" r=\"" << Px(r) << "\" style=\""
       << style << "\"/>";
}

void SvgPicture::TitledCircle(double x, double y, double r, const std::string& style,
                              const std::string& tooltip) {
  out_ << "<g><title>" << HtmlText(tooltip) << "</title>";
  Circle(x, y, r, style);
  out_ << "</g>";
}

void SvgPicture::Rect(double x, double y, double w, double h, const std::string& style) {
  out_ << "<rect x=\"" << Px(x) << "\" y=\"" << Px(y) << "\" width=\"" << Px(w) << "\" height=\""
       << Px(h) << "\" style=\"" << style << "\"/>";
}

void SvgPicture::Polyline(const std::vector<std::array<double, 2>>& points, bool closed,
                          const std::string& style) {
  out_ << (closed ? "<polygon" : "<polyline") << " points=\"";
  for (const auto& p : points) out_ << Px(p[0]) << ',' << Px(p[1]) << ' ';
  out_ << "\" style=\"fill:none;" << style << "\"/>";
}

void SvgPicture::Text(double x, double y, const std::string& text, const std::string& anchor,
                      int size) {
  out_ << "<text x=\"" << Px(x) << "\" y=\"" << Px(y) << "\" font-family=\"sans-serif\" "
       << "font-size=\"" << size << "\" text-anchor=\"" << anchor << "\">" << HtmlText(text)
       << "</text>";
}

std::string SvgPicture::Close() { return out_.str() + "</svg>"; }

std::string TickText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void DrawChartAxes(SvgPicture* svg, const ChartAxes& a, const std::string& x_label,
                   const std::string& y_label, const LabelledTicks& x_ticks,
                   const LabelledTicks& y_ticks) {
  const std::string axis = "stroke:black;stroke-width:1";
  const std::string grid = "stroke:#ddd;stroke-width:1";
  for (const auto& [t, label] : y_ticks) {
    svg->Line(a.left, a.Y(t), a.left + a.width, a.Y(t), grid);
    svg->Text(a.left - 6, a.Y(t) + 4, label, "end", 11);
  }
  for (const auto& [t, label] : x_ticks)
    svg->Text(a.X(t), a.top + a.height + 16, label, "middle", 11);
  svg->Line(a.left, a.top + a.height, a.left + a.width, a.top + a.height, axis);
  svg->Line(a.left, a.top, a.left, a.top + a.height, axis);
  svg->Text(a.left + a.width / 2, a.top + a.height + 34, x_label);
  svg->Text(14, a.top - 12, y_label, "start");
}

void DrawChartAxes(SvgPicture* svg, const ChartAxes& a, const std::string& x_label,
                   const std::string& y_label, const std::vector<double>& x_ticks,
                   const std::vector<double>& y_ticks) {
  DrawChartAxes(svg, a, x_label, y_label, Labelled(x_ticks), Labelled(y_ticks));
}

std::string ScatterChart(const std::string& title, const std::string& x_label,
                         const std::string& y_label, const std::vector<ScatterPoint>& points,
                         bool log_x, double y_min, double y_max) {
  auto x_of = [log_x](double x) { return log_x ? std::log10(x) : x; };
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const ScatterPoint& p : points) {
    x0 = std::min(x0, x_of(p.x));
    x1 = std::max(x1, x_of(p.x));
    y0 = std::min(y0, p.y - p.error);
    y1 = std::max(y1, p.y + p.error);
  }
  if (points.empty()) x0 = y0 = 0.0, x1 = y1 = 1.0;
  const auto [x_low, x_high] = Padded(x0, x1, 0.03);
  const auto [y_padded_low, y_padded_high] = Padded(std::max(y0, y_min), std::min(y1, y_max), 0.05);
  const double y_low = std::max(y_padded_low, y_min), y_high = std::min(y_padded_high, y_max);
  const ChartAxes a{x_low, x_high, y_low, y_high};
  SvgPicture svg(480, 320, title);
  LabelledTicks x_ticks;
  if (log_x) {
    for (double decade = std::ceil(x_low); decade <= x_high; ++decade) {
      x_ticks.emplace_back(decade, TickText(std::pow(10.0, decade)));
    }
  } else {
    x_ticks = Labelled(AxisTicks(x_low, x_high, 5));
  }
  DrawChartAxes(&svg, a, x_label, y_label, x_ticks, Labelled(AxisTicks(y_low, y_high, 5)));
  const std::string colour = "#1f5fa8";
  for (const ScatterPoint& p : points) {
    if (p.error > 0.0) {
      svg.Line(a.X(x_of(p.x)), a.Y(std::max(p.y - p.error, y_low)), a.X(x_of(p.x)),
               a.Y(std::min(p.y + p.error, y_high)), "stroke:" + colour + ";stroke-width:1.5");
    }
    svg.TitledCircle(a.X(x_of(p.x)), a.Y(p.y), 4, "fill:" + colour,
                     x_label + " " + TickText(p.x) + ": " + y_label + " " + TickText(p.y) +
                         (p.error > 0.0 ? " ± " + TickText(p.error) : ""));
  }
  return svg.Close();
}

std::string HeatMapChart(const std::string& title, const std::string& x_label,
                         const std::vector<std::string>& columns, const std::string& y_label,
                         const std::vector<std::string>& rows, const std::vector<HeatCell>& cells) {
  double low = INFINITY, high = -INFINITY;
  for (const HeatCell& cell : cells) {
    low = std::min(low, cell.value);
    high = std::max(high, cell.value);
  }
  ChartAxes a{-0.5, columns.size() - 0.5, -0.5, rows.size() - 0.5};
  a.left = 110;
  a.width = 440;
  a.height = 300;
  SvgPicture svg(580, 380, title);
  LabelledTicks x_ticks, y_ticks;
  for (size_t k = 0; k < columns.size(); ++k) x_ticks.emplace_back(k, columns[k]);
  for (size_t k = 0; k < rows.size(); ++k) y_ticks.emplace_back(k, rows[k]);
  DrawChartAxes(&svg, a, x_label, y_label, x_ticks, y_ticks);  // under the cells: no grid on them
  for (const HeatCell& cell : cells) {
    const double share = high > low ? (cell.value - low) / (high - low) : 0.5;
    svg.Rect(a.X(cell.column - 0.5), a.Y(cell.row + 0.5),
             a.X(cell.column + 0.5) - a.X(cell.column - 0.5),
             a.Y(cell.row - 0.5) - a.Y(cell.row + 0.5), "fill:" + RampColour(share));
    svg.Text(a.X(cell.column), a.Y(cell.row) + 4, RoundedNumber(cell.value, 3), "middle", 11);
  }
  if (!cells.empty()) {
    svg.Text(a.left + a.width, a.top - 12,
             "blue " + RoundedNumber(low, 3) + " to red " + RoundedNumber(high, 3), "end", 11);
  }
  return svg.Close();
}

}  // namespace drape
