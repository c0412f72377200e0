#ifndef DRAPE_COSTS_PLANE_CONTACT_H_
#define DRAPE_COSTS_PLANE_CONTACT_H_

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"

namespace drape {

// Contact of one node with a rigid half-space (a floor or wall) through point p with unit outer
// normal n: φ = n·(x − p),  U = ContactPenalty(φ, t, k)  (costs/contact_penalty.h).
// One-sided: everything behind the plane is solid. The push only (its friction:
// costs/obstacle_friction.h). Units: m, N/m², J.
struct PlaneContact {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  PlaneContact(const double point_in[3], const double normal_in[3], double clearance_in,
               double stiffness_in)
      : point{point_in[0], point_in[1], point_in[2]},
        normal{normal_in[0], normal_in[1], normal_in[2]},
        clearance(clearance_in),
        stiffness(stiffness_in) {}

  template <typename T>
  T Distance(const T* const x) const {
    return normal[0] * (x[0] - point[0]) + normal[1] * (x[1] - point[1]) +
           normal[2] * (x[2] - point[2]);
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = ContactPenalty(Distance(x), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero at x (InClearanceLayer, costs/contact_penalty.h).
  bool Touches(const double* x) const { return InClearanceLayer(*this, x); }

  static PlaneContact Create(const double point[3], const double normal[3], double clearance,
                             double stiffness) {
    return PlaneContact(point, normal, clearance, stiffness);
  }

  const double point[3];   // m
  const double normal[3];  // unit
  const double clearance;  // t, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_PLANE_CONTACT_H_
