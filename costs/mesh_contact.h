#ifndef DRAPE_COSTS_MESH_CONTACT_H_
#define DRAPE_COSTS_MESH_CONTACT_H_

#include <cmath>
#include <memory>
#include <utility>

#include "costs/contact_penalty.h"
#include "costs/energy_form.h"
#include "costs/nested_jet.h"
#include "costs/safe_math.h"

namespace drape {

// Contact of one node with a rigid body bounded by a closed triangle surface (a mesh obstacle):
//   φ = signed distance from x to the surface (positive outside),  U = ContactPenalty(φ, t, k)
// (costs/contact_penalty.h). The surface's part nearest x is found on x's values (Surface::Nearest:
// a face, an edge or a vertex, with the side x is on; src/geometry/triangle_surface.h); on it
//   face with corner a, unit outward normal n:  φ = n · (x − a),
//   edge a–b, unit direction e:                  φ = s |(x − a) − ((x − a) · e) e|,
//   vertex a:                                    φ = s |x − a|,
// s = ±1 the side. φ is the exact signed distance, continuous with a continuous gradient (the
// unit vector from the nearest point) wherever the nearest point is unique; its curvature jumps
// where the nearest feature changes (a face's border), as a faceted body's does. The push only (its
// friction: costs/obstacle_friction.h). Units: m, N/m², J. Not invariant (the body is fixed in
// space). Source: the pseudo-normal sign test of Bærentzen & Aanæs (IEEE TVCG 11(3), 2005); the
// penalty is every obstacle's.
//
// Surface: a type with `Feature Nearest(const double* x) const` where Feature has `corners`
// (1, 2 or 3), `corner[k][c]`, `normal[c]` and `sign`.
template <typename Surface>
struct MeshContact {
  static constexpr int kNumNodes = 1;
  static constexpr int kNumOutputs = 1;
  static constexpr EnergyForm kForm = EnergyForm::kPotential;

  MeshContact(std::shared_ptr<const Surface> surface_in, double clearance_in, double stiffness_in)
      : surface(std::move(surface_in)), clearance(clearance_in), stiffness(stiffness_in) {}

  // Signed distance from the surface, positive outside, m, where it is below 2t in magnitude; 2t
  // elsewhere (the energy is zero there either way, and the query looks no farther: a point deep
  // inside the body is never reached, as the step limit keeps every point outside, and the
  // certificate measures the exact distance).
  template <typename T>
  T Distance(const T* const x) const {
    const double value[3] = {ScalarPart(x[0]), ScalarPart(x[1]), ScalarPart(x[2])};
    const auto feature = surface->Nearest(value, 2.0 * clearance);
    if (feature.corners == 0) return T() + feature.distance;
    const T u[3] = {x[0] - feature.corner[0][0], x[1] - feature.corner[0][1],
                    x[2] - feature.corner[0][2]};
    if (feature.corners == 3) {
      return u[0] * feature.normal[0] + u[1] * feature.normal[1] + u[2] * feature.normal[2];
    }
    if (feature.corners == 1) {
      return feature.sign * SafeSqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    }
    double e[3], length = 0.0;
    for (int c = 0; c < 3; ++c) {
      e[c] = feature.corner[1][c] - feature.corner[0][c];
      length += e[c] * e[c];
    }
    length = std::sqrt(length);
    for (double& component : e) component /= length;
    const T along = u[0] * e[0] + u[1] * e[1] + u[2] * e[2];
    const T w[3] = {u[0] - along * e[0], u[1] - along * e[1], u[2] - along * e[2]};
    return feature.sign * SafeSqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }

  template <typename T>
  bool operator()(const T* const x, T* energy) const {
    energy[0] = ContactPenalty(Distance(x), clearance, stiffness);
    return true;
  }

  // Whether a point within `radius` of `centre` can be inside the clearance layer: the surface
  // comes within radius + t of it (costs/edge_contact.h's one query for a whole edge).
  bool Reaches(const double* centre, double radius) const {
    return surface->Nearest(centre, radius + clearance).corners > 0;
  }

  // Whether the energy can be nonzero at x (InClearanceLayer, costs/contact_penalty.h).
  bool Touches(const double* x) const { return InClearanceLayer(*this, x); }

  const std::shared_ptr<const Surface> surface;
  const double clearance;  // t, m
  const double stiffness;  // k, N/m²
};

}  // namespace drape

#endif  // DRAPE_COSTS_MESH_CONTACT_H_
