// The closed triangle surface of a mesh obstacle (src/geometry/triangle_surface.h): its nearest
// point and signed distance against testing every face and against the sphere it approximates;
// bounded queries; and the refusal of surfaces that are not closed and outward oriented.
#include "src/geometry/triangle_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "tests/test_meshes.h"

namespace drape {
namespace {

using Eigen::Vector3d;

// The nearest point of triangle a b c to p by brute force: the nearest of the plane's projection
// (when inside) and the three sides' nearest points.
Vector3d NearestByBruteForce(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  auto on_segment = [&p](const Vector3d& u, const Vector3d& v) {
    const double s = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
    return Vector3d(u + s * (v - u));
  };
  Vector3d best = on_segment(a, b);
  for (const Vector3d& q : {on_segment(b, c), on_segment(c, a)}) {
    if ((p - q).norm() < (p - best).norm()) best = q;
  }
  const Vector3d n = (b - a).cross(c - a).normalized();
  const Vector3d projected = p - (p - a).dot(n) * n;
  const double ab = (b - a).cross(projected - a).dot(n), bc = (c - b).cross(projected - b).dot(n),
               ca = (a - c).cross(projected - c).dot(n);
  if (ab >= 0 && bc >= 0 && ca >= 0 && (p - projected).norm() < (p - best).norm()) {
    best = projected;
  }
  return best;
}

double UnsignedDistanceByBruteForce(const TriangleSurface& surface, const Vector3d& p) {
  double best = INFINITY;
  for (const auto& f : surface.faces()) {
    const auto& v = surface.vertices();
    best = std::min(best, (p - NearestByBruteForce(p, v[f[0]], v[f[1]], v[f[2]])).norm());
  }
  return best;
}

TEST(TriangleSurface, NearestPointAgreesWithTestingEveryFace) {
  const auto sphere = testing::Icosphere(0.1, 3);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-0.25, 0.25);
  for (int k = 0; k < 2000; ++k) {
    const Vector3d p(coordinate(random), coordinate(random), coordinate(random));
    const SurfaceFeature feature = sphere->Nearest(p.data());
    EXPECT_NEAR(std::abs(feature.distance), UnsignedDistanceByBruteForce(*sphere, p), 1e-15)
        << p.transpose();
    EXPECT_NEAR((p - feature.point).norm(), std::abs(feature.distance), 1e-15);
  }
}

// The sign: a point is inside exactly where it is nearer the centre than the inscribed sphere,
// outside beyond the circumscribed one (between the two, the facets decide: checked against the
// brute-force ray parity below).
TEST(TriangleSurface, SignIsNegativeInsideAndPositiveOutside) {
  const double radius = 0.1;
  for (int level : {1, 3, 5}) {
    const auto sphere = testing::Icosphere(radius, level);
    const double inscribed = radius * std::cos(0.6 / (1 << level));  // a facet's sagitta < this
    std::mt19937 random(level);
    std::uniform_real_distribution<double> coordinate(-0.3, 0.3);
    int inside = 0, outside = 0;
    for (int k = 0; k < 4000; ++k) {
      const Vector3d p(coordinate(random), coordinate(random), coordinate(random));
      const double r = p.norm();
      const double distance = sphere->SignedDistance(p.data());
      if (r < inscribed) {
        EXPECT_LT(distance, 0.0) << "level " << level << " at " << p.transpose();
        ++inside;
      } else if (r > radius) {
        EXPECT_GT(distance, 0.0) << "level " << level << " at " << p.transpose();
        ++outside;
      }
    }
    EXPECT_GT(inside, 40);  // the ball is 1.9 % of the cube
    EXPECT_GT(outside, 1000);
  }
}

// Faceted, the surface lies between the inscribed and circumscribed spheres: its distance differs
// from the sphere's by at most a facet's sagitta.
TEST(TriangleSurface, DistanceApproachesTheSpheresAsFacetsShrink) {
  const double radius = 0.1;
  const auto sphere = testing::Icosphere(radius, 5);
  const double edge = 2.0 * radius * std::sin(0.55 / 32);  // longest edge at level 5, about
  const double sagitta = edge * edge / (2.0 * radius);
  std::mt19937 random(11);
  std::normal_distribution<double> direction;
  for (int k = 0; k < 500; ++k) {
    const Vector3d u =
        Vector3d(direction(random), direction(random), direction(random)).normalized();
    for (double height : {-0.02, -0.001, 0.0005, 0.003, 0.05}) {
      const Vector3d p = (radius + height) * u;
      EXPECT_NEAR(sphere->SignedDistance(p.data()), height, sagitta) << p.transpose();
    }
  }
}

TEST(TriangleSurface, ABoundedQueryFindsWhatIsWithinItAndNothingElse) {
  const auto sphere = testing::Icosphere(0.1, 4);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-0.2, 0.2);
  for (int k = 0; k < 2000; ++k) {
    const Vector3d p(coordinate(random), coordinate(random), coordinate(random));
    const double exact = sphere->SignedDistance(p.data());
    for (double within : {0.001, 0.01, 0.05}) {
      const SurfaceFeature bounded = sphere->Nearest(p.data(), within);
      if (std::abs(exact) < within) {
        EXPECT_EQ(bounded.distance, exact);
      } else {
        EXPECT_EQ(bounded.corners, 0);
        EXPECT_EQ(bounded.distance, within);
      }
    }
  }
}

