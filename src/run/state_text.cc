#include "src/run/state_text.h"

#include <cstdio>
#include <string>

namespace drape {

namespace {

// "fabric through the support disk (…)": how many edges pass through a support disk, and how far
// inside the rim.
std::string ThroughDiskText(const ContactReport& contact) {
  const int edges = contact.edges_through_disk;
  std::string text = "fabric through the support disk (" + std::to_string(edges) +
                     (edges == 1 ? " edge" : " edges") + " through it";
  char inside[64];
  std::snprintf(inside, sizeof inside, ", up to %.2g mm inside its rim)",
                1e3 * contact.under_disk_inside);
  return text + inside;
}

}  // namespace

std::string StateText(const RunResult& result) {
  if (!result.certificate.unsound.empty()) return "not certified: " + result.certificate.unsound;
  if (result.contact.ThroughDisk()) {
    return ThroughDiskText(result.contact) + (result.converged ? "" : ", not an equilibrium");
  }
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
