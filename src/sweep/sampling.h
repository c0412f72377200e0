// Space-filling samples of the unit cube for `drape sweep`'s `sample:` designs: a Latin hypercube
// and the Sobol sequence, each written from its definition, reproducible from a seed on every
// platform (the random numbers come from std::mt19937_64, whose output the C++ standard fixes; no
// std:: distribution or shuffle is used, since their algorithms are the library's choice).
#ifndef DRAPE_SRC_SWEEP_SAMPLING_H_
#define DRAPE_SRC_SWEEP_SAMPLING_H_

#include <cstdint>
#include <vector>

namespace drape {

// A Latin hypercube of `count` points in [0, 1)^dimensions (McKay, Beckman & Conover 1979): along
// every axis the `count` intervals [k/count, (k+1)/count) hold exactly one point each. For each
// axis in turn: a uniformly random permutation π (Fisher–Yates), then point i's coordinate is
// (π(i) + U)/count with U uniform in [0, 1), all drawn from one std::mt19937_64 seeded with `seed`.
std::vector<std::vector<double>> LatinHypercube(int count, int dimensions, std::uint64_t seed);

// The largest number of dimensions SobolSequence supports (the Joe–Kuo direction numbers it
// holds).
constexpr int kSobolMaxDimensions = 10;

// The first `count` points of the Sobol sequence in [0, 1)^dimensions (I. M. Sobol 1967), with the
// direction numbers of S. Joe and F. Y. Kuo ("Constructing Sobol sequences with better
// two-dimensional projections", SIAM J. Sci. Comput. 30, 2635–2654, 2008; their table
// new-joe-kuo-6.21201) for dimensions 2–10 and v_k = 2^-k for the first, 32 bits, points in Gray
// code order (Antonov & Saleev 1979), so point 0 is the origin. `seed` 0 gives the plain sequence;
// another seed XORs every coordinate with a random 32-bit number per dimension (a random digital
// shift, which keeps the sequence's stratification). Requires 1 <= dimensions <=
// kSobolMaxDimensions and count < 2^32.
std::vector<std::vector<double>> SobolSequence(int count, int dimensions, std::uint64_t seed);

// The direction numbers v_1..v_32 of `dimension` (1-based), as 32-bit integers (v_k's bits are the
// binary fraction, v_k / 2^32): exposed for tests.
std::vector<std::uint32_t> SobolDirections(int dimension);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_SAMPLING_H_
