#ifndef DRAPE_COSTS_TENSION_ONLY_SPRING_H_
#define DRAPE_COSTS_TENSION_ONLY_SPRING_H_

#include <cmath>

#include "costs/energy_form.h"
#include "costs/safe_math.h"

namespace drape {

// Spring that resists elongation only (Puiseux §4.1.1: k_ij = 0 when |X_ij| ≤ |X⁰⁰_ij|):
//   E = ½ k max(|x_j − x_i| − L0, 0)²,   residual r = √k max(|x_j − x_i| − L0, 0).
// Units: k in N/m, lengths in m, E in J. Rigid-motion invariant; no force while slack. The
// energy is C¹ (its Hessian jumps at L0 and is zero, so singular, while slack).
struct TensionOnlySpring {
  static constexpr int kNumNodes = 2;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  TensionOnlySpring(double stiffness, double rest_length_in)
      : sqrt_stiffness(std::sqrt(stiffness)), rest_length(rest_length_in) {}

  template <typename T>
  bool operator()(const T* const xi, const T* const xj, T* residual) const {
    const T stretch = SafeDistance(xi, xj) - rest_length;
    residual[0] = stretch > 0.0 ? T(sqrt_stiffness * stretch) : T();
    return true;
  }

  static TensionOnlySpring Create(double stiffness, double rest_length) {
    return TensionOnlySpring(stiffness, rest_length);
  }

  const double sqrt_stiffness;  // √(N/m)
  const double rest_length;     // m
};

}  // namespace drape

#endif  // DRAPE_COSTS_TENSION_ONLY_SPRING_H_
