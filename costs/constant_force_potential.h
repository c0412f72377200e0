#ifndef DRAPE_COSTS_CONSTANT_FORCE_POTENTIAL_H_
#define DRAPE_COSTS_CONSTANT_FORCE_POTENTIAL_H_

#include "costs/energy_form.h"

namespace drape {

// Potential of a constant (dead) force f on one node, measured from a reference position x_ref:
//   E = −f · (x − x_ref).
// Gravity is f = m g (m the lumped node mass); applied loads are f as given. Units: f in N, x in m,
// E in J. Invariant under translation only up to a constant: it is the term that loads the model.
struct ConstantForcePotential {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  ConstantForcePotential(const double force_in[3], const double reference_in[3])
      : force{force_in[0], force_in[1], force_in[2]},
        reference{reference_in[0], reference_in[1], reference_in[2]} {}

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = -(force[0] * (x[0] - reference[0]) + force[1] * (x[1] - reference[1]) +
                  force[2] * (x[2] - reference[2]));
    return true;
  }

  static ConstantForcePotential Create(const double force[3], const double reference[3]) {
    return ConstantForcePotential(force, reference);
  }

  const double force[3];      // N
  const double reference[3];  // m
};

}  // namespace drape

#endif  // DRAPE_COSTS_CONSTANT_FORCE_POTENTIAL_H_
