// The certificate's self-intersection check (src/model/self_intersection.h): a side of one triangle
// crossing another triangle, found by the bounding-box tree exactly as by testing every pair, never
// on a flat or folded sheet that does not pass through itself (whatever its orientation), always
// on one that does, and on a mesh read from a file.
#include "src/model/self_intersection.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <random>

#include "src/scene/mesh_file.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

using Eigen::Vector3d;

// An n × n grid of nodes on [0, 1]², each square cut along its diagonal: the triangles, and the
// positions as flat z = 0.
struct Sheet {
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> positions;
  int n = 0;
  int Node(int i, int j) const { return i * n + j; }
  Vector3d At(int i, int j) const {
    const int k = Node(i, j);
    return Vector3d(positions[3 * k], positions[3 * k + 1], positions[3 * k + 2]);
  }
  void Set(int i, int j, const Vector3d& x) {
    for (int c = 0; c < 3; ++c) positions[3 * Node(i, j) + c] = x[c];
  }
};

Sheet FlatSheet(int n) {
  Sheet sheet;
  sheet.n = n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      sheet.positions.insert(sheet.positions.end(), {i / (n - 1.0), j / (n - 1.0), 0.0});
    }
  }
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      sheet.triangles.push_back({sheet.Node(i, j), sheet.Node(i + 1, j), sheet.Node(i + 1, j + 1)});
      sheet.triangles.push_back({sheet.Node(i, j), sheet.Node(i + 1, j + 1), sheet.Node(i, j + 1)});
    }
  }
  return sheet;
}

// The sheet folded in two along x = ½: the half beyond it laid back over the other at height
// `gap` (the fold's own squares join the two layers).
Sheet FoldedSheet(int n, double gap) {
  Sheet sheet = FlatSheet(n);
  for (int i = 0; i < n; ++i) {
    const double x = i / (n - 1.0);
    if (x <= 0.5) continue;
    for (int j = 0; j < n; ++j) sheet.Set(i, j, Vector3d(1.0 - x, j / (n - 1.0), gap));
  }
  return sheet;
}

// Every (side, triangle) pair that shares no node, tested one by one: the count the tree must
// find.
int CrossingsOfEveryPair(const Sheet& sheet) {
  std::vector<std::array<int, 2>> sides;
  for (const auto& t : sheet.triangles) {
    for (int k = 0; k < 3; ++k) {
      sides.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
    }
  }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  auto at = [&](int k) { return Vector3d(sheet.positions.data() + 3 * k); };
  int crossings = 0;
  for (const auto& side : sides) {
    for (const auto& t : sheet.triangles) {
      bool shared = false;
      for (int node : t) shared = shared || node == side[0] || node == side[1];
      if (!shared && SegmentCrossesTriangle(at(side[0]), at(side[1]), at(t[0]), at(t[1]), at(t[2])))
        ++crossings;
    }
  }
  return crossings;
}

// The line through p and q meets the plane of a b c at a point strictly inside the triangle, and
// p and q lie on opposite sides of that plane: computed from the crossing point's barycentric
// coordinates, a second way to the same answer. `margin` is the smallest of the normalised
// distances and coordinates involved: where it is tiny the answer is rounding's.
bool CrossesByBarycentres(const Vector3d& p, const Vector3d& q, const Vector3d& a,
                          const Vector3d& b, const Vector3d& c, double* margin) {
  const Vector3d normal = (b - a).cross(c - a);
  const double dp = normal.dot(p - a) / normal.norm(), dq = normal.dot(q - a) / normal.norm();
  *margin = std::min(std::abs(dp), std::abs(dq));
  if (dp * dq >= 0.0) return false;
  const Vector3d x = p + dp / (dp - dq) * (q - p);
  const double area = normal.squaredNorm();
  const double u = normal.dot((b - x).cross(c - x)) / area;
  const double v = normal.dot((c - x).cross(a - x)) / area;
  const double w = 1.0 - u - v;
  *margin = std::min({*margin, std::abs(u), std::abs(v), std::abs(w)});
  return u > 0.0 && v > 0.0 && w > 0.0;
}

TEST(SegmentCrossesTriangle, AgreesWithTheCrossingPointsBarycentres) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  auto point = [&] { return Vector3d(coordinate(random), coordinate(random), coordinate(random)); };
  int crossing = 0, clear = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vector3d p = point(), q = point(), a = point(), b = point(), c = point();
    double margin = 0.0;
    const bool expected = CrossesByBarycentres(p, q, a, b, c, &margin);
    if (margin < 1e-6) continue;
    ASSERT_EQ(SegmentCrossesTriangle(p, q, a, b, c), expected) << "trial " << trial;
    ++(expected ? crossing : clear);
  }
  EXPECT_GT(crossing, 1000);
  EXPECT_GT(clear, 1000);
}

// Touching is not passing through: a side that ends on the triangle, lies in its plane across
// it, or passes exactly through its corner or along its edge is no crossing; the same side moved
// to pass through the inside is one.
TEST(SegmentCrossesTriangle, ATouchIsNoCrossing) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(SegmentCrossesTriangle({0.2, 0.2, -1}, {0.2, 0.2, 1}, a, b, c));
  EXPECT_FALSE(SegmentCrossesTriangle({0.2, 0.2, 0}, {0.2, 0.2, 1}, a, b, c));    // ends on it
  EXPECT_FALSE(SegmentCrossesTriangle({-1, 0.2, 0}, {2, 0.2, 0}, a, b, c));       // in its plane
  EXPECT_FALSE(SegmentCrossesTriangle({0, 0, -1}, {0, 0, 1}, a, b, c));           // its corner
  EXPECT_FALSE(SegmentCrossesTriangle({0.5, 0, -1}, {0.5, 0, 1}, a, b, c));       // its edge
  EXPECT_FALSE(SegmentCrossesTriangle({0.8, 0.8, -1}, {0.8, 0.8, 1}, a, b, c));   // beside it
  EXPECT_FALSE(SegmentCrossesTriangle({0.2, 0.2, 0.1}, {0.2, 0.2, 1}, a, b, c));  // above it
}

