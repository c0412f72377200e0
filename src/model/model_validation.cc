// ValidateModel: the checks that keep ceres::Problem from aborting the process.
#include <algorithm>
#include <cassert>
#include <cstdio>
#include <cstdlib>

#include "src/model/model.h"

namespace drape {

namespace {
[[noreturn]] void Fail(const char* what) {
  std::fprintf(stderr, "drape: internal error: invalid model: %s\n", what);
  std::abort();
}
}  // namespace

void ValidateModel(const Model& model) {
  const size_t dofs = static_cast<size_t>(model.num_dofs());
  if (model.positions.size() != dofs || model.initial.size() != dofs ||
      model.fixed.size() != dofs || model.applied.size() != dofs ||
      model.mass.size() != static_cast<size_t>(model.num_nodes)) {
    Fail("storage is not sized 3 per node");
  }
  for (const auto& term : model.terms) {
    std::vector<int> nodes = term->nodes();
    for (int node : nodes) {
      if (node < 0 || node >= model.num_nodes) Fail("a term refers to a node out of range");
    }
    std::sort(nodes.begin(), nodes.end());
    if (std::adjacent_find(nodes.begin(), nodes.end()) != nodes.end()) {
      Fail("a term uses the same node twice");
    }
  }
}

}  // namespace drape
