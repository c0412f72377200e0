#include "src/stability.h"

namespace drape {
Stability AnalyseStability(const Model& model, const double* positions) { return Stability{}; }
}  // namespace drape
