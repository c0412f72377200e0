// The calibration's fit (src/sweep/calibration_fit.h) on synthetic grids whose "measured" drape
// coefficients come from known constants: it recovers them, its leave-one-out predictions are
// exact where the data are, and it says when the minimum lies at the grid's end.
#include "src/sweep/calibration_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace drape {
namespace {

// A smooth, monotone DC against a bending scale s for fabric f (stiffer fabrics drape higher).
double SyntheticDc(int fabric, double scale) {
  return 0.2 + 0.1 * fabric + 0.15 * std::log(scale) / std::log(3.0);
}

// Fabric f's DC against two constants (a scale and a friction share), separable and monotone.
double SyntheticDc2(int fabric, double scale, double share) {
  return SyntheticDc(fabric, scale) + (0.02 + 0.01 * fabric) * share / 100.0;
}

CalibrationGrid ScaleGrid(int fabrics, double true_scale) {
  CalibrationGrid grid;
  grid.axes = {{1.0 / 2.25, 1.0 / 1.5, 1.0, 1.5, 2.25, 3.375}};
  for (int f = 0; f < fabrics; ++f) {
    std::vector<std::optional<double>> dc;
    for (const double s : grid.axes[0]) dc.push_back(SyntheticDc(f, s));
    grid.dc.push_back(dc);
    grid.measured.push_back(SyntheticDc(f, true_scale));
  }
  return grid;
}

TEST(CalibrationGrid, NumbersPointsWithTheLastConstantFastest) {
  CalibrationGrid grid;
  grid.axes = {{1, 2, 3}, {10, 20}};
  EXPECT_EQ(grid.Points(), 6);
  EXPECT_EQ(grid.Indices(3), (std::vector<int>{1, 1}));
  for (int p = 0; p < grid.Points(); ++p) EXPECT_EQ(grid.Point(grid.Indices(p)), p);
}

// A true value on a grid point is found exactly: the interpolant meets the data there.
TEST(CalibrationFit, RecoversAConstantOnTheGrid) {
  const CalibrationGrid grid = ScaleGrid(5, 1.5);
  const GridFit fit = FitCalibrationGrid(grid, FittableFabrics(grid));
  EXPECT_DOUBLE_EQ(fit.values[0], 1.5);
  EXPECT_NEAR(fit.rms, 0.0, 1e-15);
  EXPECT_FALSE(fit.at_edge);
  for (const LeftOut& left : LeaveOneOut(grid, FittableFabrics(grid))) {
    EXPECT_DOUBLE_EQ(left.fit.values[0], 1.5);
    EXPECT_NEAR(left.difference, 0.0, 1e-15);
  }
}

// Between grid points: within the interpolation's error. The DC is linear in ln s and the
// interpolant linear in s across a step of ratio 1.5, so the s at which the interpolant meets a
// DC is at most 2.1 % from the true one (the largest gap over 1.5–2.25), plus half the search's
// step, 1/80 of 0.75 (0.6 % of 1.5).
TEST(CalibrationFit, RecoversAConstantBetweenGridPointsToTheInterpolationsError) {
  const double truth = 1.8;
  const CalibrationGrid grid = ScaleGrid(4, truth);
  const GridFit fit = FitCalibrationGrid(grid, FittableFabrics(grid));
  EXPECT_NEAR(fit.values[0], truth, (0.021 + 0.0063) * truth);
  EXPECT_LT(fit.rms, 0.005);
}

TEST(CalibrationFit, SaysWhenTheMinimumLiesBeyondTheGrid) {
  const CalibrationGrid grid = ScaleGrid(3, 5.0);
  const GridFit fit = FitCalibrationGrid(grid, FittableFabrics(grid));
  EXPECT_TRUE(fit.at_edge);
  EXPECT_DOUBLE_EQ(fit.values[0], 3.375);
}

TEST(CalibrationFit, RecoversTwoConstants) {
  CalibrationGrid grid;
  grid.axes = {{1.0 / 2.25, 1.0 / 1.5, 1.0, 1.5, 2.25, 3.375}, {0, 12.5, 25, 50, 100, 200}};
  const double scale = 2.25, share = 50.0;
  for (int f = 0; f < 5; ++f) {
    std::vector<std::optional<double>> dc;
    for (int p = 0; p < grid.Points(); ++p) {
      const std::vector<int> i = grid.Indices(p);
      dc.push_back(SyntheticDc2(f, grid.axes[0][i[0]], grid.axes[1][i[1]]));
    }
    grid.dc.push_back(dc);
    grid.measured.push_back(SyntheticDc2(f, scale, share));
  }
  const GridFit fit = FitCalibrationGrid(grid, FittableFabrics(grid));
  EXPECT_DOUBLE_EQ(fit.values[0], scale);
  EXPECT_DOUBLE_EQ(fit.values[1], share);
  EXPECT_NEAR(InterpolatedDc(grid, 2, fit.coordinates), *grid.measured[2], 1e-15);
}

// A fabric without a measurement, or without a counted solve at some point, is not fitted.
TEST(CalibrationFit, FitsOnlyFabricsWithEveryPoint) {
  CalibrationGrid grid = ScaleGrid(4, 1.0);
  grid.measured[1].reset();
  grid.dc[2][3].reset();
  EXPECT_EQ(FittableFabrics(grid), (std::vector<int>{0, 3}));
}

}  // namespace
}  // namespace drape
