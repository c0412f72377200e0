#include "src/cli/progress.h"

#include <cstdio>
#include <string>

namespace drape {

ProgressLine::ProgressLine(std::ostream& out, double min_interval_s)
    : out_(out), min_interval_(min_interval_s) {}

bool ProgressLine::Update(const IterationRecord& record) {
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && now - last_shown_ < min_interval_) return true;
  char text[160];
  std::snprintf(text, sizeof text, "iteration %d  residual %.3e  energy %.9g J  %.1f s",
                record.iteration, record.relative_residual, record.energy, record.time_s);
  std::string line = text;
  const size_t length = line.size();
  if (length < width_) line.append(width_ - length, ' ');  // cover a longer previous line
  out_ << '\r' << line << std::flush;
  width_ = length;
  shown_ = true;
  last_shown_ = now;
  return true;
}

void ProgressLine::Clear() {
  if (!shown_) return;
  out_ << '\r' << std::string(width_, ' ') << '\r' << std::flush;
  shown_ = false;
  width_ = 0;
}

}  // namespace drape
