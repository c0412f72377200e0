// The reports' 3D view (src/output/viewer3d.h): a page without three.js says so and links the
// files; and, in a real browser (Debian's chromium-headless-shell, WebGL by SwiftShader), the
// drops, fabrics and sweep reports load with no script error and every view draws its shape on a
// canvas that is not blank.
#include "src/output/viewer3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "src/output/report_page.h"
#include "tests/run_program.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using testing::DrapeCommand;
using testing::ProgramOutcome;
using testing::RunProgram;

std::string HtmlOf(const std::vector<ReportBlock>& blocks, const fs::path& folder) {
  std::ostringstream html;
  WriteHtmlReport(blocks, folder, html);
  return html.str();
}

TEST(Viewer3d, WithoutThreeJsThePageSaysSoAndLinksTheFiles) {
  testing::ScratchFolder folder("viewer3d_test");
  std::ofstream(folder / "drape.glb") << "glTF";
  ASSERT_EQ(setenv("DRAPE_THREE_JS_DIR", (folder / "nowhere").c_str(), 1), 0);
  const std::string html =
      HtmlOf({View3dBlock({{"the cotton", "drape.glb"}}, "In 3D")}, folder.path());
  unsetenv("DRAPE_THREE_JS_DIR");
  EXPECT_NE(html.find("3D view not drawn: three.js not found: cannot read "), std::string::npos);
  EXPECT_NE(html.find("<a href=\"drape.glb\">the cotton</a>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<canvas"), std::string::npos);
}

TEST(Viewer3d, TheMarkdownLinksTheFiles) {
  std::ostringstream markdown;
  WriteMarkdownReport({View3dBlock({{"drop 1", "drops/01/drape.glb"}}, "In 3D")}, markdown);
  EXPECT_NE(markdown.str().find("[drop 1](drops/01/drape.glb)"), std::string::npos);
}

// A page's views embed three.js once and each shape's file; a file that cannot be read is left
// out of its list.
TEST(Viewer3d, ThePageEmbedsThreeJsOnceAndEachReadableShape) {
  if (!fs::exists(ThreeJsFolder() / "three.min.js")) GTEST_SKIP() << "no libjs-three";
  testing::ScratchFolder folder("viewer3d_test");
  std::ofstream(folder / "a.glb") << "AAAA";
  const std::string html = HtmlOf({View3dBlock({{"a", "a.glb"}, {"gone", "gone.glb"}}, "one"),
                                   View3dBlock({{"a again", "a.glb"}}, "two")},
                                  folder.path());
  EXPECT_EQ(std::count(html.begin(), html.end(), '\0'), 0);
  size_t loaders = 0;
  for (size_t at = html.find("exports.GLTFLoader = GLTFLoader"); at != std::string::npos;
       at = html.find("exports.GLTFLoader = GLTFLoader", at + 1)) {
    ++loaders;
  }
  EXPECT_EQ(loaders, 1u);
  EXPECT_NE(html.find("drapeViewer('drape-view-0')"), std::string::npos);
  EXPECT_NE(html.find("drapeViewer('drape-view-1')"), std::string::npos);
  EXPECT_NE(html.find("\"QUFBQQ==\""), std::string::npos);  // "AAAA" in base64
  EXPECT_EQ(html.find(">gone<"), std::string::npos);
}

// A view holds the first kViewerMaxShapes shapes and says how many of how many.
TEST(Viewer3d, AViewHoldsAtMostItsShareOfShapesAndSaysSo) {
  testing::ScratchFolder folder("viewer3d_test");
  std::vector<ViewerShape> shapes;
  for (size_t k = 0; k < kViewerMaxShapes + 6; ++k) {
    const std::string file = std::to_string(k) + ".glb";
    std::ofstream(folder / file) << "glTF";
    shapes.push_back({"shape " + std::to_string(k), file});
  }
  const std::string html = ViewerHtml(shapes, folder.path(), 0);
  EXPECT_NE(html.find(">shape " + std::to_string(kViewerMaxShapes - 1) + "<"), std::string::npos);
  EXPECT_EQ(html.find(">shape " + std::to_string(kViewerMaxShapes) + "<"), std::string::npos);
  EXPECT_NE(html.find("(the first " + std::to_string(kViewerMaxShapes) + " of " +
                      std::to_string(kViewerMaxShapes + 6) + " shapes;"),
            std::string::npos);
}

// The browser the test drives; empty where it is not installed.
std::string Browser() {
  for (const char* path : {"/usr/bin/chromium-headless-shell", "/usr/bin/chromium"}) {
    if (fs::exists(path)) return path;
  }
  return "";
}

