// The one-line progress report of a long solve: iteration, relative residual, energy and elapsed
// time, rewritten in place (carriage return) at most a few times a second on a terminal; without
// one (batch jobs), a plain line every few seconds.
#ifndef DRAPE_SRC_CLI_PROGRESS_H_
#define DRAPE_SRC_CLI_PROGRESS_H_

#include <chrono>
#include <ostream>

#include "src/solvers/solver.h"

namespace drape {

class ProgressLine {
 public:
  // `min_interval_s`: the least time between two reports (0.2 s: five a second). `plain`: for a
  // log rather than a terminal, each report is a line of its own (no carriage return).
  explicit ProgressLine(std::ostream& out, double min_interval_s = 0.2, bool plain = false);
  // Reports `record` unless the last report is too recent. Returns true (never stops a solve), so
  // it can serve as SolverOptions::on_iteration.
  bool Update(const IterationRecord& record);
  // Erases the line if anything was shown.
  void Clear();

 private:
  std::ostream& out_;
  const std::chrono::duration<double> min_interval_;
  std::chrono::steady_clock::time_point last_shown_;
  const bool plain_;
  int reports_ = 0;  // plain: intervals of solving time covered by the lines so far
  bool shown_ = false;
  size_t width_ = 0;  // length of the line on screen
};

}  // namespace drape

#endif  // DRAPE_SRC_CLI_PROGRESS_H_
