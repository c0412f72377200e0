// Conversions of KES-FB and Peirce measurements to the model's SI parameters, each checked against
// a hand calculation written out above it (1 gf = 9.80665e-3 N, 1 cm = 1e-2 m).
#include "src/scene/fabric_parameters.h"

#include <gtest/gtest.h>

namespace drape {
namespace {

// B = 0.12 gf·cm²/cm = 0.12 gf·cm = 0.12 × 9.80665e-3 N × 1e-2 m = 1.176798e-5 N·m.
TEST(FabricParameters, KesBendingRigidityIsGramForceCentimetres) {
  EXPECT_NEAR(KesBendingRigidity(0.12), 1.176798e-5, 1e-11);
  EXPECT_NEAR(KesBendingRigidity(1.0), 9.80665e-5, 1e-15);
}

// G = 0.9 gf/(cm·deg) = 0.9 × 9.80665e-3 N / 1e-2 m = 0.8825985 N/m per degree,
// × 57.2957795 degrees per radian = 50.56916 N/m per radian.
TEST(FabricParameters, KesShearRigidityIsPerRadian) {
  EXPECT_NEAR(KesShearRigidity(0.9), 50.56916, 1e-4);
  EXPECT_NEAR(KesShearRigidity(1.0), 56.18799, 1e-4);
}

// W = 12 mg/cm² = 12e-6 kg / 1e-4 m² = 0.12 kg/m² (120 g/m²).
TEST(FabricParameters, KesWeightIsAnArealDensity) {
  EXPECT_NEAR(KesArealDensity(12.0), 0.12, 1e-15);
}

// Fm = 500 gf/cm = 500 × 9.80665e-3 N / 1e-2 m = 490.3325 N/m. EMT = 4 %, LT = 0.65:
// E = LT Fm / ε_m = 0.65 × 490.3325 / 0.04 = 7967.903 N/m; LT = 1 gives the secant modulus
// 490.3325 / 0.04 = 12258.31 N/m; with Fm = 50 gf/cm (the low-load condition) a tenth of that.
TEST(FabricParameters, KesTensileRigidityFromEmtAndLinearity) {
  EXPECT_NEAR(KesTensileRigidity(4.0, 0.65), 7967.903, 1e-3);
  EXPECT_NEAR(KesTensileRigidity(4.0, 1.0), 12258.31, 1e-2);
  EXPECT_NEAR(KesTensileRigidity(4.0, 1.0, 50.0), 1225.831, 1e-3);
}

// The linear sheet stores the measured tensile energy WT = LT Fm ε_m / 2 at ε_m: ½ E ε_m² = WT.
TEST(FabricParameters, KesTensileRigidityStoresTheMeasuredTensileEnergy) {
  const double emt = 6.5, lt = 0.72;
  const double fm = 500 * kGramForce / 1e-2, strain = emt / 100;
  const double tensile_energy = lt * fm * strain / 2;  // WT, J/m²
  EXPECT_NEAR(0.5 * KesTensileRigidity(emt, lt) * strain * strain, tensile_energy,
              1e-12 * tensile_energy);
}

// Peirce: c = 2 cm, ρ = 0.12 kg/m²: D = ρ g_n c³ = 0.12 × 9.80665 × (0.02)³ = 9.414384e-6 N·m.
TEST(FabricParameters, PeirceBendingRigidityIsWeightTimesBendingLengthCubed) {
  EXPECT_NEAR(PeirceBendingRigidity(2.0, 0.12), 9.414384e-6, 1e-12);
}

// The two routes agree: Peirce's G = W c³ in his units is 12 mg/cm² × 8 cm³ = 96 mg·cm
// = 0.096 gf·cm, which is KES's B in gf·cm²/cm; both must give the same D.
TEST(FabricParameters, PeirceAndKesAgreeOnTheSameFabric) {
  const double weight = 12.0, length = 2.0;                     // mg/cm², cm
  const double b = weight * length * length * length / 1000.0;  // gf·cm
  EXPECT_NEAR(PeirceBendingRigidity(length, KesArealDensity(weight)), KesBendingRigidity(b),
              1e-12 * KesBendingRigidity(b));
}

}  // namespace
}  // namespace drape
