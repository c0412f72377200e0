#include "src/geometry/nearest_feature.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace drape {

namespace {

using Eigen::Vector3d;

// The point of segment a–b nearest p, as its parameter in [0, 1].
double NearestOnSegment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double length_squared = ab.squaredNorm();
  if (!(length_squared > 0.0)) return 0.0;
  return std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0);
}

// A triangle of zero area: the nearest of its three sides.
TrianglePoint NearestOnSides(const Vector3d& p, const std::array<Vector3d, 3>& corner) {
  TrianglePoint best;
  double best_distance = -1.0;
  for (int k = 0; k < 3; ++k) {
    const Vector3d& from = corner[k];
    const Vector3d& to = corner[(k + 1) % 3];
    const double s = NearestOnSegment(p, from, to);
    const Vector3d point = from + s * (to - from);
    const double distance = (p - point).squaredNorm();
    if (best_distance >= 0.0 && distance >= best_distance) continue;
    best_distance = distance;
    best.point = point;
    if (s <= 0.0) {
      best.corners = 1, best.first = k;
    } else if (s >= 1.0) {
      best.corners = 1, best.first = (k + 1) % 3;
    } else {
      best.corners = 2, best.first = k;
    }
  }
  return best;
}

// Where along [0, 1] a parameter is: -1 inside, else the end it is at (0 or 1) plus `offset`.
int EndOf(double parameter, int offset) {
  if (parameter <= 0.0) return offset;
  if (parameter >= 1.0) return offset + 1;
  return -1;
}

}  // namespace

TrianglePoint NearestOnTriangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, 1, 0};
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, 1, 1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + d1 / (d1 - d3) * ab, 2, 0};
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, 1, 2};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {a + d2 / (d2 - d6) * ac, 2, 2};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), 2, 1};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return NearestOnSides(p, {a, b, c});
  return {a + ab * (vb / sum) + ac * (vc / sum), 3, 0};
}

double PointTriangleDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  return (p - NearestOnTriangle(p, a, b, c).point).norm();
}

SegmentPairFeature NearestSegmentFeatures(const Vector3d& a, const Vector3d& b, const Vector3d& c,
                                          const Vector3d& d) {
  // Ericson §5.1.9: the parameters s on a–b and t on c–d of the nearest points.
  constexpr double kParallel = 1e-12;  // of |a–b|² |c–d|²: sin² of the angle between them
  const Vector3d d1 = b - a, d2 = d - c, r = a - c;
  const double aa = d1.squaredNorm(), ee = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (!(aa > 0.0) && !(ee > 0.0)) return {SegmentPairFeature::kEnds, 0, 2};
  if (!(aa > 0.0)) {
    t = std::clamp(f / ee, 0.0, 1.0);
  } else {
    const double cc = d1.dot(r);
    if (!(ee > 0.0)) {
      s = std::clamp(-cc / aa, 0.0, 1.0);
    } else {
      const double bb = d1.dot(d2), denominator = aa * ee - bb * bb;
      s = denominator > kParallel * aa * ee ? std::clamp((bb * f - cc * ee) / denominator, 0.0, 1.0)
                                            : 0.0;
      t = (bb * s + f) / ee;
      if (t < 0.0) {
        t = 0.0, s = std::clamp(-cc / aa, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0, s = std::clamp((bb - cc) / aa, 0.0, 1.0);
      }
    }
  }
  const int s_end = EndOf(s, 0), t_end = EndOf(t, 2);
  if (s_end < 0 && t_end < 0) return {SegmentPairFeature::kInsides, -1, -1};
  if (s_end >= 0 && t_end >= 0) return {SegmentPairFeature::kEnds, s_end, t_end};
  if (s_end >= 0) return {SegmentPairFeature::kEndToInside, s_end, 2};
  return {SegmentPairFeature::kEndToInside, t_end, 0};
}

double SegmentSegmentDistance(const Vector3d& a, const Vector3d& b, const Vector3d& c,
                              const Vector3d& d) {
  const std::array<const Vector3d*, 4> point = {&a, &b, &c, &d};
  const SegmentPairFeature feature = NearestSegmentFeatures(a, b, c, d);
  switch (feature.kind) {
    case SegmentPairFeature::kInsides: {
      const Vector3d normal = (b - a).cross(d - c);
      return std::abs((c - a).dot(normal)) / normal.norm();
    }
    case SegmentPairFeature::kEndToInside: {
      const Vector3d& p = *point[feature.end];
      const Vector3d& from = *point[feature.other];
      const Vector3d& to = *point[feature.other + 1];
      return (p - (from + NearestOnSegment(p, from, to) * (to - from))).norm();
    }
    case SegmentPairFeature::kEnds:
      return (*point[feature.end] - *point[feature.other]).norm();
  }
  return 0.0;
}

}  // namespace drape
