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
  int nodes_in_contact = 0;                       // nodes inside some obstacle's clearance layer
  double max_penetration = 0.0;                   // m, the deepest node's depth g inside the layer
  double max_penetration_fraction = 0.0;          // max_penetration / t
  double allowed_fraction = kAllowedPenetration;  // what the stiffness rule aims to keep
  int nodes_under_disk = 0;                       // UnderDisks: how many
  int edges_through_disk = 0;                     // UnderDisks: edges through a disk
  double under_disk_inside = 0.0;                 // UnderDisks: the farthest inside a rim, m
  // Whether the fabric has passed through a support disk (the state is no drape over it).
  bool ThroughDisk() const { return nodes_under_disk > 0 || edges_through_disk > 0; }
};

// k = F_ref / (f t)² (see above), N/m².
double ContactStiffness(const ContactSpec& contact, const Model& model);

// Adds one "<kind>_contact" term (sphere, disk, cylinder, box, plane, pin) per obstacle and
// reachable node. Call after the loads are in the model (the stiffness depends on them).
// Throws InputError for a zero thickness with obstacles, or friction (not supported: obstacles
// are frictionless).
void AddContactTerms(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                     Model* model);

// Signed distance from `x` to the obstacle's surface (positive outside), m.
double ObstacleDistance(const ObstacleSpec& obstacle, const double* x);

// Where a node that started above a support disk (ObstacleSpec kind "disk") is now: clear of it,
// over it (ρ ≤ R) in its contact layer (|h| < clearance), under it, or below the layer beside
// its rim (within the clearance inside the rim, where a lattice edge cuts the rim's corner).
enum class DiscPlace { kClear, kInLayer, kUnder, kBesideRimBelow };
DiscPlace PlaceOnDisc(const ObstacleSpec& disc, double clearance, const double* x);

// The nodes that started above a support disk and are now under it: below its plane in its
// contact layer, or below the layer more than the clearance inside the rim. The disk's contact
// acts on nodes only and from both sides, so a lattice edge can cut the rim's corner and the
// fabric hang under the disc; such a state is not a drape over it. How far inside the rim they
// are tells how much: the 30 cm drape tester on a 1.04 cm lattice, from the flat start, hangs 7
// nodes up to 3.4 mm inside the 9 cm rim, in a 4-fold pattern 17 % lower in energy than the
// drapes over the disc; the limp 36 cm polyester at 5 mm hangs 54 nodes of its vertical skirt
// up to 3.4 mm inside it.
// Also counted: the fabric's edges that pass through a disk, crossing its plane inside its rim
// (the disk has no thickness, so a node can be on either side of it and the edge between two
// such nodes through it).
struct UnderDisks {
  int nodes = 0;
  int edges = 0;        // edges through a disk
  double inside = 0.0;  // the largest R − ρ of those nodes and of those edges' crossings, m
};
UnderDisks NodesUnderDisks(const std::vector<ObstacleSpec>& obstacles, double clearance,
                           const Model& model, const double* positions);

// Penetration into the clearance layers at `positions` (3 per node), over every node and obstacle,
// and the nodes under a support disk.
ContactReport MeasureContact(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                             const Model& model, const double* positions);

// The step limit that keeps nodes from passing through obstacles between two iterates (thin ones
// too: a pin is a point, a disk has no thickness, so a long step can jump over them). A node that
// starts outside an obstacle at distance d₀ from its surface must keep, all along its straight
// move, at least half of min(d₀, contact.thickness) from it. NodeSafeFraction: the largest
// s ∈ [0, 1] such that the move of one node from `from` to from + s (to − from) (3 doubles each)
// keeps that for every obstacle of the model; ObstacleSafeFraction: the same for all nodes at once
// (3 per node). 1 when the model has no obstacles.
double NodeSafeFraction(const Model& model, const double* from, const double* to);
double ObstacleSafeFraction(const Model& model, const double* from, const double* to);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_CONTACT_H_
