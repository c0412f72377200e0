// The fuzz target's input handling (fuzz/fuzz_input.h), on its committed corpus: no seed crashes,
// and the mesh seeds reach the OBJ, PLY and STL readers, text and binary (the good ones build
// their mesh, the broken ones — a truncated binary PLY and STL among them — are refused). Before,
// the target wrote every input as a scene only and never read a mesh file.
#include "fuzz/fuzz_input.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

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

}  // namespace
}  // namespace drape