// A flat sheet in any orientation and place: its triple products are rounding's, of either sign;
// none may count as a crossing.
TEST(SelfIntersection, AFlatSheetInAnyOrientationHasNone) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Sheet sheet = FlatSheet(31);
    const Eigen::Matrix3d rotation =
        Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random))
            .normalized()
            .toRotationMatrix();
    const Vector3d shift(unit(random), unit(random), unit(random));
    for (int i = 0; i < sheet.n; ++i) {
      for (int j = 0; j < sheet.n; ++j) sheet.Set(i, j, rotation * sheet.At(i, j) + 3.0 * shift);
    }
    const SelfIntersections found = FindSelfIntersections(sheet.triangles, sheet.positions);
    EXPECT_TRUE(found.checked);
    EXPECT_EQ(found.triangles, 2 * 30 * 30);
    EXPECT_EQ(found.crossings, 0) << "trial " << trial;
  }
}

// Two layers a thousandth of the sheet apart, joined at the fold: close, not crossing.
TEST(SelfIntersection, ASheetFoldedOntoItselfWithAGapHasNone) {
  for (double gap : {1e-3, 1e-6}) {
    const Sheet sheet = FoldedSheet(21, gap);
    EXPECT_EQ(FindSelfIntersections(sheet.triangles, sheet.positions).crossings, 0) << gap;
  }
}

// One node of the upper layer pushed through the lower one: its sides cross the lower layer's
// triangles, and the first crossing named involves that node.
TEST(SelfIntersection, ANodePushedThroughTheOtherLayerIsFound) {
  Sheet sheet = FoldedSheet(21, 1e-3);
  const int i = 15, j = 10;  // an upper-layer node away from the fold and the borders
  const Vector3d x = sheet.At(i, j);
  sheet.Set(i, j, Vector3d(x.x() + 0.01, x.y() + 0.01, -0.02));
  const SelfIntersections found = FindSelfIntersections(sheet.triangles, sheet.positions);
  EXPECT_GE(found.crossings, 1);
  EXPECT_EQ(found.crossings, CrossingsOfEveryPair(sheet));
  const int pushed = sheet.Node(i, j);
  EXPECT_TRUE(found.side[0] == pushed || found.side[1] == pushed ||
              std::count(found.triangle.begin(), found.triangle.end(), pushed) == 1);
}

// A crumpled sheet (every node moved at random, up to twice the grid's spacing): the tree finds
// each crossing that testing every pair finds.
TEST(SelfIntersection, TheTreeFindsWhatTestingEveryPairFinds) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int total = 0;
  for (int trial = 0; trial < 5; ++trial) {
    Sheet sheet = FlatSheet(16);
    const double spacing = 1.0 / 15;
    for (double& coordinate : sheet.positions) coordinate += 2.0 * spacing * unit(random);
    const SelfIntersections found = FindSelfIntersections(sheet.triangles, sheet.positions);
    EXPECT_EQ(found.crossings, CrossingsOfEveryPair(sheet)) << "trial " << trial;
    total += found.crossings;
  }
  EXPECT_GT(total, 0);
}

TEST(SelfIntersection, AStateThatIsNotFiniteIsNotChecked) {
  Sheet sheet = FlatSheet(5);
  sheet.positions[7] = std::nan("");
  const SelfIntersections found = FindSelfIntersections(sheet.triangles, sheet.positions);
  EXPECT_FALSE(found.checked);
  EXPECT_EQ(found.crossings, 0);
}

// A unit square of two triangles flat at z = 0, and a square standing across it at x = 0.7 (y from
// 0.1 to 0.6, z from −½ to ½): a mesh file with the intersection planted in it. Three sides of the
// standing square cross the flat triangle 0 1 2 (x > y): its two vertical sides and its diagonal
// 4–6; no side of the flat square crosses the standing one (its diagonal meets x = 0.7 at y = 0.7).
TEST(SelfIntersection, APlantedIntersectionInAMeshFileIsFound) {
  testing::ScratchFolder folder("self_intersection_test");
  const auto path = folder / "crossed.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                         "v 0.7 0.1 -0.5\nv 0.7 0.6 -0.5\nv 0.7 0.6 0.5\nv 0.7 0.1 0.5\n"
                         "f 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\n";
  const MeshFileData mesh = ReadMeshFile(path.string());
  std::vector<std::array<int, 3>> triangles;
  for (const auto& face : mesh.faces) triangles.push_back({face[0], face[1], face[2]});
  std::vector<double> positions;
  for (const Vector3d& v : mesh.vertices) positions.insert(positions.end(), {v.x(), v.y(), v.z()});
  const SelfIntersections found = FindSelfIntersections(triangles, positions);
  EXPECT_EQ(found.crossings, 3);
  EXPECT_EQ(found.side, (std::array<int, 2>{4, 6}));
  EXPECT_EQ(found.triangle, (std::array<int, 3>{0, 1, 2}));
}

}  // namespace
}  // namespace drape
