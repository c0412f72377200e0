#ifndef DRAPE_COSTS_EDGE_CONTACT_H_
#define DRAPE_COSTS_EDGE_CONTACT_H_

#include <cmath>
#include <type_traits>
#include <utility>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/nested_jet.h"

namespace drape {

// Whether a contact offers Reaches(centre, radius): whether any point within `radius` of `centre`
// can be inside its clearance layer, answered by one query (a mesh obstacle's, whose distance
// queries are costly: one for the whole edge instead of one per point).
template <typename Contact, typename = void>
struct HasReaches : std::false_type {};
template <typename Contact>
struct HasReaches<Contact, std::void_t<decltype(std::declval<const Contact&>().Reaches(
                               static_cast<const double*>(nullptr), 0.0))>> : std::true_type {};

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

  // Whether some point of the edge a–b (values) may be inside the clearance layer: true unless the
  // contact offers Reaches (HasReaches) and the ball around the edge's middle that holds the edge
  // cannot reach the layer.
  bool MayTouch(const double* a, const double* b) const {
    if constexpr (HasReaches<Contact>::value) {
      double middle[3], half_squared = 0.0;
      for (int c = 0; c < 3; ++c) {
        middle[c] = 0.5 * (a[c] + b[c]);
        half_squared += 0.25 * (b[c] - a[c]) * (b[c] - a[c]);
      }
      return contact.Reaches(middle, std::sqrt(half_squared));
    }
    return true;
  }

  // Whether the energy can be nonzero: some point inside the clearance layer (the test the
  // operator makes point by point).
  bool Touches(const double* a, const double* b) const {
    if (!MayTouch(a, b)) return false;
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
    if (!MayTouch(a_value, b_value)) return true;
    for (int j = 1; j <= points; ++j) {
      double value[3];
      PointAt(a_value, b_value, j, value);
      const double distance = contact.Distance(value);
      if (!(distance < contact.clearance)) continue;  // no energy, no derivative
      if constexpr (std::is_same_v<T, double>) {      // the value's distance is the point's
        energy[0] += ContactPenalty(distance, contact.clearance, contact.stiffness);
        continue;
      }
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
