// `drape fabrics TABLE --calibrate KEY...`: a laboratory's calibration of drape to its own measured
// fabrics. The named constants (src/scene/calibration.h: bending_scale, bending_power, shear_scale,
// bending_friction_share; one or two of them) are set, in turn, to each point of their grid, and
// the whole table is solved there as `drape fabrics` solves it (OUT/grid/<point>/, each a complete
// fabrics run that a re-run keeps). The constants are then fitted to the measured drape
// coefficients by least squares on the grid's interpolant (src/sweep/calibration_fit.h), each
// fabric is predicted again by the constants fitted to the others alone (leave-one-out: the error
// to expect on a fabric the lab did not calibrate with), and the table is solved once more at the
// fitted constants (OUT/calibrated/), so that "after" is a solve, not an interpolation.
//
// OUT/calibration.yaml is what later runs take (`drape solve|fabrics --calibration FILE`);
// OUT/calibration.csv has a row per fabric (measured, uncalibrated, calibrated, left out);
// OUT/calibration.json the statistics; OUT/report.html predicted against measured before and
// after with the leave-one-out predictions, and each fabric's DC along a single constant's grid.
#ifndef DRAPE_SRC_SWEEP_CALIBRATE_H_
#define DRAPE_SRC_SWEEP_CALIBRATE_H_

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "src/scene/calibration.h"
#include "src/sweep/calibration_fit.h"
#include "src/sweep/fabrics.h"

namespace drape {

// The most constants one calibration fits: its grid has 6^k points, each a solve of the table.
constexpr int kMostCalibratedConstants = 2;

// The constants `names` ask for, checked: known (the nearest named otherwise), distinct, at most
// kMostCalibratedConstants, and `options` otherwise fit for a calibration (no --calibration, no
// --only). Throws InputError located at `--calibrate`.
std::vector<const CalibrationConstant*> CalibratedConstants(const FabricsOptions& options);

// The fewest measured fabrics a calibration of `constants` constants needs: each leave-one-out
// fit keeps one more fabric than it has constants.
inline int FewestCalibrationFabrics(int constants) { return constants + 2; }

struct CalibrateSummary {
  std::string directory;
  std::vector<std::string> constants;
  Calibration fitted;  // the constants' fitted values
  GridFit fit;         // to every fittable fabric
  std::vector<std::string> fabric_names;
  std::vector<std::optional<double>> measured;
  std::vector<std::optional<double>> uncalibrated, calibrated;  // solved DCs, per fabric
  std::vector<double> calibrated_error;                         // the calibrated solve's bar
  std::vector<std::optional<LeftOut>> left_out;                 // per fabric
  CalibrationGrid grid;
  FabricStatistics before, after, leave_one_out;
  int fitted_fabrics = 0;
  int solves = 0;       // this run's, over the grid and the calibrated table
  std::string problem;  // why nothing was fitted ("" when it was)
  bool interrupted = false;
  bool coordinator = true;
};

// Solves the grid and the calibrated table, fits and writes OUT. Throws InputError (before any
// solve) for bad constants or a table with too few measured fabrics, std::runtime_error when OUT
// cannot be written.
CalibrateSummary RunCalibrate(const FabricsOptions& options, std::ostream& log);

// "calibrated bending_scale 1.62 to 7 fabrics: mean |Δ| 0.085 → 0.041, leave-one-out 0.048".
std::string CalibrateLine(const CalibrateSummary& summary);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_CALIBRATE_H_
