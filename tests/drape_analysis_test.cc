#include "src/drape_analysis.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drape {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A regular polygon of `sides` around the origin, as a fan of triangles (node 0 = centre).
void Fan(int sides, double radius, double z, std::vector<double>* positions,
         std::vector<std::array<int, 3>>* triangles) {
  positions->assign({0.0, 0.0, z});
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * kPi * k / sides;
    positions->insert(positions->end(), {radius * std::cos(angle), radius * std::sin(angle), z});
    triangles->push_back({0, 1 + k, 1 + (k + 1) % sides});
  }
}

TEST(ProjectedArea, FlatSquareOfTwoTriangles) {
  const std::vector<double> positions = {0, 0, 0, 0.3, 0, 0, 0.3, 0.3, 0, 0, 0.3, 0};
  const Shadow shadow = ProjectedArea(positions, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_NEAR(shadow.area, 0.09, shadow.error_bound);
  EXPECT_LT(shadow.error_bound, 1e-3 * 0.09);  // 4 × 0.3 m × (0.3 m / 2048) / 2
}

TEST(ProjectedArea, FlatDiscIsThePolygonsArea) {
  std::vector<double> positions;
  std::vector<std::array<int, 3>> triangles;
  const int sides = 256;
  Fan(sides, 0.15, 0.0, &positions, &triangles);
  const double exact = 0.5 * sides * 0.15 * 0.15 * std::sin(2.0 * kPi / sides);
  const Shadow shadow = ProjectedArea(positions, triangles);
  EXPECT_NEAR(shadow.area, exact, shadow.error_bound);
  // The bound is honest but not loose by orders of magnitude.
  EXPECT_LT(std::abs(shadow.area - exact), shadow.error_bound);
  EXPECT_LT(shadow.error_bound, 2e-3 * exact);
}

TEST(ProjectedArea, OverlappingTrianglesCountOnce) {
  // Triangle A (0,0) (2,0) (0,2), area 2; triangle B (1,0) (3,0) (1,2) lies above it, area 2,
  // wound the other way. Their intersection is (1,0) (2,0) (1,1), area 1/2: the union is 3.5.
  const std::vector<double> positions = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 1, 1, 2, 1, 3, 0, 1};
  const Shadow shadow = ProjectedArea(positions, {{0, 1, 2}, {3, 4, 5}});
  EXPECT_NEAR(shadow.area, 3.5, shadow.error_bound);
  EXPECT_GT(std::abs(shadow.area - 4.0), 10 * shadow.error_bound);  // not the sum of the areas
}

TEST(ProjectedArea, VerticalTrianglesAndNoTrianglesCastNoShadow) {
  const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(ProjectedArea(positions, {{0, 1, 2}}).area, 0.0);
  EXPECT_EQ(ProjectedArea(positions, {}).area, 0.0);
}

TEST(ProjectedArea, FinerResolutionShrinksTheErrorBound) {
  std::vector<double> positions;
  std::vector<std::array<int, 3>> triangles;
  Fan(64, 1.0, 0.0, &positions, &triangles);
  const Shadow coarse = ProjectedArea(positions, triangles, {256});
  const Shadow fine = ProjectedArea(positions, triangles, {4096});
  EXPECT_NEAR(coarse.error_bound / fine.error_bound, 16.0, 1.0);
  EXPECT_NEAR(coarse.area, fine.area, coarse.error_bound);
}

TEST(DrapeCoefficient, RatioAndCusicksFormula) {
  Model model;
  std::vector<double> flat;
  Fan(128, 0.15, 0.0, &flat, &model.triangles);
  model.initial = flat;
  // The draped shape: the same disc shrunk to 0.12 m radius and lowered.
  model.positions = flat;
  for (size_t k = 0; k < flat.size(); k += 3) {
    model.positions[k] *= 0.8;
    model.positions[k + 1] *= 0.8;
    model.positions[k + 2] = -0.05;
  }
  const DrapeCoefficient dc = ComputeDrapeCoefficient(model, 0.09);
  EXPECT_NEAR(dc.ratio, 0.64, 1e-3);
  const double disc = kPi * 0.09 * 0.09;
  EXPECT_NEAR(dc.cusick, (0.64 * dc.flat_area - disc) / (dc.flat_area - disc), 2e-3);
  EXPECT_TRUE(std::isnan(ComputeDrapeCoefficient(model).cusick));
}

}  // namespace
}  // namespace drape
