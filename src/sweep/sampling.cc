#include "src/sweep/sampling.h"

#include <cassert>
#include <random>

namespace drape {

namespace {

// A uniform number in [0, 1) from the top 53 bits of one draw.
double Uniform(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

// A uniform integer in [0, bound), without the bias of a plain modulo (draws above the largest
// multiple of `bound` are rejected).
std::uint64_t UniformBelow(std::mt19937_64& random, std::uint64_t bound) {
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % bound;
  std::uint64_t draw = random();
  while (draw >= limit) draw = random();
  return draw % bound;
}

// One row of Joe and Kuo's table: the degree s of the primitive polynomial, its inner
// coefficients a (bits a_1..a_{s-1}, a_1 the most significant) and the initial m_1..m_s.
struct DirectionRow {
  int degree;
  unsigned coefficients;
  std::vector<std::uint32_t> initial;
};

// Dimensions 2..10 of new-joe-kuo-6.21201.
const std::vector<DirectionRow>& JoeKuoRows() {
  static const std::vector<DirectionRow> rows = {
      {1, 0, {1}},
      {2, 1, {1, 3}},
      {3, 1, {1, 3, 1}},
      {3, 2, {1, 1, 1}},
      {4, 1, {1, 1, 3, 3}},
      {4, 4, {1, 3, 5, 13}},
      {5, 2, {1, 1, 5, 5, 17}},
      {5, 4, {1, 1, 5, 5, 5}},
      {5, 7, {1, 1, 7, 11, 19}},
  };
  return rows;
}

}  // namespace

std::vector<std::vector<double>> LatinHypercube(int count, int dimensions, std::uint64_t seed) {
  assert(count >= 1 && dimensions >= 1);
  std::mt19937_64 random(seed);
  std::vector<std::vector<double>> points(count, std::vector<double>(dimensions));
  std::vector<int> permutation(count);
  for (int d = 0; d < dimensions; ++d) {
    for (int i = 0; i < count; ++i) permutation[i] = i;
    for (int i = count - 1; i > 0; --i) {
      const auto j = static_cast<int>(UniformBelow(random, static_cast<std::uint64_t>(i) + 1));
      std::swap(permutation[i], permutation[j]);
    }
    for (int i = 0; i < count; ++i) points[i][d] = (permutation[i] + Uniform(random)) / count;
  }
  return points;
}

std::vector<std::uint32_t> SobolDirections(int dimension) {
  assert(dimension >= 1 && dimension <= kSobolMaxDimensions);
  std::vector<std::uint32_t> v(33, 0);  // v[1..32]
  if (dimension == 1) {
    for (int k = 1; k <= 32; ++k) v[k] = std::uint32_t{1} << (32 - k);
    return {v.begin() + 1, v.end()};
  }
  const DirectionRow& row = JoeKuoRows()[dimension - 2];
  const int s = row.degree;
  for (int k = 1; k <= s && k <= 32; ++k) v[k] = row.initial[k - 1] << (32 - k);
  // The recurrence of the primitive polynomial x^s + a_1 x^{s-1} + ... + a_{s-1} x + 1:
  // v_k = a_1 v_{k-1} ^ a_2 v_{k-2} ^ ... ^ a_{s-1} v_{k-s+1} ^ v_{k-s} ^ (v_{k-s} >> s).
  for (int k = s + 1; k <= 32; ++k) {
    std::uint32_t value = v[k - s] ^ (v[k - s] >> s);
    for (int j = 1; j < s; ++j) {
      if ((row.coefficients >> (s - 1 - j)) & 1u) value ^= v[k - j];
    }
    v[k] = value;
  }
  return {v.begin() + 1, v.end()};
}

std::vector<std::vector<double>> SobolSequence(int count, int dimensions, std::uint64_t seed) {
  assert(count >= 1 && dimensions >= 1 && dimensions <= kSobolMaxDimensions);
  std::vector<std::vector<std::uint32_t>> directions;
  for (int d = 1; d <= dimensions; ++d) directions.push_back(SobolDirections(d));
  std::vector<std::uint32_t> shift(dimensions, 0);
  if (seed != 0) {
    std::mt19937_64 random(seed);
    for (auto& bits : shift) bits = static_cast<std::uint32_t>(random() >> 32);
  }
  std::vector<std::vector<double>> points(count, std::vector<double>(dimensions));
  std::vector<std::uint32_t> x(dimensions, 0);
  for (int i = 0; i < count; ++i) {
    if (i > 0) {
      // Gray code order: point i differs from point i-1 by the direction number of the lowest
      // zero bit of i-1.
      int c = 0;
      for (std::uint32_t n = static_cast<std::uint32_t>(i - 1); n & 1u; n >>= 1) ++c;
      for (int d = 0; d < dimensions; ++d) x[d] ^= directions[d][c];
    }
    for (int d = 0; d < dimensions; ++d) points[i][d] = (x[d] ^ shift[d]) * 0x1.0p-32;
  }
  return points;
}

}  // namespace drape
