#ifndef DRAPE_COSTS_FV_MEMBRANE_H_
#define DRAPE_COSTS_FV_MEMBRANE_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"
#include "costs/quadratic_form_factor.h"

namespace drape {

// In-plane (membrane) energy of one quarter section bPa of control volume P (Hu/Teng §9.2.3.2,
// eqs. 9.3–9.6), for the warp arm P→A (A = E or W) and the weft arm P→B (B = N or S):
//   U = ½ (E1 ε1² + 2 E12 ε1 ε2 + E2 ε2² + G γ²) A_q,
//   ε1 = (|A−P| − l_PA)/l_PA,   ε2 = (|B−P| − l_PB)/l_PB,   γ = π/2 − ∠(A−P, B−P),
//   E1 = E_warp/(1 − ν_warp ν_weft),  E2 = E_weft/(1 − ν_warp ν_weft),
//   E12 = ν_warp E_weft/(1 − ν_warp ν_weft),
// A_q = l_PA l_PB / 4 the quarter's area (faces midway between grid nodes). The shear angle is
// exact: γ = asin(u·v/(|u||v|)) for the arms u, v — smooth wherever the arms are not parallel
// (at rest γ = 0 and asin' = 1), so no acos at the flat state (docs/architecture.md, fact 5). The
// rest grid is orthogonal (γ = 0 at rest). Residuals, the Cholesky factor of the form, × √A_q:
//   r0 = √E1 ε1 + E12/√E1 ε2,   r1 = √(E2 − E12²/E1) ε2,   r2 = √G γ.
// Needs E1 > 0 and E1 E2 ≥ E12². Units: E, G in N/m (rigidity per unit width), lengths in m,
// U in J. Invariant under rigid motions; zero force at rest.
struct FvMembrane {
  static constexpr int kNumNodes = 3;
  static constexpr int kNumOutputs = 3;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  // e1, e2, e12: E1, E2, E12 as above (N/m); g: G (N/m); rest arm lengths l_PA, l_PB (m).
  FvMembrane(double e1, double e2, double e12, double g, double rest_a_in, double rest_b_in)
      : rest_a(rest_a_in),
        rest_b(rest_b_in),
        stretch(e1, e12, e2, rest_a_in * rest_b_in / 4.0),
        shear_factor(std::sqrt(g * rest_a_in * rest_b_in / 4.0)) {
    assert(e1 > 0.0 && e2 * e1 >= e12 * e12 && g >= 0.0 && rest_a > 0.0 && rest_b > 0.0);
  }

  // Nodes P, A (warp neighbour), B (weft neighbour). Written in two stages, so that the fast
  // derivatives (src/derivatives/fast_hessian.h) can chain them: the arms' Gram entries (quadratic
  // in the coordinates), then the residuals as functions of those three numbers alone.
  template <typename T>
  bool operator()(const T* const p, const T* const a, const T* const b, T* residual) const {
    T gram[3];
    ArmGram(p, a, b, gram);
    return Residuals(gram, residual);
  }

  // The Gram entries of the arms u = A − P, v = B − P: u·u, v·v, u·v (m²).
  template <typename T>
  static void ArmGram(const T* p, const T* a, const T* b, T* gram) {
    const T u[3] = {a[0] - p[0], a[1] - p[1], a[2] - p[2]};
    const T v[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
    gram[0] = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    gram[1] = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    gram[2] = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  }

  // The residuals from the Gram entries: |u| = √(u·u), |v| = √(v·v), sin γ = u·v/(|u||v|).
  template <typename T>
  bool Residuals(const T* gram, T* residual) const {
    using std::sqrt;
    if (!(gram[0] > 0.0) || !(gram[1] > 0.0)) return false;  // an arm of zero length
    const T da = sqrt(gram[0]), db = sqrt(gram[1]);
    const T strain_a = (da - rest_a) / rest_a;
    const T strain_b = (db - rest_b) / rest_b;
    T shear;
    if (!ShearAngle(gram, da, db, &shear)) return false;
    residual[0] = stretch.l11 * strain_a + stretch.l12 * strain_b;
    residual[1] = stretch.l22 * strain_b;
    residual[2] = shear_factor * shear;
    return true;
  }

  // The shear angle γ = asin(u·v/(|u||v|)) from the Gram entries and the arms' lengths |u|, |v|;
  // false where the arms are parallel (no quarter left). FvShearFriction's angle too.
  template <typename T>
  static bool ShearAngle(const T* gram, const T& da, const T& db, T* shear) {
    using std::asin;
    const T cosine = gram[2] / (da * db);
    if (!(cosine < 1.0) || !(cosine > -1.0)) return false;
    *shear = asin(cosine);
    return true;
  }

  static FvMembrane Create(double e1, double e2, double e12, double g, double rest_a,
                           double rest_b) {
    return FvMembrane(e1, e2, e12, g, rest_a, rest_b);
  }

  const double rest_a, rest_b;        // l_PA, l_PB, m
  const QuadraticFormFactor stretch;  // of A_q [E1 E12; E12 E2], √(N/m)·m
  const double shear_factor;          // √(G A_q)
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_MEMBRANE_H_
