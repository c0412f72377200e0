// Every scene in configs/ loads and builds, so none can rot.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/test_scenes.h"

namespace drape {
namespace {

std::vector<std::string> SceneFiles() {
  std::vector<std::string> files;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(testing::SourcePath("configs"))) {
    const auto& path = entry.path();
    if (path.extension() != ".yaml") continue;
    if (path.filename().string().rfind("fit", 0) == 0) continue;  // fit files: drape fit
    // sweep files: drape sweep (tests/sweep_file_test.cc loads them)
    if (path.filename().string().rfind("sweep", 0) == 0) continue;
    files.push_back(path.string());
  }
  return files;
}

TEST(Configs, EverySceneLoadsAndBuilds) {
  const auto files = SceneFiles();
  ASSERT_GE(files.size(), 6u);
  for (const auto& file : files) {
    SCOPED_TRACE(file);
    try {
      const Scene scene = LoadScene(file);
      const Model model = BuildModel(scene);
      EXPECT_GE(model.num_nodes, 2);
      EXPECT_FALSE(model.terms.empty());
      EXPECT_TRUE(FindSolver(scene.solver.method)) << scene.solver.method;
    } catch (const InputError& error) {
      ADD_FAILURE() << error.what();
    }
  }
}

}  // namespace
}  // namespace drape
