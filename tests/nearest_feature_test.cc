// The nearest parts of a triangle and of two segments (src/geometry/nearest_feature.h): the
// distances against a dense sampling of the shapes (never farther than any sample, and within the
// sampling's spacing of the nearest), and the part named in cases worked out by hand.
#include "src/geometry/nearest_feature.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <random>

namespace drape {
namespace {

using Eigen::Vector3d;

constexpr int kSamples = 200;  // per side of the sampling grids

Vector3d RandomPoint(std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  return Vector3d(coordinate(random), coordinate(random), coordinate(random));
}

// The smallest distance from p to points of the triangle on a barycentric grid, and the grid's
// spacing (its largest cell's side).
double SampledTriangleDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                               const Vector3d& c, double* spacing) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSamples; ++i) {
    for (int j = 0; i + j <= kSamples; ++j) {
      const double u = static_cast<double>(i) / kSamples, v = static_cast<double>(j) / kSamples;
      best = std::min(best, (p - (a + u * (b - a) + v * (c - a))).norm());
    }
  }
  *spacing = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / kSamples;
  return best;
}

TEST(NearestFeature, PointTriangleDistanceIsTheSmallestOverTheTriangle) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3d p = RandomPoint(random), a = RandomPoint(random), b = RandomPoint(random),
                   c = RandomPoint(random);
    double spacing = 0.0;
    const double sampled = SampledTriangleDistance(p, a, b, c, &spacing);
    const double exact = PointTriangleDistance(p, a, b, c);
    EXPECT_LE(exact, sampled + 1e-12) << "trial " << trial;
    EXPECT_GE(exact, sampled - spacing) << "trial " << trial;
  }
}

TEST(NearestFeature, SegmentSegmentDistanceIsTheSmallestOverBoth) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3d a = RandomPoint(random), b = RandomPoint(random), c = RandomPoint(random),
                   d = RandomPoint(random);
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= kSamples; ++i) {
      for (int j = 0; j <= kSamples; ++j) {
        const double s = static_cast<double>(i) / kSamples, t = static_cast<double>(j) / kSamples;
        sampled = std::min(sampled, (a + s * (b - a) - (c + t * (d - c))).norm());
      }
    }
    const double spacing = std::max((b - a).norm(), (d - c).norm()) / kSamples;
    const double exact = SegmentSegmentDistance(a, b, c, d);
    EXPECT_LE(exact, sampled + 1e-12) << "trial " << trial;
    EXPECT_GE(exact, sampled - spacing) << "trial " << trial;
  }
}

TEST(NearestFeature, NamesTheInsideASideOrACornerOfATriangle) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const TrianglePoint inside = NearestOnTriangle(Vector3d(0.2, 0.3, 0.5), a, b, c);
  EXPECT_EQ(inside.corners, 3);
  EXPECT_TRUE(inside.point.isApprox(Vector3d(0.2, 0.3, 0)));
  const TrianglePoint side = NearestOnTriangle(Vector3d(0.6, 0.6, 0.1), a, b, c);  // over b–c
  EXPECT_EQ(side.corners, 2);
  EXPECT_EQ(side.first, 1);
  EXPECT_TRUE(side.point.isApprox(Vector3d(0.5, 0.5, 0)));
  const TrianglePoint corner = NearestOnTriangle(Vector3d(-0.1, -0.2, 0.3), a, b, c);
  EXPECT_EQ(corner.corners, 1);
  EXPECT_EQ(corner.first, 0);
  // A triangle of zero area: the nearest of its sides.
  const TrianglePoint flat = NearestOnTriangle(Vector3d(0.5, 0.2, 0), a, b, Vector3d(2, 0, 0));
  EXPECT_LT(flat.corners, 3);
  EXPECT_NEAR((flat.point - Vector3d(0.5, 0, 0)).norm(), 0.0, 1e-15);
}

TEST(NearestFeature, NamesTheNearestPartsOfTwoSegments) {
  const Vector3d a(0, 0, 0), b(1, 0, 0);
  // Crossing 0.3 apart: both insides.
  EXPECT_EQ(NearestSegmentFeatures(a, b, Vector3d(0.5, -1, 0.3), Vector3d(0.5, 1, 0.3)).kind,
            SegmentPairFeature::kInsides);
  // b against the inside of c–d.
  const SegmentPairFeature end =
      NearestSegmentFeatures(a, b, Vector3d(1.5, -1, 0), Vector3d(1.5, 1, 0));
  EXPECT_EQ(end.kind, SegmentPairFeature::kEndToInside);
  EXPECT_EQ(end.end, 1);
  EXPECT_EQ(end.other, 2);
  // b and c.
  const SegmentPairFeature ends =
      NearestSegmentFeatures(a, b, Vector3d(1.2, 0.1, 0), Vector3d(2, 1, 0));
  EXPECT_EQ(ends.kind, SegmentPairFeature::kEnds);
  EXPECT_EQ(ends.end, 1);
  EXPECT_EQ(ends.other, 2);
  // Parallel and overlapping, 0.2 apart: an end against the other's inside, at that distance.
  const Vector3d c(0.5, 0.2, 0), d(1.5, 0.2, 0);
  EXPECT_NE(NearestSegmentFeatures(a, b, c, d).kind, SegmentPairFeature::kInsides);
  EXPECT_NEAR(SegmentSegmentDistance(a, b, c, d), 0.2, 1e-15);
}

}  // namespace
}  // namespace drape
