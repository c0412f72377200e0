#include "src/model/self_contact.h"

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>
#include <vector>

#include "costs/edge_edge_contact.h"
#include "costs/point_triangle_contact.h"
#include "src/geometry/box_tree.h"
#include "src/geometry/nearest_feature.h"
#include "src/model/contact.h"
#include "src/model/self_intersection.h"

namespace drape {

namespace {

using Eigen::Vector3d;
using Pairs = std::vector<std::array<int, 2>>;

Vector3d At(const double* positions, int node) {
  return Vector3d(positions[3 * node], positions[3 * node + 1], positions[3 * node + 2]);
}

bool Shares(const std::array<int, 3>& triangle, int node) {
  return triangle[0] == node || triangle[1] == node || triangle[2] == node;
}

bool Shares(const std::array<int, 2>& side, const std::array<int, 2>& other) {
  return side[0] == other[0] || side[0] == other[1] || side[1] == other[0] || side[1] == other[1];
}

double NodeTriangleDistance(const double* x, int node, const std::array<int, 3>& triangle) {
  return PointTriangleDistance(At(x, node), At(x, triangle[0]), At(x, triangle[1]),
                               At(x, triangle[2]));
}

double SideSideDistance(const double* x, const std::array<int, 2>& one,
                        const std::array<int, 2>& other) {
  return SegmentSegmentDistance(At(x, one[0]), At(x, one[1]), At(x, other[0]), At(x, other[1]));
}

template <size_t N>
std::vector<Box> BoxesAt(const std::vector<std::array<int, N>>& items, const double* x) {
  std::vector<Box> boxes(items.size());
  for (size_t k = 0; k < items.size(); ++k) {
    for (int node : items[k]) boxes[k].Add(At(x, node));
  }
  return boxes;
}

Box Inflated(Box box, double margin) {
  box.low.array() -= margin;
  box.high.array() += margin;
  return box;
}

template <size_t N>
bool AllFullyFixed(const Model& model, const std::array<int, N>& nodes) {
  return std::all_of(nodes.begin(), nodes.end(), [&](int node) { return model.fully_fixed(node); });
}

// The nodes on the fabric's triangles, each once.
std::vector<int> SurfaceNodes(const Model& model) {
  std::vector<char> on(model.num_nodes, 0);
  for (const auto& triangle : model.triangles) {
    for (int node : triangle) on[node] = 1;
  }
  std::vector<int> nodes;
  for (int k = 0; k < model.num_nodes; ++k) {
    if (on[k]) nodes.push_back(k);
  }
  return nodes;
}

// Calls visit_point(node, t) for every node of the surface and triangle t that does not have it
// as a corner, and visit_sides(s, o) for every two sides s < o that share no node, whose boxes at
// x come within `radius` of each other: every pair nearer than `radius` is among them.
template <typename VisitPoint, typename VisitSides>
void ForEachPairInBoxes(const Model& model, const double* x, double radius, VisitPoint visit_point,
                        VisitSides visit_sides) {
  const Model::SelfContact& self = model.self_contact;
  const BoxTree triangles(BoxesAt(model.triangles, x));
  for (int node : SurfaceNodes(model)) {
    Box query;
    query.Add(At(x, node));
    triangles.ForEachOverlap(Inflated(query, radius), [&](int t) {
      if (!Shares(model.triangles[t], node)) visit_point(node, t);
    });
  }
  const BoxTree sides(BoxesAt(self.sides, x));
  for (int s = 0; s < static_cast<int>(self.sides.size()); ++s) {
    Box query;
    query.Add(At(x, self.sides[s][0]));
    query.Add(At(x, self.sides[s][1]));
    sides.ForEachOverlap(Inflated(query, radius), [&](int o) {
      if (o > s && !Shares(self.sides[s], self.sides[o])) visit_sides(s, o);
    });
  }
}

// Whether `item` is among the sorted neighbours of `of` in a compressed list.
bool Listed(const std::vector<int>& starts, const std::vector<int>& items, int of, int item) {
  return std::binary_search(items.begin() + starts[of], items.begin() + starts[of + 1], item);
}

// Whether node `node` and triangle `t` are rest-shape neighbours: from the list where it has been
// made (FindRestNeighbours, at a model's first UpdateSelfContact), else from their distance.
bool RestNeighbours(const Model& model, int node, int t) {
  const Model::SelfContact& self = model.self_contact;
  if (!self.neighbours_found) {
    return NodeTriangleDistance(model.initial.data(), node, model.triangles[t]) <
           kSelfRestFactor * self.clearance;
  }
  return Listed(self.neighbour_triangle_start, self.neighbour_triangles, node, t);
}

// The same for sides `s` and `o`.
bool RestNeighbourSides(const Model& model, int s, int o) {
  const Model::SelfContact& self = model.self_contact;
  if (!self.neighbours_found) {
    return SideSideDistance(model.initial.data(), self.sides[s], self.sides[o]) <
           kSelfRestFactor * self.clearance;
  }
  return Listed(self.neighbour_side_start, self.neighbour_sides, s, o);
}

// Pairs as a compressed list: for each of `count` firsts, its seconds, sorted.
void Compress(Pairs pairs, int count, std::vector<int>* starts, std::vector<int>* items) {
  std::sort(pairs.begin(), pairs.end());
  starts->assign(count + 1, 0);
  items->clear();
  for (const auto& [first, second] : pairs) {
    ++(*starts)[first + 1];
    items->push_back(second);
  }
  for (int k = 0; k < count; ++k) (*starts)[k + 1] += (*starts)[k];
}

// The rest-shape neighbours: the pairs nearer than kSelfRestFactor × C in Model::initial.
void FindRestNeighbours(Model* model) {
  Model::SelfContact& self = model->self_contact;
  const double* rest = model->initial.data();
  const double radius = kSelfRestFactor * self.clearance;
  Pairs point_triangle, sides;
  ForEachPairInBoxes(
      *model, rest, radius,
      [&](int node, int t) {
        if (NodeTriangleDistance(rest, node, model->triangles[t]) < radius) {
          point_triangle.push_back({node, t});
        }
      },
      [&](int s, int o) {
        if (SideSideDistance(rest, self.sides[s], self.sides[o]) < radius) sides.push_back({s, o});
      });
  Compress(std::move(point_triangle), model->num_nodes, &self.neighbour_triangle_start,
           &self.neighbour_triangles);
  Compress(std::move(sides), static_cast<int>(self.sides.size()), &self.neighbour_side_start,
           &self.neighbour_sides);
  self.neighbours_found = true;
}

// The pairs nearer than `radius` at x that may have a term: sharing no node, not all fixed, and
// not rest-shape neighbours.
void FindPairs(const Model& model, const double* x, double radius, Pairs* point_triangle,
               Pairs* edge_edge) {
  const Model::SelfContact& self = model.self_contact;
  point_triangle->clear();
  edge_edge->clear();
  ForEachPairInBoxes(
      model, x, radius,
      [&](int node, int t) {
        const auto& triangle = model.triangles[t];
        if (RestNeighbours(model, node, t)) return;
        if (AllFullyFixed(model, std::array<int, 4>{node, triangle[0], triangle[1], triangle[2]})) {
          return;
        }
        if (NodeTriangleDistance(x, node, triangle) < radius) point_triangle->push_back({node, t});
      },
      [&](int s, int o) {
        const auto& side = self.sides[s];
        const auto& other = self.sides[o];
        if (RestNeighbourSides(model, s, o)) return;
        if (AllFullyFixed(model, std::array<int, 4>{side[0], side[1], other[0], other[1]})) return;
        if (SideSideDistance(x, side, other) < radius) edge_edge->push_back({s, o});
      });
  std::sort(point_triangle->begin(), point_triangle->end());
  std::sort(edge_edge->begin(), edge_edge->end());
}

void BuildTerms(const Pairs& point_triangle, const Pairs& edge_edge, const double* x,
                Model* model) {
  Model::SelfContact& self = model->self_contact;
  model->terms.resize(self.first_term);
  const double c = self.clearance, k = self.stiffness;
  // Least-squares shift of the potential (src/model/term.h): the energy at a full clearance's
  // depth, as the obstacles' terms take.
  const double shift = k / 3.0 * c * c * c;
  for (const auto& [node, t] : point_triangle) {
    const auto& triangle = model->triangles[t];
    model->terms.push_back(MakeTerm("self_contact", {node, triangle[0], triangle[1], triangle[2]},
                                    PointTriangleContact(c, k), shift));
  }
  for (const auto& [s, o] : edge_edge) {
    const auto& side = self.sides[s];
    const auto& other = self.sides[o];
    model->terms.push_back(MakeTerm("self_edge_contact", {side[0], side[1], other[0], other[1]},
                                    EdgeEdgeContact(c, k), shift));
  }
  self.point_triangle = point_triangle;
  self.edge_edge = edge_edge;
  self.built_at.assign(x, x + model->num_dofs());
}

// From distance d₀ at s = 0, the fraction s where a pair whose distance d(s) changes at most
// `rate` per unit s first comes within 1 % of `floor` above it (d(s) ≥ floor up to it), or
// `limit` if it does not before; after kMaxAdvances steps, where it is (a grazing move is cut
// short, never let through).
template <typename DistanceAt>
double AdvanceToFloor(double start, double floor, double rate, double limit,
                      DistanceAt distance_at) {
  constexpr int kMaxAdvances = 100;
  double s = 0.0, distance = start;
  for (int k = 0; k < kMaxAdvances; ++k) {
    const double margin = distance - floor;
    if (margin <= 0.01 * floor) return s;
    s += margin / rate;
    if (s >= limit) return limit;
    distance = distance_at(s);
  }
  return s;
}

class SweptPositions {
 public:
  SweptPositions(const double* from, const double* to) : from_(from), to_(to) {}
  Vector3d Along(int node, double s) const {
    return At(from_, node) + s * (At(to_, node) - At(from_, node));
  }
  Vector3d Move(int node) const { return At(to_, node) - At(from_, node); }
  // The largest |Δa − Δb| over a of `one` and b of `other`: how fast, per unit of the step's
  // fraction, any point of the one's hull can come nearer any point of the other's (a point of a
  // hull moves by a convex combination of its corners' moves).
  template <size_t N, size_t M>
  double RelativeRate(const std::array<int, N>& one, const std::array<int, M>& other) const {
    double rate = 0.0;
    for (int a : one) {
      for (int b : other) rate = std::max(rate, (Move(a) - Move(b)).squaredNorm());
    }
    return std::sqrt(rate);
  }
  // The distance between the hulls' boxes at the step's start: at most the hulls' distance.
  template <size_t N, size_t M>
  double StartBoxDistance(const std::array<int, N>& one, const std::array<int, M>& other) const {
    Box first, second;
    for (int a : one) first.Add(At(from_, a));
    for (int b : other) second.Add(At(from_, b));
    const Vector3d gap =
        (first.low - second.high).cwiseMax(second.low - first.high).cwiseMax(Vector3d::Zero());
    return gap.norm();
  }
  template <size_t N>
  std::vector<Box> Boxes(const std::vector<std::array<int, N>>& items) const {
    std::vector<Box> boxes = BoxesAt(items, from_);
    for (size_t k = 0; k < items.size(); ++k) {
      for (int node : items[k]) boxes[k].Add(At(to_, node));
    }
    return boxes;
  }

