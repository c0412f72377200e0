// The solver interface: every method takes a Model and Options and returns a Summary. Methods are
// described in the catalogue (src/scene/solver_methods.h; `drape solvers` prints it) and their
// code is registered under the same names (solver_registry.cc).
#ifndef DRAPE_SRC_SOLVERS_SOLVER_H_
#define DRAPE_SRC_SOLVERS_SOLVER_H_

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/numerics/round_off_floor.h"
#include "src/numerics/sparse_hessian.h"

namespace drape {

struct IterationRecord {
  int iteration = 0;
  double time_s = 0.0;             // since the solve started
  double energy = 0.0;             // J
  double relative_residual = 0.0;  // ‖free residual forces‖ / reference force
};

// The termination of a solve that SolverOptions::on_iteration stopped.
inline constexpr char kStoppedByCaller[] = "stopped by caller";

struct SolverOptions {
  double tolerance = 1e-8;  // relative residual to reach
  int max_iterations = 1000;
  double time_limit = 600.0;  // s
  // solver.<method>.<key> as given; the solver reads each through MethodOptionValue
  // (src/scene/solver_methods.h), which supplies the registered default.
  std::map<std::string, double> method_options;
  // Called after every iteration, with model.positions at the current iterate. Returning false
  // stops the solve (termination kStoppedByCaller).
  std::function<bool(const IterationRecord&)> on_iteration;
  // The model's free Hessian and its CHOLMOD analysis, when the caller has built them (RunSolve,
  // which certifies the answer in them afterwards): a solver that assembles or factorises the
  // Hessian uses these instead of building its own. May be null.
  HessianWorkspace* workspace = nullptr;
};

struct SolverSummary {
  std::string solver;
  bool converged = false;
  std::string termination;  // why it stopped, in words
  int iterations = 0;
  double wall_time_s = 0.0;
  std::vector<IterationRecord> history;
  // Extra per-method figures worth reporting (e.g. "factorizations"), written to summary.json.
  std::map<std::string, double> statistics;
  // The round-off floor of the relative residual where the solve stopped on it (else 0).
  double residual_floor = 0.0;
  // Forces of a constraint the method enforces besides the energy (Provot's stretch limit), on
  // each node at the final positions, 3 per node, N; empty if none. The certificate counts them.
  std::vector<double> constraint_forces;
  // A per-step series beyond the history (the dynamic scheme's kinetic energy, written to
  // kinetic_<method>.csv, src/scene/output_kinds.h): column names, then one row per step.
  std::vector<std::string> trace_columns;
  std::vector<std::vector<double>> trace;
};

class Solver {
 public:
  virtual ~Solver() = default;
  // Moves model.positions towards equilibrium; leaves there the last (best) iterate.
  virtual SolverSummary Solve(Model& model, const SolverOptions& options) const = 0;
};

// The code of one method; its description and options are in the catalogue under the same name
// (src/scene/solver_methods.h).
struct SolverInfo {
  std::string name;
  std::function<std::unique_ptr<Solver>()> make;
  // Whether the method assembles and factorises the free Hessian (SolverOptions::workspace):
  // RunSolve then builds the workspace before the solve, else only after it, for the certificate.
  bool uses_hessian_workspace = false;
};

const std::vector<SolverInfo>& AllSolvers();
const SolverInfo* FindSolver(const std::string& name);

// Shared stopping rule and history: every solver calls Record() once per iteration (iteration 0
// is the start), with model.positions at the iterate, and stops when it returns true. It stops on
// the relative residual, the round-off floor, the iteration and time limits, an interrupt (SIGINT
// or SIGTERM), or the caller's callback, and says which in the summary.
//
// The round-off floor: when the residual has not halved for kStagnantIterations iterations, the
// floor is estimated at the iterate (src/numerics/round_off_floor.h); a residual above the
// tolerance but within kFloorFactor of the floor stops the solve, converged (the tolerance is
// below what double precision can certify; the summary says so and records the floor).
class IterationMonitor {
 public:
  static constexpr int kStagnantIterations = 20;
  IterationMonitor(const Model& model, const SolverOptions& options, SolverSummary* summary);
  // `may_converge` false: the residual criterion does not stop the solve at this iterate (a
  // method that has found it to be a saddle and moves on).
  bool Record(int iteration, double energy, double relative_residual, bool may_converge = true);
  // Whether `relative_residual` meets the tolerance.
  bool Reached(double relative_residual) const { return relative_residual <= options_.tolerance; }
  double ElapsedSeconds() const;
  // For a method that stops for its own reason (a line search failing, a non-finite step).
  void Stop(const std::string& termination);
  // For a method that can make no more progress: converged at the round-off floor if the
  // residual is within kFloorFactor of it (measured here), else Stop(termination).
  void StopStalled(double relative_residual, const std::string& termination);

 private:
  const Model& model_;
  const SolverOptions& options_;
  bool AtRoundOffFloor(int iteration, double relative_residual);
  // Marks the summary converged at the floor summary_->residual_floor, saying so.
  void ConvergeAtFloor(double relative_residual);

  SolverSummary* summary_;
  ResidualFloorEstimator floor_;
  std::chrono::steady_clock::time_point start_;
  double stagnation_mark_ = INFINITY;  // residual at the last halving
  int stagnation_iteration_ = 0;       // iteration of the last halving (or floor check)
  int stagnation_wait_ = kStagnantIterations;
};

// Set by the SIGINT and SIGTERM handler that the command installs; solvers stop at the next
// iteration and the last iterate is written, marked interrupted. InterruptSignal: the signal
// received (SIGINT when requested by RequestInterrupt), 0 if none.
bool InterruptRequested();
int InterruptSignal();
void RequestInterrupt();
// For a command that goes on after an interrupt stopped one stage (drape fit's closing solves).
void ClearInterrupt();
void InstallInterruptHandler();

}  // namespace drape

#endif  // DRAPE_SRC_SOLVERS_SOLVER_H_
