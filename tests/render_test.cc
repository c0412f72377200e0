// drape.png's legend (src/output/render.h): its entries come from the table the painting reads,
// one per kind the picture draws, and each entry's mark is painted in that kind's colour.
#include "src/output/render.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

TEST(DrapeLegend, EveryKindHasOneStyleAndTheFacesDiffer) {
  std::set<DrawnKind> kinds;
  std::set<std::string> labels;
  for (const DrawnStyle& style : DrawnStyles()) {
    EXPECT_TRUE(kinds.insert(style.kind).second) << style.label;
    EXPECT_TRUE(labels.insert(style.label).second) << style.label;
    EXPECT_EQ(&StyleOf(style.kind), &style) << style.label;
  }
  EXPECT_EQ(kinds.size(), 6u);
  const Rgb up = StyleOf(DrawnKind::kUpperFace).colour,
            down = StyleOf(DrawnKind::kLowerFace).colour;
  EXPECT_FALSE(up.r == down.r && up.g == down.g && up.b == down.b);
}

// A sheet hung by one corner and held in z only at the other, over a plane.
struct Picture {
  Scene scene;
  Model model;
};

Picture SheetOverAPlane() {
  Picture picture;
  picture.scene =
      testing::LoadConfig("configs/examples/hanging_sheet.yaml",
                          {"mesh.nodes=[5,5]", "fixed[1].dofs=[z]",
                           "obstacles=[{plane: {point: [0, 0, -2], normal: [0, 0, 1]}}]"});
  picture.model = BuildModel(picture.scene);
  return picture;
}

TEST(DrapeLegend, OneEntryPerDrawnKind) {
  const Picture sheet = SheetOverAPlane();
  EXPECT_EQ(
      DrapeLegend(sheet.scene, sheet.model),
      (std::vector<DrawnKind>{DrawnKind::kUpperFace, DrawnKind::kLowerFace, DrawnKind::kFixedNode,
                              DrawnKind::kPartlyFixedNode, DrawnKind::kObstacle}));
  const Scene chain = testing::LoadConfig("configs/examples/chain.yaml");
  EXPECT_EQ(DrapeLegend(chain, BuildModel(chain)),
            (std::vector<DrawnKind>{DrawnKind::kChain, DrawnKind::kFixedNode}));
  // No fixed node and no obstacle: only the faces.
  const Scene plain =
      testing::LoadConfig("configs/examples/hanging_sheet.yaml", {"mesh.nodes=[3,3]"});
  Model model = BuildModel(plain);
  std::fill(model.fixed.begin(), model.fixed.end(), 0);
  EXPECT_EQ(DrapeLegend(plain, model),
            (std::vector<DrawnKind>{DrawnKind::kUpperFace, DrawnKind::kLowerFace}));
}

cairo_status_t ReadFromString(void* closure, unsigned char* data, unsigned int length) {
  auto* in = static_cast<std::istringstream*>(closure);
  in->read(reinterpret_cast<char*>(data), length);
  return in->gcount() == static_cast<std::streamsize>(length) ? CAIRO_STATUS_SUCCESS
                                                              : CAIRO_STATUS_READ_ERROR;
}

// The picture's legend marks are painted in their kinds' colours (read back from the PNG).
TEST(DrapeLegend, EachMarkIsPaintedInItsKindsColour) {
  const Picture sheet = SheetOverAPlane();
  DrapeViewOptions options;
  std::ostringstream png;
  DrawDrapeView(sheet.scene, sheet.model, png, options);
  std::istringstream in(png.str());
  cairo_surface_t* image = cairo_image_surface_create_from_png_stream(ReadFromString, &in);
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  ASSERT_EQ(cairo_image_surface_get_width(image), options.width);
  const unsigned char* pixels = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const std::vector<DrawnKind> legend = DrapeLegend(sheet.scene, sheet.model);
  ASSERT_EQ(legend.size(), 5u);
  for (size_t k = 0; k < legend.size(); ++k) {
    const DrawnStyle& style = StyleOf(legend[k]);
    const auto [column, row] = LegendMarkPixel(static_cast<int>(k), style.mark, options.width);
    std::uint32_t pixel = 0;  // CAIRO_FORMAT_RGB24: 0x00RRGGBB in a native 32-bit word
    std::memcpy(&pixel, pixels + row * stride + 4 * column, 4);
    const double painted[3] = {((pixel >> 16) & 0xff) / 255.0, ((pixel >> 8) & 0xff) / 255.0,
                               (pixel & 0xff) / 255.0};
    const double wanted[3] = {style.colour.r, style.colour.g, style.colour.b};
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(painted[c], wanted[c], 1.0 / 255.0) << style.label << " channel " << c;
    }
  }
  cairo_surface_destroy(image);
}

}  // namespace
}  // namespace drape
