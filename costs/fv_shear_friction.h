#ifndef DRAPE_COSTS_FV_SHEAR_FRICTION_H_
#define DRAPE_COSTS_FV_SHEAR_FRICTION_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"
#include "costs/fv_membrane.h"

namespace drape {

// The friction between a fabric's yarns in shear (Kawabata's KES-FB1 hysteresis 2HG: the shear
// force per unit width is about G γ + HG on loading, HG = 2HG/2), for one quarter section bPa of
// control volume P, warp arm P→A, weft arm P→B (the quarter of FvMembrane):
//   U = HG A_q (√(γ² + δ²) − δ),   γ = asin(u·v/(|u||v|)),   u = A − P, v = B − P,
// γ the quarter's shear angle (FvMembrane's, exact; 0 at rest) and A_q = l_PA l_PB / 4 its area.
// It is the potential of a rigid–plastic friction force in series with the elastic one, for a
// drape formed by monotone loading from the rest state (deformation theory of plasticity, as
// FvBendingFriction for 2HB): dU/dγ = HG A_q γ/√(γ² + δ²) → HG A_q sgn γ as δ → 0, so beside
// ½ G γ² A_q the shear force is G γ + HG wherever |γ| ≫ δ, and the quarter stays square where the
// load's shear force is below HG. δ (rad) smooths the kink of |γ| at the rest state, where every
// drape starts; the answer converges as δ → 0 (tests/fv_shear_friction_test.cc). Units: HG in
// N/m, A_q in m², γ and δ in rad, U in J. Invariant under rigid motions; zero force at rest
// (dU/dγ = 0 at γ = 0).
// In a load step of the incremental form (FvBendingFrictionStep, for 2HB, says what it is) the
// kink sits at γ0, the shear angle at the end of the previous step: U = HG A_q (√((γ − γ0)² + δ²)
// − δ). γ0 = 0 is the form above, bit for bit.
struct FvShearFriction {
  static constexpr int kNumNodes = 3;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  // friction: HG (N/m); rest arm lengths l_PA, l_PB (m); smoothing: δ (rad); previous: γ0 (rad).
  FvShearFriction(double friction, double rest_a, double rest_b, double smoothing_in,
                  double previous_in = 0.0)
      : weight(friction * rest_a * rest_b / 4.0), smoothing(smoothing_in), previous(previous_in) {
    assert(friction >= 0.0 && rest_a > 0.0 && rest_b > 0.0 && smoothing_in > 0.0);
  }

  // γ (rad), FvMembrane's shear angle of quarter P, A, B; false where an arm has no length or the
  // angle is not defined.
  template <typename T>
  static bool ShearAngleOf(const T* p, const T* a, const T* b, T* shear) {
    using std::sqrt;
    T gram[3];
    FvMembrane::ArmGram(p, a, b, gram);
    if (!(gram[0] > 0.0) || !(gram[1] > 0.0)) return false;  // an arm of zero length
    return FvMembrane::ShearAngle(gram, sqrt(gram[0]), sqrt(gram[1]), shear);
  }

  // Nodes P, A (warp neighbour), B (weft neighbour), as FvMembrane.
  template <typename T>
  bool operator()(const T* const p, const T* const a, const T* const b, T* energy) const {
    using std::sqrt;
    T shear;
    if (!ShearAngleOf(p, a, b, &shear)) return false;
    const T slip = shear - previous;
    energy[0] = weight * (sqrt(slip * slip + smoothing * smoothing) - smoothing);
    return true;
  }

  static FvShearFriction Create(double friction, double rest_a, double rest_b, double smoothing,
                                double previous = 0.0) {
    return FvShearFriction(friction, rest_a, rest_b, smoothing, previous);
  }

  const double weight;     // HG A_q, N·m
  const double smoothing;  // δ, rad
  const double previous;   // γ0, rad
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_SHEAR_FRICTION_H_
