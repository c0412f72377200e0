// Fabric parameters as textile laboratories measure them, converted to the finite-volume model's
// SI parameters (material.finite_volume: E in N/m, G in N/m, D in N·m, density in kg/m²).
//
// Kawabata's evaluation system (KES-FB), as defined in S. Kawabata, "The Standardization and
// Analysis of Hand Evaluation", 2nd ed., The Textile Machinery Society of Japan, Osaka, 1980:
//   B   bending rigidity per unit width (KES-FB2), the slope of bending moment per unit width vs
//       curvature between 0.5 and 1.5 cm⁻¹, in gf·cm²/cm;
//   G   shear stiffness (KES-FB1), the slope of shear force per unit width vs shear angle between
//       0.5° and 5°, in gf/(cm·deg);
//   W   weight per unit area, in mg/cm²;
//   EMT tensile strain at the maximum load Fm (500 gf/cm in the standard condition), in %;
//   LT  linearity of the load–strain curve, WT / (Fm·EMT/2) with WT the tensile energy (the
//       area under the curve up to Fm): 1 for a straight line, < 1 for the usual J-shaped curve.
// Peirce's cantilever (F. T. Peirce, "The 'handle' of cloth as a measurable quantity", J. Textile
// Institute 21, T377–T416, 1930; ASTM D1388, BS 3356): the bending length c (cm) and the
// flexural rigidity per unit width G = W c³ (W the weight per unit area).
// The gram-force is the standard one, 1 gf = 9.80665e-3 N (g_n = 9.80665 m/s²).
#ifndef DRAPE_SRC_SCENE_FABRIC_PARAMETERS_H_
#define DRAPE_SRC_SCENE_FABRIC_PARAMETERS_H_

namespace drape {

constexpr double kStandardGravity = 9.80665;            // g_n, m/s²
constexpr double kGramForce = kStandardGravity * 1e-3;  // 1 gf in N
constexpr double kKesStandardMaximumLoad = 500.0;       // KES-FB1 Fm, gf/cm

// KES B (gf·cm²/cm = gf·cm) → D (N·m): D = B × 9.80665e-3 N × 1e-2 m = B × 9.80665e-5.
double KesBendingRigidity(double b_gf_cm);

// KES 2HB (gf·cm/cm, the width of the bending hysteresis) → the friction moment per unit width
// H = 2HB/2 (N·m/m = N): H = 2HB/2 × 9.80665e-3 N × 1e-2 m / 1e-2 m = 2HB × 4.903325e-3.
double KesBendingFriction(double two_hb_gf_cm_per_cm);

// KES 2HG (gf/cm, the width of the shear hysteresis at a shear angle of 0.5°) → the friction force
// per unit width HG = 2HG/2 (N/m): HG = 2HG/2 × 9.80665e-3 N / 1e-2 m = 2HG × 0.4903325.
double KesShearFriction(double two_hg_gf_per_cm);

// KES G (gf/(cm·deg)) → the model's G (N/m, per radian of shear angle):
// G = G_kes × (9.80665e-3 N / 1e-2 m) × (180/π) = G_kes × 56.188.
double KesShearRigidity(double g_gf_per_cm_deg);

// KES W (mg/cm²) → areal density (kg/m²): ρ = W × 1e-6 kg / 1e-4 m² = W / 100.
double KesArealDensity(double w_mg_per_cm2);

// KES EMT (%) at the maximum load Fm (gf/cm) with linearity LT → the membrane rigidity E (N/m)
// of the linear sheet that stores the same tensile energy WT up to the same strain:
//   ½ E ε_m² = WT = LT Fm ε_m / 2   ⇒   E = LT Fm / ε_m,   ε_m = EMT / 100,
// with Fm in N/m (500 gf/cm = 490.33 N/m). LT = 1 gives the secant modulus Fm / ε_m.
double KesTensileRigidity(double emt_percent, double lt,
                          double fm_gf_per_cm = kKesStandardMaximumLoad);

// Peirce's bending length c (cm) of a fabric of areal density ρ (kg/m²) → D (N·m):
//   D = ρ g_n c³ (Peirce's G = W c³ per unit width, in SI), c in m, g_n the standard gravity
// (the test is done under Earth's gravity; D is a property of the fabric and does not change
// with the scene's gravity).
double PeirceBendingRigidity(double bending_length_cm, double density_kg_per_m2);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_FABRIC_PARAMETERS_H_
