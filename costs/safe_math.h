// Autodiff-safe helpers shared by the cost functors (docs/architecture.md, fact 5).
#ifndef DRAPE_COSTS_SAFE_MATH_H_
#define DRAPE_COSTS_SAFE_MATH_H_

#include <cmath>

#include "costs/nested_jet.h"

namespace drape {

// √s of a squared length s ≥ 0, with a zero derivative (not NaN or ∞) at s = 0.
template <typename T>
T SafeSqrt(const T& squared) {
  using std::sqrt;
  if (squared > 0.0) return sqrt(squared);
  return T();
}

// |d| for d = b − a, with a zero derivative (not NaN) when the two points coincide.
template <typename T>
T SafeDistance(const T* a, const T* b) {
  const T dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  return SafeSqrt(dx * dx + dy * dy + dz * dz);
}

// The distance from a point to a line, |u × e| / |e|, for u = the point − a point of the line and
// e the line's direction (not zero): the side and end-to-inside distances of the self-contact
// functors (costs/point_triangle_contact.h, costs/edge_edge_contact.h).
template <typename T>
T DistanceToLine(const T* u, const T* e) {
  const T w[3] = {u[1] * e[2] - u[2] * e[1], u[2] * e[0] - u[0] * e[2], u[0] * e[1] - u[1] * e[0]};
  return SafeSqrt((w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) /
                  (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]));
}

}  // namespace drape

#endif  // DRAPE_COSTS_SAFE_MATH_H_
