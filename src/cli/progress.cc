#include "src/cli/progress.h"

#include <cstdio>
#include <string>

namespace drape {

ProgressLine::ProgressLine(std::ostream& out, double min_interval_s, bool plain)
    : out_(out), min_interval_(min_interval_s), plain_(plain) {}

bool ProgressLine::Update(const IterationRecord& record) {
  const auto now = std::chrono::steady_clock::now();
  // A plain line only once the solve has run for an interval (short solves print nothing).
  if (plain_ && record.time_s < (reports_ + 1) * min_interval_.count()) return true;
  if (!plain_ && shown_ && now - last_shown_ < min_interval_) return true;
  char text[160];
  std::snprintf(text, sizeof text, "iteration %d  residual %.3e  energy %.9g J  %.1f s",
                record.iteration, record.relative_residual, record.energy, record.time_s);
  if (plain_) {
    out_ << "drape: " << text << std::endl;
    reports_ = static_cast<int>(record.time_s / min_interval_.count());
    shown_ = true;
    last_shown_ = now;
    return true;
  }
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
  if (!shown_ || plain_) return;
  out_ << '\r' << std::string(width_, ' ') << '\r' << std::flush;
  shown_ = false;
  width_ = 0;
}

}  // namespace drape
