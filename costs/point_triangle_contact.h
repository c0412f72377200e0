#ifndef DRAPE_COSTS_POINT_TRIANGLE_CONTACT_H_
#define DRAPE_COSTS_POINT_TRIANGLE_CONTACT_H_

#include <Eigen/Core>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/nested_jet.h"
#include "costs/safe_math.h"
#include "src/geometry/nearest_feature.h"

namespace drape {

// Contact of the fabric with itself, one node p and one triangle a b c of the fabric that does not
// have p as a corner (src/model/self_contact.h chooses the pairs):
//   d = the distance from p to the triangle,  U = ContactPenalty(d, C, k) (costs/contact_penalty.h)
// with C the fabric's thickness (twice `contact.thickness`, the half-thickness each layer keeps off
// an obstacle): two layers' mid-surfaces are kept C apart as a node is kept t off a body. The
// triangle's part nearest p is decided on p's values (NearestOnTriangle, src/geometry/
// nearest_feature.h), and on it
//   inside, n = (b − a) × (c − a):   d = |n · (p − a)| / |n|,
//   side q₀–q₁:                       d = |(p − q₀) × (q₁ − q₀)| / |q₁ − q₀|,
//   corner q:                         d = |p − q|,
// so d is the exact distance, continuous with a continuous gradient wherever the nearest point is
// unique; its curvature jumps where the nearest part changes, as a faceted surface's does. The
// distance is unsigned (a sheet has two sides): the step filter (SelfSafeFraction) keeps d > 0, so
// the sign never changes during a solve. Units: m, N/m², J. Invariant under rigid motions (a
// function of the four nodes' relative positions). Frictionless. Source: the penalty is every
// obstacle's; the pair and its distance types are IPC's point–triangle (Li et al. 2020,
// "Incremental Potential Contact", ACM Trans. Graph. 39(4), §4.2).
struct PointTriangleContact {
  static constexpr int kNumNodes = 4;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;
  static constexpr bool kTranslationInvariant = true;

  PointTriangleContact(double clearance_in, double stiffness_in)
      : clearance(clearance_in), stiffness(stiffness_in) {}

  template <typename T>
  T Distance(const T* p, const T* a, const T* b, const T* c) const {
    const auto value = [](const T* x) {
      return Eigen::Vector3d(ScalarPart(x[0]), ScalarPart(x[1]), ScalarPart(x[2]));
    };
    const T* corner[3] = {a, b, c};
    const TrianglePoint nearest = NearestOnTriangle(value(p), value(a), value(b), value(c));
    const T* q0 = corner[nearest.first];
    const T u[3] = {p[0] - q0[0], p[1] - q0[1], p[2] - q0[2]};
    if (nearest.corners == 1) return SafeSqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (nearest.corners == 2) {
      const T* q1 = corner[(nearest.first + 1) % 3];
      const T e[3] = {q1[0] - q0[0], q1[1] - q0[1], q1[2] - q0[2]};
      return DistanceToLine(u, e);
    }
    const T ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const T ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const T n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                    ab[0] * ac[1] - ab[1] * ac[0]};
    const T along = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
    return SafeSqrt(along * along / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
  }

  template <typename T>
  bool operator()(const T* p, const T* a, const T* b, const T* c, T* energy) const {
    energy[0] = ContactPenalty(Distance(p, a, b, c), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero here: p is nearer the triangle than the clearance.
  bool Touches(const double* p, const double* a, const double* b, const double* c) const {
    return Distance(p, a, b, c) < clearance;
  }

  const double clearance;  // C, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_POINT_TRIANGLE_CONTACT_H_
