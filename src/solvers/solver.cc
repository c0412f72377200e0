#include "src/solvers/solver.h"

#include <atomic>
#include <csignal>
#include <cstdio>

#include "src/numerics/round_off_floor.h"

namespace drape {

namespace {
volatile std::sig_atomic_t interrupt_signal = 0;
void OnInterrupt(int signal) { interrupt_signal = signal; }
}  // namespace

bool InterruptRequested() { return interrupt_signal != 0; }
int InterruptSignal() { return interrupt_signal; }
void RequestInterrupt() { interrupt_signal = SIGINT; }
void ClearInterrupt() { interrupt_signal = 0; }
void InstallInterruptHandler() {
  std::signal(SIGINT, OnInterrupt);
  std::signal(SIGTERM, OnInterrupt);
}

const SolverInfo* FindSolver(const std::string& name) {
  for (const auto& info : AllSolvers()) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

IterationMonitor::IterationMonitor(const Model& model, const SolverOptions& options,
                                   SolverSummary* summary)
    : model_(model),
      options_(options),
      summary_(summary),
      floor_(model),
      start_(std::chrono::steady_clock::now()) {
  summary_->converged = false;
  summary_->termination.clear();
  summary_->history.clear();
}

double IterationMonitor::ElapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void IterationMonitor::Stop(const std::string& termination) {
  summary_->termination = termination;
  summary_->wall_time_s = ElapsedSeconds();
}

void IterationMonitor::StopStalled(double relative_residual, const std::string& termination) {
  const double floor = floor_.At(model_.positions.data());
  if (std::isfinite(relative_residual) && relative_residual <= kFloorFactor * floor) {
    summary_->residual_floor = floor;
    ConvergeAtFloor(relative_residual);
    summary_->wall_time_s = ElapsedSeconds();
    return;
  }
  Stop(termination);
}

void IterationMonitor::ConvergeAtFloor(double relative_residual) {
  summary_->converged = true;
  char text[240];
  std::snprintf(text, sizeof text,
                "at the round-off floor (≈ %.3g); tolerance %.3g is below what double precision "
                "can certify (relative residual %.3g)",
                summary_->residual_floor, options_.tolerance, relative_residual);
  summary_->termination = text;
}

bool IterationMonitor::AtRoundOffFloor(int iteration, double relative_residual) {
  if (relative_residual < 0.5 * stagnation_mark_ || iteration == 0) {
    stagnation_mark_ = relative_residual;
    stagnation_iteration_ = iteration;
    stagnation_wait_ = kStagnantIterations;
    return false;
  }
  if (iteration - stagnation_iteration_ < stagnation_wait_) return false;
  stagnation_iteration_ = iteration;  // check again after twice as many (the check costs a Hessian)
  stagnation_wait_ *= 2;
  const double floor = floor_.At(model_.positions.data());
  if (!(relative_residual <= kFloorFactor * floor)) return false;
  summary_->residual_floor = floor;
  return true;
}

bool IterationMonitor::Record(int iteration, double energy, double relative_residual,
                              bool may_converge) {
  IterationRecord record{iteration, ElapsedSeconds(), energy, relative_residual};
  summary_->history.push_back(record);
  summary_->iterations = iteration;
  summary_->wall_time_s = record.time_s;
  const bool caller_continues = !options_.on_iteration || options_.on_iteration(record);
  char text[240];
  if (may_converge && relative_residual <= options_.tolerance) {
    summary_->converged = true;
    std::snprintf(text, sizeof text, "relative residual %.3g reached the tolerance %.3g",
                  relative_residual, options_.tolerance);
    summary_->termination = text;
    return true;
  }
  if (may_converge && std::isfinite(relative_residual) &&
      AtRoundOffFloor(iteration, relative_residual)) {
    ConvergeAtFloor(relative_residual);
    return true;
  }
  if (!caller_continues) {
    summary_->termination = kStoppedByCaller;
    return true;
  }
  if (InterruptRequested()) {
    summary_->termination =
        InterruptSignal() == SIGTERM ? "interrupted (SIGTERM)" : "interrupted (SIGINT)";
    return true;
  }
  if (iteration >= options_.max_iterations) {
    std::snprintf(text, sizeof text, "iteration limit %d reached (relative residual %.3g)",
                  options_.max_iterations, relative_residual);
    summary_->termination = text;
    return true;
  }
  if (record.time_s >= options_.time_limit) {
    std::snprintf(text, sizeof text, "time limit %.3g s reached (relative residual %.3g)",
                  options_.time_limit, relative_residual);
    summary_->termination = text;
    return true;
  }
  return false;
}

}  // namespace drape
