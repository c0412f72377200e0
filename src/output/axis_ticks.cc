#include "src/output/axis_ticks.h"

#include <cassert>
#include <cmath>

namespace drape {

std::vector<double> AxisTicks(double low, double high, int count) {
  assert(high > low && count >= 1 && "an axis of positive length and a tick count");
  const double raw = (high - low) / count;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * decade;
  for (double factor : {1.0, 2.0, 5.0}) {
    if (factor * decade >= raw) {
      step = factor * decade;
      break;
    }
  }
  std::vector<double> ticks;
  // Each tick is k × step for an integer k, so no error accumulates along the axis.
  for (double k = std::ceil(low / step - 1e-9); k * step <= high + 1e-9 * step; k += 1.0) {
    ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
  }
  return ticks;
}

}  // namespace drape
