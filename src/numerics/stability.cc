// The stability certificate. The free-dof Hessian is assembled exactly (no projection) at the
// final positions and factorised with CHOLMOD: positive definite means a strict local minimum.
//
// Zero modes. Some equilibria have exact zero-energy motions (a sheet hung by one corner turns
// freely about the vertical through that corner; slack tension-only springs). These are neutral,
// not unstable, so the test is on H + τ I with τ = 1e-10 × the mean diagonal of H: eigenvalues
// above −τ count as non-negative. The rounding of the Hessian itself is far below τ.
//
// Estimate of the most negative eigenvalue (when H + τ I is not positive definite): the smallest
// shift σ that makes H + σ I positive definite is −λ_min. It is bracketed by trying shifts ten
// times larger each time, then narrowed by bisection on log σ to 5 %; finally a few steps of
// inverse iteration with (H + σ_hi I)⁻¹ give a Rayleigh quotient, kept inside the bracket.
#include "src/numerics/stability.h"

#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/numerics/sparse_hessian.h"

namespace drape {

namespace {

constexpr double kNeutralTolerance = 1e-10;  // τ relative to the mean diagonal
constexpr double kBracketRatio = 1.05;       // bisection stops when σ_hi / σ_lo is below this
constexpr int kInverseIterations = 20;

double MeanAbsoluteDiagonal(const FreeHessian& hessian) {
  double sum = 0.0;
  for (int k : hessian.diagonal()) sum += std::abs(hessian.values()[k]);
  return sum / hessian.size();
}

bool PositiveDefiniteWithShift(const FreeHessian& hessian, SparseCholesky* cholesky, double shift) {
  const std::vector<double> diagonal(hessian.size(), shift);
  return cholesky->Factorize(hessian.values(), &diagonal);
}

// Rayleigh quotient of H at the vector v to which inverse iteration with the current factor of
// H + σ I converges: an upper bound of λ_min that is close to it when the gap is clear.
double InverseIterationEstimate(const FreeHessian& hessian, SparseCholesky* cholesky,
                                std::vector<double>* vector = nullptr) {
  const int n = hessian.size();
  std::vector<double> local;
  std::vector<double>& v = vector ? *vector : local;
  v.resize(n);
  std::vector<double> w(n);
  for (int k = 0; k < n; ++k) v[k] = 1.0 + 0.1 * std::sin(1.7 * k);  // not orthogonal to much
  for (int step = 0; step < kInverseIterations; ++step) {
    cholesky->Solve(v, &w);
    const double norm = std::sqrt(std::inner_product(w.begin(), w.end(), w.begin(), 0.0));
    for (int k = 0; k < n; ++k) v[k] = w[k] / norm;
  }
  hessian.Multiply(hessian.values(), v.data(), w.data());
  return std::inner_product(v.begin(), v.end(), w.begin(), 0.0);
}

// λ_min of H when H + τ I is not positive definite, and (if `vector`) its eigenvector, unit norm.
double MostNegativeEigenvalue(const FreeHessian& hessian, SparseCholesky* cholesky, double tau,
                              std::vector<double>* vector = nullptr) {
  // A shift that underflows (stiffnesses of 1e-320 give τ = 0 or a subnormal τ) would never grow
  // by tenfold steps: the bracket starts at the smallest normal number at least.
  double low = std::max(tau, std::numeric_limits<double>::min()), high = 10.0 * low;
  while (!PositiveDefiniteWithShift(hessian, cholesky, high)) {
    low = high;
    high *= 10.0;
    if (!std::isfinite(high)) return -INFINITY;
  }
  while (high / low > kBracketRatio) {
    const double middle = std::sqrt(low) * std::sqrt(high);  // low · high may underflow
    if (PositiveDefiniteWithShift(hessian, cholesky, middle)) {
      high = middle;
    } else {
      low = middle;
    }
  }
  PositiveDefiniteWithShift(hessian, cholesky, high);
  const double estimate = InverseIterationEstimate(hessian, cholesky, vector);
  return std::min(-low, std::max(-high, estimate));
}

// τ: the shift below which an eigenvalue counts as a neutral zero mode.
double NeutralShift(const FreeHessian& hessian) {
  const double scale = MeanAbsoluteDiagonal(hessian);
  return kNeutralTolerance * (scale > 0.0 ? scale : 1.0);
}

}  // namespace

bool NegativeCurvature(const FreeHessian& hessian, double* eigenvalue,
                       std::vector<double>* direction, SparseCholesky* cholesky) {
  std::unique_ptr<SparseCholesky> own;
  if (!cholesky) cholesky = (own = std::make_unique<SparseCholesky>(hessian)).get();
  const double tau = NeutralShift(hessian);
  if (PositiveDefiniteWithShift(hessian, cholesky, tau)) return false;
  *eigenvalue = MostNegativeEigenvalue(hessian, cholesky, tau, direction);
  return std::isfinite(*eigenvalue);
}

Stability AnalyseStability(const Model& model, const double* positions,
                           HessianWorkspace* workspace) {
  Stability stability;
  if (model.num_free_dofs() == 0) {  // nothing can move: trivially stable
    stability.computed = true;
    stability.stable = true;
    return stability;
  }
  std::unique_ptr<HessianWorkspace> own;
  if (!workspace) workspace = (own = std::make_unique<HessianWorkspace>(model)).get();
  FreeHessian& hessian = workspace->hessian;
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  if (!hessian.Assemble(positions, /*project=*/false, &assembly, &gradient)) return stability;
  const double tau = NeutralShift(hessian);
  stability.computed = true;
  stability.stable = PositiveDefiniteWithShift(hessian, &workspace->cholesky, tau);
  if (!stability.stable) {
    stability.min_eigenvalue = MostNegativeEigenvalue(hessian, &workspace->cholesky, tau);
  }
  return stability;
}

}  // namespace drape
