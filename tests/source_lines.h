// The program's own source text, for tests of how it is written: the lines of src/, costs/,
// python/ and tools/ (.h and .cc files) that match a pattern.
#ifndef DRAPE_TESTS_SOURCE_LINES_H_
#define DRAPE_TESTS_SOURCE_LINES_H_

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace drape::testing {

// Each line that matches `pattern`, as "path:line: text" (path relative to the clone), in the
// order of the sorted paths; `files` counts the files read.
inline std::vector<std::string> SourceLinesMatching(const std::regex& pattern, int* files) {
  namespace fs = std::filesystem;
  const fs::path root(drape_tests::kSourceDir);
  std::vector<fs::path> paths;
  for (const char* top : {"src", "costs", "python", "tools"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const auto extension = entry.path().extension();
      if (entry.is_regular_file() && (extension == ".h" || extension == ".cc")) {
        paths.push_back(entry.path());
      }
    }
  }
  std::sort(paths.begin(), paths.end());
  *files = static_cast<int>(paths.size());
  std::vector<std::string> found;
  for (const fs::path& path : paths) {
    std::ifstream in(path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (std::regex_search(line, pattern)) {
        found.push_back(fs::relative(path, root).generic_string() + ":" + std::to_string(number) +
                        ": " + line);
      }
    }
  }
  return found;
}

// Fails once for each line of the program that compares a value of the enum `qualified`
// ("MaterialModel", "MeshSpec::Kind") with == or != instead of switching over it.
inline void ExpectEveryDispatchIsASwitch(const std::string& qualified) {
  const std::regex compared("[=!]=\\s*" + qualified + "::k|" + qualified + "::k\\w+\\s*[=!]=");
  int files = 0;
  const std::vector<std::string> found = SourceLinesMatching(compared, &files);
  EXPECT_GT(files, 100);
  for (const std::string& line : found) ADD_FAILURE() << "compared, not switched: " << line;
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_SOURCE_LINES_H_
