#ifndef DRAPE_COSTS_SPHERE_CONTACT_H_
#define DRAPE_COSTS_SPHERE_CONTACT_H_

#include <cmath>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/safe_math.h"

namespace drape {

// Contact of one node with a rigid sphere (centre c, radius R), and with a pin: a point support
// is the sphere of radius 0 around the pin's tip, so the clearance t makes it a small ball.
//   φ = |x − c| − R,   U = ContactPenalty(φ, t, k)  (costs/contact_penalty.h).
// The push only (its friction: costs/obstacle_friction.h). Units: m, N/m², J. Not invariant (the
// sphere is fixed in space).
struct SphereContact {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  SphereContact(const double center_in[3], double radius_in, double clearance_in,
                double stiffness_in)
      : center{center_in[0], center_in[1], center_in[2]},
        radius(radius_in),
        clearance(clearance_in),
        stiffness(stiffness_in) {}

  // Signed distance from the surface, positive outside, m.
  template <typename T>
  T Distance(const T* const x) const {
    const T dx = x[0] - center[0], dy = x[1] - center[1], dz = x[2] - center[2];
    return SafeSqrt(dx * dx + dy * dy + dz * dz) - radius;
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = ContactPenalty(Distance(x), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero at x (InClearanceLayer, costs/contact_penalty.h).
  bool Touches(const double* x) const { return InClearanceLayer(*this, x); }

  static SphereContact Create(const double center[3], double radius, double clearance,
                              double stiffness) {
    return SphereContact(center, radius, clearance, stiffness);
  }

  const double center[3];  // m
  const double radius;     // m (0 for a pin)
  const double clearance;  // t, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_SPHERE_CONTACT_H_
