#ifndef DRAPE_COSTS_FV_BENDING_FRICTION_H_
#define DRAPE_COSTS_FV_BENDING_FRICTION_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"
#include "costs/fv_bending.h"

namespace drape {

// The friction between a fabric's fibres and yarns in bending (Kawabata's KES-FB2 hysteresis
// 2HB: the bending moment per unit width is about D κ + HB on loading, HB = 2HB/2), for one
// control volume P in one grid direction, nodes a → P → b (W, P, E or S, P, N):
//   U = H A_P (√(κ² + δ²) − δ),   κ = |κb| / l_P,
// κb the curvature binormal of FvBendingEdge (2 tan(φ/2), φ the turning angle) and l_P the
// control volume's size at rest, A_P its area. It is the potential of a rigid–plastic friction
// moment in series with the elastic one, for a drape formed by monotone loading from the flat
// state (deformation theory of plasticity: the loading branch M = D κ + H sgn κ of the KES-FB2
// curve has this potential): dU/dκ = H A_P κ/√(κ² + δ²) → H A_P sgn κ as δ → 0,
// so beside ½ D κ² A_P the moment is D κ + H wherever |κ| ≫ δ, and the fabric stays straight
// where the load's moment is below H. |κ| has a kink at the flat state, where every drape starts:
// δ (1/m) smooths it over curvatures below δ (radii of curvature above 1/δ); the answer converges
// as δ → 0 (tests/fv_bending_friction_test.cc; docs/reference.md). Units: H in N·m/m = N, A in m²,
// l and 1/δ in m, U in J. Invariant under rigid motions; zero force when straight (dU/dκ = 0 at
// κ = 0).
struct FvBendingFriction {
  static constexpr int kNumNodes = 3;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  FvBendingFriction(double friction, double volume_size, double volume_area, double smoothing_in)
      : weight(friction * volume_area), size(volume_size), smoothing(smoothing_in) {
    assert(friction >= 0.0 && volume_size > 0.0 && volume_area > 0.0 && smoothing_in > 0.0);
  }

  template <typename T>
  bool operator()(const T* const a, const T* const p, const T* const b, T* energy) const {
    T binormal[3];
    CurvatureBinormal(a, p, b, binormal);
    energy[0] = OfBinormal(binormal);
    return true;
  }

  // The energy as a function of the curvature binormal κb: the stage the fast derivatives
  // differentiate (src/derivatives/fast_hessian.cc).
  template <typename T>
  T OfBinormal(const T* binormal) const {
    const T curvature_squared =
        (binormal[0] * binormal[0] + binormal[1] * binormal[1] + binormal[2] * binormal[2]) /
        (size * size);
    using std::sqrt;
    return weight * (sqrt(curvature_squared + smoothing * smoothing) - smoothing);
  }

  static FvBendingFriction Create(double friction, double volume_size, double volume_area,
                                  double smoothing) {
    return FvBendingFriction(friction, volume_size, volume_area, smoothing);
  }

  const double weight;     // H A_P, N·m²
  const double size;       // l_P, m
  const double smoothing;  // δ, 1/m
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_BENDING_FRICTION_H_
