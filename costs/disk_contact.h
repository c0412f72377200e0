#ifndef DRAPE_COSTS_DISK_CONTACT_H_
#define DRAPE_COSTS_DISK_CONTACT_H_

#include <cmath>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/safe_math.h"

namespace drape {

// Contact of one node with a thin horizontal disc (a drape tester's pedestal top): centre c,
// radius R, normal +z. With d = x − c, h = d_z and ρ = |(d_x, d_y)|, the distance to the disc is
//   φ = |h|                     over the disc (ρ ≤ R),
//   φ = √((ρ − R)² + h²)        beyond its rim,
// and U = ContactPenalty(φ, t, k) (costs/contact_penalty.h): the clearance t turns the disc into a
// slab of thickness 2t with a rounded rim of radius t, over which the fabric folds. φ has a
// continuous gradient across the rim circle (the energy is C¹ there and C² elsewhere). Works
// from both sides. The push only (its friction: costs/obstacle_friction.h). Units: m, N/m², J.
struct DiskContact {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  DiskContact(const double center_in[3], double radius_in, double clearance_in, double stiffness_in)
      : center{center_in[0], center_in[1], center_in[2]},
        radius(radius_in),
        clearance(clearance_in),
        stiffness(stiffness_in) {}

  template <typename T>
  T Distance(const T* const x) const {
    using std::sqrt;
    const T dx = x[0] - center[0], dy = x[1] - center[1], h = x[2] - center[2];
    const T radial_squared = dx * dx + dy * dy;
    if (!(radial_squared > radius * radius)) return h < 0.0 ? T(-h) : h;
    const T beyond = sqrt(radial_squared) - radius;
    return SafeSqrt(beyond * beyond + h * h);
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = ContactPenalty(Distance(x), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero at x (InClearanceLayer, costs/contact_penalty.h).
  bool Touches(const double* x) const { return InClearanceLayer(*this, x); }

  static DiskContact Create(const double center[3], double radius, double clearance,
                            double stiffness) {
    return DiskContact(center, radius, clearance, stiffness);
  }

  const double center[3];  // m
  const double radius;     // m
  const double clearance;  // t, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_DISK_CONTACT_H_
