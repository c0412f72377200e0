// The fuzz target's input handling (fuzz/fuzz_input.h), on its committed corpus: no seed crashes,
// and the mesh seeds reach the OBJ, PLY and STL readers, text and binary (the good ones build
// their mesh, the broken ones — a truncated binary PLY and STL among them — are refused). Before,
// the target wrote every input as a scene only and never read a mesh file.
#include "fuzz/fuzz_input.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

int RunSeed(const std::string& name) {
  std::ifstream file(fs::path(drape_tests::kSourceDir) / "fuzz" / "corpus" / name,
                     std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(bytes.empty()) << name;
  return drape_fuzz::RunInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

TEST(FuzzInput, MeshSeedsReachTheMeshReaders) {
  const std::map<std::string, int> expected = {
      {"mesh_square_obj", 4},       {"mesh_square_ply", 4},        {"mesh_quad_obj", 4},
      {"mesh_zero_area_obj", -1},   {"mesh_truncated_obj", -1},    {"mesh_bad_index_obj", -1},
      {"mesh_nan_obj", -1},         {"mesh_binary_ply", -1},       {"mesh_square_binary_ply", 4},
      {"mesh_square_ascii_stl", 4}, {"mesh_square_binary_stl", 4}, {"mesh_truncated_stl", -1}};
  for (const auto& [name, nodes] : expected) EXPECT_EQ(RunSeed(name), nodes) << name;
}

TEST(FuzzInput, EverySeedLoadsOrIsRefused) {
  for (const auto& entry :
       fs::directory_iterator(fs::path(drape_tests::kSourceDir) / "fuzz" / "corpus")) {
    const int outcome = RunSeed(entry.path().filename().string());
    EXPECT_GE(outcome, -2) << entry.path();
  }
}

// The folder a fuzzing process writes its inputs into is removed when the process ends (the
// fuzzer, and this test binary, once left one in /tmp per process). A child process runs one seed
// with TMPDIR in a scratch folder, says where it wrote, and exits normally.
TEST(FuzzInput, ItsFolderIsRemovedWhenTheProcessEnds) {
  const testing::ScratchFolder scratch("fuzz_input");
  const fs::path report = scratch / "folder.txt";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    setenv("TMPDIR", scratch.path().c_str(), 1);
    const int nodes = RunSeed("mesh_square_obj");
    std::ofstream(report) << drape_fuzz::InputFolder();
    std::exit(nodes == 4 ? 0 : 1);  // std::exit: the static objects' destructors run
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  std::ifstream in(report);
  std::string folder;
  std::getline(in, folder);
  ASSERT_FALSE(folder.empty());
  EXPECT_EQ(fs::path(folder).parent_path(), scratch.path());
  EXPECT_FALSE(fs::exists(folder)) << folder;
}

}  // namespace
}  // namespace drape
