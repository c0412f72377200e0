// A hanging chain of springs against its exact discrete equilibrium, the funicular polygon.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "tests/test_scenes.h"

namespace drape {
namespace {

// Chain of `segments` springs (stiffness k, rest length L0) between supports at the same height
// `span` apart, every interior node carrying `weight`. In equilibrium the horizontal tension H is
// the same in every segment and the vertical one grows by `weight` at each node: V_i = V_0 + i w.
// Segment i has tension T_i = √(H² + V_i²), length L0 + T_i/k, direction (H, V_i)/T_i. The span
// and the level of the far end close the polygon. By symmetry V_0 = −(N − 1) w / 2 closes the
// level; the span grows monotonically with H, so bisection finds H.
struct Funicular {
  int segments;
  double k, rest, weight, span;

  Eigen::Vector2d Closure(double H, double V0) const {
    Eigen::Vector2d sum(-span, 0.0);
    for (int i = 0; i < segments; ++i) {
      const double V = V0 + i * weight, T = std::hypot(H, V), length = rest + T / k;
      sum += length / T * Eigen::Vector2d(H, V);
    }
    return sum;
  }

  Eigen::Vector2d SolveTensions() const {
    const double V0 = -0.5 * (segments - 1) * weight;
    double low = 1e-12, high = 1e6;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (low + high);
      (Closure(mid, V0)[0] < 0.0 ? low : high) = mid;
    }
    return Eigen::Vector2d(0.5 * (low + high), V0);
  }

  std::vector<Eigen::Vector2d> Nodes(const Eigen::Vector2d& start, double H, double V0) const {
    std::vector<Eigen::Vector2d> nodes{start};
    for (int i = 0; i < segments; ++i) {
      const double V = V0 + i * weight, T = std::hypot(H, V);
      nodes.push_back(nodes.back() + (rest + T / k) / T * Eigen::Vector2d(H, V));
    }
    return nodes;
  }
};

void ExpectMatchesFunicular(const testing::Solved& solved) {
  const Model& model = solved.model;
  const int segments = model.num_nodes - 1;
  const double g = 9.81, node_mass = 0.01;
  const Funicular polygon{segments, 50.0, 0.1, node_mass * g, 0.8};
  const Eigen::Vector2d tensions = polygon.SolveTensions();
  ASSERT_LT(polygon.Closure(tensions[0], tensions[1]).norm(), 1e-14);
  const auto expected = polygon.Nodes(Eigen::Vector2d(0.1, 0.0), tensions[0], tensions[1]);
  for (int node = 0; node < model.num_nodes; ++node) {
    const Eigen::Vector3d p = testing::Position(model, node);
    EXPECT_NEAR(p.x(), expected[node].x(), 1e-6) << "node " << node;
    EXPECT_NEAR(p.z(), expected[node].y(), 1e-6) << "node " << node;
    EXPECT_EQ(p.y(), 0.0);
  }
  // The left support pulls the chain back with H; all supports together carry all the weight.
  const auto& forces = solved.result.certificate.node_forces;
  EXPECT_NEAR(forces[0], -tensions[0], 1e-6);
  EXPECT_NEAR(solved.result.certificate.reaction_sum.z(), model.num_nodes * node_mass * g, 1e-9);
  EXPECT_NEAR(solved.result.certificate.reaction_sum.x(), 0.0, 1e-9);
}

TEST(FunicularChain, CeresLbfgsReachesTheExactPolygon) {
  const auto solved =
      testing::SolveConfig("configs/validation/funicular_chain.yaml", "ceres-lbfgs");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_LE(solved.result.certificate.relative_residual, 1e-9);
  ExpectMatchesFunicular(solved);
}

TEST(FunicularChain, NewtonReachesTheExactPolygon) {
  const auto solved = testing::SolveConfig("configs/validation/funicular_chain.yaml", "newton");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesFunicular(solved);
}

TEST(FunicularChain, ExampleChainIsTheSameScene) {
  const auto solved = testing::SolveConfig("configs/examples/chain.yaml", "ceres-lbfgs");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesFunicular(solved);
}

TEST(FunicularChain, PuiseuxFixedPointReachesTheExactPolygon) {
  const auto solved =
      testing::SolveConfig("configs/validation/funicular_chain.yaml", "puiseux-fixed-point");
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesFunicular(solved);
}

TEST(FunicularChain, PuiseuxDynamicComesToRestOnThePolygon) {
  const auto solved =
      testing::SolveConfig("configs/validation/funicular_chain.yaml", "puiseux-dynamic",
                           {"solver.puiseux-dynamic={dt: 0.05, beta: 0.05, epsilon: 1e-15}"});
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  ExpectMatchesFunicular(solved);
  const auto& trace = solved.result.summary.trace;
  ASSERT_GT(trace.size(), 2u);
  EXPECT_GT(trace[1][2], 0.0);  // it moved
  EXPECT_LT(trace.back()[2], trace[1][2]);
}

}  // namespace
}  // namespace drape
