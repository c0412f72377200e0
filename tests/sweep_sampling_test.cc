// The Latin hypercube and the Sobol sequence against their definitions: strata, bounds, seeds, the
// direction numbers' recurrence and the Gray-code construction.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <vector>

#include "src/sweep/sampling.h"

namespace drape {
namespace {

// Every coordinate of every point in [0, 1), and each of the `count` strata [k/count, (k+1)/count)
// of every axis holding exactly `per_stratum` points.
void ExpectStratified(const std::vector<std::vector<double>>& points, int count, int dimensions) {
  ASSERT_EQ(static_cast<int>(points.size()) % count, 0);
  const int per_stratum = static_cast<int>(points.size()) / count;
  for (int d = 0; d < dimensions; ++d) {
    std::vector<int> hits(count, 0);
    for (const auto& point : points) {
      ASSERT_EQ(static_cast<int>(point.size()), dimensions);
      ASSERT_GE(point[d], 0.0);
      ASSERT_LT(point[d], 1.0);
      ++hits[static_cast<int>(point[d] * count)];
    }
    for (int k = 0; k < count; ++k)
      EXPECT_EQ(hits[k], per_stratum) << "axis " << d << ", stratum " << k;
  }
}

TEST(LatinHypercube, EveryStratumOfEveryAxisHoldsOnePoint) {
  for (const int count : {1, 2, 7, 16, 100}) {
    SCOPED_TRACE(count);
    ExpectStratified(LatinHypercube(count, 3, 42), count, 3);
  }
}

TEST(LatinHypercube, TheSeedReproducesTheSampleAndAnotherSeedChangesIt) {
  EXPECT_EQ(LatinHypercube(20, 4, 7), LatinHypercube(20, 4, 7));
  EXPECT_NE(LatinHypercube(20, 4, 7), LatinHypercube(20, 4, 8));
}

TEST(LatinHypercube, PermutationsAreNotTheIdentity) {
  // A "hypercube" whose axes were all sorted would put the points on the diagonal.
  const auto points = LatinHypercube(50, 2, 3);
  int same_stratum = 0;
  for (const auto& p : points)
    same_stratum += static_cast<int>(p[0] * 50) == static_cast<int>(p[1] * 50);
  EXPECT_LT(same_stratum, 10);
}

// m_k of a Sobol dimension from its direction numbers: v_k = m_k / 2^k.
std::vector<std::uint64_t> InitialNumbers(int dimension) {
  const auto v = SobolDirections(dimension);
  std::vector<std::uint64_t> m;
  for (int k = 1; k <= 32; ++k) m.push_back(v[k - 1] >> (32 - k));
  return m;
}

TEST(Sobol, DirectionNumbersFollowTheirPrimitivePolynomials) {
  // Every m_k is odd and below 2^k (each v_k has its lowest set bit at 2^-k: the definition).
  for (int d = 1; d <= kSobolMaxDimensions; ++d) {
    const auto m = InitialNumbers(d);
    for (int k = 1; k <= 32; ++k) {
      EXPECT_EQ(m[k - 1] % 2, 1u) << "dimension " << d << ", k " << k;
      EXPECT_LT(m[k - 1], std::uint64_t{1} << k) << "dimension " << d << ", k " << k;
      EXPECT_EQ(SobolDirections(d)[k - 1] & ((std::uint64_t{1} << (32 - k)) - 1), 0u);
    }
  }
  // Dimension 1: v_k = 2^-k, m_k = 1.
  for (const auto m : InitialNumbers(1)) EXPECT_EQ(m, 1u);
  // Dimension 2, polynomial x + 1 (degree 1): m_k = 2 m_{k-1} xor m_{k-1} = 3 m_{k-1} in GF(2).
  const auto m2 = InitialNumbers(2);
  for (int k = 2; k <= 32; ++k) EXPECT_EQ(m2[k - 1], (2 * m2[k - 2]) ^ m2[k - 2]);
  // Dimension 3, polynomial x^2 + x + 1: m_k = 2 m_{k-1} xor 4 m_{k-2} xor m_{k-2}, from 1, 3.
  const auto m3 = InitialNumbers(3);
  EXPECT_EQ(m3[0], 1u);
  EXPECT_EQ(m3[1], 3u);
  for (int k = 3; k <= 32; ++k) {
    EXPECT_EQ(m3[k - 1], (2 * m3[k - 2]) ^ (4 * m3[k - 3]) ^ m3[k - 3]) << k;
  }
}

TEST(Sobol, PointsAreTheXorOfTheDirectionNumbersOfTheGrayCode) {
  const int count = 300, dimensions = kSobolMaxDimensions;
  const auto points = SobolSequence(count, dimensions, 0);
  ASSERT_EQ(static_cast<int>(points.size()), count);
  for (int d = 0; d < dimensions; ++d) {
    const auto v = SobolDirections(d + 1);
    for (int i = 0; i < count; ++i) {
      const std::uint32_t gray = static_cast<std::uint32_t>(i ^ (i >> 1));
      std::uint32_t x = 0;
      for (int k = 0; k < 32; ++k) {
        if ((gray >> k) & 1u) x ^= v[k];
      }
      EXPECT_EQ(points[i][d], x * 0x1.0p-32) << "point " << i << ", dimension " << d;
    }
  }
  // The first points: the origin, then 1/2 on every axis, then the quarter points.
  for (int d = 0; d < dimensions; ++d) {
    EXPECT_EQ(points[0][d], 0.0);
    EXPECT_EQ(points[1][d], 0.5);
    EXPECT_TRUE(points[2][d] == 0.25 || points[2][d] == 0.75);
    EXPECT_EQ(points[2][d] + points[3][d], 1.0);
  }
  EXPECT_EQ(points[2][0], 0.75);  // van der Corput in Gray-code order: 0, 1/2, 3/4, 1/4
  EXPECT_EQ(points[3][0], 0.25);
}

TEST(Sobol, FirstPowersOfTwoAreStratifiedOnEveryAxis) {
  for (const int count : {2, 8, 64, 512}) {
    SCOPED_TRACE(count);
    ExpectStratified(SobolSequence(count, kSobolMaxDimensions, 0), count, kSobolMaxDimensions);
    ExpectStratified(SobolSequence(count, kSobolMaxDimensions, 11), count, kSobolMaxDimensions);
  }
}

TEST(Sobol, TheFirstTwoDimensionsFormANet) {
  // A (0, m, 2)-net in base 2: every box [a 2^-j, (a+1) 2^-j) × [b 2^-(m-j), (b+1) 2^-(m-j))
  // holds exactly one of the first 2^m points.
  const int m = 8, count = 1 << m;
  const auto points = SobolSequence(count, 2, 0);
  for (int j = 0; j <= m; ++j) {
    std::set<std::pair<int, int>> boxes;
    for (const auto& p : points) {
      boxes.insert({static_cast<int>(p[0] * (1 << j)), static_cast<int>(p[1] * (1 << (m - j)))});
    }
    EXPECT_EQ(static_cast<int>(boxes.size()), count) << "j = " << j;
  }
}

TEST(Sobol, TheSeedShiftsReproducibly) {
  EXPECT_EQ(SobolSequence(16, 3, 5), SobolSequence(16, 3, 5));
  EXPECT_NE(SobolSequence(16, 3, 5), SobolSequence(16, 3, 0));
  EXPECT_NE(SobolSequence(16, 3, 5), SobolSequence(16, 3, 6));
}

}  // namespace
}  // namespace drape
