#include "src/model/spring_laplacian.h"

#include "costs/constant_force_potential.h"
#include "costs/pressure_potential.h"
#include "costs/spring_stretch.h"
#include "costs/tension_only_spring.h"
#include "costs/zero_length_spring.h"

namespace drape {

double SpringStiffness(const Term& term) {
  double root = 0.0;
  if (const auto* spring = FunctorOf<SpringStretch>(term)) root = spring->sqrt_stiffness;
  if (const auto* spring = FunctorOf<TensionOnlySpring>(term)) root = spring->sqrt_stiffness;
  if (const auto* spring = FunctorOf<ZeroLengthSpring>(term)) root = spring->sqrt_stiffness;
  return root * root;
}

std::string UnsupportedTermType(const Model& model) {
  for (const auto& term : model.terms) {
    if (SpringStiffness(*term) > 0.0 || FunctorOf<ConstantForcePotential>(*term)) continue;
    if (FunctorOf<PressurePotential>(*term)) continue;  // a load: in the residual, not in A0
    return term->type();
  }
  return "";
}

bool SpringLaplacianSolver::Factorize(const Model& model, double mass_scale, double shift,
                                      std::string* error) {
  for (int c = 0; c < 3; ++c) {
    std::vector<int> block_index(model.num_nodes, -1);
    free_nodes_[c].clear();
    for (int node = 0; node < model.num_nodes; ++node) {
      if (model.fixed[3 * node + c]) continue;
      block_index[node] = static_cast<int>(free_nodes_[c].size());
      free_nodes_[c].push_back(node);
    }
    const int size = static_cast<int>(free_nodes_[c].size());
    factorizations_[c].reset();
    if (size == 0) continue;
    std::vector<Eigen::Triplet<double>> entries;
    for (int b = 0; b < size; ++b) {
      entries.emplace_back(b, b, mass_scale * model.mass[free_nodes_[c][b]] + shift);
    }
    for (const auto& term : model.terms) {
      const double k = SpringStiffness(*term);
      if (k == 0.0) continue;
      const int a = block_index[term->nodes()[0]], b = block_index[term->nodes()[1]];
      if (a >= 0) entries.emplace_back(a, a, k);
      if (b >= 0) entries.emplace_back(b, b, k);
      if (a >= 0 && b >= 0) {
        entries.emplace_back(a, b, -k);
        entries.emplace_back(b, a, -k);
      }
    }
    Eigen::SparseMatrix<double> block(size, size);
    block.setFromTriplets(entries.begin(), entries.end());
    factorizations_[c] = std::make_unique<Factorization>(block);
    if (factorizations_[c]->info() != Eigen::Success) {
      *error = std::string("the stiffness matrix A0 over the free ") + "xyz"[c] +
               " coordinates is singular (a free node that no spring holds?)";
      return false;
    }
  }
  return true;
}

void SpringLaplacianSolver::Solve(const std::vector<double>& rhs,
                                  std::vector<double>* solution) const {
  for (int c = 0; c < 3; ++c) {
    if (!factorizations_[c]) continue;
    const auto& nodes = free_nodes_[c];
    Eigen::VectorXd b(nodes.size());
    for (size_t k = 0; k < nodes.size(); ++k) b[k] = rhs[3 * nodes[k] + c];
    const Eigen::VectorXd x = factorizations_[c]->solve(b);
    for (size_t k = 0; k < nodes.size(); ++k) (*solution)[3 * nodes[k] + c] = x[k];
  }
}

}  // namespace drape
