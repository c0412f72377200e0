// Comments point only into the repository: a comment that cites a tracker's issue number ("issue
// N, item M") means nothing to a clone, so the sources state the behaviour itself. A reference to
// another project's tracker names that project ("NLopt issue #86") and is allowed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace drape {
namespace source_comments_test {

namespace fs = std::filesystem;

bool IsSourceText(const fs::path& file) {
  const std::string extension = file.extension().string();
  return extension == ".h" || extension == ".cc" || extension == ".in" || extension == ".py" ||
         extension == ".cmake" || extension == ".gp" || file.filename() == "CMakeLists.txt";
}

std::vector<fs::path> CommentedFiles() {
  const fs::path root(drape_tests::kSourceDir);
  std::vector<fs::path> files;
  for (const char* top : {"src", "costs", "tests", "tools", "python", "cmake", ".ci"}) {
    if (!fs::exists(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const bool script = entry.path().parent_path().filename() == ".ci";
      if (entry.is_regular_file() && (IsSourceText(entry.path()) || script)) {
        files.push_back(entry.path());
      }
    }
  }
  files.push_back(root / "CMakeLists.txt");
  return files;
}

// "issue N", "Issue N,", "issues N and M", "#N item M" (N a number), unless a project's name comes
// first.
std::vector<std::string> IssueCitations(const fs::path& file) {
  static const std::regex citation(R"((^|[^A-Za-z])([Ii]ssues? #?[0-9]+|#[0-9]+ item))");
  static const std::regex other_project(
      R"((NLopt|Ceres|Eigen|yaml-cpp|CLI11|pybind11|GCC|CMake) issue)");
  std::vector<std::string> found;
  std::ifstream in(file);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (std::regex_search(line, citation) && !std::regex_search(line, other_project)) {
      found.push_back(file.string() + ":" + std::to_string(number) + ": " + line);
    }
  }
  return found;
}

TEST(SourceComments, CiteNoIssueNumbers) {
  const auto files = CommentedFiles();
  ASSERT_GT(files.size(), 100U) << "the sources were not found under " << drape_tests::kSourceDir;
  for (const auto& file : files) {
    for (const auto& citation : IssueCitations(file)) ADD_FAILURE() << citation;
  }
}

}  // namespace source_comments_test
}  // namespace drape
