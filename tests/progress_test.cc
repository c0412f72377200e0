// The progress line: rewritten in place, rate-limited, erased at the end.
#include "src/cli/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace drape {
namespace {

IterationRecord Record(int iteration) { return {iteration, 1.5, -2.25, 3e-4}; }

TEST(ProgressLine, RewritesOneLineInPlace) {
  std::ostringstream out;
  ProgressLine progress(out, 0.0);
  EXPECT_TRUE(progress.Update(Record(7)));
  const std::string first = out.str();
  EXPECT_EQ(first.front(), '\r');
  EXPECT_EQ(first.find('\n'), std::string::npos);
  EXPECT_NE(first.find("iteration 7"), std::string::npos);
  EXPECT_NE(first.find("3.000e-04"), std::string::npos);
  EXPECT_NE(first.find("1.5 s"), std::string::npos);
  EXPECT_TRUE(progress.Update(Record(12345)));
  EXPECT_NE(out.str().find("iteration 12345"), std::string::npos);
}

TEST(ProgressLine, ShowsNothingNewUntilTheIntervalHasPassed) {
  std::ostringstream out;
  ProgressLine progress(out, 1e9);  // an interval no test outlives
  progress.Update(Record(1));
  const std::string shown = out.str();
  EXPECT_TRUE(progress.Update(Record(2)));  // never stops the solve
  EXPECT_EQ(out.str(), shown);
}

TEST(ProgressLine, ClearErasesTheLineAndOnlyIfShown) {
  std::ostringstream out;
  ProgressLine progress(out, 0.0);
  progress.Clear();
  EXPECT_TRUE(out.str().empty());
  progress.Update(Record(3));
  const size_t width = out.str().size() - 1;  // without the leading '\r'
  progress.Clear();
  const std::string erased = out.str().substr(width + 1);
  EXPECT_EQ(erased, "\r" + std::string(width, ' ') + "\r");
}

// Without a terminal: a plain line of its own every interval of solving time,
// nothing before the first interval has passed, and nothing to erase.
TEST(ProgressLine, PlainModePrintsALineEveryIntervalOfSolvingTime) {
  std::ostringstream out;
  ProgressLine progress(out, 5.0, /*plain=*/true);
  IterationRecord record;
  for (double t : {0.0, 1.0, 4.9, 5.1, 6.0, 9.0, 10.2, 10.3, 31.0}) {
    record.time_s = t;
    ++record.iteration;
    progress.Update(record);
  }
  progress.Clear();
  const std::string text = out.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;  // at 5.1, 10.2 and 31.0
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("iteration 4 "), std::string::npos) << text;
}

}  // namespace
}  // namespace drape
