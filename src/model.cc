#include "src/model.h"

namespace drape {
int Model::num_free_dofs() const {
  int count = 0;
  for (char f : fixed) count += f ? 0 : 1;
  return count;
}
std::map<std::string, int> Model::TermCounts() const {
  std::map<std::string, int> counts;
  for (const auto& term : terms) ++counts[term->type()];
  return counts;
}
Model BuildModel(const Scene& scene) {
  throw InputError(scene.root, "models are not implemented yet");
}
}  // namespace drape
