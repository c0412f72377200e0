// A drape built by hand (no solve): a circular specimen of radius R whose centre (ρ ≤ Rd) lies on
// a disc at z = 0 and whose skirt (ρ > Rd) hangs in n lobes. A flat point at polar coordinates (ρ,
// φ) of the skirt, the distance s = ρ − Rd from the disc edge is at
//   horizontal distance from the disc edge  d = s (0.45 + 0.35 cos nφ)   (0.8 s on a crest, 0.1 s
//                                                                          in a trough),
//   angle                                   φ' = φ + (s / L)(β / n) sin nφ,   L = R − Rd,
//   height                                  z = −sqrt(s² − d²)           (s is the hanging length).
// With β > 1 the angle map folds over itself near the troughs' outer edge (dφ'/dφ < 0): there
// the projected triangles overlap, as in a real fold. The crests stay on the rays φ = 2πj/n,
// where the outline reaches Rd + 0.8 L.
#ifndef DRAPE_TESTS_FOLDED_SKIRT_H_
#define DRAPE_TESTS_FOLDED_SKIRT_H_

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "src/model/model.h"

namespace drape {

struct SkirtShape {
  int lobes = 6;
  double disc_radius = 0.09;      // Rd, m
  double specimen_radius = 0.15;  // R, m
  double beta = 1.5;              // angular fold-over (overlap where β s / L > 1)
  int rings = 20, spokes = 120;   // polar mesh: rings of nodes beyond the centre, nodes per ring
};

inline double SkirtCrestRadius(const SkirtShape& shape) {
  return shape.disc_radius + 0.8 * (shape.specimen_radius - shape.disc_radius);
}

// The draped position of the flat point (fx, fy) (the centre of the specimen at the origin).
inline Eigen::Vector3d SkirtPoint(const SkirtShape& shape, double fx, double fy) {
  const double rho = std::hypot(fx, fy);
  if (rho <= shape.disc_radius) return {fx, fy, 0.0};
  const double length = shape.specimen_radius - shape.disc_radius;
  const double phi = std::atan2(fy, fx);
  const double s = rho - shape.disc_radius;
  const double d = s * (0.45 + 0.35 * std::cos(shape.lobes * phi));
  const double angle = phi + s / length * shape.beta / shape.lobes * std::sin(shape.lobes * phi);
  const double r = shape.disc_radius + d;
  return {r * std::cos(angle), r * std::sin(angle), -std::sqrt(std::max(s * s - d * d, 0.0))};
}

// A model of the given flat nodes (z = 0) and triangles, draped by SkirtPoint; nothing fixed.
inline Model SkirtModel(const SkirtShape& shape, const std::vector<Eigen::Vector3d>& flat,
                        const std::vector<std::array<int, 3>>& triangles) {
  Model model;
  for (const Eigen::Vector3d& p : flat) {
    const Eigen::Vector3d q = SkirtPoint(shape, p.x(), p.y());
    model.positions.insert(model.positions.end(), {q.x(), q.y(), q.z()});
    model.initial.insert(model.initial.end(), {p.x(), p.y(), 0.0});
  }
  model.triangles = triangles;
  model.num_nodes = static_cast<int>(flat.size());
  model.mass.assign(model.num_nodes, 1e-3);
  model.fixed.assign(3 * model.num_nodes, 0);
  model.applied.assign(3 * model.num_nodes, 0.0);
  model.grid_index.assign(model.num_nodes, {-1, -1});
  model.size = 2.0 * shape.specimen_radius;
  return model;
}

// On a polar mesh: `rings` rings of `spokes` nodes around a centre node.
inline Model FoldedSkirt(const SkirtShape& shape) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<Eigen::Vector3d> flat = {Eigen::Vector3d::Zero()};
  for (int ring = 1; ring <= shape.rings; ++ring) {
    const double rho = shape.specimen_radius * ring / shape.rings;
    for (int spoke = 0; spoke < shape.spokes; ++spoke) {
      const double phi = 2.0 * kPi * spoke / shape.spokes;
      flat.emplace_back(rho * std::cos(phi), rho * std::sin(phi), 0.0);
    }
  }
  auto id = [&shape](int ring, int spoke) {
    return ring == 0 ? 0 : 1 + (ring - 1) * shape.spokes + (spoke % shape.spokes);
  };
  std::vector<std::array<int, 3>> triangles;
  for (int spoke = 0; spoke < shape.spokes; ++spoke) {
    triangles.push_back({0, id(1, spoke), id(1, spoke + 1)});
    for (int ring = 1; ring < shape.rings; ++ring) {
      triangles.push_back({id(ring, spoke), id(ring + 1, spoke), id(ring + 1, spoke + 1)});
      triangles.push_back({id(ring, spoke), id(ring + 1, spoke + 1), id(ring, spoke + 1)});
    }
  }
  return SkirtModel(shape, flat, triangles);
}

}  // namespace drape

#endif  // DRAPE_TESTS_FOLDED_SKIRT_H_
