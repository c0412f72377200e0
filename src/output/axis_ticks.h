// The tick values of a plot's axis: one rule for every picture drape draws itself (fit.svg's
// views, the drops report's profile and histogram), so that their axes read alike.
#ifndef DRAPE_SRC_OUTPUT_AXIS_TICKS_H_
#define DRAPE_SRC_OUTPUT_AXIS_TICKS_H_

#include <vector>

namespace drape {

// The ticks over [low, high] (high > low, count ≥ 1): the multiples in it of the smallest step of
// 1, 2 or 5 × 10^k that is at least (high − low)/count: the step is at most 2.5 times that, so
// there are count/2.5 to count + 1 ticks (2 to 6 for the default 5). Zero is 0, never −0.
std::vector<double> AxisTicks(double low, double high, int count = 5);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_AXIS_TICKS_H_
