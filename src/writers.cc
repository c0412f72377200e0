#include "src/writers.h"

namespace drape {
void WriteOutputs(const Scene& scene, const Model& model, const RunResult& result,
                  const std::string& directory) {}
}  // namespace drape
