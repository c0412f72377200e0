#ifndef DRAPE_COSTS_STRETCH_LIMIT_BARRIER_H_
#define DRAPE_COSTS_STRETCH_LIMIT_BARRIER_H_

#include <cmath>

#include "costs/energy_form.h"
#include "costs/safe_math.h"

namespace drape {

// Penalty on a spring stretched beyond its limit (the energy solvers' form of Provot's stretch
// limit, Rusinko & Swan §3.3: "most yarn can only stretch 10% beyond their natural length"):
//   E = ½ κ max(|x_j − x_i| − λ L0, 0)²,   residual r = √κ max(|x_j − x_i| − λ L0, 0),
// with λ the stretch limit (maximum ratio length / rest length, > 1), L0 the spring's rest length
// and κ the penalty stiffness. Units: κ in N/m, lengths in m, E in J. Zero energy and force up to
// λ L0; C¹ beyond (like a tension-only spring whose rest length is λ L0). It acts in parallel with
// the spring, so where the limit is active the tension T is shared: T = k (l − L0) + κ (l − λ L0).
// Tolerance: a spring that would reach the stretch ratio λ_free under the same tension without
// the limit ends at λ + (λ_free − λ) k / (k + κ); with κ = 1000 k (src/model/stretch_limit.cc) the
// excess is about 1e-3 (λ_free − λ). Rigid-motion invariant.
struct StretchLimitBarrier {
  static constexpr int kNumNodes = 2;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  StretchLimitBarrier(double stiffness, double limit_length_in)
      : sqrt_stiffness(std::sqrt(stiffness)), limit_length(limit_length_in) {}

  template <typename T>
  bool operator()(const T* const xi, const T* const xj, T* residual) const {
    const T excess = SafeDistance(xi, xj) - limit_length;
    residual[0] = excess > 0.0 ? T(sqrt_stiffness * excess) : T();
    return true;
  }

  // `stiffness` κ in N/m; the limit length λ L0 in m.
  static StretchLimitBarrier Create(double stiffness, double limit_length) {
    return StretchLimitBarrier(stiffness, limit_length);
  }

  const double sqrt_stiffness;  // √(N/m)
  const double limit_length;    // m, λ L0
};

}  // namespace drape

#endif  // DRAPE_COSTS_STRETCH_LIMIT_BARRIER_H_
