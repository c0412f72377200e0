// Loading the repository's scene files in tests, and solving them.
#ifndef DRAPE_TESTS_TEST_SCENES_H_
#define DRAPE_TESTS_TEST_SCENES_H_

#include <filesystem>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"
#include "tests/test_paths.h"

namespace drape::testing {

inline std::string SourcePath(const std::string& relative) {
  return std::string(drape_tests::kSourceDir) + "/" + relative;
}

// Every scene file shipped under configs/ (not the fit and sweep files, which name a scene).
inline std::vector<std::string> ShippedSceneFiles() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SourcePath("configs"))) {
    const auto& path = entry.path();
    if (path.extension() != ".yaml") continue;
    const std::string name = path.filename().string();
    if (name.rfind("fit", 0) == 0 || name.rfind("sweep", 0) == 0) continue;
    files.push_back(path.string());
  }
  return files;
}

inline Scene LoadConfig(const std::string& relative,
                        const std::vector<std::string>& overrides = {}) {
  return LoadScene(SourcePath(relative), overrides);
}

struct Solved {
  Scene scene;
  Model model;
  RunResult result;
};

// Loads, builds and solves a scene from the repository with the given method.
inline Solved SolveConfig(const std::string& relative, const std::string& method,
                          const std::vector<std::string>& overrides = {}) {
  Solved solved{LoadConfig(relative, overrides), Model{}, RunResult{}};
  solved.model = BuildModel(solved.scene);
  solved.result = RunSolve(solved.scene, solved.model, method);
  return solved;
}

inline Eigen::Vector3d Position(const Model& model, int node) {
  return Eigen::Vector3d(model.positions[3 * node], model.positions[3 * node + 1],
                         model.positions[3 * node + 2]);
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_TEST_SCENES_H_
