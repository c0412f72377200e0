#include "src/solvers/solver.h"

#include <atomic>
#include <csignal>
#include <cstdio>

namespace drape {

namespace {
std::atomic<bool> interrupt_requested{false};
void OnInterrupt(int) { interrupt_requested = true; }
}  // namespace

bool InterruptRequested() { return interrupt_requested; }
void RequestInterrupt() { interrupt_requested = true; }
void ClearInterrupt() { interrupt_requested = false; }
void InstallInterruptHandler() { std::signal(SIGINT, OnInterrupt); }

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

bool IterationMonitor::Record(int iteration, double energy, double relative_residual) {
  IterationRecord record{iteration, ElapsedSeconds(), energy, relative_residual};
  summary_->history.push_back(record);
  summary_->iterations = iteration;
  summary_->wall_time_s = record.time_s;
  const bool caller_continues = !options_.on_iteration || options_.on_iteration(record);
  char text[160];
  if (relative_residual <= options_.tolerance) {
    summary_->converged = true;
    std::snprintf(text, sizeof text, "relative residual %.3g reached the tolerance %.3g",
                  relative_residual, options_.tolerance);
    summary_->termination = text;
    return true;
  }
  if (!caller_continues) {
    summary_->termination = "stopped by caller";
    return true;
  }
  if (InterruptRequested()) {
    summary_->termination = "interrupted (SIGINT)";
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