TEST(TriangleSurface, TheNearestFacesOfAMoveAreAmongThoseNearItsBox) {
  const auto sphere = testing::Icosphere(0.1, 4);
  Box box;
  box.Add(Vector3d(0.0, 0.0, 0.1005));
  box.Add(Vector3d(0.01, 0.004, 0.1009));
  const std::vector<int> faces = sphere->FacesNear(box, 0.002);
  ASSERT_FALSE(faces.empty());
  for (double s : {0.0, 0.3, 1.0}) {
    const Vector3d p = box.low + s * (box.high - box.low);
    EXPECT_NEAR(sphere->DistanceToFaces(faces, p.data()), sphere->SignedDistance(p.data()), 1e-15);
  }
}

TEST(TriangleSurface, PlacesAFileScaledTurnedThenMoved) {
  const Vector3d placed =
      PlaceVertex(Vector3d(1, 0, 0), 2.0, Vector3d(0, 0, 90), Vector3d(0, 0, 5));
  EXPECT_NEAR((placed - Vector3d(0, 2, 5)).norm(), 0.0, 1e-15);
  // About x first, then z: x's turn takes y to z, z's leaves z alone.
  const Vector3d turned =
      PlaceVertex(Vector3d(0, 1, 0), 1.0, Vector3d(90, 0, 90), Vector3d::Zero());
  EXPECT_NEAR((turned - Vector3d(0, 0, 1)).norm(), 0.0, 1e-15);
}

// ------------------------------------------------------------------------------ refusals

std::pair<std::vector<Vector3d>, std::vector<std::array<int, 3>>> Octahedron() {
  return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
          {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

int FaceOfError(std::vector<Vector3d> vertices, std::vector<std::array<int, 3>> faces,
                const std::string& says) {
  try {
    TriangleSurface::Make(std::move(vertices), std::move(faces));
  } catch (const SurfaceError& error) {
    EXPECT_NE(std::string(error.what()).find(says), std::string::npos) << error.what();
    return error.face;
  }
  ADD_FAILURE() << "no error; expected one that says: " << says;
  return -2;
}

TEST(TriangleSurface, TheOctahedronIsClosedAndOutward) {
  auto [vertices, faces] = Octahedron();
  const auto surface = TriangleSurface::Make(vertices, faces);
  EXPECT_NEAR(surface->volume(), 4.0 / 3.0, 1e-15);
  const double centre[3] = {0, 0, 0}, far[3] = {3, 0, 0};
  EXPECT_NEAR(surface->SignedDistance(centre), -1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(surface->SignedDistance(far), 2.0, 1e-15);
}

TEST(TriangleSurface, RefusesAHole) {
  auto [vertices, faces] = Octahedron();
  faces.pop_back();
  EXPECT_GE(FaceOfError(vertices, faces, "has a hole"), 0);
}

TEST(TriangleSurface, RefusesAFaceTurnedOver) {
  auto [vertices, faces] = Octahedron();
  std::swap(faces[5][0], faces[5][1]);
  const int face = FaceOfError(vertices, faces, "the same way as");
  EXPECT_TRUE(face == 5 || face > 5) << face;
}

TEST(TriangleSurface, RefusesASurfaceInsideOut) {
  auto [vertices, faces] = Octahedron();
  for (auto& f : faces) std::swap(f[0], f[1]);
  EXPECT_EQ(FaceOfError(vertices, faces, "inside out"), -1);
}

TEST(TriangleSurface, RefusesAFaceOfZeroArea) {
  auto [vertices, faces] = Octahedron();
  vertices[4] = Vector3d(0.5, 0.5, 0.0);  // the top vertex into the plane of a side: collinear
  vertices[2] = Vector3d(0.0, 1.0, 0.0);
  vertices.push_back(Vector3d(1, 0, 0));
  faces[0] = {0, 6, 4};  // 0 and 6 coincide: zero area
  EXPECT_EQ(FaceOfError(vertices, faces, "zero area"), 0);
}

TEST(TriangleSurface, RefusesAVertexOutOfRange) {
  auto [vertices, faces] = Octahedron();
  faces[3][1] = 9;
  EXPECT_EQ(FaceOfError(vertices, faces, "names vertex 10"), 3);
}

}  // namespace
}  // namespace drape
