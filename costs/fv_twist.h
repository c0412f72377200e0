#ifndef DRAPE_COSTS_FV_TWIST_H_
#define DRAPE_COSTS_FV_TWIST_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"

namespace drape {

// Twisting of one lattice cell, the term of the orthotropic plate's bending energy that the grid
// lines' curvatures (costs/fv_bending.h) cannot see:
//   U = ½ · 4 D66 κ12² · A = 2 D66 κ12² A,
// the plate's energy per unit area ½ (D1 κ11² + 2 D12 κ11 κ22 + D2 κ22² + 4 D66 κ12²) (Timoshenko &
// Woinowsky-Krieger, Theory of Plates and Shells, 1959, §86, D_xy; Lekhnitskii's torsional
// rigidity; the twist Hu/Teng's assumption 2 leaves out). D66 is the torsional rigidity (N·m):
// M12 = D66 · 2κ12; an isotropic plate has D66 = D (1 − ν)/2.
//
// The cell has corners P = (i, j), E = (i+1, j), N = (i, j+1) and C = (i+1, j+1) of a rectangular
// rest lattice with sides h1 (warp) and h2 (weft). Its twist is the mixed second difference along
// the normal:
//   κ12 = (d · n) / (h1 h2),   d = C − E − N + P,   n = m / |m|,   m = (C − P) × (N − E),
// n the unit normal of the cell's two diagonals (the bilinear patch's normal at its centre). For
// w = c x y, d = (0, 0, c h1 h2) and κ12 = c exactly in the linear limit; for w = f(x) + g(y) (pure
// bending along the grid lines, a cylinder about a grid line) d = 0 and κ12 = 0 exactly, at any
// amplitude. A cylinder of curvature κ about an axis at angle α to the warp has κ12 = κ sin α cos
// α, which with κ11 = κ cos²α, κ22 = κ sin²α gives the isotropic plate ½ D κ² at every α. The
// residual is r = 2 √(D66 A) κ12 (U = ½ r²). `weight` = D66 A (N·m · m²) is the sum, over the
// cell's corners, of each corner's D66 times the share of its control volume's area that the cell
// carries (src/model/finite_volume.cc), so that the cells' areas add up to the fabric's.
// Units: lengths in m, D66 in N·m, U in J. Invariant under rigid motions (d and m turn together;
// d·m changes sign under a reflection and U does not); d = 0 at the flat rest state, where m ≠ 0,
// so U is smooth there with zero force. Undefined (false) only for a cell folded flat onto a line
// (m = 0).
struct FvTwist {
  static constexpr int kNumNodes = 4;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  FvTwist(double weight, double size1, double size2)
      : scale(2.0 * std::sqrt(weight) / (size1 * size2)) {
    assert(weight >= 0.0 && size1 > 0.0 && size2 > 0.0);
  }

  // Nodes P, E, N, C (the cell's corners (i, j), (i+1, j), (i, j+1), (i+1, j+1)). Written in
  // stages, so that the fast derivatives (src/derivatives/fast_hessian.h) can differentiate the
  // one non-linear stage, the normal, on its own: d and the diagonals (linear in the nodes), the
  // unit normal n of the diagonals, and the residual (linear in d for a given n).
  template <typename T>
  bool operator()(const T* const p, const T* const e, const T* const n, const T* const c,
                  T* residual) const {
    T d[3], diagonal1[3], diagonal2[3], normal[3];
    for (int k = 0; k < 3; ++k) {
      d[k] = c[k] - e[k] - n[k] + p[k];
      diagonal1[k] = c[k] - p[k];
      diagonal2[k] = n[k] - e[k];
    }
    if (!Normal(diagonal1, diagonal2, normal)) return false;
    Residual(d, normal, residual);
    return true;
  }

  // n = (a × b) / |a × b| for the diagonals a = C − P, b = N − E; false where a × b = 0.
  template <typename T>
  static bool Normal(const T* a, const T* b, T* normal) {
    const T m[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0]};
    const T m_squared = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
    if (!(m_squared > 0.0)) return false;
    using std::sqrt;
    const T inverse = 1.0 / sqrt(m_squared);
    for (int k = 0; k < 3; ++k) normal[k] = m[k] * inverse;
    return true;
  }

  // r = 2 √(D66 A) (d · n) / (h1 h2).
  template <typename T>
  void Residual(const T* d, const T* normal, T* residual) const {
    residual[0] = scale * (d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]);
  }

  static FvTwist Create(double weight, double size1, double size2) {
    return FvTwist(weight, size1, size2);
  }

  const double scale;  // 2 √(D66 A) / (h1 h2), √(N·m)/m
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_TWIST_H_
