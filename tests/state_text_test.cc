// StateText: what drape solve's result line and drape sweep's rows say of the final state. A run
// that stopped short of the tolerance (an iteration or time limit) is not an equilibrium, whatever
// its Hessian: it used to be called a "stable minimum" there.
#include "src/solvers/state_text.h"

#include <gtest/gtest.h>

namespace drape {
namespace {

RunResult Result(bool converged, bool stable, double min_eigenvalue) {
  RunResult result;
  result.converged = converged;
  result.stability.computed = true;
  result.stability.stable = stable;
  result.stability.min_eigenvalue = min_eigenvalue;
  return result;
}

TEST(StateText, AConvergedRunIsAStableMinimumOrASaddle) {
  EXPECT_EQ(StateText(Result(true, true, 0.25)), "stable minimum");
  EXPECT_EQ(StateText(Result(true, false, -0.49)), "saddle: most negative eigenvalue -0.49 N/m");
}

TEST(StateText, ARunThatDidNotConvergeIsNotAnEquilibrium) {
  EXPECT_EQ(StateText(Result(false, true, 0.25)),
            "not an equilibrium (Hessian positive definite there)");
  EXPECT_EQ(StateText(Result(false, false, -0.49)),
            "not an equilibrium (most negative eigenvalue -0.49 N/m)");
}

TEST(StateText, NoVerdictWhereTheStateIsUnsoundOrStabilityWasNotComputed) {
  RunResult unsound = Result(true, true, 0.25);
  unsound.certificate.unsound = "a force is not finite";
  EXPECT_EQ(StateText(unsound), "not certified: a force is not finite");
  RunResult not_computed;
  not_computed.converged = true;
  EXPECT_EQ(StateText(not_computed), "stability not computed");
}

}  // namespace
}  // namespace drape
