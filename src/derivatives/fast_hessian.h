// Fast exact energy, gradient and Hessian of the finite-volume functors, derived from the
// functors' own stages by the chain rule (the physics stays written once, in costs/).
//
// FvBending and FvBendingEdge compute their residuals in stages: curvature binormals (3 nodes
// each), unit tangents (2 nodes each), sections (FvBending only: 6 numbers each) and residuals
// linear in the last stage. FvMembrane computes the Gram entries of its two arms (quadratic in
// the coordinates), then its residuals from those 3 numbers; FvCellShear the same of its cell's
// centre tangents. FvBendingFriction computes one
// curvature binormal, then its energy from those 3 numbers. Nested Jets over one whole functor
// carry 6–12 derivatives through every operation; here each stage is differentiated on its own
// with the few variables it reads (6 relative coordinates for a binormal, 3 for a tangent, 6 for
// a section, 3 Gram entries), and the results are chained: for E = ½|r|², r = L y(Q(x)),
//   ∇E = J_Qᵀ g_Q,   ∇²E = J_Qᵀ H_Q J_Q + Σ_j g_Q,j ∇²Q_j,
// where g_Q, H_Q are the gradient and Hessian of E over the intermediate values Q (themselves from
// the chain rule through the sections and the constant matrix L, read off the functor's linear
// residual stage by a first-order Jet). The bending stages' values are the functor's own stage
// functions; their Jacobians and weighted Hessians Σ_j g_j ∇²Q_j are closed forms
// (stage_derivatives.h, each checked against second-order automatic differentiation of the same
// stage function). FvMembrane's residual stage is differentiated by second-order forward
// differentiation (second_order.h: value, gradient and packed Hessian in one number). Every
// result is checked against the nested-Jet Hessian of the whole functor in tests/term_checks.h.
//
// Projection (StagedProjection, for the projected-Newton matrix H₊): a term whose exact local
// Hessian is positive semidefinite (Cholesky, to 1e-12 of its largest entry; FvBending's tested on
// its 12×12 block without P, the Hessian over the other nodes' positions relative to P) gives it
// unchanged.
// Otherwise:
//   FvMembrane, FvBendingEdge: the chain-rule sum is formed again with the Gauss–Newton part kept
//     as it is (it is semidefinite) and each small curvature block made semidefinite on its own
//     (psd_projection.h: negative eigenvalues clamped to zero, or replaced by their magnitudes):
//     FvMembrane: ∇²φ over the Gram entries (3×3) and M (2×2, the Gram entries' own curvature);
//     FvBendingEdge: the binormal's Σ g ∇²k (6×6). A sum of semidefinite blocks mapped by linear
//     maps is semidefinite, and as each block only gains (B₊ − B ⪰ 0), H₊ − H ⪰ 0 too. H₊ is then
//     not the nearest semidefinite matrix to H but a larger one (a compressed membrane arm of
//     axial stiffness k keeps k·l/|u| > k along itself, where the whole term's projection would
//     keep k); it replaces a 9×9 eigen-decomposition by a 3×3 and a 2×2 one.
//   FvBendingFriction: the eigenvalues filtered of its whole Hessian over the relative coordinates
//     (6×6, a − p and b − p; fast_hessian.cc says why not blockwise), mapped to the nodes.
//   FvBending: the Gauss–Newton part Jᵀ J of E = ½|r|² (J = ∂r/∂x, 8×15), which the chain rule
//     has already formed: no decomposition at all. It drops the curvature Σ r_i ∇²r_i whole, the
//     positive part too, so H₊ − H ⪰ 0 does not hold here; the filter does not apply. Measured
//     against the nearest semidefinite matrix (the eigen-decomposition of its 12×12 restriction
//     to the motions that are not translations; docs/benchmarks.md, session 13): an assembly
//     with H₊ about half as costly, and fewer newton iterations on four benchmark scenes of
//     five (the sphere took more), as far as the scatter of the paths through the folds shows.
// tests/term_checks.h (ExpectStagedProjectionValid) checks, for every finite-volume functor on
// every derivative check, H₊ ⪰ 0, translations in its null space, H₊ = H where H ⪰ 0, and where H
// is indefinite H₊ − H ⪰ 0 (StandIn::kAboveHessian) or H₊ = Jᵀ J with J from Ceres's
// differentiation of the functor's residuals (StandIn::kGaussNewton).
//
//   FvCellShear: as FvMembrane, its Gram stage taken over the cell's centre tangents (linear in
//     its four nodes), both curvature blocks made semidefinite on their own.
//   FvTwist: one residual r, so ∇²E = ∇r ∇rᵀ + r ∇²r; its stand-in is ∇r ∇rᵀ, the Gauss–Newton
//     part, as FvBending's.
// FvTwist computes its residual in stages too: the mixed difference d and the diagonals a, b
// (linear in the coordinates), the unit normal n(a, b), and the residual linear in d; the normal
// and the residual stage are each differentiated in SecondOrder<6> numbers (second_order.h) and
// chained through the constant map from the relative positions.
//
// FastHessian<Functor>::kAvailable says whether a functor has such a path (src/model/term.h uses
// it in place of the nested Jets). The paths are defined in fast_hessian.cc, compiled once: this
// header is read by nearly every file (through term.h), and their second-order numbers, were they
// inline here, would be instantiated again in each (about a minute per file in the sanitized
// build).
#ifndef DRAPE_SRC_DERIVATIVES_FAST_HESSIAN_H_
#define DRAPE_SRC_DERIVATIVES_FAST_HESSIAN_H_

