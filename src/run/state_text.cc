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

// "fabric through itself (3 crossings of a triangle's side and a triangle; the first: side 12–13
// through triangle 40 41 52)".
std::string ThroughItselfText(const SelfIntersections& found) {
  const int n = found.crossings;
  return "fabric through itself (" + std::to_string(n) + (n == 1 ? " crossing" : " crossings") +
         " of a triangle's side and a triangle; " + (n == 1 ? "" : "the first: ") + "side " +
         std::to_string(found.side[0]) + "–" + std::to_string(found.side[1]) +
         " through triangle " + std::to_string(found.triangle[0]) + " " +
         std::to_string(found.triangle[1]) + " " + std::to_string(found.triangle[2]) + ")";
}

// "fabric through a mesh obstacle (3 edges cross its surface)".
std::string ThroughBodyText(const ContactReport& contact) {
  const int edges = contact.edges_through_body;
  return "fabric through a mesh obstacle (" + std::to_string(edges) +
         (edges == 1 ? " edge crosses" : " edges cross") + " its surface)";
}

// What makes the state no drape: through a disk, a mesh obstacle, itself, or several.
std::string PassesThroughText(const RunResult& result) {
  std::string text;
  if (result.contact.ThroughDisk()) text = ThroughDiskText(result.contact);
  if (result.contact.ThroughBody()) {
    text += (text.empty() ? "" : "; ") + ThroughBodyText(result.contact);
  }
  if (result.self_intersections.Any()) {
    text += (text.empty() ? "" : "; ") + ThroughItselfText(result.self_intersections);
  }
  return text;
}

}  // namespace

std::string StateText(const RunResult& result) {
  if (!result.certificate.unsound.empty()) return "not certified: " + result.certificate.unsound;
  if (result.PassesThrough()) {
    return PassesThroughText(result) + (result.converged ? "" : ", not an equilibrium");
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
