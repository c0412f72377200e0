#ifndef DRAPE_COSTS_CYLINDER_CONTACT_H_
#define DRAPE_COSTS_CYLINDER_CONTACT_H_

#include <cmath>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/safe_math.h"

namespace drape {

// Contact of one node with a solid vertical cylinder (a pedestal): `center` is the centre of its
// top face, radius R, and it extends down by its height H. With d = x − c, ρ = |(d_x, d_y)| and
// the excesses q_r = ρ − R (outside the mantle) and q_z = max(d_z, −H − d_z) (above the top or
// below the bottom), the signed distance is
//   φ = √(q_r² + q_z²)  beyond a rim (both > 0),   q_r or q_z  beside one face,
//   φ = max(q_r, q_z)   inside (negative),
// and U = ContactPenalty(φ, t, k) (costs/contact_penalty.h): the rims are rounded by the
// clearance t. φ has a continuous gradient outside the solid (the energy is C¹ where the region
// changes, C² elsewhere). The push only (its friction: costs/obstacle_friction.h). Units: m, N/m²,
// J.
struct CylinderContact {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  CylinderContact(const double center_in[3], double radius_in, double height_in,
                  double clearance_in, double stiffness_in)
      : center{center_in[0], center_in[1], center_in[2]},
        radius(radius_in),
        height(height_in),
        clearance(clearance_in),
        stiffness(stiffness_in) {}

  template <typename T>
  T Distance(const T* const x) const {
    using std::sqrt;
    const T dx = x[0] - center[0], dy = x[1] - center[1], dz = x[2] - center[2];
    const T radial = SafeSqrt(dx * dx + dy * dy);
    const T q_r = radial - radius;
    const T below = -height - dz;
    const T q_z = dz > below ? dz : below;
    if (q_r > 0.0 && q_z > 0.0) return sqrt(q_r * q_r + q_z * q_z);
    if (q_r > 0.0) return q_r;
    if (q_z > 0.0) return q_z;
    return q_r > q_z ? q_r : q_z;
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = ContactPenalty(Distance(x), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero at x (InClearanceLayer, costs/contact_penalty.h).
  bool Touches(const double* x) const { return InClearanceLayer(*this, x); }

  static CylinderContact Create(const double center[3], double radius, double height,
                                double clearance, double stiffness) {
    return CylinderContact(center, radius, height, clearance, stiffness);
  }

  const double center[3];  // centre of the top face, m
  const double radius;     // m
  const double height;     // m, downwards from the top face
  const double clearance;  // t, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_CYLINDER_CONTACT_H_
