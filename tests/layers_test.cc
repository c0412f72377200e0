// The dependency rule of docs/architecture.md: src/ is a stack of layers, and a file includes only
// from its own layer and the layers below it. costs/ sits under model (it includes only costs/).
// An include that points up the stack fails this test.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace drape {
namespace layers_test {

namespace fs = std::filesystem;

// Top to bottom; fit, compare and sweep are side by side (none includes another).
const std::vector<std::set<std::string>> kLayers = {
    {"cli"},      {"commands"},    {"fit", "compare", "sweep"},
    {"parallel"}, {"output"},      {"run"},
    {"analysis"}, {"solvers"},     {"numerics"},
    {"model"},    {"derivatives"}, {"costs"},
    {"scene"},    {"geometry"}};

// Includes that break the rule today, each to be removed (not added to): none.
const std::set<std::pair<std::string, std::string>> kKnownExceptions = {};

int LayerIndex(const std::string& folder) {
  for (size_t i = 0; i < kLayers.size(); ++i) {
    if (kLayers[i].count(folder)) return static_cast<int>(i);
  }
  return -1;
}

// "src/model/model.h" -> "model"; "costs/fv_bending.h" -> "costs".
std::string FolderOf(const std::string& repo_path) {
  const auto parts = fs::path(repo_path);
  auto it = parts.begin();
  if (*it == "src") ++it;
  return it->string();
}

std::vector<std::string> RepoIncludes(const fs::path& file) {
  static const std::regex include_line(R"(^\s*#\s*include\s+"((src|costs)/[^"]+)\")");
  std::vector<std::string> includes;
  std::ifstream in(file);
  std::string line;
  std::smatch match;
  while (std::getline(in, line)) {
    if (std::regex_search(line, match, include_line)) includes.push_back(match[1]);
  }
  return includes;
}

std::vector<fs::path> SourceFiles() {
  std::vector<fs::path> files;
  for (const char* top : {"src", "costs"}) {
    for (const auto& entry :
         fs::recursive_directory_iterator(fs::path(drape_tests::kSourceDir) / top)) {
      const auto ext = entry.path().extension();
      if (entry.is_regular_file() && (ext == ".h" || ext == ".cc")) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string ReadText(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The layers as docs/architecture.md draws them: the code block under "## The dependency rule",
// one line per layer, its folders first ("fit | compare | sweep    three commands ...").
std::vector<std::set<std::string>> DocumentedLayers() {
  std::ifstream in(fs::path(drape_tests::kSourceDir) / "docs/architecture.md");
  std::string line;
  while (std::getline(in, line) && line != "## The dependency rule") {
  }
  while (std::getline(in, line) && line.rfind("```", 0) != 0) {
  }
  std::vector<std::set<std::string>> layers;
  static const std::regex folder(R"(^\s*([a-z]+)\s*(\|)?)");
  while (std::getline(in, line) && line.rfind("```", 0) != 0) {
    std::set<std::string> folders;
    std::smatch match;
    std::string rest = line;
    while (std::regex_search(rest, match, folder)) {
      folders.insert(match[1]);
      rest = match.suffix();
      if (!match[2].matched) break;
    }
    layers.push_back(folders);
  }
  return layers;
}

TEST(LayerRule, TheArchitectureDocumentDrawsTheseLayers) {
  EXPECT_EQ(DocumentedLayers(), kLayers)
      << "docs/architecture.md's layer diagram (under \"## The dependency rule\") is not this "
         "test's kLayers";
}

// Every file of the program is named (by its stem: `levels` for levels.h and levels.cc) in
// docs/architecture.md, so the document follows the tree.
TEST(LayerRule, TheArchitectureDocumentNamesEveryFile) {
  const std::string text = ReadText(fs::path(drape_tests::kSourceDir) / "docs/architecture.md");
  auto files = SourceFiles();
  for (const auto& entry : fs::directory_iterator(fs::path(drape_tests::kSourceDir) / "python")) {
    if (entry.path().extension() == ".cc") files.push_back(entry.path());
  }
  for (const auto& file : files) {
    const std::string stem = file.filename().string().substr(0, file.filename().string().find('.'));
    EXPECT_NE(text.find(stem), std::string::npos)
        << fs::relative(file, drape_tests::kSourceDir).generic_string()
        << " is not named in docs/architecture.md";
  }
}

TEST(LayerRule, EverySourceFileLivesInALayerFolder) {
  for (const auto& file : SourceFiles()) {
    const auto relative = fs::relative(file, drape_tests::kSourceDir).generic_string();
    EXPECT_GE(LayerIndex(FolderOf(relative)), 0) << relative << " is in no layer folder";
  }
}

// Only tests end in `_test` (tests/<unit>_test.cc): a program file so named would read as a test
// to every `*_test.cc` glob (hence src/scene/drape_tester.h, not drape_test.h).
TEST(LayerRule, NoSourceFileIsNamedLikeATest) {
  const auto files = SourceFiles();
  ASSERT_GT(files.size(), 100u);
  for (const auto& file : files) {
    const std::string stem = file.stem().string();
    const std::string suffix = "_test";
    EXPECT_FALSE(stem.size() >= suffix.size() &&
                 stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
        << fs::relative(file, drape_tests::kSourceDir).generic_string()
        << " is named like a test (tests/<unit>_test.cc)";
  }
}

TEST(LayerRule, NoIncludePointsUpTheStack) {
  int checked = 0;
  for (const auto& file : SourceFiles()) {
    const auto relative = fs::relative(file, drape_tests::kSourceDir).generic_string();
    const int own = LayerIndex(FolderOf(relative));
    for (const auto& include : RepoIncludes(file)) {
      const int target = LayerIndex(FolderOf(include));
      ++checked;
      EXPECT_GE(target, 0) << relative << " includes " << include << ", in no layer folder";
      const bool same_layer_sibling =
          target == own && FolderOf(include) != FolderOf(relative);  // fit <-> compare
      if (kKnownExceptions.count({relative, include})) continue;
      EXPECT_TRUE(target >= own && !same_layer_sibling)
          << relative << " (layer " << FolderOf(relative) << ") includes " << include << " (layer "
          << FolderOf(include) << "), which is above it or beside it";
    }
  }
  EXPECT_GT(checked, 100);  // the files were found and read
}

}  // namespace layers_test
}  // namespace drape