 private:
  const double* from_;
  const double* to_;
};

// The step-filter rule for one pair: `distance_at(s)` its distance at fraction s, `rate` the
// bound on its change per unit s.
template <typename DistanceAt>
double PairSafeFraction(double clearance, double rate, double limit, DistanceAt distance_at) {
  if (std::isnan(rate)) return 0.0;  // a step that is not finite passes nothing
  if (!(rate > 0.0)) return limit;
  const double start = distance_at(0.0);
  if (!(start > 0.0)) return limit;  // touching or crossed already: nothing to guard
  const double floor = 0.5 * std::min(start, clearance);
  if (start - rate * limit >= floor) return limit;
  if (!std::isfinite(rate)) return 0.0;
  return AdvanceToFloor(start, floor, rate, limit, distance_at);
}

// The step filter's limit for node `node` and triangle `t`, given the limit so far.
double NodeTriangleLimit(const Model& model, const SweptPositions& swept, int node, int t,
                         double limit) {
  const auto& tri = model.triangles[t];
  const std::array<int, 1> point = {node};
  const double rate = swept.RelativeRate(point, tri);
  const double clearance = model.self_contact.clearance;
  if (swept.StartBoxDistance(point, tri) - rate * limit >= 0.5 * clearance) return limit;
  if (RestNeighbours(model, node, t)) return limit;
  return PairSafeFraction(clearance, rate, limit, [&](double s) {
    return PointTriangleDistance(swept.Along(node, s), swept.Along(tri[0], s),
                                 swept.Along(tri[1], s), swept.Along(tri[2], s));
  });
}

// The same for sides `s` and `o`.
double SideSideLimit(const Model& model, const SweptPositions& swept, int s, int o, double limit) {
  const Model::SelfContact& self = model.self_contact;
  const auto& side = self.sides[s];
  const auto& other = self.sides[o];
  const double rate = swept.RelativeRate(side, other);
  if (swept.StartBoxDistance(side, other) - rate * limit >= 0.5 * self.clearance) return limit;
  if (RestNeighbourSides(model, s, o)) return limit;
  return PairSafeFraction(self.clearance, rate, limit, [&](double f) {
    return SegmentSegmentDistance(swept.Along(side[0], f), swept.Along(side[1], f),
                                  swept.Along(other[0], f), swept.Along(other[1], f));
  });
}

// Every pair whose boxes swept by the step come within C/2 of each other.
double SweptPairsLimit(const Model& model, const SweptPositions& swept) {
  const Model::SelfContact& self = model.self_contact;
  const double margin = 0.5 * self.clearance;
  double limit = 1.0;
  const BoxTree triangles(swept.Boxes(model.triangles));
  for (int node : SurfaceNodes(model)) {
    Box query;
    query.Add(swept.Along(node, 0.0));
    query.Add(swept.Along(node, 1.0));
    triangles.ForEachOverlap(Inflated(query, margin), [&](int t) {
      if (!Shares(model.triangles[t], node)) {
        limit = NodeTriangleLimit(model, swept, node, t, limit);
      }
    });
    if (!(limit > 0.0)) return limit;
  }
  const BoxTree sides(swept.Boxes(self.sides));
  for (int s = 0; s < static_cast<int>(self.sides.size()); ++s) {
    Box query;
    for (int node : self.sides[s]) {
      query.Add(swept.Along(node, 0.0));
      query.Add(swept.Along(node, 1.0));
    }
    sides.ForEachOverlap(Inflated(query, margin), [&](int o) {
      if (o > s && !Shares(self.sides[s], self.sides[o])) {
        limit = SideSideLimit(model, swept, s, o, limit);
      }
    });
    if (!(limit > 0.0)) return limit;
  }
  return limit;
}

// Only the pairs with terms: enough where no other pair can come within C/2 (SelfSafeFraction).
double NearPairsLimit(const Model& model, const SweptPositions& swept) {
  const Model::SelfContact& self = model.self_contact;
  double limit = 1.0;
  for (const auto& [node, t] : self.point_triangle) {
    limit = NodeTriangleLimit(model, swept, node, t, limit);
  }
  for (const auto& [s, o] : self.edge_edge) limit = SideSideLimit(model, swept, s, o, limit);
  return limit;
}

double LargestMoveBetween(const double* from, const double* to, int nodes) {
  double largest = 0.0;
  for (int k = 0; k < nodes; ++k) largest = std::max(largest, (At(to, k) - At(from, k)).norm());
  return largest;
}

}  // namespace

bool SelfContactApplies(const Scene& scene, const Model& model) {
  return scene.contact.self && model.dimension == 3 && !model.triangles.empty();
}

void SetUpSelfContact(const Scene& scene, Model* model) {
  if (!SelfContactApplies(scene, *model)) return;
  Model::SelfContact& self = model->self_contact;
  self.enabled = true;
  self.clearance = 2.0 * scene.contact.thickness;
  ContactSpec layers = scene.contact;
  layers.thickness = self.clearance;
  self.stiffness = ContactStiffness(layers, *model);
  self.first_term = static_cast<int>(model->terms.size());
  self.sides = SidesOf(model->triangles);
  // No pair has a term at the start: the model is built at Model::initial, the rest shape, where
  // every pair nearer than the build radius is a rest-shape neighbour (kSelfRestFactor ≥
  // kSelfBuildFactor). The neighbours are listed at the first UpdateSelfContact, so that a model
  // only built (drape check, a scene's tests) does not pay for them.
  assert(model->positions == model->initial && "built at the start");
  BuildTerms({}, {}, model->positions.data(), model);
}

bool UpdateSelfContact(Model* model, const double* positions) {
  Model::SelfContact& self = model->self_contact;
  if (!self.enabled) return false;
  if (!self.neighbours_found) FindRestNeighbours(model);
  assert(static_cast<int>(model->terms.size()) ==
             self.first_term +
                 static_cast<int>(self.point_triangle.size() + self.edge_edge.size()) &&
         "the self-contact terms are the model's last");
  // A pair farther than the build radius when the terms were built comes within the trigger
  // radius only if its ends moved (together) more than the difference.
  const double margin = (kSelfBuildFactor - kSelfTriggerFactor) * self.clearance;
  if (LargestMoveBetween(self.built_at.data(), positions, model->num_nodes) < 0.5 * margin) {
    return false;
  }
  Pairs point_triangle, edge_edge;
  FindPairs(*model, positions, kSelfBuildFactor * self.clearance, &point_triangle, &edge_edge);
  const auto covered = [](const Pairs& have, const Pairs& need) {
    return std::includes(have.begin(), have.end(), need.begin(), need.end());
  };
  if (covered(self.point_triangle, point_triangle) && covered(self.edge_edge, edge_edge)) {
    // Every pair within the build radius here has its term: the terms stand as if built here.
    self.built_at.assign(positions, positions + model->num_dofs());
    return false;
  }
  const double trigger = kSelfTriggerFactor * self.clearance;
  const auto within_trigger = [&](const Pairs& pairs, bool sides) {
    Pairs near;
    for (const auto& pair : pairs) {
      const double distance =
          sides ? SideSideDistance(positions, self.sides[pair[0]], self.sides[pair[1]])
                : NodeTriangleDistance(positions, pair[0], model->triangles[pair[1]]);
      if (distance < trigger) near.push_back(pair);
    }
    return near;
  };
  if (covered(self.point_triangle, within_trigger(point_triangle, false)) &&
      covered(self.edge_edge, within_trigger(edge_edge, true))) {
    return false;
  }
  BuildTerms(point_triangle, edge_edge, positions, model);
  ++self.generation;
  return true;
}

double SelfSafeFraction(const Model& model, const double* from, const double* to) {
  const Model::SelfContact& self = model.self_contact;
  if (!self.enabled) return 1.0;
  const SweptPositions swept(from, to);
  // A pair without a term was at least the build radius apart where the terms were found; its
  // distance has fallen since by at most twice the largest move, and falls by at most twice the
  // step's largest move along it: if that leaves C/2, only the pairs with terms can be limited.
  const double since_built = LargestMoveBetween(self.built_at.data(), from, model.num_nodes);
  const double step = LargestMoveBetween(from, to, model.num_nodes);
  if (2.0 * (since_built + step) < (kSelfBuildFactor - 0.5) * self.clearance) {
    return NearPairsLimit(model, swept);
  }
  return SweptPairsLimit(model, swept);
}

double StepSafeFraction(const Model& model, const double* from, const double* to) {
  const double obstacles = ObstacleSafeFraction(model, from, to);
  if (!(obstacles > 0.0)) return obstacles;
  return std::min(obstacles, SelfSafeFraction(model, from, to));
}

}  // namespace drape
