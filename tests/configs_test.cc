// Every scene in configs/ loads and builds, so none can rot.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/test_scenes.h"

namespace drape {
namespace {

TEST(Configs, EverySceneLoadsAndBuilds) {
  const auto files = testing::ShippedSceneFiles();
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
