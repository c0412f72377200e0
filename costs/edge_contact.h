#ifndef DRAPE_COSTS_EDGE_CONTACT_H_
#define DRAPE_COSTS_EDGE_CONTACT_H_

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/nested_jet.h"

namespace drape {

// Contact of the inside of one fabric edge a–b with an obstacle: the obstacle's node contact
// (Contact, costs/*_contact.h: its signed Distance φ, clearance t and stiffness k) at m points
// evenly inside the edge,
//   U = Σ_{j=1..m} ContactPenalty(φ(x_j), t, k),   x_j = a + s_j (b − a),   s_j = j / (m + 1),
// the nodes themselves having their own node terms. Why: a node term keeps the nodes out of an
// obstacle, but the straight edge between a node on a disc's top and one hanging beside its rim
// cuts the rim's corner, and the fabric slides through the disc edge first. With points at most t
// apart along the edge (AddContactTerms picks m from the edge's length), every point of the edge
// lies within t/2 of one that is kept at least (1 − g/t) t outside, so no point of the edge enters
// the obstacle while the penetration g stays below t/2 (the stiffness rule aims at 0.1 t).
// Each point weighs as much as a node: a point pressed with force F rests √(F/k) deep, as a node
// does. The energy is C² where the Contact's distance is (ContactPenalty), and 0 with zero
// derivatives unless some point is inside the clearance layer: that is decided on the values
// alone, so that Jets are spent only on points in contact. Invariance: none (the obstacle is
// fixed in space). Units: m, N/m², J. Source: the surface-contact idea of continuous contact
// formulations (e.g. Li et al., Incremental Potential Contact, SIGGRAPH 2020, which puts the
// barrier on edge–edge distances); here the edge is sampled instead.
template <typename Contact>
struct EdgeContact {
  static constexpr int kNumNodes = 2;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  EdgeContact(const Contact& contact_in, int points_in) : contact(contact_in), points(points_in) {}

  // s_j of point j = 1..points.
  double Fraction(int j) const { return static_cast<double>(j) / (points + 1); }

  // Point j's position x_j on the edge a–b (values).
  void PointAt(const double* a, const double* b, int j, double* point) const {
    const double s = Fraction(j);
    for (int c = 0; c < 3; ++c) point[c] = a[c] + s * (b[c] - a[c]);
  }

  // Whether the energy can be nonzero: some point inside the clearance layer (the test the
  // operator makes point by point).
  bool Touches(const double* a, const double* b) const {
    for (int j = 1; j <= points; ++j) {
      double point[3];
      PointAt(a, b, j, point);
      if (InClearanceLayer(contact, point)) return true;
    }
    return false;
  }

  template <typename T>
  bool operator()(const T* const a, const T* const b, T* energy) const {
    energy[0] = T();
    const double a_value[3] = {ScalarPart(a[0]), ScalarPart(a[1]), ScalarPart(a[2])};
    const double b_value[3] = {ScalarPart(b[0]), ScalarPart(b[1]), ScalarPart(b[2])};
    for (int j = 1; j <= points; ++j) {
      double value[3];
      PointAt(a_value, b_value, j, value);
      if (!InClearanceLayer(contact, value)) continue;  // no energy, no derivative
      const double s = Fraction(j);
      const T point[3] = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]),
                          a[2] + s * (b[2] - a[2])};
      energy[0] += ContactPenalty(contact.Distance(point), contact.clearance, contact.stiffness);
    }
    return true;
  }

  const Contact contact;
  const int points;  // m ≥ 1
};

}  // namespace drape

#endif  // DRAPE_COSTS_EDGE_CONTACT_H_
