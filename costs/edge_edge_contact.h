#ifndef DRAPE_COSTS_EDGE_EDGE_CONTACT_H_
#define DRAPE_COSTS_EDGE_EDGE_CONTACT_H_

#include <Eigen/Core>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/nested_jet.h"
#include "costs/safe_math.h"
#include "src/geometry/nearest_feature.h"

namespace drape {

// Contact of the fabric with itself, two edges a–b and c–d of the fabric (triangle sides) that
// share no node (src/model/self_contact.h chooses the pairs): what the node–triangle contact
// (costs/point_triangle_contact.h) misses where two folds cross edge over edge:
//   d = the distance between the two segments,  U = ContactPenalty(d, C, k)
// with the same clearance C (the fabric's thickness) and stiffness k. The nearest parts are
// decided on values (NearestSegmentFeatures, src/geometry/nearest_feature.h), and on them
//   both insides, n = (b − a) × (d − c):   d = |n · (c − a)| / |n|,
//   an end p and the other's inside q₀–q₁: d = |(p − q₀) × (q₁ − q₀)| / |q₁ − q₀|,
//   two ends p, q:                          d = |p − q|,
// the exact distance, with a continuous gradient wherever the nearest points are unique. Nearly
// parallel edges (sin² of their angle below 1e-12) are taken end to inside, where the lines'
// distance is not defined by one pair of points. Units: m, N/m², J. Invariant under rigid motions.
// Frictionless. Source: IPC's edge–edge distance types (Li et al. 2020, ACM Trans. Graph. 39(4),
// §4.2), without their mollifier (the penalty is zero at first touch, not a barrier).
struct EdgeEdgeContact {
  static constexpr int kNumNodes = 4;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;
  static constexpr bool kTranslationInvariant = true;

  EdgeEdgeContact(double clearance_in, double stiffness_in)
      : clearance(clearance_in), stiffness(stiffness_in) {}

  template <typename T>
  T Distance(const T* a, const T* b, const T* c, const T* d) const {
    const auto value = [](const T* x) {
      return Eigen::Vector3d(ScalarPart(x[0]), ScalarPart(x[1]), ScalarPart(x[2]));
    };
    const T* end[4] = {a, b, c, d};
    const SegmentPairFeature nearest =
        NearestSegmentFeatures(value(a), value(b), value(c), value(d));
    if (nearest.kind == SegmentPairFeature::kInsides) {
      const T e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const T f[3] = {d[0] - c[0], d[1] - c[1], d[2] - c[2]};
      const T n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
                      e[0] * f[1] - e[1] * f[0]};
      const T along = n[0] * (c[0] - a[0]) + n[1] * (c[1] - a[1]) + n[2] * (c[2] - a[2]);
      return SafeSqrt(along * along / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
    }
    const T* p = end[nearest.end];
    const T* q0 = end[nearest.other];
    const T u[3] = {p[0] - q0[0], p[1] - q0[1], p[2] - q0[2]};
    if (nearest.kind == SegmentPairFeature::kEnds) {
      return SafeSqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    }
    const T* q1 = end[nearest.other + 1];
    const T e[3] = {q1[0] - q0[0], q1[1] - q0[1], q1[2] - q0[2]};
    return DistanceToLine(u, e);
  }

  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, const T* d, T* energy) const {
    energy[0] = ContactPenalty(Distance(a, b, c, d), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero here: the edges are nearer each other than the clearance.
  bool Touches(const double* a, const double* b, const double* c, const double* d) const {
    return Distance(a, b, c, d) < clearance;
  }

  const double clearance;  // C, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_EDGE_EDGE_CONTACT_H_
