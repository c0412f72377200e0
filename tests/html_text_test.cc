#include "src/output/html_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace drape {
namespace {

TEST(Base64, EncodesTheStandardsVectors) {  // RFC 4648, section 10
  EXPECT_EQ(Base64(""), "");
  EXPECT_EQ(Base64("f"), "Zg==");
  EXPECT_EQ(Base64("fo"), "Zm8=");
  EXPECT_EQ(Base64("foo"), "Zm9v");
  EXPECT_EQ(Base64("foob"), "Zm9vYg==");
  EXPECT_EQ(Base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(Base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(Base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(HtmlPngImage, EmbedsTheFileAndEscapesItsAltText) {
  const std::filesystem::path png =
      std::filesystem::path(::testing::TempDir()) / "drape_html_text_test.png";
  std::ofstream(png, std::ios::binary) << "foobar";
  EXPECT_EQ(HtmlPngImage(png, "a <b> & \"c\""),
            "<img alt=\"a &lt;b&gt; &amp; &quot;c&quot;\" src=\"data:image/png;base64,Zm9vYmFy\">");
  std::filesystem::remove(png);
}

}  // namespace
}  // namespace drape
