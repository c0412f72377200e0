// Synthetic measurements for the fit tests: solve a repository scene at known ("true") parameters,
// then write what an instrument would have measured, with optional Gaussian noise from a seeded
// generator, into a temporary folder together with a fit file.
#ifndef DRAPE_TESTS_FIT_TEST_SUPPORT_H_
#define DRAPE_TESTS_FIT_TEST_SUPPORT_H_

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "src/fit/fit_file.h"
#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape::testing {

// A fresh, empty temporary folder per call, removed when the test process ends.
inline std::string FitTempDir(const std::string& name) {
  return ScratchFolderUntilExit("fit_" + name).string();
}

inline void WriteTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// The equilibrium of a repository scene with `overrides` (the true parameters), solved tightly.
struct TrueSolve {
  Scene scene;
  Model model;
};
inline TrueSolve SolveTruth(const std::string& relative,
                            const std::vector<std::string>& overrides) {
  TrueSolve truth{LoadConfig(relative, overrides), Model{}};
  truth.scene.solver.tolerance = 1e-10;
  truth.model = BuildModel(truth.scene);
  const RunResult result = RunSolve(truth.scene, truth.model, "newton");
  EXPECT_LT(result.certificate.relative_residual, 1e-9);
  return truth;
}

// id,x,y,z of every free node, each coordinate with N(0, noise²) added (seeded).
inline void WriteNodePositions(const Model& model, double noise, unsigned seed,
                               const std::string& path) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0.0, noise);
  std::ofstream out(path);
  out.precision(17);
  out << "id,x,y,z\n";
  for (int k = 0; k < model.num_nodes; ++k) {
    if (model.fixed[3 * k]) continue;
    out << k;
    for (int c = 0; c < 3; ++c) {
      out << "," << model.positions[3 * k + c] + (noise > 0 ? gaussian(generator) : 0.0);
    }
    out << "\n";
  }
}

// A scan: points on the drape's surface (the centroid and the midpoints of the free triangles'
// edges, not nodes), as x,y,z, each coordinate with N(0, noise²) added (seeded).
inline void WriteScan(const Model& model, double noise, unsigned seed, const std::string& path) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0.0, noise);
  std::ofstream out(path);
  out.precision(17);
  out << "x,y,z\n";
  auto node = [&](int k) { return Position(model, k); };
  for (const auto& t : model.triangles) {
    if (model.fixed[3 * t[0]] && model.fixed[3 * t[1]] && model.fixed[3 * t[2]]) continue;
    const Eigen::Vector3d points[2] = {(node(t[0]) + node(t[1]) + node(t[2])) / 3.0,
                                       0.5 * (node(t[0]) + node(t[1]))};
    for (const auto& p : points) {
      out << p.x() + (noise > 0 ? gaussian(generator) : 0.0) << ","
          << p.y() + (noise > 0 ? gaussian(generator) : 0.0) << ","
          << p.z() + (noise > 0 ? gaussian(generator) : 0.0) << "\n";
    }
  }
}

inline double RelativeError(double value, double truth) { return std::abs(value / truth - 1.0); }

}  // namespace drape::testing

#endif  // DRAPE_TESTS_FIT_TEST_SUPPORT_H_
