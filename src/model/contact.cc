#include "src/model/contact.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include "costs/obstacle_friction.h"
#include "src/model/obstacle_kinds.h"
#include "src/model/self_intersection.h"

namespace drape {

namespace {

void CheckContactInput(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact) {
  for (const ObstacleSpec& obstacle : obstacles) {
    CheckedObstacleKind(obstacle);
  }
  if (!obstacles.empty() && !(contact.thickness > 0.0)) {
    const Location& where = contact.where.line > 0 ? contact.where : obstacles.front().where;
    throw InputError(where, "contact.thickness must be positive when there are obstacles");
  }
}

// Every edge of the fabric once (the triangles' sides and the line elements), as (lower, higher)
// node ids.
std::set<std::pair<int, int>> FabricEdges(const Model& model) {
  std::set<std::pair<int, int>> edges;
  auto add = [&edges](int a, int b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  for (const auto& triangle : model.triangles) {
    for (int side = 0; side < 3; ++side) add(triangle[side], triangle[(side + 1) % 3]);
  }
  for (const auto& edge : model.edges) add(edge[0], edge[1]);
  return edges;
}

}  // namespace

bool HasObstacleFriction(const std::vector<ObstacleSpec>& obstacles) {
  return std::any_of(obstacles.begin(), obstacles.end(),
                     [](const ObstacleSpec& obstacle) { return obstacle.friction > 0.0; });
}

double ContactReferenceForce(const Model& model) {
  double reference = 0.0;
  for (int k = 0; k < model.num_nodes; ++k) {
    reference += model.applied_force(k).norm();
  }
  return reference > 0.0 ? reference : 1.0;
}

double ContactStiffness(const ContactSpec& contact, const Model& model) {
  const double allowed = kAllowedPenetration * contact.thickness;
  return ContactReferenceForce(model) / (allowed * allowed);
}

std::vector<Model::Push> FrictionObstaclePushes(const Model& model, const double* positions) {
  std::vector<std::vector<double>> forces(model.obstacles.size());
  double gradient[3 * 32];
  for (const Model::ContactTerm& contact : model.contact_terms) {
    if (contact.friction || !(model.obstacles[contact.obstacle].friction > 0.0)) continue;
    const Term& term = *model.terms[contact.term];
    double energy = 0.0;
    if (!term.Touches(positions) || !term.EnergyGradient(positions, &energy, gradient)) continue;
    std::vector<double>& force = forces[contact.obstacle];
    if (force.empty()) force.assign(model.num_dofs(), 0.0);
    const std::vector<int>& nodes = term.nodes();
    for (size_t a = 0; a < nodes.size(); ++a) {
      for (int c = 0; c < 3; ++c) force[3 * nodes[a] + c] -= gradient[3 * a + c];
    }
  }
  std::vector<Model::Push> pushes;
  for (size_t obstacle = 0; obstacle < forces.size(); ++obstacle) {
    if (forces[obstacle].empty()) continue;
    for (int node = 0; node < model.num_nodes; ++node) {
      const Eigen::Vector3d force = NodeAt(forces[obstacle], node);
      if (force.squaredNorm() > 0.0 && force.allFinite()) {
        pushes.push_back({static_cast<int>(obstacle), node, force});
      }
    }
  }
  return pushes;
}

namespace {

// The outward normal of `obstacle`'s surface nearest x: the signed distance's gradient, by central
// differences at a thousandth of the clearance.
Eigen::Vector3d OutwardNormal(const ObstacleSpec& obstacle, double clearance, const double* x) {
  const double step = 1e-3 * clearance;
  Eigen::Vector3d gradient;
  for (int c = 0; c < 3; ++c) {
    double plus[3] = {x[0], x[1], x[2]}, minus[3] = {x[0], x[1], x[2]};
    plus[c] += step;
    minus[c] -= step;
    gradient[c] =
        (ObstacleDistance(obstacle, plus) - ObstacleDistance(obstacle, minus)) / (2 * step);
  }
  return gradient.normalized();
}

// FrictionObstaclePushes at `positions`, and for a node on a frictional obstacle's layer edge that
// it does not push on, the push of the node's own load against the surface
// (AddObstacleFrictionTerms).
std::vector<Model::Push> PushesWithLoads(const Model& model, const double* positions) {
  std::vector<Model::Push> pushes = FrictionObstaclePushes(model, positions);
  std::set<std::pair<int, int>> pushed;
  for (const Model::Push& push : pushes) pushed.insert({push.obstacle, push.node});
  const double clearance = model.contact.thickness;
  for (size_t index = 0; index < model.obstacles.size(); ++index) {
    const ObstacleSpec& obstacle = model.obstacles[index];
    if (!(obstacle.friction > 0.0)) continue;
    const int o = static_cast<int>(index);
    for (int node = 0; node < model.num_nodes; ++node) {
      if (pushed.count({o, node}) || model.fully_fixed(node)) continue;
      const double* x = positions + 3 * node;
      if (ObstacleDistance(obstacle, x) > (1.0 + kAllowedPenetration) * clearance) continue;
      const Eigen::Vector3d normal = OutwardNormal(obstacle, clearance, x);
      const double against = -model.applied_force(node).dot(normal);
      if (against > 0.0 && normal.allFinite()) pushes.push_back({o, node, against * normal});
    }
  }
  std::sort(pushes.begin(), pushes.end(), [](const Model::Push& a, const Model::Push& b) {
    return std::make_pair(a.obstacle, a.node) < std::make_pair(b.obstacle, b.node);
  });
  return pushes;
}

}  // namespace

void AddObstacleFrictionTerms(const std::vector<double>& start,
                              const std::vector<double>* pushed_at, Model* model) {
  if (!HasObstacleFriction(model->obstacles)) return;
  assert(start.size() == model->positions.size());
  assert(!pushed_at || pushed_at->size() == start.size());
  const double smoothing = kFrictionSlipFraction * model->contact.thickness;
  model->friction_pushes = pushed_at ? FrictionObstaclePushes(*model, pushed_at->data())
                                     : PushesWithLoads(*model, start.data());
  for (const Model::Push& push : model->friction_pushes) {
    if (model->fully_fixed(push.node)) continue;
    const ObstacleSpec& obstacle = model->obstacles[push.obstacle];
    const double normal_force = push.force.norm();
    const Eigen::Vector3d normal = push.force / normal_force;
    // Least-squares shift (src/model/term.h): the friction's work over a slip of the fabric's size.
    const double shift = obstacle.friction * normal_force * model->size;
    model->contact_terms.push_back(
        {static_cast<int>(model->terms.size()), push.obstacle, 0, /*friction=*/true});
    model->terms.push_back(
        MakeTerm(obstacle.kind + "_friction", {push.node},
                 ObstacleFriction::Create(obstacle.friction, normal_force, normal.data(),
                                          &start[3 * push.node], smoothing),
                 shift));
  }
}

double FrictionPushChange(const Model& model, const double* positions) {
  if (!HasObstacleFriction(model.obstacles)) return 0.0;
  std::map<std::pair<int, int>, Eigen::Vector3d> difference;
  for (const Model::Push& push : FrictionObstaclePushes(model, positions)) {
    difference[{push.obstacle, push.node}] = push.force;
  }
  for (const Model::Push& push : model.friction_pushes) {
    auto [it, added] = difference.try_emplace({push.obstacle, push.node}, Eigen::Vector3d::Zero());
    it->second -= push.force;
  }
  double change = 0.0;
  for (const auto& [key, force] : difference) change += force.norm();
  return change / ContactReferenceForce(model);
}

double ObstacleDistance(const ObstacleSpec& obstacle, const double* x) {
  return ObstacleKindOf(obstacle).distance(obstacle, x);
}

void AddContactTerms(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                     Model* model) {
  CheckContactInput(obstacles, contact);
  if (obstacles.empty()) return;
  model->obstacles = obstacles;
  model->contact = contact;
  const double stiffness = ContactStiffness(contact, *model);
  bool anchored = false;
  for (int k = 0; k < model->num_nodes; ++k) anchored = anchored || model->fully_fixed(k);
  const double reach = kReachFactor * model->size;
  // Least-squares shift of the potential (src/model/term.h): the energy at a full clearance's
  // depth.
  const double shift = stiffness * std::pow(contact.thickness, 3) / 3.0;
  const std::set<std::pair<int, int>> edges = FabricEdges(*model);
  for (size_t index = 0; index < obstacles.size(); ++index) {
    const ObstacleSpec& obstacle = obstacles[index];
    const ObstacleKind& kind = ObstacleKindOf(obstacle);
    auto within_reach = [&](int node) {
      return !anchored ||
             ObstacleDistance(obstacle, model->position(node).data()) - contact.thickness <= reach;
    };
    for (int k = 0; k < model->num_nodes; ++k) {
      if (model->fully_fixed(k) || !within_reach(k)) continue;
      model->contact_terms.push_back(
          {static_cast<int>(model->terms.size()), static_cast<int>(index), 0});
      model->terms.push_back(kind.make_term(obstacle, k, contact.thickness, stiffness, shift));
    }
    if (!kind.make_edge_term) continue;
    for (const auto& [a, b] : edges) {
      if (model->fully_fixed(a) && model->fully_fixed(b)) continue;
      if (!within_reach(a) && !within_reach(b)) continue;
      const int points = EdgeContactPoints(model->position(a), model->position(b), contact);
      if (points == 0) continue;
      model->contact_terms.push_back(
          {static_cast<int>(model->terms.size()), static_cast<int>(index), points});
      model->terms.push_back(
          kind.make_edge_term(obstacle, a, b, points, contact.thickness, stiffness, shift));
    }
  }
}

int EdgeContactPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const ContactSpec& contact) {
  // A length within a millionth of t of a multiple of t counts as that multiple, so that lattice
  // edges of such lengths (1 cm with t = 1 mm) get the same count after a change of units.
  const double spacing = (b - a).norm() / contact.thickness - 1e-6;
  if (!(spacing > 1.0)) return 0;
  return static_cast<int>(std::ceil(spacing)) - 1;
}

bool NodeInContact(const std::vector<double>& contact_forces, int node) {
  if (contact_forces.empty()) return false;
  assert(3 * node + 2 < static_cast<int>(contact_forces.size()));
  for (int c = 0; c < 3; ++c) {
    const double force = contact_forces[3 * node + c];
    if (std::isfinite(force) && force != 0.0) return true;
  }
  return false;
}

ContactReport MeasureContact(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                             const Model& model, const double* positions,
                             const std::vector<double>& contact_forces) {
  ContactReport report;
  report.thickness = contact.thickness;
  if (obstacles.empty()) return report;
  report.stiffness = ContactStiffness(contact, model);
  for (const auto& term : model.terms) {
    const std::string& type = term->type();
    const std::string suffix = "_contact";
    if (type.size() > suffix.size() &&
        type.compare(type.size() - suffix.size(), suffix.size(), suffix) == 0) {
      ++report.terms;
    }
  }
  for (int k = 0; k < model.num_nodes; ++k) {
    double deepest = 0.0;
    for (const ObstacleSpec& obstacle : obstacles) {
      deepest = std::max(
          deepest, contact.thickness - ObstacleDistance(obstacle, NodeAt(positions, k).data()));
    }
    if (NodeInContact(contact_forces, k)) ++report.nodes_in_contact;
    report.max_penetration = std::max(report.max_penetration, deepest);
  }
  if (contact.thickness > 0.0) {
    report.max_penetration_fraction = report.max_penetration / contact.thickness;
  }
  const UnderDisks under = NodesUnderDisks(obstacles, contact.thickness, model, positions);
  report.nodes_under_disk = under.nodes;
  report.edges_through_disk = under.edges;
  report.under_disk_inside = under.inside;
  report.edges_through_body = EdgesThroughBodies(obstacles, model, positions);
  return report;
}

namespace {

// ρ: a point's distance from a disk's axis.
double DistanceFromAxis(const ObstacleSpec& disc, const double* x) {
  return std::hypot(x[0] - disc.center.x(), x[1] - disc.center.y());
}

// Adds the fabric's edges that cross a disk's plane inside its rim to `under`.
void CountEdgesThroughDisks(const std::vector<ObstacleSpec>& obstacles, const Model& model,
                            const double* positions, UnderDisks* under) {
  bool any_disk = false;
  for (const ObstacleSpec& obstacle : obstacles) any_disk = any_disk || obstacle.kind == "disk";
  if (!any_disk) return;
  for (const auto& [a, b] : FabricEdges(model)) {
    const double* x_a = positions + 3 * a;
    const double* x_b = positions + 3 * b;
    for (const ObstacleSpec& disc : obstacles) {
      if (disc.kind != "disk") continue;
      const double h_a = x_a[2] - disc.center.z(), h_b = x_b[2] - disc.center.z();
      if (!((h_a > 0.0 && h_b < 0.0) || (h_a < 0.0 && h_b > 0.0))) continue;
      const double s = h_a / (h_a - h_b);
      const double crossing[3] = {x_a[0] + s * (x_b[0] - x_a[0]), x_a[1] + s * (x_b[1] - x_a[1]),
                                  disc.center.z()};
      const double inside = disc.radius - DistanceFromAxis(disc, crossing);
      if (!(inside > 0.0)) continue;
      ++under->edges;
      under->inside = std::max(under->inside, inside);
      break;
    }
  }
}

}  // namespace

int EdgesThroughBodies(const std::vector<ObstacleSpec>& obstacles, const Model& model,
                       const double* positions) {
  int crossing = 0;
  for (const ObstacleSpec& body : obstacles) {
    if (body.surface == nullptr) continue;
    const TriangleSurface& surface = *body.surface;
    for (const auto& [a, b] : FabricEdges(model)) {
      const Eigen::Vector3d p = NodeAt(positions, a), q = NodeAt(positions, b);
      Box box;
      box.Add(p);
      box.Add(q);
      for (int f : surface.FacesNear(box, 0.0)) {
        const auto& corner = surface.faces()[f];
        const auto& v = surface.vertices();
        if (SegmentCrossesTriangle(p, q, v[corner[0]], v[corner[1]], v[corner[2]])) {
          ++crossing;
          break;
        }
      }
    }
  }
  return crossing;
}

DiscPlace PlaceOnDisc(const ObstacleSpec& disc, double clearance, const double* x) {
  const double h = x[2] - disc.center.z();
  const double rho = DistanceFromAxis(disc, x);
  if (rho > disc.radius || h >= clearance) return DiscPlace::kClear;
  if (h > -clearance) return DiscPlace::kInLayer;
  return rho <= disc.radius - clearance ? DiscPlace::kUnder : DiscPlace::kBesideRimBelow;
}

UnderDisks NodesUnderDisks(const std::vector<ObstacleSpec>& obstacles, double clearance,
                           const Model& model, const double* positions) {
  UnderDisks under;
  for (int k = 0; k < model.num_nodes; ++k) {
    const double* x = positions + 3 * k;
    bool counted = false;
    for (const ObstacleSpec& disc : obstacles) {
      if (disc.kind != "disk" || !(model.initial[3 * k + 2] > disc.center.z())) continue;
      const DiscPlace place = PlaceOnDisc(disc, clearance, x);
      const bool below_mid_plane = x[2] < disc.center.z();
      if (place != DiscPlace::kUnder && !(place == DiscPlace::kInLayer && below_mid_plane))
        continue;
      if (!counted) ++under.nodes;
      counted = true;
    }
  }
  CountEdgesThroughDisks(obstacles, model, positions, &under);
  return under;
}

namespace {

// Signed distance to `obstacle` at x where its magnitude is below `within`, else `within`.
double DistanceWithin(const ObstacleSpec& obstacle, const double* x, double within) {
  const ObstacleKind& kind = ObstacleKindOf(obstacle);
  if (kind.bounded_distance) return kind.bounded_distance(obstacle, x, within);
  return std::min(kind.distance(obstacle, x), within);
}

// Signed distance to `obstacle` at from + s (to − from).
double DistanceAlong(const ObstacleSpec& obstacle, const double* from, const double* to, double s) {
  const double x[3] = {from[0] + s * (to[0] - from[0]), from[1] + s * (to[1] - from[1]),
                       from[2] + s * (to[2] - from[2])};
  return ObstacleDistance(obstacle, x);
}

// For a body that is not convex (a mesh obstacle's surface): conservative advancement. The distance
// is 1-Lipschitz, so from s the point cannot come within `floor` before s + (d(s) − floor) /
// length; each step goes that far, and stops where the point comes within 1 % of the floor's
// margin of it (or after kMaxAdvances steps, where it stays: a grazing move is cut short, never
// let through). d(s) is bounded below by the distance to the faces near the move (within 2 floor
// of its box): exact where it is below 2 floor, which is all the advancement needs, and cheap.
double AdvanceToFloor(const TriangleSurface& surface, const double* from, const double* to,
                      double start, double floor, double length) {
  constexpr int kMaxAdvances = 100;
  Box swept;
  swept.Add(Eigen::Vector3d(from[0], from[1], from[2]));
  swept.Add(Eigen::Vector3d(to[0], to[1], to[2]));
  const double reach = 2.0 * floor;
  const std::vector<int> faces = surface.FacesNear(swept, reach);
  if (faces.empty()) return 1.0;
  double s = 0.0, distance = start;
  for (int k = 0; k < kMaxAdvances; ++k) {
    const double margin = distance - floor;
    if (margin <= 0.01 * floor) return s;
    s += margin / length;
    if (s >= 1.0) return 1.0;
    const double x[3] = {from[0] + s * (to[0] - from[0]), from[1] + s * (to[1] - from[1]),
                         from[2] + s * (to[2] - from[2])};
    distance = std::min(surface.DistanceToFaces(faces, x), reach);
  }
  return s;
}

// The step-limit rule for one node and obstacle (see NodeSafeFraction).
double SafeFractionFor(const ObstacleSpec& obstacle, double thickness, const double* from,
                       const double* to) {
  const double length =
      std::sqrt((to[0] - from[0]) * (to[0] - from[0]) + (to[1] - from[1]) * (to[1] - from[1]) +
                (to[2] - from[2]) * (to[2] - from[2]));
  // Farther than the move and the clearance: the move cannot come within the floor.
  const double within = length + 2.0 * thickness;
  const double start = DistanceWithin(obstacle, from, within);
  if (start >= within) return 1.0;
  if (!(start > 0.0)) return 1.0;  // already inside (or on) the body: nothing to guard
  const double floor = 0.5 * std::min(start, thickness);
  if (start - length >= floor) return 1.0;  // the distance is 1-Lipschitz: cannot get there
  if (!std::isfinite(length)) return 0.0;
  if (!ObstacleKindOf(obstacle).convex) {
    assert(obstacle.surface != nullptr && "a body that is not convex is a mesh obstacle's");
    return AdvanceToFloor(*obstacle.surface, from, to, start, floor, length);
  }
  // d(s) is convex along the segment (the body is): golden-section search
  // for its minimum, then bisection for where it first falls to the floor.
  constexpr double kGolden = 0.6180339887498949;
  double low = 0.0, high = 1.0;
  for (int k = 0; k < 60 && high - low > 1e-12; ++k) {
    const double a = high - kGolden * (high - low), b = low + kGolden * (high - low);
    if (DistanceAlong(obstacle, from, to, a) <= DistanceAlong(obstacle, from, to, b)) {
      high = b;
    } else {
      low = a;
    }
  }
  const double lowest = 0.5 * (low + high);
  if (DistanceAlong(obstacle, from, to, lowest) >= floor) return 1.0;
  // d falls from start ≥ 2 floor at s = 0 to below the floor at `lowest`, monotonically.
  double safe = 0.0, unsafe = lowest;
  for (int k = 0; k < 60 && unsafe - safe > 1e-12; ++k) {
    const double middle = 0.5 * (safe + unsafe);
    (DistanceAlong(obstacle, from, to, middle) >= floor ? safe : unsafe) = middle;
  }
  return safe;
}

// Whether every point of the edge a–b moving to a'–b' stays farther than the clearance from the
// obstacle: each point starts within half the edge's length of its middle and moves no farther
// than the farther-moving end, so all stay in the ball around the middle of that radius.
bool EdgeStaysClear(const ObstacleSpec& obstacle, double thickness, const double* a,
                    const double* b, const double* a_to, const double* b_to) {
  double middle[3], half = 0.0, move_a = 0.0, move_b = 0.0;
  for (int c = 0; c < 3; ++c) {
    middle[c] = 0.5 * (a[c] + b[c]);
    half += 0.25 * (b[c] - a[c]) * (b[c] - a[c]);
    move_a += (a_to[c] - a[c]) * (a_to[c] - a[c]);
    move_b += (b_to[c] - b[c]) * (b_to[c] - b[c]);
  }
  const double within = std::sqrt(half) + std::sqrt(std::max(move_a, move_b)) + 2.0 * thickness;
  return std::isfinite(within) && DistanceWithin(obstacle, middle, within) >= within;
}

}  // namespace

double NodeSafeFraction(const Model& model, const double* from, const double* to) {
  double fraction = 1.0;
  for (const ObstacleSpec& obstacle : model.obstacles) {
    fraction = std::min(fraction, SafeFractionFor(obstacle, model.contact.thickness, from, to));
  }
  return fraction;
}

double ObstacleSafeFraction(const Model& model, const double* from, const double* to) {
  if (model.obstacles.empty()) return 1.0;
  double fraction = 1.0;
  for (int node = 0; node < model.num_nodes; ++node) {
    fraction = std::min(fraction, NodeSafeFraction(model, from + 3 * node, to + 3 * node));
  }
  for (const Model::ContactTerm& term : model.contact_terms) {
    if (term.edge_points == 0) continue;
    const std::vector<int>& ends = model.terms[term.term]->nodes();
    const ObstacleSpec& obstacle = model.obstacles[term.obstacle];
    if (EdgeStaysClear(obstacle, model.contact.thickness, from + 3 * ends[0], from + 3 * ends[1],
                       to + 3 * ends[0], to + 3 * ends[1])) {
      continue;
    }
    for (int j = 1; j <= term.edge_points; ++j) {
      const double s = static_cast<double>(j) / (term.edge_points + 1);
      double point_from[3], point_to[3];
      for (int c = 0; c < 3; ++c) {
        point_from[c] = from[3 * ends[0] + c] + s * (from[3 * ends[1] + c] - from[3 * ends[0] + c]);
        point_to[c] = to[3 * ends[0] + c] + s * (to[3 * ends[1] + c] - to[3 * ends[0] + c]);
      }
      fraction = std::min(fraction,
                          SafeFractionFor(obstacle, model.contact.thickness, point_from, point_to));
    }
  }
  return fraction;
}

}  // namespace drape
