// A taut elastic cable under its own weight against Irvine's elastic catenary (H. M. Irvine,
// Cable Structures, 1981, §2.2), for supports at the same height. With unstretched length L0,
// axial stiffness EA, weight w per unstretched length (W = w L0) and span l, the horizontal
// tension H solves
//   l = H L0 / EA + (2H / w) asinh(W / 2H),
// and the sag at mid-span is
//   d = W L0 / (8 EA) + (H / w) (√(1 + (W / 2H)²) − 1).
// A chain of N springs with lumped masses approximates the cable to O(h²), h = L0 / N: the test
// checks the error is small and falls by about 4 when N doubles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/test_scenes.h"

namespace drape {
namespace {

constexpr double kLength = 1.0, kAxialStiffness = 100.0, kLinearDensity = 0.1, kGravity = 9.81;
constexpr double kSpan = 0.95;

struct Catenary {
  double horizontal_tension;
  double sag;
};

Catenary Irvine() {
  const double w = kLinearDensity * kGravity, W = w * kLength;
  auto span = [&](double H) {
    return H * kLength / kAxialStiffness + 2 * H / w * std::asinh(W / (2 * H));
  };
  double low = 1e-6, high = 1e6;  // span(H) increases with H
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(low * high);
    (span(mid) < kSpan ? low : high) = mid;
  }
  const double H = std::sqrt(low * high);
  const double sag =
      W * kLength / (8 * kAxialStiffness) + H / w * (std::sqrt(1 + std::pow(W / (2 * H), 2)) - 1);
  return {H, sag};
}

Catenary SolveChain(int segments) {
  const double h = kLength / segments;
  const auto solved =
      testing::SolveConfig("configs/validation/elastic_catenary.yaml", "newton",
                           {"mesh.nodes=" + std::to_string(segments + 1),
                            "material.springs.structural=" + std::to_string(kAxialStiffness / h),
                            "fixed[1].nodes.ids=[" + std::to_string(segments) + "]"});
  EXPECT_TRUE(solved.result.converged) << solved.result.summary.termination;
  const double support_height = solved.model.positions[2];
  const double mid_height = solved.model.positions[3 * (segments / 2) + 2];
  return {-solved.result.certificate.node_forces[0], support_height - mid_height};
}

TEST(ElasticCatenary, ChainConvergesToIrvineAtSecondOrder) {
  const Catenary exact = Irvine();
  ASSERT_GT(exact.sag, 0.0);
  double previous_error = 0.0;
  for (int segments : {20, 40, 80}) {
    const Catenary chain = SolveChain(segments);
    const double tension_error = std::abs(chain.horizontal_tension / exact.horizontal_tension - 1);
    const double sag_error = std::abs(chain.sag / exact.sag - 1);
    const double h = kLength / segments;
    // O(h²) with a modest constant: at h = 0.05 the error is below 1%.
    EXPECT_LT(tension_error, 4 * h * h) << segments << " segments";
    EXPECT_LT(sag_error, 4 * h * h) << segments << " segments";
    if (previous_error > 0.0) {
      const double ratio = previous_error / tension_error;
      EXPECT_GT(ratio, 3.0) << "halving h should divide the error by about 4";
      EXPECT_LT(ratio, 5.0) << "halving h should divide the error by about 4";
    }
    previous_error = tension_error;
  }
}

}  // namespace
}  // namespace drape
