// Rigid obstacles as contact energies (costs/*_contact.h): one term per obstacle and node that can
// reach it, and the penetration report written to summary.json.
//
// Stiffness rule. Every contact term is the cubic penalty U = (k/3) g³ of a node that is g deep
// inside the clearance layer of thickness t = contact.thickness (costs/contact_penalty.h), so a
// node pressed with force F rests at g = √(F/k). With
//   k = F_ref / (f t)²,   F_ref = Σ_nodes |weight + applied load|,   f = kAllowedPenetration = 0.1,
// any node whose contact force is at most F_ref — the whole load, which bounds the force of a
// single support point unless opposing contacts squeeze the fabric — stays at most f t = 10 % of
// the thickness deep: g/t = f √(F/F_ref). A scene without weight or loads (only prescribed
// displacements) uses F_ref = 1 N. MeasureContact reports the penetration actually reached.
//
// Which nodes get terms. A node fully fixed never does. If no node is fully fixed, the whole
// fabric may move anywhere (it rests on the obstacles), so every node gets a term for every
// obstacle. Otherwise a node stays within (1 + ε) × (its distance along the fabric to a fixed
// node) of that node, at most (1 + ε) × the fabric's size (Model::size) for a flat convex piece,
// so it can only touch an obstacle whose surface lies within 2.5 × size of its start (ε ≤ 0.5);
// farther obstacles get no term for it.
#ifndef DRAPE_SRC_MODEL_CONTACT_H_
#define DRAPE_SRC_MODEL_CONTACT_H_

#include <vector>

#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

constexpr double kAllowedPenetration = 0.1;  // of contact.thickness, the stiffness rule's f
constexpr double kReachFactor = 2.5;         // × Model::size: the farthest a node may travel

struct ContactReport {
  int terms = 0;                                  // contact terms in the model
  double thickness = 0.0;                         // contact.thickness t, m
  double stiffness = 0.0;                         // k of the penalty, N/m²
  int nodes_in_contact = 0;                       // nodes an obstacle pushes on (NodeInContact)
  double max_penetration = 0.0;                   // m, the deepest node's depth g inside the layer
  double max_penetration_fraction = 0.0;          // max_penetration / t
  double allowed_fraction = kAllowedPenetration;  // what the stiffness rule aims to keep
  int nodes_under_disk = 0;                       // UnderDisks: nodes hanging under a disk
  int edges_through_disk = 0;                     // UnderDisks: edges through a disk
  double under_disk_inside = 0.0;                 // UnderDisks: those edges' farthest inside, m
  int edges_through_body = 0;                     // fabric edges crossing a mesh obstacle's surface
  // The obstacles' friction, where one has it (src/run/run.cc, SettleObstacleFriction): the solves
  // with its normal forces taken again at the last one's result, how far the pushes at the final
  // state are from those its terms were made with (FrictionPushChange), and whether that is within
  // kFrictionPushTolerance.
  bool friction = false;
  int friction_passes = 0;
  double friction_push_change = 0.0;
  bool friction_settled = true;
  // Whether the fabric has passed through a support disk (the state is no drape over it).
  bool ThroughDisk() const { return edges_through_disk > 0; }
  // Whether the fabric has passed through a mesh obstacle's surface (no edge crosses an analytic
  // body's without a node inside it, which the certificate refuses; a mesh's thin parts can be
  // crossed by an edge whose nodes are both outside).
  bool ThroughBody() const { return edges_through_body > 0; }
};

// k = F_ref / (f t)² (see above), N/m².
double ContactStiffness(const ContactSpec& contact, const Model& model);

// Adds one "<kind>_contact" term (sphere, disk, cylinder, box, plane, pin, mesh) per obstacle and
// reachable node, and one "<kind>_edge_contact" term per obstacle (but a plane or a pin) and edge
// (triangle side or chain link) with a reachable, not fully fixed end and EdgeContactPoints > 0.
// Call after the loads are in the model (the stiffness depends on them).
// Throws InputError for a zero thickness with obstacles.
void AddContactTerms(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                     Model* model);

