// What the certificate says of a run's final state, in words: drape solve's result line and
// drape sweep's `certificate` column.
#ifndef DRAPE_SRC_RUN_STATE_TEXT_H_
#define DRAPE_SRC_RUN_STATE_TEXT_H_

#include <string>

#include "src/run/run.h"

namespace drape {

// "fabric through the support disk (…)" where edges pass through a support disk, "fabric through
// itself (…)" where a triangle's side crosses another triangle (src/model/self_intersection.h),
// or both joined by "; " (the state is no drape, whatever the Hessian says); otherwise
// "stable minimum" or "saddle: most negative eigenvalue … N/m" for a converged run; for one that
// did not converge, "not an equilibrium" with what the Hessian shows there (a state whose Hessian
// is positive definite but whose forces do not balance is no minimum); "not certified: …" or
// "stability not computed" where there is no verdict.
std::string StateText(const RunResult& result);

}  // namespace drape

#endif  // DRAPE_SRC_RUN_STATE_TEXT_H_
