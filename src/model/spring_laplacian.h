// Puiseux's constant matrix A⁰ (seed 000, §2.2): the Laplacian of the spring network weighted by
// the stiffnesses, A⁰_ii = Σ_j k_ij, A⁰_ij = −k_ij, the same for each coordinate. Its free block,
// plus an optional diagonal (M/dt² + β/(2dt) for the dynamic scheme), is factorised once per
// coordinate with CHOLMOD and reused for every iteration.
#ifndef DRAPE_SRC_MODEL_SPRING_LAPLACIAN_H_
#define DRAPE_SRC_MODEL_SPRING_LAPLACIAN_H_

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "src/model/model.h"

namespace drape {

// k of a spring term (SpringStretch, TensionOnlySpring, ZeroLengthSpring), 0 for any other term.
double SpringStiffness(const Term& term);

// Empty when every term is a spring or a constant force (the model Puiseux's solvers handle);
// otherwise the name of a term type they cannot handle.
std::string UnsupportedTermType(const Model& model);

class SpringLaplacianSolver {
 public:
  // Factorises, for each coordinate c, the block of A⁰ + diag(mass_scale·m_i + shift) over the
  // nodes whose coordinate c is free. False (with `error`) if a block is not positive definite,
  // e.g. a free node that no spring reaches.
  bool Factorize(const Model& model, double mass_scale, double shift, std::string* error);

  // Solves the blocks for the right-hand sides `rhs` (3 per node; entries at fixed coordinates
  // are ignored) and writes the solution at free coordinates into `solution` (3 per node).
  void Solve(const std::vector<double>& rhs, std::vector<double>* solution) const;

 private:
  using Factorization = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>;
  std::array<std::vector<int>, 3> free_nodes_;
  std::array<std::unique_ptr<Factorization>, 3> factorizations_;
};

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_SPRING_LAPLACIAN_H_
