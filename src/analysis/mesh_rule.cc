#include "src/analysis/mesh_rule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/levels.h"
#include "src/scene/material_models.h"

namespace drape {

namespace {

// x rounded down to two significant digits (0.0031331 → 0.0031): a spacing a person can type,
// which keeps the rule's error at or under its limit, as the unrounded one does.
double RoundedDownToTwoDigits(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::floor(x / unit) * unit;
}

}  // namespace

std::optional<MeshAdvice> AdviseMesh(const Scene& scene, const Model& model) {
  if (!HasDrapeCoefficient(scene, model)) return std::nullopt;
  return AdviseMeshOfScene(scene);
}

std::optional<MeshAdvice> AdviseMeshOfScene(const Scene& scene) {
  const MaterialSpec& material = scene.material;
  switch (material.model) {
    case MaterialModel::kSprings:
      return std::nullopt;  // the rule is the finite-volume fabric's refinement study's
    case MaterialModel::kFiniteVolume:
      break;
  }
  if (material.mass_kind != MaterialSpec::MassKind::kDensity || !scene.loads.gravity) {
    return std::nullopt;
  }
  if (!(DiscRadius(scene) > 0.0)) return std::nullopt;
  const double spacing = LatticeSpacing(scene.mesh);
  const double rigidity = std::min(material.finite_volume.D_warp, material.finite_volume.D_weft);
  const double weight = material.mass_value * scene.loads.gravity->norm();  // N/m²
  if (!(spacing > 0.0) || !(rigidity > 0.0) || !(weight > 0.0)) return std::nullopt;
  MeshAdvice advice;
  advice.spacing = spacing;
  advice.bending_length = std::cbrt(rigidity / weight);
  const double linear = kDrapeErrorPerSpacing * spacing / advice.bending_length;
  advice.unresolved = linear >= kMostDrapeError;
  advice.expected_error = std::min(linear, kMostDrapeError);
  advice.spacing_needed =
      RoundedDownToTwoDigits(kCoarseDrapeError * advice.bending_length / kDrapeErrorPerSpacing);
  advice.coarse = advice.expected_error > kCoarseDrapeError;
  return advice;
}

std::string MeshRuleBasis(double bending_length) {
  return "mesh rule for a " + LengthText(bending_length, 2) + " bending length";
}

std::string CoarseMeshWarning(const MeshAdvice& advice) {
  char error[96];
  std::snprintf(error, sizeof error, "%.2g", advice.expected_error);
  char limit[16];
  std::snprintf(limit, sizeof limit, "%.2g", kCoarseDrapeError);
  const std::string head = "mesh.spacing " + LengthText(advice.spacing, 2) +
                           " is coarse for this fabric (bending length " +
                           LengthText(advice.bending_length, 2) + " in its limper direction): ";
  const std::string body =
      advice.unresolved
          ? std::string(
                "the lattice resolves none of its folds, and its drape coefficient may be "
                "off by as much as ") +
                error + " (docs/drape-tester.md)"
          : std::string("expect its drape coefficient to be off by about ") + error +
                " (the error is first order in the spacing, docs/drape-tester.md)";
  return head + body + "; " + LengthText(advice.spacing_needed, 2) + " or finer keeps it within " +
         limit;
}

void WidenToMeshRule(const MeshAdvice& advice, DrapeErrorBar* bar) {
  bar->mesh_rule_error = advice.expected_error;
  bar->mesh_rule_bending_length = advice.bending_length;
}

}  // namespace drape
