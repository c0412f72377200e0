// The fabric's contact with itself (`contact.self`): folds that press together are kept the
// fabric's thickness apart, and no step of a solve lets one piece of the fabric pass through
// another.
//
// The energy. A node and a triangle of the fabric (costs/point_triangle_contact.h), and two
// triangle sides (costs/edge_edge_contact.h), that share no node are kept C = 2 × contact.thickness
// apart (contact.thickness is the half-thickness each layer keeps off an obstacle) by the
// obstacles' cubic penalty, with the obstacles' stiffness rule for the clearance C:
// k = F_ref / (f C)² (src/model/contact.h), so two layers pressed together by the whole load sit
// at least (1 − f) C = 0.9 C apart.
//
// Which pairs have terms. Only pairs that are near: the terms are the last of Model::terms and are
// replaced as the fabric moves (UpdateSelfContact; newton asks at every iterate, RunSolve before
// and after every method). A pair nearer than kSelfTriggerFactor × C must have its term; when one
// has not, every pair nearer than kSelfBuildFactor × C gets one (so a layer approaching the margin
// between the two is already covered), and the Hessian's pattern is built again
// (Model::SelfContact::generation). A pair nearer than kSelfRestFactor × C in the fabric's rest
// shape (Model::initial) never has a term: such points are neighbours along the fabric, within
// the arc (π/2) C of the tightest fold a sheet of thickness C can make, so they never face each
// other as two layers do, and a term would push at rest (zero force at rest holds because
// kSelfRestFactor ≥ kSelfBuildFactor).
//
// The step filter. SelfSafeFraction limits a step as newton's obstacle step limit does
// (ObstacleSafeFraction): every node–triangle and side–side pair that shares no node and is not a
// rest-shape neighbour, with or without a term, keeps at least half of min(d₀, C) all along the
// straight move, d₀ its distance at the step's start, by conservative advancement (the pair's
// distance changes with the step's fraction s at most as fast as the largest move of one of its
// nodes relative to another). So no step passes a piece of the fabric through another (IPC's
// filtered line search: Li et al. 2020, "Incremental Potential Contact", ACM Trans. Graph. 39(4),
// §4.3, with a floor instead of a root of the distance). Candidate pairs come from a bounding-box
// tree over the triangles' (and sides') boxes swept by the step; where no pair without a term can
// have come within C/2 since the terms were found, only the pairs with terms are checked.
#ifndef DRAPE_SRC_MODEL_SELF_CONTACT_H_
#define DRAPE_SRC_MODEL_SELF_CONTACT_H_

#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

constexpr double kSelfTriggerFactor = 1.5;  // × C: a pair this near must have its term
constexpr double kSelfBuildFactor = 2.0;    // × C: pairs this near get one when terms are built
constexpr double kSelfRestFactor = 2.0;     // × C: pairs this near at rest never get one
static_assert(kSelfRestFactor >= kSelfBuildFactor, "no pair has a term at rest");

// Whether the scene's fabric gets contact with itself: contact.self, a fabric of triangles (a
// chain's links have no surface to press) in 3 dimensions.
bool SelfContactApplies(const Scene& scene, const Model& model);

// Sets up the fabric's contact with itself where it applies, after every other term is in the
// model (its terms must be the last), with the terms of the pairs near at model.positions.
void SetUpSelfContact(const Scene& scene, Model* model);

// Replaces the self-contact terms where a pair nearer than kSelfTriggerFactor × C at `positions`
// (3 per node) has none (see above). Returns whether the terms changed: a Hessian pattern built
// on the model before is then stale.
bool UpdateSelfContact(Model* model, const double* positions);

// The largest s ∈ [0, 1] such that the move from `from` to from + s (to − from) (3 per node)
// keeps every pair of the fabric's surface that shares no node at least half of min(d₀, C) apart
// (see above); 1 without self-contact.
double SelfSafeFraction(const Model& model, const double* from, const double* to);

// The step limit every solver applies: the smaller of ObstacleSafeFraction (src/model/contact.h)
// and SelfSafeFraction.
double StepSafeFraction(const Model& model, const double* from, const double* to);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_SELF_CONTACT_H_
