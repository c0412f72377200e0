#include "src/model/stretch_limit.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "costs/spring_stretch.h"
#include "costs/stretch_limit_barrier.h"
#include "costs/tension_only_spring.h"

namespace drape {

std::vector<SpringLink> ModelSprings(const Model& model) {
  std::vector<SpringLink> springs;
  for (const auto& term : model.terms) {
    double root = 0.0, rest = 0.0;
    if (const auto* spring = FunctorOf<SpringStretch>(*term)) {
      root = spring->sqrt_stiffness;
      rest = spring->rest_length;
    } else if (const auto* tension_only = FunctorOf<TensionOnlySpring>(*term)) {
      root = tension_only->sqrt_stiffness;
      rest = tension_only->rest_length;
    } else {
      continue;
    }
    springs.push_back({term->nodes()[0], term->nodes()[1], rest, root * root});
  }
  return springs;
}

void AddStretchLimitTerms(double limit, Model* model) {
  assert(limit > 1.0);
  for (const SpringLink& spring : ModelSprings(*model)) {
    const double penalty = kStretchLimitPenaltyRatio * spring.stiffness;
    model->terms.push_back(
        MakeTerm("stretch_limit", {spring.a, spring.b},
                 StretchLimitBarrier::Create(penalty, limit * spring.rest_length)));
  }
  model->stretch_limit = limit;
}

double MaxStretchRatio(const Model& model, const double* positions) {
  double largest = 0.0;
  for (const SpringLink& spring : ModelSprings(model)) {
    if (!(spring.rest_length > 0.0)) continue;
    double squared = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = positions[3 * spring.b + c] - positions[3 * spring.a + c];
      squared += d * d;
    }
    largest = std::max(largest, std::sqrt(squared) / spring.rest_length);
  }
  return largest;
}

}  // namespace drape