// The page's DOM after its scripts ran, as the browser serialises it (--dump-dom); WebGL by
// SwiftShader, as on a machine without a GPU.
std::string LoadedDom(const fs::path& page, const fs::path& scratch) {
  const std::string command =
      ShellQuoted(Browser()) +
      " --headless --no-sandbox --disable-gpu-sandbox --use-angle=swiftshader "
      "--enable-unsafe-swiftshader --window-size=1200,900 --virtual-time-budget=60000 "
      "--dump-dom " +
      ShellQuoted("file://" + fs::absolute(page).string());
  const ProgramOutcome outcome = RunProgram("timeout 180 " + command, scratch);
  EXPECT_EQ(outcome.exit_status, 0) << outcome.err;
  return outcome.out;
}

// Every view of the page drew a shape on a canvas with painted pixels, and no script failed.
void ExpectEveryViewDrawn(const fs::path& page, const fs::path& scratch, int views) {
  ASSERT_TRUE(fs::exists(page)) << page;
  const std::string dom = LoadedDom(page, scratch);
  // The attributes as set (the script that sets them is in the DOM too, without `="`).
  for (const char* error : {"data-script-error=\"", " data-error=\""}) {
    const size_t at = dom.find(error);
    EXPECT_EQ(at, std::string::npos) << page << ": " << dom.substr(at, 300);
  }
  EXPECT_EQ(dom.find("3D view not drawn"), std::string::npos) << page;
  const std::regex drawn(
      R"re(class="drape-view" id="drape-view-\d+"[^>]*data-drawn="[^"]+"[^>]*data-painted="(\d+)")re");
  int seen = 0;
  for (std::sregex_iterator it(dom.begin(), dom.end(), drawn), end; it != end; ++it) {
    ++seen;
    EXPECT_GT(std::stoi((*it)[1].str()), 5000) << "a blank canvas in " << page;
  }
  EXPECT_EQ(seen, views) << page << "\n" << dom.substr(0, 2000);
}

class BrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (Browser().empty() || !fs::exists(ThreeJsFolder() / "three.min.js")) {
      // CI installs both (README's test command): there, a missing one is a failure.
      if (std::getenv("CI")) FAIL() << "no headless Chromium or three.js on CI";
      GTEST_SKIP() << "no headless Chromium (chromium-headless-shell) or three.js (libjs-three)";
    }
  }
  ProgramOutcome Drape(const std::vector<std::string>& args) const {
    return RunProgram(DrapeCommand(args), scratch_.path());
  }
  std::string Tester() const {
    return std::string(drape_tests::kSourceDir) + "/configs/fv/drape_tester_cotton_30.yaml";
  }
  testing::ScratchFolder scratch_{"viewer3d_browser_test"};
};

TEST_F(BrowserTest, TheDropsReportShowsTheDropsIn3d) {
  const fs::path out = scratch_ / "drops";
  const ProgramOutcome run = Drape({"solve", Tester(), "--drops", "2", "--threads", "1", "--set",
                                    "mesh.spacing=0.02", "-o", out.string()});
  ASSERT_NE(run.exit_status, 2) << run.err;
  ExpectEveryViewDrawn(out / "report.html", scratch_.path(), 1);
}

TEST_F(BrowserTest, TheFabricsReportShowsTheFabricsIn3d) {
  const fs::path table = scratch_ / "fabrics.csv";
  std::ofstream(table) << "name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft,"
                          "measured_dc\nstiff,12,0.12,0.08,0.9,4,7,0.70\n"
                          "limp,8,0.02,0.02,0.4,4,7,0.40\n";
  const fs::path out = scratch_ / "fabrics";
  const ProgramOutcome run = Drape({"fabrics", table.string(), "--threads", "1", "--set",
                                    "mesh.spacing=0.05", "-o", out.string()});
  ASSERT_NE(run.exit_status, 2) << run.err;
  ExpectEveryViewDrawn(out / "report.html", scratch_.path(), 1);
}

TEST_F(BrowserTest, TheSweepReportShowsTheKeptShapesIn3d) {
  const fs::path sweep = scratch_ / "sweep.yaml";
  std::ofstream(sweep) << "scene: " << Tester()
                       << "\nset:\n  mesh.spacing: 0.05\ngrid:\n  material.finite_volume.kes.W: "
                          "[8.0, 16.0]\nkeep: [summary, shape]\n";
  const fs::path out = scratch_ / "sweep";
  const ProgramOutcome run = Drape({"sweep", sweep.string(), "--threads", "1", "-o", out.string()});
  ASSERT_NE(run.exit_status, 2) << run.err;
  ExpectEveryViewDrawn(out / "sweep.html", scratch_.path(), 1);
}

}  // namespace
}  // namespace drape
