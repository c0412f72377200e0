// Conversions of KES-FB, SiroFAST and Peirce measurements; formulas and sources in
// fabric_parameters.h.
#include "src/scene/fabric_parameters.h"

#include <cassert>
#include <cmath>

namespace drape {

namespace {
constexpr double kCentimetre = 1e-2;  // m
}  // namespace

double KesBendingFriction(double two_hb_gf_cm_per_cm) {
  return 0.5 * two_hb_gf_cm_per_cm * kGramForce;
}

double KesShearFriction(double two_hg_gf_per_cm) {
  return 0.5 * two_hg_gf_per_cm * kGramForce / kCentimetre;
}

double KesBendingRigidity(double b_gf_cm) { return b_gf_cm * kGramForce * kCentimetre; }

double KesShearRigidity(double g_gf_per_cm_deg) {
  return g_gf_per_cm_deg * kGramForce / kCentimetre * (180.0 / M_PI);
}

double KesArealDensity(double w_mg_per_cm2) {
  return w_mg_per_cm2 * 1e-6 / (kCentimetre * kCentimetre);
}

double KesTensileRigidity(double emt_percent, double lt, double fm_gf_per_cm) {
  assert(emt_percent > 0.0 && lt > 0.0 && fm_gf_per_cm > 0.0);
  const double fm = fm_gf_per_cm * kGramForce / kCentimetre;  // N/m
  return lt * fm / (emt_percent / 100.0);
}

double FastArealDensity(double w_g_per_m2) { return w_g_per_m2 * 1e-3; }

double FastBendingRigidity(double b_micro_newton_metre) { return b_micro_newton_metre * 1e-6; }

double FastShearRigidity(double eb5_percent) {
  assert(eb5_percent > 0.0);
  return kFastShearConstant / eb5_percent;
}

double FastTensileRigidity(double e100_percent) {
  return KesTensileRigidity(e100_percent, 1.0, kFastTensileLoad);
}

double PeirceBendingRigidity(double bending_length_cm, double density_kg_per_m2) {
  const double c = bending_length_cm * kCentimetre;
  return density_kg_per_m2 * kStandardGravity * c * c * c;
}

// S11 + S22 + 2 S12 of the bending compliance (fabric_parameters.h): (D1 + D2 − 2 D12) / Δ.
double PrincipalCompliance(double d_warp, double d_weft, double d_12) {
  return (d_warp + d_weft - 2.0 * d_12) / (d_warp * d_weft - d_12 * d_12);
}

double BiasTorsionalRigidity(double b45, double d_warp, double d_weft, double d_12) {
  return 1.0 / (4.0 / b45 - PrincipalCompliance(d_warp, d_weft, d_12));
}

double StiffestBiasRigidity(double d_warp, double d_weft, double d_12) {
  return 4.0 / PrincipalCompliance(d_warp, d_weft, d_12);
}

double DefaultTorsionalRigidity(double d_warp, double d_weft) {
  return kDefaultTwistRatio * std::sqrt(d_warp * d_weft);
}

}  // namespace drape
