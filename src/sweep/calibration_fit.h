// The fit behind `drape fabrics --calibrate` (src/sweep/calibrate.h), apart from the solves: each
// fabric's drape coefficient solved on a grid of the calibrated constants' values, read between
// the grid's points by multilinear interpolation (piecewise linear along each constant, in the
// grid's own steps), and the constants chosen to minimise the sum over the fabrics of
// (predicted − measured)². The minimum is searched on a dense sub-grid of the interpolant
// (kFitSubdivisions points per grid step along each constant): it is the interpolant's, found to
// 1/kFitSubdivisions of a step, which is finer than the interpolation's own error.
//
// Leave-one-out: each measured fabric's DC predicted by the constants fitted to the others alone,
// which is the error a lab should expect on a fabric it did not calibrate with.
#ifndef DRAPE_SRC_SWEEP_CALIBRATION_FIT_H_
#define DRAPE_SRC_SWEEP_CALIBRATION_FIT_H_

#include <optional>
#include <vector>

namespace drape {

constexpr int kFitSubdivisions = 40;

struct CalibrationGrid {
  std::vector<std::vector<double>> axes;  // each constant's values, increasing
  // dc[fabric][point]: the fabric's DC at grid point `point`, none where it has no counted solve.
  // Points are numbered with the last constant's index fastest.
  std::vector<std::vector<std::optional<double>>> dc;
  std::vector<std::optional<double>> measured;  // per fabric

  int Points() const;
  std::vector<int> Indices(int point) const;  // each constant's index of grid point `point`
  int Point(const std::vector<int>& indices) const;
};

// The fabrics a fit can use: measured, with a counted solve at every grid point.
std::vector<int> FittableFabrics(const CalibrationGrid& grid);

// Fabric `fabric`'s DC at grid coordinates `u` (each in [0, its count − 1]; integer on a point).
double InterpolatedDc(const CalibrationGrid& grid, int fabric, const std::vector<double>& u);

// The constants' values at grid coordinates `u`.
std::vector<double> ValuesAt(const CalibrationGrid& grid, const std::vector<double>& u);

struct GridFit {
  std::vector<double> coordinates;  // grid coordinates of the minimum
  std::vector<double> values;       // the constants there
  double rms = 0.0;                 // of predicted − measured over the fitted fabrics
  bool at_edge = false;             // a constant at its grid's end: the minimum may lie beyond
};

// The least-squares constants for `fabrics` (FittableFabrics' indices; at least one).
GridFit FitCalibrationGrid(const CalibrationGrid& grid, const std::vector<int>& fabrics);

struct LeftOut {
  int fabric = 0;
  GridFit fit;              // to the other fabrics
  double predicted = 0.0;   // the left-out fabric's DC at their constants
  double difference = 0.0;  // predicted − measured
};

// One fit per fabric of `fabrics`, to the others.
std::vector<LeftOut> LeaveOneOut(const CalibrationGrid& grid, const std::vector<int>& fabrics);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_CALIBRATION_FIT_H_