// The obstacles' friction (costs/obstacle_friction.h), Coulomb's with the normal force lagged.
// Its smoothing ε, the slip below which the kink at a node's start is rounded, is
// kFrictionSlipFraction × contact.thickness: a node that sticks under a tangential force F < μ λ
// creeps ε (F/μλ) / √(1 − (F/μλ)²), 0.58 ε at half the limit, so a stuck node is resolved to the
// same 10 % of the thickness that the stiffness rule holds its depth to.
constexpr double kFrictionSlipFraction = kAllowedPenetration;
// The friction's normal forces are lagged: a solve takes them from the state its model was built
// at, and is repeated from its result with that result's pushes until they move by at most
// kFrictionPushTolerance of the load (FrictionPushChange), in at most kMaxFrictionPasses solves.
// 1 %: the friction force it leaves uncertain, μ × 1 % of the load, is below the scatter of a
// measured fabric friction coefficient (several % between specimens on the inclined plane or
// KES-FB4), so a tighter lag would be precision the input has not.
constexpr double kFrictionPushTolerance = 0.01;
constexpr int kMaxFrictionPasses = 10;

// Whether an obstacle has a friction (ObstacleSpec::friction > 0).
bool HasObstacleFriction(const std::vector<ObstacleSpec>& obstacles);

// F_ref of the stiffness rule: Σ |weight + applied load| over the nodes, N (1 N without any).
double ContactReferenceForce(const Model& model);

// The push of every obstacle with a friction (μ > 0) on each node at `positions`: −∇ of that
// obstacle's node and edge contact terms (not its friction terms) on the node, N. Only the
// nonzero ones, by obstacle, then node.
std::vector<Model::Push> FrictionObstaclePushes(const Model& model, const double* positions);

// Adds one "<kind>_friction" term per obstacle with a friction and node not fully fixed that it
// pushes on at `pushed_at` (FrictionObstaclePushes): λ n that push, x0 the node's place in `start`
// (3 per node each). Records the pushes in model->friction_pushes. Nothing without a friction.
// Call after AddContactTerms. `pushed_at` null: nothing is solved yet, and a fabric laid on an
// obstacle touches its layer's edge without a push; so at `start`, a node within
// (1 + kAllowedPenetration) × t of a frictional obstacle that does not push on it gets the push its
// own weight and load make against the surface, max(0, −F·n) n (n the surface's outward normal):
// exact for a sheet lying flat, a first guess elsewhere that the passes correct. Without it the
// first solve would have no friction, and a fabric that only friction holds would slide away. A
// node that touches only later in the step still has its kink at `start`: its friction opposes its
// whole slip across n since then, contact or not, which load steps
// (FiniteVolumeSpec::friction_load_steps) make small.
void AddObstacleFrictionTerms(const std::vector<double>& start,
                              const std::vector<double>* pushed_at, Model* model);

// How far the obstacles' pushes at `positions` are from those the friction terms were made with:
// Σ |f − f_made| over the obstacles with a friction and their nodes, over ContactReferenceForce.
// 0 without a friction.
double FrictionPushChange(const Model& model, const double* positions);

// How many points inside the edge a–b its contact term (costs/edge_contact.h) samples: the fewest
// that leave no gap longer than the clearance t along it, ⌈|b − a| / t⌉ − 1 (0: an edge no longer
// than t, which its nodes' terms guard alone).
int EdgeContactPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const ContactSpec& contact);

// Signed distance from `x` to the obstacle's surface (positive outside), m.
double ObstacleDistance(const ObstacleSpec& obstacle, const double* x);

// Where a node that started above a support disk (ObstacleSpec kind "disk") is now: clear of it,
// over it (ρ ≤ R) in its contact layer (|h| < clearance), under it, or below the layer beside
// its rim (within the clearance inside the rim, where a lattice edge cuts the rim's corner).
enum class DiscPlace { kClear, kInLayer, kUnder, kBesideRimBelow };
DiscPlace PlaceOnDisc(const ObstacleSpec& disc, double clearance, const double* x);

