#ifndef DRAPE_COSTS_ZERO_LENGTH_SPRING_H_
#define DRAPE_COSTS_ZERO_LENGTH_SPRING_H_

#include <cmath>

#include "costs/energy_form.h"

namespace drape {

// Spring of zero rest length (`rest_length: zero`): E = ½ k |x_j − x_i|², residuals
// r = √k (x_j − x_i) (three, so the energy stays smooth where the nodes meet). Its force is linear
// in the positions, so a net of them under fixed loads is exactly a discrete Laplace problem.
// Units: k in N/m, x in m, E in J. Invariant under rigid translations and rotations.
struct ZeroLengthSpring {
  static constexpr int kNumNodes = 2;
  static constexpr int kNumOutputs = 3;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  explicit ZeroLengthSpring(double stiffness) : sqrt_stiffness(std::sqrt(stiffness)) {}

  template <typename T>
  bool operator()(const T* const xi, const T* const xj, T* residual) const {
    for (int c = 0; c < 3; ++c) residual[c] = sqrt_stiffness * (xj[c] - xi[c]);
    return true;
  }

  static ZeroLengthSpring Create(double stiffness) { return ZeroLengthSpring(stiffness); }

  const double sqrt_stiffness;  // √(N/m)
};

}  // namespace drape

#endif  // DRAPE_COSTS_ZERO_LENGTH_SPRING_H_
