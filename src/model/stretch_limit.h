// The stretch limit (material.springs.stretch_limit): no spring longer than limit × rest length.
// For the energy solvers it is a penalty term per spring (costs/stretch_limit_barrier.h); the
// explicit-euler solver enforces it geometrically with Provot's constraint instead.
#ifndef DRAPE_SRC_MODEL_STRETCH_LIMIT_H_
#define DRAPE_SRC_MODEL_STRETCH_LIMIT_H_

#include <vector>

#include "src/model/model.h"

namespace drape {

// Penalty stiffness κ over the spring's stiffness k (sets the tolerance: see the barrier's
// comment).
constexpr double kStretchLimitPenaltyRatio = 1000.0;

// A spring of the model: its two nodes, rest length (m) and stiffness (N/m).
struct SpringLink {
  int a = 0, b = 0;
  double rest_length = 0.0;
  double stiffness = 0.0;
};

// The elastic springs of the model (SpringStretch and TensionOnlySpring terms; zero-length springs
// have no rest length to limit and are left out).
std::vector<SpringLink> ModelSprings(const Model& model);

// Adds one "stretch_limit" penalty term per spring (κ = kStretchLimitPenaltyRatio × k, limit
// length = limit × rest length) and sets model->stretch_limit. `limit` > 1.
void AddStretchLimitTerms(double limit, Model* model);

// The largest length / rest length over the model's springs at `positions`.
double MaxStretchRatio(const Model& model, const double* positions);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_STRETCH_LIMIT_H_
