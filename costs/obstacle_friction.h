#ifndef DRAPE_COSTS_OBSTACLE_FRICTION_H_
#define DRAPE_COSTS_OBSTACLE_FRICTION_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"

namespace drape {

// Coulomb friction of one node on a rigid obstacle in one load step of the incremental form, with
// the normal force lagged (the friction of IPC: M. Li et al., "Incremental Potential Contact",
// ACM Trans. Graph. 39(4), 2020, §5, there in time steps, here in load steps):
//   U = μ λ (√(|u|² + ε²) − ε),   u = (I − n nᵀ)(x − x0),
// μ the obstacle's friction coefficient, λ n the obstacle's push on the node (its contact terms'
// −∇, N) at the lagged state, x0 where the node was at the start of the step (where the kink
// sits), u the node's slip since then across n, and ε the slip (m) below which the kink is
// smoothed. The force −∇U = −μ λ u / √(|u|² + ε²) opposes the slip and never exceeds μ λ: below
// that a node stays within ε-order of x0 (it sticks), above it the node slides and the friction
// does the work μ λ |u|. The energetic (rate-independent) form of dry friction, as for the fibres'
// (costs/fv_bending_friction_step.h): a load step is a minimisation of E(x) + Σ μ λ |u|, and the
// passes of src/run/run.cc take λ and n again at each pass's result until they settle. Convex in
// x (a norm of a linear map), so its Hessian is positive semidefinite. Units: λ in N, lengths in
// m, U in J. Not invariant under rigid motions of the fabric alone: the obstacle is the frame.
struct ObstacleFriction {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  // normal_in: the unit normal n; start: x0.
  ObstacleFriction(double coefficient, double normal_force, const double normal_in[3],
                   const double start[3], double smoothing_in)
      : weight(coefficient * normal_force),
        normal{normal_in[0], normal_in[1], normal_in[2]},
        origin{start[0], start[1], start[2]},
        smoothing(smoothing_in) {
    assert(coefficient >= 0.0 && normal_force >= 0.0 && smoothing_in > 0.0);
  }

  // u, the slip across n since x0, m.
  template <typename T>
  void Slip(const T* const x, T* slip) const {
    const T moved[3] = {x[0] - origin[0], x[1] - origin[1], x[2] - origin[2]};
    const T along = moved[0] * normal[0] + moved[1] * normal[1] + moved[2] * normal[2];
    for (int c = 0; c < 3; ++c) slip[c] = moved[c] - along * normal[c];
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    using std::sqrt;
    T slip[3];
    Slip(x, slip);
    const T squared = slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2];
    energy[0] = weight * (sqrt(squared + smoothing * smoothing) - smoothing);
    return true;
  }

  static ObstacleFriction Create(double coefficient, double normal_force, const double normal[3],
                                 const double start[3], double smoothing) {
    return ObstacleFriction(coefficient, normal_force, normal, start, smoothing);
  }

  const double weight;     // μ λ, N
  const double normal[3];  // n, unit
  const double origin[3];  // x0, m
  const double smoothing;  // ε, m
};

}  // namespace drape

#endif  // DRAPE_COSTS_OBSTACLE_FRICTION_H_
