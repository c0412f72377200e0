// Charts drawn as inline SVG text: the one chart path of the HTML reports (the drops report, the
// fabrics report, sweep.html), which stand alone without any program beside drape. Pixel
// coordinates, the title first (what a screen reader and a tooltip say), numbers with one decimal.
#ifndef DRAPE_SRC_OUTPUT_SVG_CHART_H_
#define DRAPE_SRC_OUTPUT_SVG_CHART_H_

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace drape {

// `value` with `decimals` decimals ("%.*f").
std::string FixedText(double value, int decimals);

// Distinct colours for up to ten series, then repeated.
std::string SeriesColour(int index);

class SvgPicture {
 public:
  SvgPicture(int width, int height, const std::string& title);
  void Line(double x0, double y0, double x1, double y1, const std::string& style);
  void Circle(double x, double y, double r, const std::string& style);
  void Rect(double x, double y, double w, double h, const std::string& style);
  void Polyline(const std::vector<std::array<double, 2>>& points, bool closed,
                const std::string& style);
  void Text(double x, double y, const std::string& text, const std::string& anchor = "middle",
            int size = 12);
  // A circle with a tooltip (a group with a <title>): what a pointer over it shows.
  void TitledCircle(double x, double y, double r, const std::string& style,
                    const std::string& tooltip);
  std::string Close();

 private:
  std::ostringstream out_;
};

// A chart's data window in its pixel frame.
struct ChartAxes {
  double x0, x1, y0, y1;                                  // data
  double left = 60, top = 30, width = 400, height = 240;  // pixels
  double X(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double Y(double y) const { return top + height - (y - y0) / (y1 - y0) * height; }
};

// "%g" of a tick.
std::string TickText(double value);

// The frame, the grid at `y_ticks`, the tick labels and the axis labels.
void DrawChartAxes(SvgPicture* svg, const ChartAxes& axes, const std::string& x_label,
                   const std::string& y_label, const std::vector<double>& x_ticks,
                   const std::vector<double>& y_ticks);

// A tick: where on its axis (data units) and its label.
using LabelledTicks = std::vector<std::pair<double, std::string>>;

// The same with labelled ticks (a log axis's decades, a grid's values).
void DrawChartAxes(SvgPicture* svg, const ChartAxes& axes, const std::string& x_label,
                   const std::string& y_label, const LabelledTicks& x_ticks,
                   const LabelledTicks& y_ticks);

// A point of a scatter chart, with a ± bar on y (0: none).
struct ScatterPoint {
  double x = 0.0, y = 0.0, error = 0.0;
};

// The points in one colour against their axes (x logarithmic when `log_x`, every x then > 0),
// which span the points and their bars, the y axis within [y_min, y_max] (a drape coefficient's
// 0 to 1: bars beyond it are cut at it); `title` first.
std::string ScatterChart(const std::string& title, const std::string& x_label,
                         const std::string& y_label, const std::vector<ScatterPoint>& points,
                         bool log_x, double y_min = -INFINITY, double y_max = INFINITY);

// A cell of a heat map: its column and row (from 0) and its value.
struct HeatCell {
  int column = 0, row = 0;
  double value = 0.0;
};

// The cells coloured from blue (the lowest value) to red (the highest), each labelled with its
// value (3 digits); the columns and rows labelled; cells not given left blank.
std::string HeatMapChart(const std::string& title, const std::string& x_label,
                         const std::vector<std::string>& columns, const std::string& y_label,
                         const std::vector<std::string>& rows, const std::vector<HeatCell>& cells);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_SVG_CHART_H_
