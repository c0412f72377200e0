#include "src/sweep/calibration_fit.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace drape {
namespace {

int Count(const CalibrationGrid& grid, size_t axis) {
  return static_cast<int>(grid.axes[axis].size());
}

// The cell of coordinate u along an axis of `count` values, and where u lies in it.
std::pair<int, double> Cell(double u, int count) {
  const int cell = std::clamp(static_cast<int>(std::floor(u)), 0, std::max(0, count - 2));
  return {cell, u - cell};
}

double SumOfSquares(const CalibrationGrid& grid, const std::vector<int>& fabrics,
                    const std::vector<double>& u) {
  double sum = 0.0;
  for (const int f : fabrics) {
    const double delta = InterpolatedDc(grid, f, u) - *grid.measured[f];
    sum += delta * delta;
  }
  return sum;
}

// Whether `u` is at an end of some axis.
bool AtEdge(const CalibrationGrid& grid, const std::vector<double>& u) {
  for (size_t a = 0; a < u.size(); ++a) {
    if (u[a] <= 0.0 || u[a] >= Count(grid, a) - 1) return true;
  }
  return false;
}

}  // namespace

int CalibrationGrid::Points() const {
  int points = 1;
  for (const auto& axis : axes) points *= static_cast<int>(axis.size());
  return points;
}

std::vector<int> CalibrationGrid::Indices(int point) const {
  std::vector<int> indices(axes.size());
  for (size_t a = axes.size(); a-- > 0;) {
    const int count = static_cast<int>(axes[a].size());
    indices[a] = point % count;
    point /= count;
  }
  return indices;
}

int CalibrationGrid::Point(const std::vector<int>& indices) const {
  int point = 0;
  for (size_t a = 0; a < axes.size(); ++a)
    point = point * static_cast<int>(axes[a].size()) + indices[a];
  return point;
}

std::vector<int> FittableFabrics(const CalibrationGrid& grid) {
  std::vector<int> fabrics;
  for (size_t f = 0; f < grid.dc.size(); ++f) {
    bool complete = grid.measured[f].has_value();
    for (const auto& dc : grid.dc[f]) complete = complete && dc.has_value();
    if (complete) fabrics.push_back(static_cast<int>(f));
  }
  return fabrics;
}

double InterpolatedDc(const CalibrationGrid& grid, int fabric, const std::vector<double>& u) {
  const size_t k = grid.axes.size();
  assert(u.size() == k);
  std::vector<std::pair<int, double>> cells(k);
  for (size_t a = 0; a < k; ++a) cells[a] = Cell(u[a], Count(grid, a));
  double sum = 0.0;
  for (int corner = 0; corner < (1 << k); ++corner) {
    std::vector<int> indices(k);
    double weight = 1.0;
    for (size_t a = 0; a < k; ++a) {
      const bool upper = (corner >> a) & 1;
      const auto [cell, t] = cells[a];
      const bool single = Count(grid, a) == 1;
      if (single && upper) weight = 0.0;
      indices[a] = single ? 0 : cell + (upper ? 1 : 0);
      weight *= single ? 1.0 : (upper ? t : 1.0 - t);
    }
    if (weight == 0.0) continue;
    const std::optional<double>& dc = grid.dc[fabric][grid.Point(indices)];
    assert(dc && "FittableFabrics");
    sum += weight * *dc;
  }
  return sum;
}

std::vector<double> ValuesAt(const CalibrationGrid& grid, const std::vector<double>& u) {
  std::vector<double> values(u.size());
  for (size_t a = 0; a < u.size(); ++a) {
    const std::vector<double>& axis = grid.axes[a];
    if (axis.size() == 1) {
      values[a] = axis.front();
      continue;
    }
    const auto [cell, t] = Cell(u[a], Count(grid, a));
    values[a] = axis[cell] + t * (axis[cell + 1] - axis[cell]);
  }
  return values;
}

GridFit FitCalibrationGrid(const CalibrationGrid& grid, const std::vector<int>& fabrics) {
  assert(!fabrics.empty());
  const size_t k = grid.axes.size();
  std::vector<int> samples(k);
  long total = 1;
  for (size_t a = 0; a < k; ++a) {
    samples[a] = (Count(grid, a) - 1) * kFitSubdivisions + 1;
    total *= samples[a];
  }
  GridFit best;
  double lowest = std::numeric_limits<double>::infinity();
  std::vector<double> u(k);
  for (long sample = 0; sample < total; ++sample) {
    long rest = sample;
    for (size_t a = k; a-- > 0;) {
      u[a] = static_cast<double>(rest % samples[a]) / kFitSubdivisions;
      rest /= samples[a];
    }
    const double sum = SumOfSquares(grid, fabrics, u);
    if (sum < lowest) lowest = sum, best.coordinates = u;
  }
  best.values = ValuesAt(grid, best.coordinates);
  best.rms = std::sqrt(lowest / static_cast<double>(fabrics.size()));
  best.at_edge = AtEdge(grid, best.coordinates);
  return best;
}

std::vector<LeftOut> LeaveOneOut(const CalibrationGrid& grid, const std::vector<int>& fabrics) {
  std::vector<LeftOut> results;
  for (const int left : fabrics) {
    std::vector<int> others;
    for (const int f : fabrics) {
      if (f != left) others.push_back(f);
    }
    LeftOut result;
    result.fabric = left;
    result.fit = FitCalibrationGrid(grid, others);
    result.predicted = InterpolatedDc(grid, left, result.fit.coordinates);
    result.difference = result.predicted - *grid.measured[left];
    results.push_back(result);
  }
  return results;
}

}  // namespace drape
