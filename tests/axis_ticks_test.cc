#include "src/output/axis_ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace drape {
namespace {

TEST(AxisTicks, AreRoundAndCoverTheRange) {
  const std::vector<double> ticks = AxisTicks(-0.013, 0.25);  // a fifth: 0.0526 → step 0.1
  ASSERT_EQ(ticks.size(), 3u);
  EXPECT_EQ(ticks[0], 0.0);
  EXPECT_NEAR(ticks[1], 0.1, 1e-15);
  EXPECT_NEAR(ticks[2], 0.2, 1e-15);
  const std::vector<double> fine = AxisTicks(1.0, 1.001);  // step 2e-4
  ASSERT_EQ(fine.size(), 6u);
  EXPECT_NEAR(fine.front(), 1.0, 1e-12);
  EXPECT_NEAR(fine.back(), 1.001, 1e-12);
}

TEST(AxisTicks, FollowTheAskedCount) {
  // An eighth of 360° is 45°: the step is 50°, and 0 to 350° are its multiples in the range.
  const std::vector<double> angles = AxisTicks(0.0, 360.0, 8);
  ASSERT_EQ(angles.size(), 8u);
  for (size_t k = 0; k < angles.size(); ++k) EXPECT_EQ(angles[k], 50.0 * k);
  // A range that starts below zero: zero is a tick, written as 0 and not −0.
  const std::vector<double> across = AxisTicks(-3.0, 3.0, 3);  // a third: 2 → step 2
  ASSERT_EQ(across.size(), 3u);
  EXPECT_EQ(across[1], 0.0);
  EXPECT_FALSE(std::signbit(across[1]));
  EXPECT_EQ(across.front(), -2.0);
  EXPECT_EQ(across.back(), 2.0);
}

}  // namespace
}  // namespace drape
