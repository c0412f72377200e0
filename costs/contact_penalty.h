// The one-sided penalty shared by every obstacle's contact functor (costs/*_contact.h).
#ifndef DRAPE_COSTS_CONTACT_PENALTY_H_
#define DRAPE_COSTS_CONTACT_PENALTY_H_

#include "costs/nested_jet.h"

namespace drape {

// Energy of a node at distance φ from an obstacle's surface that must keep a clearance t (the
// fabric's half-thickness, `contact.thickness`):
//   U = (k/3) g³ for g = t − φ > 0 (the node is inside the clearance layer), 0 otherwise.
// The pushing force is k g² along the surface normal and the stiffness 2 k g: the energy is C²
// (its Hessian is continuous, zero at first touch), so Newton keeps quadratic convergence as
// nodes come into contact. Units: k in N/m², lengths in m, U in J. At equilibrium a node pressed
// with force F sits g = √(F/k) inside the layer (src/model/contact.h states the stiffness rule).
template <typename T>
T ContactPenalty(const T& distance, double clearance, double stiffness) {
  const T gap = clearance - distance;
  if (!(gap > 0.0)) return T();
  return (stiffness / 3.0) * gap * gap * gap;
}

// Whether a node contact (a functor with a signed Distance φ and a clearance t) has energy at `x`:
// φ < t, ContactPenalty's gap > 0 read on values. Where it is false the contact's energy, gradient
// and Hessian are exactly zero, which is what lets the assembly skip it (a contact's Touches, the
// active set of src/numerics/sparse_hessian.h) and the edge contact skip a point's Jets.
template <typename Contact>
bool InClearanceLayer(const Contact& contact, const double* x) {
  return contact.Distance(x) < contact.clearance;
}

}  // namespace drape

#endif  // DRAPE_COSTS_CONTACT_PENALTY_H_
