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

// FAST's B is Peirce's rigidity in µN·m: W C³ × 9.81e-6 with W in g/m², C in mm (De Boos &
// Tester 1994). A 168 g/m² fabric with C = 15 mm has B = 5.56 µN·m; the same as a bending length.
TEST(FabricParameters, FastBendingRigidityIsPeircesInMicroNewtonMetres) {
  const double w = 168.0, c_mm = 15.0;
  const double b = w * c_mm * c_mm * c_mm * kStandardGravity * 1e-6;  // µN·m
  EXPECT_NEAR(b, 5.56, 0.005);
  EXPECT_NEAR(FastBendingRigidity(b), PeirceBendingRigidity(c_mm / 10, FastArealDensity(w)),
              1e-12 * FastBendingRigidity(b));
  EXPECT_DOUBLE_EQ(FastArealDensity(120.0), KesArealDensity(12.0));
}

// FAST's shear rigidity G = 123/EB5 N/m is the bias strip's T/(4ε) at T = 5 gf/cm.
TEST(FabricParameters, FastShearRigidityIsTheBiasStripsSmallStrainRelation) {
  EXPECT_DOUBLE_EQ(FastShearRigidity(4.7), 123.0 / 4.7);
  const double tension = 5.0 * kGramForce / 1e-2;  // N/m
  EXPECT_NEAR(FastShearRigidity(2.0), tension / (4.0 * 0.02), 0.01 * FastShearRigidity(2.0));
}

// E100's secant modulus: 100 gf/cm over the strain, as KES's EMT with LT = 1 at Fm = 100 gf/cm.
TEST(FabricParameters, FastTensileRigidityIsTheSecantAtOneHundredGramForcePerCentimetre) {
  EXPECT_NEAR(FastTensileRigidity(2.0), 98.0665 / 0.02, 1e-9);
  EXPECT_DOUBLE_EQ(FastTensileRigidity(3.0), KesTensileRigidity(3.0, 1.0, 100.0));
}

// The bias conversion inverts the orthotropic plate's compliance at 45°: a plate of D1, D2, D12,
// D66 has 1/B45 = (S11 + S22 + 2 S12 + 1/D66)/4 with S = [D1 D12; D12 D2]⁻¹ (fabric_parameters.h).
// Written out for D1 = 1e-5, D2 = 0.6e-5, D12 = 0.2e-5, D66 = 0.3e-5 N·m: Δ = 6e-11 − 4e-12 =
// 5.6e-11, S11 = 0.6e-5/Δ = 107142.86, S22 = 1e-5/Δ = 178571.43, S12 = −0.2e-5/Δ = −35714.29,
// 1/D66 = 333333.33, so 4/B45 = 547619.05 and B45 = 7.304348e-6 N·m.
TEST(FabricParameters, BiasTorsionalRigidityInvertsThePlatesCompliance) {
  const double b45 = 4.0 / 547619.05;
  EXPECT_NEAR(b45, 7.304348e-6, 1e-12);
  EXPECT_NEAR(BiasTorsionalRigidity(b45, 1e-5, 0.6e-5, 0.2e-5), 0.3e-5, 1e-12);
}

// An isotropic plate (D1 = D2 = D, D12 = ν D, D66 = D (1 − ν)/2) bends alike in every direction: a
// strip free across has the rigidity D (1 − ν²) (S11 = 1/(D (1 − ν²))) at 0° and at 45° alike,
// which converts back to D66 = D (1 − ν)/2 for any ν.
TEST(FabricParameters, AnIsotropicPlatesBiasGivesItsTorsionalRigidity) {
  const double d = 2e-5;
  for (double nu : {0.0, 0.3}) {
    const double strip = d * (1 - nu * nu);
    EXPECT_NEAR(BiasTorsionalRigidity(strip, d, d, nu * d), d * (1 - nu) / 2, 1e-12 * d) << nu;
  }
}

// No finite D66 makes the bias stiffer than 4/(S11 + S22 + 2 S12), with D12 = 0 twice the harmonic
// mean of D1 and D2: for D1 = 1e-5 and D2 = 0.6e-5 N·m, 4/(1e5 + 166666.67) = 1.5e-5 N·m. At that
// bound D66 is infinite, beyond it negative: the loader refuses both.
TEST(FabricParameters, ABiasStifferThanAnyTwistAllowsIsRecognised) {
  EXPECT_NEAR(StiffestBiasRigidity(1e-5, 0.6e-5, 0.0), 1.5e-5, 1e-15);
  EXPECT_LT(BiasTorsionalRigidity(1.6e-5, 1e-5, 0.6e-5, 0.0), 0.0);
  EXPECT_GT(BiasTorsionalRigidity(1.4e-5, 1e-5, 0.6e-5, 0.0), 0.0);
}

// The default: D66 = √(D_warp D_weft)/3; for a balanced fabric (D1 = D2 = D) a bias rigidity of
// 4/(2/D + 3/D) = 0.8 D, the median bias ratio it is taken from.
TEST(FabricParameters, TheDefaultTwistGivesTheMedianBiasRatio) {
  EXPECT_NEAR(DefaultTorsionalRigidity(1e-5, 0.64e-5), 0.8e-5 / 3.0, 1e-18);
  const double d = 1e-5, d66 = DefaultTorsionalRigidity(d, d);
  const double b45 = 4.0 / (2.0 / d + 1.0 / d66);
  EXPECT_NEAR(b45 / d, 0.8, 1e-12);
}

}  // namespace
}  // namespace drape
