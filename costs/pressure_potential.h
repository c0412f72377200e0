#ifndef DRAPE_COSTS_PRESSURE_POTENTIAL_H_
#define DRAPE_COSTS_PRESSURE_POTENTIAL_H_

#include "costs/energy_form.h"

namespace drape {

// Pressure inside a closed 2-D chain (Puiseux §4.1.2, the paraglider profile): the potential of
// the whole loop is −p × A, with A the area it encloses in the x–z plane. By the shoelace formula
// A = ½ Σ (x_i z_j − x_j z_i) over its links i → j, so each link carries
//   E = −p · ½ ((x_i − c_x)(z_j − c_z) − (x_j − c_x)(z_i − c_z)),
// where c is any fixed point (its contributions cancel around the loop; the centre of the initial
// profile keeps the numbers small). Links run counter-clockwise as seen with x to the right and
// z up (A > 0), so p > 0 inflates. The force on node i, −∂E/∂x_i, is p/2 times the normal of its
// two links turned outwards: a follower load (it turns with the fabric) that is conservative.
// Units: p in N/m (force per unit length of the profile, per unit depth), x in m, E in J.
// Invariant under translations in x–z and rotations about y (of the whole loop); y is ignored.
struct PressurePotential {
  static constexpr int kNumNodes = 2;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  PressurePotential(double pressure_in, double centre_x_in, double centre_z_in)
      : pressure(pressure_in), centre_x(centre_x_in), centre_z(centre_z_in) {}

  template <typename T>
  bool operator()(const T* const xi, const T* const xj, T* energy) const {
    const T ax = xi[0] - centre_x, az = xi[2] - centre_z;
    const T bx = xj[0] - centre_x, bz = xj[2] - centre_z;
    energy[0] = -0.5 * pressure * (ax * bz - bx * az);
    return true;
  }

  static PressurePotential Create(double pressure, double centre_x, double centre_z) {
    return PressurePotential(pressure, centre_x, centre_z);
  }

  const double pressure;  // N/m
  const double centre_x;  // m
  const double centre_z;  // m
};

}  // namespace drape

#endif  // DRAPE_COSTS_PRESSURE_POTENTIAL_H_
