#include "src/analysis/mesh_rule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/levels.h"

namespace drape {

std::optional<MeshAdvice> AdviseMesh(const Scene& scene, const Model& model) {
  if (!HasDrapeCoefficient(scene, model)) return std::nullopt;
  return AdviseMeshOfScene(scene);
}

std::optional<MeshAdvice> AdviseMeshOfScene(const Scene& scene) {
  if (!(DiscRadius(scene) > 0.0)) return std::nullopt;
  const std::optional<double> bending_length = LimperBendingLength(scene);
  const double spacing = LatticeSpacing(scene.mesh);
  if (!bending_length || !(spacing > 0.0)) return std::nullopt;
  MeshAdvice advice;
  advice.spacing = spacing;
  advice.bending_length = *bending_length;
  advice.error_per_spacing = DrapeErrorPerSpacing(scene);
  advice.expected_error = ExpectedDrapeError(spacing, *bending_length, advice.error_per_spacing);
  advice.unresolved = advice.expected_error >= kMostDrapeError;  // K h / c reached the cap
  advice.accuracy = AskedDrapeAccuracy(scene);
  advice.spacing_needed =
      SpacingForDrapeError(advice.accuracy, *bending_length, advice.error_per_spacing);
  advice.spacing_chosen = scene.drape_test && scene.drape_test->spacing_chosen;
  advice.coarse = advice.expected_error > advice.accuracy;
  return advice;
}

std::string MeshRuleBasis(double bending_length) {
  return "mesh rule for a " + LengthText(bending_length, 2) + " bending length";
}

std::string CoarseMeshWarning(const MeshAdvice& advice) {
  char error[96];
  std::snprintf(error, sizeof error, "%.2g", advice.expected_error);
  char limit[16];
  std::snprintf(limit, sizeof limit, "%.2g", advice.accuracy);
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
