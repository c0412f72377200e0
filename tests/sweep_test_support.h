// Shared by the sweep tests: fresh folders, sweep files written next to a copy of the repository's
// cotton drape tester, and sweep.csv read back as cells.
#ifndef DRAPE_TESTS_SWEEP_TEST_SUPPORT_H_
#define DRAPE_TESTS_SWEEP_TEST_SUPPORT_H_

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/output/csv_field.h"
#include "src/sweep/sweep.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape::testing {

// A fresh, empty temporary folder per call, removed when the test process ends.
inline std::string SweepTempDir(const std::string& name) {
  return ScratchFolderUntilExit("sweep_" + name).string();
}

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// `folder`/sweep.yaml with `text`, the base scene copied beside it as base.yaml (a fast, coarse
// drape tester: `set: {mesh.spacing: 0.05}` in the sweep files below).
inline std::string WriteSweep(const std::string& folder, const std::string& text) {
  std::filesystem::copy_file(SourcePath("configs/fv/drape_tester_cotton_30.yaml"),
                             folder + "/base.yaml",
                             std::filesystem::copy_options::overwrite_existing);
  WriteText(folder + "/sweep.yaml", text);
  return folder + "/sweep.yaml";
}

// A CSV file as rows of cells (header first).
inline std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) rows.push_back(SplitCsvLine(line));
  return rows;
}

// The column of `name` in a header row; -1 if absent.
inline int ColumnOf(const std::vector<std::string>& header, const std::string& name) {
  for (size_t k = 0; k < header.size(); ++k) {
    if (header[k] == name) return static_cast<int>(k);
  }
  return -1;
}

// The rows without their time_s column (the one thing that differs between identical solves).
inline std::vector<std::vector<std::string>> WithoutTime(
    std::vector<std::vector<std::string>> rows) {
  if (rows.empty()) return rows;
  const int time = ColumnOf(rows.front(), "time_s");
  for (auto& row : rows) {
    if (time >= 0 && time < static_cast<int>(row.size())) row.erase(row.begin() + time);
  }
  return rows;
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_SWEEP_TEST_SUPPORT_H_
