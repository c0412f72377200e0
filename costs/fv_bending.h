#ifndef DRAPE_COSTS_FV_BENDING_H_
#define DRAPE_COSTS_FV_BENDING_H_

#include <algorithm>
#include <cassert>
#include <cmath>

#include "costs/energy_form.h"
#include "costs/quadratic_form_factor.h"
#include "costs/safe_math.h"

namespace drape {

// Curvature binormal of the polyline a → p → b with arms e0 = p − a, e1 = b − p:
//   κb = 2 e0×e1 / (|e0||e1| + e0·e1),   |κb| = 2 tan(φ/2) = 2 cot(θ/2)
// for the turning angle φ (θ = π − φ the angle between the arms, Hu/Teng eq. 9.1). Smooth at the
// straight (flat) state φ = 0, where acos-based formulas have NaN derivatives
// (docs/architecture.md, fact 5); undefined only when an arm has zero length or the arms fold back
// (φ = π).
template <typename T>
void CurvatureBinormal(const T* a, const T* p, const T* b, T* binormal) {
  const T e0[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const T e1[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
  const T denominator =
      SafeDistance(a, p) * SafeDistance(p, b) + (e0[0] * e1[0] + e0[1] * e1[1] + e0[2] * e1[2]);
  const T scale = 2.0 / denominator;
  binormal[0] = scale * (e0[1] * e1[2] - e0[2] * e1[1]);
  binormal[1] = scale * (e0[2] * e1[0] - e0[0] * e1[2]);
  binormal[2] = scale * (e0[0] * e1[1] - e0[1] * e1[0]);
}

// Unit vector along b − a (zero if a = b).
template <typename T>
void UnitDirection(const T* a, const T* b, T* unit) {
  const T length = SafeDistance(a, b);
  for (int c = 0; c < 3; ++c) unit[c] = length > 0.0 ? T((b[c] - a[c]) / length) : T();
}

// Bending of one control volume P in one grid direction only: an edge volume, whose other
// direction ends at the fabric's edge (Hu/Teng §9.2.5), or a node of a 2-D strip (a single row).
// Nodes a → P → b are the neighbours along that direction (W, P, E or S, P, N).
//   U = ½ D κ² A_P,   κ = 2 tan(φ/2) / l_P,   residuals r = √(D A_P) κb / l_P (3 of them),
// with l_P = (|a−P| + |P−b|)/2 at rest (the control-volume size, for non-uniform grids too) and
// A_P the control-volume area. κ² = |κb|²/l² uses the full 3-D angle between the arms, as the
// paper's eq. 9.20 does. The rest state is flat (κ = 0). Units: D in N·m, lengths in m, A in m²,
// U in J. Invariant under rigid motions; zero force when straight.
struct FvBendingEdge {
  static constexpr int kNumNodes = 3;
  static constexpr int kNumOutputs = 3;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  FvBendingEdge(double rigidity, double volume_size, double volume_area)
      : scale(std::sqrt(rigidity * volume_area) / volume_size) {
    assert(rigidity >= 0.0 && volume_size > 0.0 && volume_area > 0.0);
  }

  // In two stages, binormal then residuals linear in it, for the fast derivatives
  // (src/derivatives/fast_hessian.h).
  template <typename T>
  bool operator()(const T* const a, const T* const p, const T* const b, T* residual) const {
    T binormal[3];
    CurvatureBinormal(a, p, b, binormal);
    Residuals(binormal, residual);
    return true;
  }

  template <typename T>
  void Residuals(const T* binormal, T* residual) const {
    for (int c = 0; c < 3; ++c) residual[c] = scale * binormal[c];
  }

  static FvBendingEdge Create(double rigidity, double volume_size, double volume_area) {
    return FvBendingEdge(rigidity, volume_size, volume_area);
  }

  const double scale;  // √(D A_P) / l_P, √(N·m)
};

// Bending of an internal control volume P (Hu/Teng §9.2.3.1, eqs. 9.1–9.2):
//   U = ½ (D1 κ1² + 2 D12 κ1 κ2 + D2 κ2²) A_P
// with κ1 from the warp nodes W → P → E and κ2 from the weft nodes S → P → N, each
// κ = 2 tan(φ/2)/l (= 2 cot(θ/2)/l for the arm angle θ), l_P1 = (|W−P| + |P−E|)/2 and
// l_P2 = (|S−P| + |P−N|)/2 at rest, A_P the control-volume area. Units: D in N·m, U in J.
//
// Sign rule (the ± of eq. 9.21): κ1 κ2 < 0 on anticlastic (saddle) surfaces, > 0 on synclastic
// ones. With the binormals k1 = κb(W,P,E)/l_P1, k2 = κb(S,P,N)/l_P2 and the unit grid tangents
// t1 = (E−W)/|E−W|, t2 = (N−S)/|N−S|, the normal curvatures signed by the surface normal
// t1×t2 are s1 = −k1·t2 and s2 = k2·t1 (k1 = κ1 t1×n). Splitting k1 = (k1·t2) t2 + k1⊥ exactly
// (and k2 likewise along t1),
//   2U/A_P = D1 s1² + 2 D12 s1 s2 + D2 s2² + D1 |k1⊥|² + D2 |k2⊥|²,
// so D1 κ1² = D1 |k1|² and D2 κ2² = D2 |k2|² stay the paper's full-angle curvatures, and the
// coupling uses the signed curvatures. Residuals (the Cholesky factor of the 2×2 form, then the
// out-of-section parts), all × √A_P:
//   r0 = √D1 s1 + D12/√D1 s2,  r1 = √(D2 − D12²/D1) s2,  r2..4 = √D1 k1⊥,  r5..7 = √D2 k2⊥.
// Needs D12² ≤ D1 D2 (a positive semidefinite energy). Everything is smooth at the flat state.
// Invariant under rigid motions; zero force when flat.
struct FvBending {
  static constexpr int kNumNodes = 5;
  static constexpr int kNumOutputs = 8;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  FvBending(double d1, double d2, double d12, double size1_in, double size2_in, double area)
      : size1(size1_in),
        size2(size2_in),
        coupling(d1, d12, d2, area),
        off1(std::sqrt(d1 * area)),
        off2(std::sqrt(d2 * area)) {
    assert(d1 >= 0.0 && d2 >= 0.0 && d12 * d12 <= d1 * d2 * (1.0 + 1e-12));
    assert(size1 > 0.0 && size2 > 0.0 && area > 0.0);
  }

  // Nodes in the paper's order W, P, E, S, N. Written in stages, so that the fast derivatives
  // (src/derivatives/fast_hessian.h) can differentiate each stage on its own and chain them: the
  // two binormals (3 nodes each) and unit tangents (2 nodes each), the two sections (of one
  // binormal and the other direction's tangent), then residuals linear in the sections.
  template <typename T>
  bool operator()(const T* const w, const T* const p, const T* const e, const T* const s,
                  const T* const n, T* residual) const {
    T k1[3], k2[3], t1[3], t2[3], section1[4], section2[4];
    CurvatureBinormal(w, p, e, k1);
    CurvatureBinormal(s, p, n, k2);
    UnitDirection(w, e, t1);
    UnitDirection(s, n, t2);
    Section(k1, t2, size1, section1);
    Section(k2, t1, size2, section2);
    Residuals(section1, section2, residual);
    return true;
  }

  // One direction's section: from its binormal k, the other direction's unit tangent t and the
  // control-volume size l, the component along t, k·t/l, and the rest, k/l − (k·t/l) t.
  template <typename T>
  static void Section(const T* k, const T* t, double size, T* section) {
    section[0] = (k[0] * t[0] + k[1] * t[1] + k[2] * t[2]) / size;
    for (int c = 0; c < 3; ++c) section[1 + c] = k[c] / size - section[0] * t[c];
  }

  // The residuals from the two sections (s1 = −along1, s2 = along2): linear in the sections.
  template <typename T>
  void Residuals(const T* section1, const T* section2, T* residual) const {
    const T s1 = -section1[0], s2 = section2[0];
    residual[0] = coupling.l11 * s1 + coupling.l12 * s2;
    residual[1] = coupling.l22 * s2;
    for (int c = 0; c < 3; ++c) {
      residual[2 + c] = off1 * section1[1 + c];
      residual[5 + c] = off2 * section2[1 + c];
    }
  }

  static FvBending Create(double d1, double d2, double d12, double size1, double size2,
                          double area) {
    return FvBending(d1, d2, d12, size1, size2, area);
  }

  const double size1, size2;           // l_P1, l_P2: control-volume sizes, m
  const QuadraticFormFactor coupling;  // of A_P [D1 D12; D12 D2], √(N·m)·m
  const double off1, off2;             // √(D1 A_P), √(D2 A_P)
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_BENDING_H_
