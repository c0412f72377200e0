#include "src/model/self_intersection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "src/geometry/box_tree.h"

namespace drape {

namespace {

using Eigen::Vector3d;

// The sign of u · (v × w): +1 or −1, or 0 within kCrossingTolerance |u| |v| |w|.
int TripleProductSign(const Vector3d& u, const Vector3d& v, const Vector3d& w) {
  const double product = u.dot(v.cross(w));
  const double zero = kCrossingTolerance * u.norm() * v.norm() * w.norm();
  return product > zero ? 1 : (product < -zero ? -1 : 0);
}

Vector3d Point(const std::vector<double>& positions, int node) {
  return Vector3d(positions[3 * node], positions[3 * node + 1], positions[3 * node + 2]);
}

bool SharesANode(const std::array<int, 2>& side, const std::array<int, 3>& triangle) {
  for (int node : triangle) {
    if (node == side[0] || node == side[1]) return true;
  }
  return false;
}

bool AllFinite(const std::vector<std::array<int, 3>>& triangles,
               const std::vector<double>& positions) {
  for (const auto& triangle : triangles) {
    for (int node : triangle) {
      if (!Point(positions, node).allFinite()) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<std::array<int, 2>> SidesOf(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::array<int, 2>> sides;
  sides.reserve(3 * triangles.size());
  for (const auto& triangle : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = triangle[k], b = triangle[(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  return sides;
}

bool SegmentCrossesTriangle(const Vector3d& p, const Vector3d& q, const Vector3d& a,
                            const Vector3d& b, const Vector3d& c) {
  const int side_p = TripleProductSign(b - a, c - a, p - a);
  const int side_q = TripleProductSign(b - a, c - a, q - a);
  if (side_p == 0 || side_q == 0 || side_p == side_q) return false;
  const Vector3d direction = q - p;
  const int ab = TripleProductSign(direction, a - p, b - p);
  const int bc = TripleProductSign(direction, b - p, c - p);
  const int ca = TripleProductSign(direction, c - p, a - p);
  return ab != 0 && ab == bc && bc == ca;
}

SelfIntersections FindSelfIntersections(const std::vector<std::array<int, 3>>& triangles,
                                        const std::vector<double>& positions) {
  SelfIntersections found;
  found.triangles = static_cast<int>(triangles.size());
  if (!AllFinite(triangles, positions)) return found;
  found.checked = true;
  std::vector<Box> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int node : triangles[t]) boxes[t].Add(Point(positions, node));
  }
  const BoxTree tree(std::move(boxes));
  for (const auto& side : SidesOf(triangles)) {
    const Vector3d p = Point(positions, side[0]), q = Point(positions, side[1]);
    Box query;
    query.Add(p);
    query.Add(q);
    int first_triangle = -1;
    tree.ForEachOverlap(query, [&](int t) {
      const auto& triangle = triangles[t];
      if (SharesANode(side, triangle)) return;
      if (!SegmentCrossesTriangle(p, q, Point(positions, triangle[0]),
                                  Point(positions, triangle[1]), Point(positions, triangle[2]))) {
        return;
      }
      ++found.crossings;
      if (first_triangle < 0 || t < first_triangle) first_triangle = t;
    });
    if (first_triangle >= 0 && found.side[0] < 0) {
      found.side = side;
      found.triangle = triangles[first_triangle];
    }
  }
  return found;
}

SelfIntersections FindSelfIntersections(const Model& model, const std::vector<double>& positions) {
  assert(positions.size() == static_cast<std::size_t>(model.num_dofs()));
  return FindSelfIntersections(model.triangles, positions);
}

}  // namespace drape
