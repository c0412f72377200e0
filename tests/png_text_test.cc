#include "src/output/png_text.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "src/output/version.h"

namespace drape {
namespace {

// A small PNG as cairo writes it.
std::string CairoPng() {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 4, 3);
  std::string png;
  cairo_surface_write_to_png_stream(
      surface,
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &png);
  cairo_surface_destroy(surface);
  return png;
}

// Cairo reads the picture back as it was (the chunk's CRC is right: libpng refuses a wrong one),
// and the chunk says drape's version.
TEST(PngText, CairoReadsThePictureBackWithTheVersionInIt) {
  const std::string png = PngWithDrapeVersion(CairoPng());
  EXPECT_EQ(PngTexts(png).at("Software"), "drape " + DrapeVersion());
  size_t offset = 0;
  std::pair<const std::string*, size_t*> state{&png, &offset};
  cairo_surface_t* surface = cairo_image_surface_create_from_png_stream(
      [](void* closure, unsigned char* data, unsigned int length) {
        auto* read = static_cast<std::pair<const std::string*, size_t*>*>(closure);
        if (*read->second + length > read->first->size()) return CAIRO_STATUS_READ_ERROR;
        read->first->copy(reinterpret_cast<char*>(data), length, *read->second);
        *read->second += length;
        return CAIRO_STATUS_SUCCESS;
      },
      &state);
  EXPECT_EQ(cairo_surface_status(surface), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(surface), 4);
  cairo_surface_destroy(surface);
}

TEST(PngText, LeavesWhatIsNotAPngAlone) {
  EXPECT_EQ(PngWithDrapeVersion("not a picture"), "not a picture");
  EXPECT_TRUE(PngTexts("not a picture").empty());
}

}  // namespace
}  // namespace drape
