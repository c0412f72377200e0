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
// CSIRO's SiroFAST (Fabric Assurance by Simple Testing; A. De Boos and D. Tester, "SiroFAST —
// Fabric Assurance by Simple Testing", CSIRO Division of Wool Technology, Report WT92.02, 1994;
// the definitions as tabulated by S. Kuijpers, C. Luible-Bär and R. H. Gong, "The Measurement of
// Fabric Properties for Virtual Simulation", IEEE SA Industry Connections report, 2020, Table 2):
//   W     mass per unit area, in g/m²;
//   B     bending rigidity per unit width (FAST-2, from the bending length C by Peirce's
//         cantilever: B = W C³ × 9.81e-6 with C in mm), in µN·m;
//   EB5   the bias extensibility at 5 gf/cm (FAST-3), in %, from which FAST defines the shear
//         rigidity G = 123 / EB5 in N/m;
//   E100  the extensibility at 100 gf/cm (FAST-3) along the warp or the weft, in %.
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

// FAST W (g/m²) → areal density (kg/m²): ρ = W / 1000.
double FastArealDensity(double w_g_per_m2);

// FAST B (µN·m, per unit width) → D (N·m): D = B × 1e-6.
double FastBendingRigidity(double b_micro_newton_metre);

// FAST EB5 (%) → the model's G (N/m): FAST's own shear rigidity G = 123 / EB5. The constant is
// the bias strip's small-strain relation: under a tension T per unit width a strip cut at 45°
// carries the shear force T/2 per unit width across the warp and weft and shears by γ = 2ε (ε its
// strain), so G = (T/2)/γ = T/(4ε); T = 5 gf/cm = 4.903 N/m and ε = EB5/100 give 122.6/EB5.
double FastShearRigidity(double eb5_percent);
constexpr double kFastShearConstant = 123.0;  // N/m · %

// FAST E100 (%) → the membrane rigidity E (N/m). FAST defines no modulus; drape takes the secant
// modulus at FAST's 100 gf/cm, E = (100 gf/cm = 98.0665 N/m) / (E100/100), as KesTensileRigidity
// with LT = 1 (a drape hardly feels it: the fabric hardly stretches under its own weight).
double FastTensileRigidity(double e100_percent);
constexpr double kFastTensileLoad = 100.0;  // gf/cm, FAST-3's largest load

// Peirce's bending length c (cm) of a fabric of areal density ρ (kg/m²) → D (N·m):
//   D = ρ g_n c³ (Peirce's G = W c³ per unit width, in SI), c in m, g_n the standard gravity
// (the test is done under Earth's gravity; D is a property of the fabric and does not change
// with the scene's gravity).
double PeirceBendingRigidity(double bending_length_cm, double density_kg_per_m2);

// The torsional rigidity D66 (N·m) from the bending rigidity B45 (N·m) of a strip cut at 45° to
// the warp, by the orthotropic plate's bending compliance in direction θ (S. G. Lekhnitskii,
// Anisotropic Plates, 1968, §11; the form Cooper 1960 and Lloyd, Shanahan & Konopasek 1978 used
// for fabrics): a narrow strip bent by a moment M along θ, free across, has
//   1/B(θ) = S11 cos⁴θ + (2 S12 + S66) cos²θ sin²θ + S22 sin⁴θ,
// S = D⁻¹ the compliance of [D1 D12 0; D12 D2 0; 0 0 D66] (S11 = D2/Δ, S22 = D1/Δ, S12 = −D12/Δ,
// Δ = D1 D2 − D12², S66 = 1/D66), so at θ = 45°
//   D66 = 1 / (4/B45 − S11 − S22 − 2 S12)   (with D12 = 0: 1 / (4/B45 − 1/D1 − 1/D2)).
// Returns a value ≤ 0 or infinite where no finite D66 ≥ 0 gives that B45: the bias must be less
// stiff than 4 / (S11 + S22 + 2 S12) (with D12 = 0, twice the harmonic mean of D1 and D2).
double BiasTorsionalRigidity(double b45, double d_warp, double d_weft, double d_12);

// The largest B45 that a finite D66 gives (BiasTorsionalRigidity's bound), N·m.
double StiffestBiasRigidity(double d_warp, double d_weft, double d_12);

// The default D66 where a fabric gives no bias measurement (docs/reference.md, "Twist"):
//   D66 = √(D_warp D_weft) / 3,
// from the bias bending rigidities measured on ten garment fabrics (Wang, O'Brien & Ramamoorthi,
// "Data-driven elastic models for cloth", ACM Trans. Graphics 30(4), 71, 2011): B45/√(B1 B2) =
// 0.58–1.05, median 0.8, which BiasTorsionalRigidity turns into D66/√(B1 B2) = 0.21–0.55, median
// 0.35 (0.26–0.53 on their five wovens). An isotropic plate with ν = 0 (Huber's rule) would have
// D/2, the bias as stiff as warp and weft; measured fabrics are softer at the bias.
double DefaultTorsionalRigidity(double d_warp, double d_weft);
constexpr double kDefaultTwistRatio = 1.0 / 3.0;  // D66 / √(D_warp D_weft)

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_FABRIC_PARAMETERS_H_