// A support disk has no thickness, so what keeps the fabric over it is that no part of the
// fabric's surface crosses it: the node terms keep the nodes out of its clearance layer, the edge
// terms (costs/edge_contact.h) the straight edges between them, and newton's step limit
// (ObstacleSafeFraction) keeps both from jumping across it between iterates.
// Counted here, at `positions`:
// - edges: the fabric's edges (triangle sides and line elements) that cross a disk's plane inside
//   its rim: the fabric passes through the disk, the state is no drape over it (ThroughDisk); at
//   most the edge contact's penetration limit allows none (costs/edge_contact.h). Before the edge
//   terms, the limp 30 cm tester at 2.6 mm passed 216 nodes through the rim's corner, up to
//   6.2 mm inside it;
// - inside: the largest R − ρ of those edges' crossings, m;
// - nodes: the nodes that started above a disk and now hang under it, below its plane in its
//   contact layer or below the layer more than the clearance inside the rim, with no edge through
//   it: the fabric went round the rim (a fold's trough of a limp fabric hangs a few mm inside the
//   rim's radius: the limp 30 cm tester at 2.6 mm, 80 nodes up to 2.9 mm inside it). Reported,
//   not a fault.
struct UnderDisks {
  int nodes = 0;
  int edges = 0;        // edges through a disk
  double inside = 0.0;  // the largest R − ρ of those edges' crossings, m
};
UnderDisks NodesUnderDisks(const std::vector<ObstacleSpec>& obstacles, double clearance,
                           const Model& model, const double* positions);

// The fabric's edges (triangle sides and line elements) at `positions` that cross the surface of a
// mesh obstacle (src/geometry/triangle_surface.h): SegmentCrossesTriangle
// (src/model/self_intersection.h) against the faces whose boxes the edge's box meets.
int EdgesThroughBodies(const std::vector<ObstacleSpec>& obstacles, const Model& model,
                       const double* positions);

// Whether an obstacle pushes on `node`: its force in `contact_forces` (3 per node, N: −∇ of the
// contact terms, Certificate::contact_forces, empty without obstacles) is finite and not zero. The
// one meaning of "in contact": summary.json's contact.nodes_in_contact counts these nodes, and
// nodes.csv and mesh.vtk mark them (in_contact). A node's own term pushes while the node is inside
// the clearance layer; an edge's term pushes on both its ends while a point inside the edge is
// (costs/edge_contact.h), so a node held only where its edges cross a support disk's rim, outside
// every layer itself, is in contact, as is a fixed node at such an edge's other end.
bool NodeInContact(const std::vector<double>& contact_forces, int node);

// Penetration into the clearance layers at `positions` (3 per node), over every node and obstacle;
// the nodes in contact by `contact_forces`, the contact forces at `positions` (NodeInContact); and
// the nodes under a support disk.
ContactReport MeasureContact(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                             const Model& model, const double* positions,
                             const std::vector<double>& contact_forces);

// The step limit that keeps nodes from passing through obstacles between two iterates (thin ones
// too: a pin is a point, a disk has no thickness, so a long step can jump over them). A node that
// starts outside an obstacle at distance d₀ from its surface must keep, all along its straight
// move, at least half of min(d₀, contact.thickness) from it. NodeSafeFraction: the largest
// s ∈ [0, 1] such that the move of one node from `from` to from + s (to − from) (3 doubles each)
// keeps that for every obstacle of the model; ObstacleSafeFraction: the same for all nodes at once
// (3 per node) and for the points of every edge contact term (costs/edge_contact.h) against its
// obstacle. 1 when the model has no obstacles. Against a mesh body (not convex) the fraction is
// found by conservative advancement, which may stop a little short of the largest: a safe one.
double NodeSafeFraction(const Model& model, const double* from, const double* to);
double ObstacleSafeFraction(const Model& model, const double* from, const double* to);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_CONTACT_H_