#include "src/derivatives/psd_projection.h"

namespace drape {

struct FvBending;
struct FvBendingEdge;
struct FvBendingFriction;
struct FvCellShear;
struct FvMembrane;
struct FvTwist;

// What a term's stand-in is where its Hessian is indefinite (see "Projection" above).
enum class StandIn {
  kAboveHessian,  // H₊ − H ⪰ 0: each small curvature block made semidefinite on its own
  kGaussNewton,   // H₊ = Jᵀ J, the Gauss–Newton part of E = ½|r|²
};

namespace internal {

template <typename Functor>
struct FastHessian {
  static constexpr bool kAvailable = false;
};

// A positive semidefinite stand-in for a term's Hessian, built from its stages (see "Projection"
// above): `hessian` (row-major, the term's size) receives it; `changed` says whether it differs
// from the exact Hessian.
struct StagedProjection {
  EigenvalueFilter filter = EigenvalueFilter::kClamp;
  double* hessian = nullptr;
  bool changed = false;
};

// Energy, gradient and Hessian (row-major, over the functor's 3N coordinates) of `functor` at
// nodes x[0..N−1], and, given `projection`, the semidefinite stand-in. False if not finite.
template <>
struct FastHessian<FvBending> {
  static constexpr bool kAvailable = true;
  static constexpr StandIn kStandIn = StandIn::kGaussNewton;
  static bool Evaluate(const FvBending& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian, StagedProjection* projection = nullptr);
};

template <>
struct FastHessian<FvBendingEdge> {
  static constexpr bool kAvailable = true;
  static constexpr StandIn kStandIn = StandIn::kAboveHessian;
  static bool Evaluate(const FvBendingEdge& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian, StagedProjection* projection = nullptr);
};

// Its stand-in is its relative 6×6 Hessian's eigenvalues filtered (H₊ − H ⪰ 0 holds for that too).
template <>
struct FastHessian<FvBendingFriction> {
  static constexpr bool kAvailable = true;
  static constexpr StandIn kStandIn = StandIn::kAboveHessian;
  static bool Evaluate(const FvBendingFriction& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian, StagedProjection* projection = nullptr);
};

template <>
struct FastHessian<FvMembrane> {
  static constexpr bool kAvailable = true;
  static constexpr StandIn kStandIn = StandIn::kAboveHessian;
  static bool Evaluate(const FvMembrane& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian, StagedProjection* projection = nullptr);
};

template <>
struct FastHessian<FvCellShear> {
  static constexpr bool kAvailable = true;
  static constexpr StandIn kStandIn = StandIn::kAboveHessian;
  static bool Evaluate(const FvCellShear& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian, StagedProjection* projection = nullptr);
};

template <>
struct FastHessian<FvTwist> {
  static constexpr bool kAvailable = true;
  static constexpr StandIn kStandIn = StandIn::kGaussNewton;
  static bool Evaluate(const FvTwist& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian, StagedProjection* projection = nullptr);
};

}  // namespace internal
}  // namespace drape

#endif  // DRAPE_SRC_DERIVATIVES_FAST_HESSIAN_H_
