#ifndef DRAPE_COSTS_FV_CELL_SHEAR_H_
#define DRAPE_COSTS_FV_CELL_SHEAR_H_

#include <cassert>
#include <cmath>

#include "costs/energy_form.h"
#include "costs/fv_membrane.h"

namespace drape {

// In-plane shear of one lattice cell P, E, N, C (corners (i, j), (i+1, j), (i, j+1), (i+1, j+1)),
// taken once, at the cell's centre (one-point quadrature of the shear):
//   U = ½ G γ_c² A_c,   γ_c = π/2 − ∠(u_c, v_c) = asin(u_c·v_c / (|u_c||v_c|)),
//   u_c = ((E − P) + (C − N))/2,   v_c = ((N − P) + (C − E))/2,
// the bilinear cell's tangents at its centre, A_c = l_PE l_PN its area at rest. It replaces the
// shear of the four corner quarters of FvMembrane (Hu/Teng eqs. 9.3–9.6, the angle between a
// node's two arms) in every whole cell, unless `finite_volume.cell_shear: false` keeps Hu/Teng's
// corners; the quarters keep their stretch.
// Why (docs/drape-tester.md, "Where the first-order error comes from"): a fold oblique to the
// lattice bends each cell about a diagonal, which keeps the cell's four sides (an isometry of its
// two triangles) but closes the arm angles at the two corners off the fold, by
// Δ = asin((1 − cos α)/2) for a fold angle α. The corner form charges that as shear, ¼ G Δ² A in
// all, energy of order G h² (h κ)⁴ per cell that a uniform lattice sheds only as h → 0 and that
// stiffens every fold the lattice does not run along (shear locking, the failing that reduced
// integration of the shear cures in finite elements: T. J. R. Hughes, The Finite Element Method,
// 1987, §4.5). At the centre the same fold reads about Δ/2 over the whole cell, ⅛ G Δ² A: half.
// A homogeneous in-plane shear reads γ at every corner and at the centre alike, so it costs what
// it did. No in-plane motion of a cell costs nothing here that the arms' stretch does not resist
// (an hourglass pattern changes an arm's length). Units: G in N/m, lengths in m, A in m², U in J.
// Invariant under rigid motions; zero force at rest (the rest cell is a rectangle, γ_c = 0).
struct FvCellShear {
  static constexpr int kNumNodes = 4;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kSquares;
  static constexpr bool kTranslationInvariant = true;  // E depends on differences only

  // g: G (N/m); area: A_c (m²).
  FvCellShear(double g, double area) : scale(std::sqrt(g * area)) {
    assert(g >= 0.0 && area > 0.0);
  }

  // Written in stages, so that the fast derivatives (src/derivatives/fast_hessian.h) can chain
  // them: the centre tangents (linear in the nodes), their Gram entries, then the residual.
  template <typename T>
  bool operator()(const T* const p, const T* const e, const T* const n, const T* const c,
                  T* residual) const {
    T u[3], v[3], gram[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = 0.5 * ((e[k] - p[k]) + (c[k] - n[k]));
      v[k] = 0.5 * ((n[k] - p[k]) + (c[k] - e[k]));
    }
    gram[0] = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    gram[1] = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    gram[2] = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    return Residuals(gram, residual);
  }

  // r = √(G A_c) γ_c from the Gram entries u·u, v·v, u·v of the centre tangents.
  template <typename T>
  bool Residuals(const T* gram, T* residual) const {
    using std::sqrt;
    if (!(gram[0] > 0.0) || !(gram[1] > 0.0)) return false;  // a degenerate cell
    T shear;
    if (!FvMembrane::ShearAngle(gram, sqrt(gram[0]), sqrt(gram[1]), &shear)) return false;
    residual[0] = scale * shear;
    return true;
  }

  static FvCellShear Create(double g, double area) { return FvCellShear(g, area); }

  const double scale;  // √(G A_c), √(N·m)
};

}  // namespace drape

#endif  // DRAPE_COSTS_FV_CELL_SHEAR_H_
