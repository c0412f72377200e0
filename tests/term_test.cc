// AutoDiffTerm: the derivatives of a translation-invariant functor, taken over the relative
// positions x_a − x_0 and mapped back, equal those over all coordinates.
#include "src/model/term.h"

#include <gtest/gtest.h>

#include <vector>

#include "costs/fv_bending.h"
#include "costs/fv_membrane.h"
#include "costs/pressure_potential.h"
#include "costs/spring_stretch.h"
#include "costs/stretch_limit_barrier.h"
#include "costs/tension_only_spring.h"
#include "costs/zero_length_spring.h"
#include "tests/term_checks.h"

namespace drape {
namespace {

template <typename Functor>
void ExpectRelativeDerivativesEqualFullOnes(const Functor& functor, unsigned seed) {
  static_assert(internal::TranslationInvariant<Functor>::value);
  constexpr int kDofs = 3 * Functor::kNumNodes;
  // Nodes near a unit-spaced configuration, so that every spring is taut and every volume regular.
  std::vector<double> positions = testing::RandomPositions(Functor::kNumNodes, 0.3, seed);
  for (int a = 0; a < Functor::kNumNodes; ++a) positions[3 * a] += 1.0 * a;
  const double* x[Functor::kNumNodes];
  for (int a = 0; a < Functor::kNumNodes; ++a) x[a] = positions.data() + 3 * a;
  double energy_full, energy_relative;
  std::vector<double> gradient_full(kDofs), gradient_relative(kDofs);
  std::vector<double> hessian_full(kDofs * kDofs), hessian_relative(kDofs * kDofs);
  ASSERT_TRUE(internal::NestedJetHessian<false>(functor, x, &energy_full, gradient_full.data(),
                                                hessian_full.data()));
  ASSERT_TRUE(internal::NestedJetHessian<true>(functor, x, &energy_relative,
                                               gradient_relative.data(), hessian_relative.data()));
  EXPECT_GT(std::abs(energy_full), 0.0);  // a configuration away from rest: the test can fail
  EXPECT_NEAR(energy_relative, energy_full, 1e-14 * std::abs(energy_full));
  double g_scale = 0.0, h_scale = 0.0;
  for (double g : gradient_full) g_scale = std::max(g_scale, std::abs(g));
  for (double h : hessian_full) h_scale = std::max(h_scale, std::abs(h));
  ASSERT_GT(g_scale, 0.0);
  ASSERT_GT(h_scale, 0.0);
  for (int k = 0; k < kDofs; ++k) {
    EXPECT_NEAR(gradient_relative[k], gradient_full[k], 1e-12 * g_scale) << "gradient " << k;
  }
  for (int k = 0; k < kDofs * kDofs; ++k) {
    EXPECT_NEAR(hessian_relative[k], hessian_full[k], 1e-12 * h_scale) << "Hessian " << k;
  }
}

TEST(AutoDiffTerm, RelativePositionDerivativesEqualAllCoordinateOnes) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    ExpectRelativeDerivativesEqualFullOnes(SpringStretch::Create(100.0, 0.8), seed);
    ExpectRelativeDerivativesEqualFullOnes(TensionOnlySpring::Create(100.0, 0.5), seed);
    ExpectRelativeDerivativesEqualFullOnes(ZeroLengthSpring::Create(30.0), seed);
    ExpectRelativeDerivativesEqualFullOnes(StretchLimitBarrier::Create(10.0, 0.5), seed);
    ExpectRelativeDerivativesEqualFullOnes(FvMembrane::Create(50.0, 30.0, 5.0, 2.0, 0.9, 0.9),
                                           seed);
    ExpectRelativeDerivativesEqualFullOnes(FvBendingEdge::Create(1e-3, 0.5, 0.25), seed);
    ExpectRelativeDerivativesEqualFullOnes(FvBending::Create(1e-3, 2e-3, 1e-4, 0.5, 0.5, 0.25),
                                           seed);
  }
}

TEST(AutoDiffTerm, OnlyDeclaredTranslationInvariantFunctorsTakeTheRelativePath) {
  EXPECT_TRUE(internal::TranslationInvariant<SpringStretch>::value);
  EXPECT_TRUE(internal::TranslationInvariant<FvBending>::value);
  // A pressure segment's energy (swept area about a centre) changes under translation.
  EXPECT_FALSE(internal::TranslationInvariant<PressurePotential>::value);
}

}  // namespace
}  // namespace drape
