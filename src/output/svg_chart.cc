#include "src/output/svg_chart.h"

#include <cstdio>

#include "src/output/html_text.h"

namespace drape {
namespace {

std::string Px(double v) { return FixedText(v, 1); }

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
                   const std::string& y_label, const std::vector<double>& x_ticks,
                   const std::vector<double>& y_ticks) {
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

}  // namespace drape
