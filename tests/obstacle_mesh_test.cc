// A mesh obstacle end to end (src/scene/obstacle_mesh.h, src/model/obstacle_kinds.h): its file read
// and placed when the scene loads, and a drape over it that is the analytic body's within the
// facets' error; a fabric edge through a thin part of a body is no stable minimum.
#include "src/scene/obstacle_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "src/model/contact.h"
#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

std::string Shipped(const std::string& file) {
  return std::string(drape_tests::kSourceDir) + "/configs/" + file;
}

TEST(ObstacleMesh, TheFileIsReadAndPlacedWhenTheSceneLoads) {
  const Scene scene = LoadScene(Shipped("fv/sphere_mesh.yaml"));
  ASSERT_EQ(scene.obstacles.size(), 1u);
  const ObstacleSpec& ball = scene.obstacles.front();
  ASSERT_NE(ball.surface, nullptr);
  EXPECT_EQ(ball.surface->faces().size(), 5120u);
  // Its vertices lie on the sphere of radius 0.1 m about the translation.
  const Eigen::Vector3d centre(0.0013, 0.0007, -0.1);
  for (const Eigen::Vector3d& v : ball.surface->vertices()) {
    EXPECT_NEAR((v - centre).norm(), 0.1, 1e-8);  // the file's 9 digits
  }
  // Scaled, turned about x by 90° (z to −y), moved: the apex at (0, −0.2, 0) + (1, 2, 3).
  const Scene turned = LoadScene(Shipped("fv/sphere_mesh.yaml"),
                                 {"obstacles=[{mesh: {file: " + Shipped("obstacles/sphere.obj") +
                                  ", scale: 2, rotation: [90, 0, 0], translation: [1, 2, 3]}}]"});
  const double below_apex[3] = {1.0, 2.0 - 0.2 - 0.01, 3.0};
  EXPECT_NEAR(turned.obstacles.front().surface->SignedDistance(below_apex), 0.01, 1e-9);
}

// The sphere scene at 21 × 21 nodes (2 cm) over the analytic ball and over its 5,120-facet mesh:
// the same support (the vertical force is the weight, 1 %), the clearance kept as on the ball
// (penetration below 0.1 t), no edge through the surface, and the same mean height within 1 mm
// (the facets lie up to their sagitta, e²/(8R) = 0.07 mm for the 7.6 mm edges, inside the ball).
// Where the hanging sides settle their folds (a lattice cell apart or not) moves single nodes by
// more, so the mean of |Δz| over the nodes is no test measure (2.6 mm here; 1.1 mm for the
// 81,920-facet ball at 31 × 31 nodes, docs/benchmarks.md).
TEST(ObstacleMesh, ADrapeOverTheMeshIsTheDrapeOverTheBall) {
  const std::vector<std::string> coarse = {"mesh.nodes=[21, 21]", "solver.max_iterations=1500"};
  auto solve = [&coarse](const std::string& file, Model* model) {
    const Scene scene = LoadScene(Shipped(file), coarse);
    *model = BuildModel(scene);
    return RunSolve(scene, *model, "newton");
  };
  Model ball, mesh;
  const RunResult on_ball = solve("fv/sphere.yaml", &ball);
  const RunResult on_mesh = solve("fv/sphere_mesh.yaml", &mesh);
  ASSERT_TRUE(on_ball.converged) << on_ball.summary.termination;
  ASSERT_TRUE(on_mesh.converged) << on_mesh.summary.termination;
  EXPECT_FALSE(on_mesh.PassesThrough());
  EXPECT_EQ(on_mesh.contact.edges_through_body, 0);
  double mean_ball = 0.0, mean_mesh = 0.0;
  for (int k = 0; k < ball.num_nodes; ++k) {
    mean_ball += ball.position(k).z() / ball.num_nodes;
    mean_mesh += mesh.position(k).z() / ball.num_nodes;
  }
  EXPECT_NEAR(mean_mesh, mean_ball, 1e-3);
  const double weight = on_ball.certificate.contact_sum.z();
  EXPECT_NEAR(on_mesh.certificate.contact_sum.z(), weight, 0.01 * weight);
  EXPECT_LE(on_mesh.contact.max_penetration_fraction, kAllowedPenetration);
}

// A chain of two fixed nodes on either side of a thin octahedron: neither node is inside the body,
// but the link between them crosses its surface. No contact term can act (both ends are fixed),
// and the certificate says the fabric passes through the body.
TEST(ObstacleMesh, AnEdgeThroughTheBodyIsCounted) {
  const Scene scene =
      LoadScene(Shipped("examples/chain.yaml"),
                {"mesh={kind: chain, points: [[-1, 0.05, 0.02], [1, 0.05, 0.02]]}",
                 "fixed=[{nodes: {ids: [0, 1]}}]", "loads={gravity: [0, 0, 0]}",
                 "obstacles=[{mesh: {file: " + std::string(drape_tests::kSourceDir) +
                     "/tests/data/meshes/octahedron.obj, scale: 0.5}}]"});
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  EXPECT_EQ(result.contact.edges_through_body, 1);
  EXPECT_TRUE(result.PassesThrough());
}

}  // namespace
}  // namespace drape
