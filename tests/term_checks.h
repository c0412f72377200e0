// Checks every cost functor passes (through its Term): derivatives against central differences,
// rigid-motion invariance, balanced forces. Shared by the per-cost test files; defined in
// term_checks.cc, compiled once (each of them compiled its own copy of Eigen's eigensolver before).
#ifndef DRAPE_TESTS_TERM_CHECKS_H_
#define DRAPE_TESTS_TERM_CHECKS_H_

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "src/model/term.h"

namespace drape::testing {

// Largest node id of the term + 1, so that `positions` can be sized.
inline int NodesSpanned(const Term& term) {
  int count = 0;
  for (int node : term.nodes()) count = std::max(count, node + 1);
  return count;
}

// The term's energy, gradient and Hessian (by whatever path EnergyHessian takes: the staged chain
// rule of src/derivatives/fast_hessian.h for the finite-volume bending) equal those of nested Jets
// over the whole functor (ReferenceHessian), to `tolerance` relative to the largest entry.
void ExpectHessianMatchesReference(const Term& term, const std::vector<double>& positions,
                                   double tolerance = 1e-10);

// Jᵀ J (row-major, over the term's coordinates) for the Jacobian J of the term's residuals, as
// Ceres differentiates them for its own solvers (Term::NewCostFunction): the Gauss–Newton part of
// E = ½|r|², by a path that shares nothing with src/derivatives/fast_hessian.h.
Eigen::MatrixXd GaussNewtonByCeres(const Term& term, const std::vector<double>& positions);

// A term's staged projection (Term::EnergyHessianProjected, src/derivatives/fast_hessian.h), with
// `filter`: the energy, gradient and Hessian are EnergyHessian's, bit for bit; the stand-in H₊ is
// symmetric, positive semidefinite, keeps the translations in its null space, and equals H exactly
// where H is semidefinite. Where H is not: H₊ is never below H (H₊ − H ⪰ 0) for
// StandIn::kAboveHessian, and equals Ceres's Jᵀ J to 1e-10 for StandIn::kGaussNewton. Returns
// whether H₊ ≠ H (`changed`).
bool ExpectStagedProjectionValid(const Term& term, const std::vector<double>& positions,
                                 EigenvalueFilter filter);

// Energy and its gradient/Hessian from the term agree with central differences of the energy
// (and of the gradient), to `tolerance` relative to the largest entry; and the Hessian equals the
// nested-Jet reference to 1e-10 (ExpectHessianMatchesReference), and a staged projection, where
// the term has one, passes ExpectStagedProjectionValid. Every functor's test calls this.
void ExpectDerivativesMatchDifferences(const Term& term, std::vector<double> positions,
                                       double tolerance = 1e-6);

// The energy does not change under a rigid translation and rotation of the term's nodes.
void ExpectRigidMotionInvariant(const Term& term, const std::vector<double>& positions);

// The term's nodal forces sum to zero and have zero total moment (internal forces).
void ExpectForcesBalance(const Term& term, const std::vector<double>& positions);

// The forces vanish (the energy is stationary) at `positions`.
void ExpectZeroForce(const Term& term, const std::vector<double>& positions,
                     double tolerance = 1e-12);

// The forces vanish at `positions` and at the same nodes turned and shifted as a rigid body (a
// rest state in any orientation).
void ExpectZeroForceInAnyOrientation(const Term& term, const std::vector<double>& positions,
                                     double tolerance);

// Positions of `count` nodes drawn uniformly in a box of side `size`.
std::vector<double> RandomPositions(int count, double size, unsigned seed);

// `positions` with each coordinate moved by a uniform draw in [-amplitude, amplitude].
std::vector<double> Perturbed(std::vector<double> positions, double amplitude, unsigned seed);

}  // namespace drape::testing

#endif  // DRAPE_TESTS_TERM_CHECKS_H_
