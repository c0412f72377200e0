#ifndef DRAPE_COSTS_SPRING_STRETCH_H_
#define DRAPE_COSTS_SPRING_STRETCH_H_

#include <cmath>

#include "costs/energy_form.h"
#include "costs/safe_math.h"

namespace drape {

// Elastic spring between nodes i and j (Puiseux, eq. 1):
//   E = ½ k (|x_j − x_i| − L0)²,   residual r = √k (|x_j − x_i| − L0),
// whose force on i is Φ_ij = k (|X_ij| − L0) X_ij/|X_ij|.
// Units: k in N/m, L0 and x in m, E in J. Invariant under rigid translations and rotations;
// zero force at |x_j − x_i| = L0. Used for the structural, shear and flexion families.
struct SpringStretch {
  static constexpr int kNumNodes = 2;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  SpringStretch(double stiffness, double rest_length_in)
      : sqrt_stiffness(std::sqrt(stiffness)), rest_length(rest_length_in) {}

  template <typename T>
  bool operator()(const T* const xi, const T* const xj, T* residual) const {
    residual[0] = sqrt_stiffness * (SafeDistance(xi, xj) - rest_length);
    return true;
  }

  static SpringStretch Create(double stiffness, double rest_length) {
    return SpringStretch(stiffness, rest_length);
  }

  const double sqrt_stiffness;  // √(N/m)
  const double rest_length;     // m
};

}  // namespace drape

#endif  // DRAPE_COSTS_SPRING_STRETCH_H_
