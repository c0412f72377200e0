// One equilibrium run: solve a model with a named method, then certify the result afresh.
#ifndef DRAPE_SRC_SOLVERS_RUN_H_
#define DRAPE_SRC_SOLVERS_RUN_H_

#include <functional>
#include <string>

#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "src/scene/scene.h"
#include "src/solvers/solver.h"
#include "src/numerics/stability.h"

namespace drape {

struct RunResult {
  SolverSummary summary;    // what the solver says
  Certificate certificate;  // recomputed at the final positions
  Stability stability;
  bool converged = false;  // the solver's claim, confirmed by the certificate
};

// Solves with scene.solver (method, tolerance, limits, method options). `on_iteration` may be
// empty. Throws InputError if the method is unknown or refuses the model (e.g. too large).
RunResult RunSolve(const Scene& scene, Model& model, const std::string& method,
                   const std::function<bool(const IterationRecord&)>& on_iteration = {});

}  // namespace drape

#endif  // DRAPE_SRC_SOLVERS_RUN_H_
