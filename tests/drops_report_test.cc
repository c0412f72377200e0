// The drops report (src/sweep/drops_report.h): its pictures are there and labelled, its table is
// the drops', and the standard's specimen-size advice appears where the drape coefficient calls
// for it.
#include "src/sweep/drops_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

int Occurrences(const std::string& text, const std::string& what) {
  int count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

Scene DrapeTestScene() {
  const testing::ScratchFile file("drops_report", "scene.yaml", R"(name: report
drape_test: {}
material: {model: finite_volume, density: 0.1,
           finite_volume: {E_warp: 900, E_weft: 800, G: 20, D_warp: 2e-6, D_weft: 2e-6}}
)");
  return LoadScene(file.path().string());
}

// Three drops with wavy outlines (n folds) whose drape coefficients are `dc`; the third failed.
DropsSummary HandMadeSummary(double dc) {
  DropsSummary summary;
  const int folds[] = {7, 8, 7};
  for (int k = 0; k < 3; ++k) {
    DropRecord record;
    record.drop = k + 1;
    record.offset = Eigen::Vector2d(0.0013, 0.0007);
    record.drape_coefficient = dc + 0.01 * k;
    record.folds = folds[k];
    record.counted = k < 2;
    record.state = k < 2 ? "stable minimum" : "failed: <no model>";
    summary.drops.push_back(record);
    DropOutline outline;
    outline.centre = record.offset;
    for (int j = 0; j < 360; ++j) {
      outline.radius.push_back(0.12 + 0.02 * std::cos(folds[k] * j * 3.14159265358979323846 / 180));
    }
    summary.outlines.push_back(k < 2 ? outline : DropOutline{});
  }
  summary.statistics = ComputeDropStatistics(summary.drops);
  return summary;
}

TEST(DropsReport, ItsPicturesAreThereAndLabelled) {
  const Scene scene = DrapeTestScene();
  std::ostringstream html;
  WriteDropsReport(scene, HandMadeSummary(0.5), {}, html);
  const std::string page = html.str();
  EXPECT_EQ(Occurrences(page, "<svg "), 4) << page;  // outlines, two histograms, profiles
  EXPECT_EQ(Occurrences(page, "<title>"), 5);        // the page's and each picture's
  for (const std::string label :
       {"Shadow outlines of 3 drops", "drape coefficient</text>", "folds</text>", "r (cm)</text>",
        "θ (degrees from the warp, x)</text>", "disc 18 cm", "flat specimen 30 cm"}) {
    EXPECT_NE(page.find(label), std::string::npos) << label;
  }
  // The outlines of the two drops that have one; the failed drop is a row, its state escaped.
  EXPECT_EQ(Occurrences(page, "<polygon"), 2);
  EXPECT_NE(page.find("failed: &lt;no model&gt;"), std::string::npos);
  EXPECT_EQ(Occurrences(page, "<tr><td>"), 3 + 10);  // 3 drops, 10 material values
  EXPECT_NE(page.find("3 drops (2 at a stable minimum, counted): drape coefficient 0.505"),
            std::string::npos);
  EXPECT_EQ(page.find("nan"), std::string::npos);
  EXPECT_EQ(page.find("Specimen size"), std::string::npos);  // 0.5: the 30 cm is right
}

TEST(DropsReport, SpecimenSizeAdviceFollowsTheStandard) {
  EXPECT_FALSE(SpecimenSizeAdvice(0.30, 0.5));
  EXPECT_FALSE(SpecimenSizeAdvice(0.24, 0.2));  // only the 30 cm test is redirected
  const auto limp = SpecimenSizeAdvice(0.30, 0.25);
  ASSERT_TRUE(limp);
  EXPECT_NE(limp->find("below 0.30"), std::string::npos) << *limp;
  EXPECT_NE(limp->find("a 24 cm specimen (--set drape_test.specimen_diameter=0.24)"),
            std::string::npos)
      << *limp;
  const auto stiff = SpecimenSizeAdvice(0.30, 0.9);
  ASSERT_TRUE(stiff);
  EXPECT_NE(stiff->find("36 cm"), std::string::npos) << *stiff;

  std::ostringstream html;
  WriteDropsReport(DrapeTestScene(), HandMadeSummary(0.2), {}, html);
  EXPECT_NE(html.str().find("Specimen size: the drape coefficient 0.205 is below 0.30"),
            std::string::npos);
}

}  // namespace
}  // namespace drape
