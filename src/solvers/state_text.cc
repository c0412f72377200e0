#include "src/solvers/state_text.h"

#include <cstdio>

namespace drape {

std::string StateText(const RunResult& result) {
  if (!result.certificate.unsound.empty()) return "not certified: " + result.certificate.unsound;
  const Stability& stability = result.stability;
  if (!stability.computed) return "stability not computed";
  char eigenvalue[80];
  std::snprintf(eigenvalue, sizeof eigenvalue, "most negative eigenvalue %.3g N/m",
                stability.min_eigenvalue);
  if (!result.converged) {
    return stability.stable ? "not an equilibrium (Hessian positive definite there)"
                            : std::string("not an equilibrium (") + eigenvalue + ")";
  }
  return stability.stable ? "stable minimum" : std::string("saddle: ") + eigenvalue;
}

}  // namespace drape
