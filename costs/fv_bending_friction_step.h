#ifndef DRAPE_COSTS_FV_BENDING_FRICTION_STEP_H_
#define DRAPE_COSTS_FV_BENDING_FRICTION_STEP_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"
#include "costs/fv_bending.h"
#include "costs/safe_math.h"

namespace drape {

// The friction between a fabric's fibres and yarns in bending (KES-FB2's 2HB, HB = 2HB/2) in one
// load step of the incremental form, for one control volume P in one grid direction, nodes
// a → P → b (W, P, E or S, P, N) and d, P's neighbour across it (N or E; where the lattice ends
// there, S or W, with σ = −1):
//   U = H A_P (√((κ − κ0)² + δ²) − δ),   κ = (κb · t) / (|t| l_P),   t = σ (d − P),
// κb the curvature binormal of FvBendingEdge (2 tan(φ/2) times the unit normal of the plane aPb)
// and κ0 the same at the end of the previous load step. Bending along a → b turns about the
// other direction, so κb lies along t and κ is the curvature signed by the side it bends to.
// The energetic (rate-independent) form of a rigid–plastic friction moment in series with the
// elastic one (A. Mielke, "Evolution of rate-independent systems", Handbook of Differential
// Equations: Evolutionary Equations 2, 2005): a load history is a sequence of minimisations of
// E(x) + Σ H A |κ − κ0|, each step's dissipation the friction's work H A |Δκ|, so that a fold
// that unloads or reverses is held by the friction instead of springing back. Where κ grows
// monotonically along the load path, the steps' dissipations add up to H A |κ| and the steps reach
// FvBendingFriction's deformation-theory equilibrium. δ (1/m) smooths the kink at κ = κ0, where
// each step starts. Units: H in N, A in m², l and 1/δ in m, U in J. Invariant under rigid motions
// (κb · t is); zero force where κ = κ0.
struct FvBendingFrictionStep {
  static constexpr int kNumNodes = 4;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  // across_sign: σ, +1 where d is the high neighbour (N or E), −1 the low one (S or W).
  FvBendingFrictionStep(double friction, double volume_size, double volume_area,
                        double smoothing_in, double previous_curvature, double across_sign)
      : weight(friction * volume_area),
        size(volume_size),
        smoothing(smoothing_in),
        previous(previous_curvature),
        sign(across_sign) {
    assert(friction >= 0.0 && volume_size > 0.0 && volume_area > 0.0 && smoothing_in > 0.0);
    assert(across_sign == 1.0 || across_sign == -1.0);
  }

  // κ (1/m), the curvature along a → P → b signed by t = σ (d − P); false where d is on P (no
  // direction across).
  template <typename T>
  static bool SignedCurvature(const T* a, const T* p, const T* b, const T* d, double size,
                              double sign, T* curvature) {
    const T length = SafeDistance(p, d);
    if (!(length > 0.0)) return false;
    T binormal[3];
    CurvatureBinormal(a, p, b, binormal);
    const T across[3] = {d[0] - p[0], d[1] - p[1], d[2] - p[2]};
    const T along = binormal[0] * across[0] + binormal[1] * across[1] + binormal[2] * across[2];
    *curvature = sign * along / (length * size);
    return true;
  }

  template <typename T>
  bool operator()(const T* const a, const T* const p, const T* const b, const T* const d,
                  T* energy) const {
    using std::sqrt;
    T curvature;
    if (!SignedCurvature(a, p, b, d, size, sign, &curvature)) return false;
    const T slip = curvature - previous;
    energy[0] = weight * (sqrt(slip * slip + smoothing * smoothing) - smoothing);
    return true;
  }

  static FvBendingFrictionStep Create(double friction, double volume_size, double volume_area,
                                      double smoothing, double previous_curvature,
                                      double across_sign) {
    return FvBendingFrictionStep(friction, volume_size, volume_area, smoothing, previous_curvature,
                                 across_sign);
  }

  const double weight;     // H A_P, N·m²
  const double size;       // l_P, m
  const double smoothing;  // δ, 1/m
  const double previous;   // κ0, 1/m
  const double sign;       // σ
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_BENDING_FRICTION_STEP_H_
