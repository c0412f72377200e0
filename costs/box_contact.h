#ifndef DRAPE_COSTS_BOX_CONTACT_H_
#define DRAPE_COSTS_BOX_CONTACT_H_

#include <cmath>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"

namespace drape {

// Contact of one node with a solid axis-aligned box (a table), edges and corners included.
// With the centre c, half-sizes a and q_i = |x_i − c_i| − a_i (how far outside each pair of
// faces), the signed distance is
//   φ = √(Σ_{q_i > 0} q_i²)  outside (exactly q_i beside a face, the distance to an edge or
//                            corner beyond them),
//   φ = max_i q_i            inside (negative),
// and U = ContactPenalty(φ, t, k) (costs/contact_penalty.h): the clearance t rounds the table's
// edges to radius t, over which the fabric folds. φ has a continuous gradient outside the box
// (the energy is C¹ across the face/edge regions, C² inside each). The push only (its friction:
// costs/obstacle_friction.h). Units: m, N/m², J.
struct BoxContact {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  BoxContact(const double min[3], const double max[3], double clearance_in, double stiffness_in)
      : center{0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1]), 0.5 * (min[2] + max[2])},
        half{0.5 * (max[0] - min[0]), 0.5 * (max[1] - min[1]), 0.5 * (max[2] - min[2])},
        clearance(clearance_in),
        stiffness(stiffness_in) {}

  template <typename T>
  T Distance(const T* const x) const {
    using std::sqrt;
    T q[3];
    for (int c = 0; c < 3; ++c) {
      const T d = x[c] - center[c];
      q[c] = (d < 0.0 ? T(-d) : d) - half[c];
    }
    int outside = 0, last = 0;
    T squared = T(), largest = q[0];
    for (int c = 0; c < 3; ++c) {
      if (q[c] > largest) largest = q[c];
      if (q[c] > 0.0) {
        ++outside;
        last = c;
        squared += q[c] * q[c];
      }
    }
    if (outside == 0) return largest;
    if (outside == 1) return q[last];
    return sqrt(squared);
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = ContactPenalty(Distance(x), clearance, stiffness);
    return true;
  }

  // Whether the energy can be nonzero at x (InClearanceLayer, costs/contact_penalty.h).
  bool Touches(const double* x) const { return InClearanceLayer(*this, x); }

  static BoxContact Create(const double min[3], const double max[3], double clearance,
                           double stiffness) {
    return BoxContact(min, max, clearance, stiffness);
  }

  const double center[3];  // m
  const double half[3];    // half-sizes, m
  const double clearance;  // t, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_BOX_CONTACT_H_
