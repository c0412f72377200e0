// The energy measured locally, from an anchor point, as the integral of the gradient along the
// straight step (trapezoid rule, exact for the quadratic energy near a minimum):
//   E(x) ≈ E(x_a) + ½ (g(x_a) + g(x)) · (x − x_a).
// Near equilibrium a step changes the energy by about |g|²/k, far below the roundoff of the total
// energy (1e-16 |E| in double, 1e-19 |E| even in long double), so line searches that compare
// energies stall around a relative residual of 1e-7. Differences of this local energy carry the
// roundoff of the step instead. Used by the L-BFGS-type solvers (ceres-lbfgs, nlopt-*).
#ifndef DRAPE_SRC_DERIVATIVES_LOCAL_ENERGY_H_
#define DRAPE_SRC_DERIVATIVES_LOCAL_ENERGY_H_

#include <cassert>
#include <vector>

namespace drape {

class LocalEnergy {
 public:
  bool anchored() const { return !anchor_point_.empty(); }

  // Moves the anchor to `point` (free coordinates), where the gradient is `gradient` and the local
  // energy has the value `value` (0 to measure from there).
  void Anchor(const std::vector<double>& point, const std::vector<double>& gradient, double value) {
    anchor_point_ = point;
    anchor_gradient_ = gradient;
    anchor_value_ = value;
  }

  // The local energy at `point`, where the gradient is `gradient` (both of the anchor's size).
  double At(const double* point, const double* gradient) const {
    assert(anchored());
    long double change = 0.0L;
    for (size_t f = 0; f < anchor_point_.size(); ++f) {
      change += 0.5L * (anchor_gradient_[f] + gradient[f]) *
                (static_cast<long double>(point[f]) - anchor_point_[f]);
    }
    return anchor_value_ + static_cast<double>(change);
  }

 private:
  std::vector<double> anchor_point_, anchor_gradient_;
  double anchor_value_ = 0.0;
};

}  // namespace drape

#endif  // DRAPE_SRC_DERIVATIVES_LOCAL_ENERGY_H_
