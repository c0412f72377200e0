// The inline-SVG charts of the HTML reports (src/output/svg_chart.h): a scatter chart with error
// bars and a log axis, a heat map with its cells, labels and colour ramp.
#include "src/output/svg_chart.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace drape {
namespace {

size_t Occurrences(const std::string& text, const std::string& what) {
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

TEST(SvgChart, AScatterChartHasAPointPerValueItsBarsAndItsTitleFirst) {
  const std::string svg =
      ScatterChart("dc against W", "W", "dc", {{8.0, 0.6, 0.05}, {16.0, 0.5, 0.0}}, false);
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_LT(svg.find("<title>dc against W</title>"), svg.find("<circle"));
  EXPECT_EQ(Occurrences(svg, "<circle"), 2u);
  EXPECT_EQ(Occurrences(svg, "stroke-width:1.5"), 1u);  // the one error bar
  EXPECT_NE(svg.find("<title>W 8: dc 0.6 ± 0.05</title>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">W</text>"), std::string::npos);
}

// A drape coefficient's axis stays within 0 to 1, its bars cut there.
TEST(SvgChart, TheYAxisStaysWithinItsLimits) {
  const std::string svg =
      ScatterChart("t", "x", "dc", {{1.0, 0.9, 0.5}, {2.0, 0.2, 0.0}}, false, 0.0, 1.0);
  EXPECT_NE(svg.find(">1</text>"), std::string::npos) << svg;
  EXPECT_EQ(svg.find(">1.2</text>"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("=\"-"), std::string::npos) << svg;  // nothing above the frame
}

TEST(SvgChart, ALogAxisIsLabelledAtItsDecades) {
  const std::string svg = ScatterChart("t", "k", "e", {{0.01, 1.0}, {10.0, 2.0}}, true);
  for (const char* decade : {">0.01</text>", ">0.1</text>", ">1</text>", ">10</text>"}) {
    EXPECT_NE(svg.find(decade), std::string::npos) << decade << "\n" << svg;
  }
}

TEST(SvgChart, AHeatMapColoursItsCellsFromBlueToRedAndLabelsThem) {
  const std::string svg = HeatMapChart("dc", "W", {"8", "16"}, "B", {"0.06", "0.24"},
                                       {{0, 0, 0.4}, {1, 0, 0.5}, {1, 1, 0.6}});
  EXPECT_EQ(Occurrences(svg, "<rect x="), 3u);                    // the missing cell is blank
  EXPECT_NE(svg.find("fill:#4575b4"), std::string::npos) << svg;  // the lowest
  EXPECT_NE(svg.find("fill:#d73027"), std::string::npos) << svg;  // the highest
  for (const char* label : {">0.4</text>", ">0.6</text>", ">16</text>", ">0.24</text>"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  EXPECT_NE(svg.find("blue 0.4 to red 0.6"), std::string::npos);
}

}  // namespace
}  // namespace drape
