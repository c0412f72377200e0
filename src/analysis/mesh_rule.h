// The mesh rule (src/scene/drape_mesh_rule.h: the refinement study's expected error of a drape
// coefficient, K h / c) applied to a solve: the advice on its lattice, the warning on a coarse one,
// and the error bar it widens.
#ifndef DRAPE_SRC_ANALYSIS_MESH_RULE_H_
#define DRAPE_SRC_ANALYSIS_MESH_RULE_H_

#include <optional>
#include <string>

#include "src/analysis/levels.h"
#include "src/model/model.h"
#include "src/scene/drape_mesh_rule.h"
#include "src/scene/scene.h"

namespace drape {

struct MeshAdvice {
  double spacing = 0.0;            // h, m
  double bending_length = 0.0;     // c, m
  double error_per_spacing = 0.0;  // K (DrapeErrorPerSpacing)
  double expected_error = 0.0;     // K h / c, at most kMostDrapeError
  double accuracy = 0.0;           // the drape coefficient's error asked for (AskedDrapeAccuracy)
  double spacing_needed = 0.0;     // the largest h of two digits with e ≤ accuracy, m
  bool spacing_chosen = false;     // the loader chose the spacing for the accuracy (drape_test)
  bool coarse = false;             // expected_error > accuracy
  bool unresolved = false;         // K h / c reached kMostDrapeError: the lattice resolves no fold
};

// The advice for a drape test (a scene with a drape coefficient and a support disc) on a lattice
// (grid or circle) of a finite-volume fabric with bending rigidity, density and gravity; none
// for any other scene.
std::optional<MeshAdvice> AdviseMesh(const Scene& scene, const Model& model);

// The same advice from the scene alone, before its model is built (a sweep's tasks before their
// solves): a lattice always has the triangles a drape coefficient needs, which is all AdviseMesh
// asks of the model.
std::optional<MeshAdvice> AdviseMeshOfScene(const Scene& scene);

// The basis every report gives the rule's figure: "mesh rule for a 9.6 mm bending length".
std::string MeshRuleBasis(double bending_length);

// "mesh.spacing 1 cm is coarse for this fabric (bending length 1.9 cm in its limper direction):
// expect its drape coefficient to be off by about 0.16 ...".
std::string CoarseMeshWarning(const MeshAdvice& advice);

// Adds the rule's expected error to the error bar (`mesh_rule_error`), which is then the larger of
// the levels' estimate and the rule's: two levels outside the asymptotic range can change by a
// fraction of the finest level's error. Where the rule is larger, the bar's basis() names it and
// the levels' figure: "mesh rule for a 9.6 mm bending length; change from the 2 cm level 0.018".
void WidenToMeshRule(const MeshAdvice& advice, DrapeErrorBar* bar);

}  // namespace drape

#endif  // DRAPE_SRC_ANALYSIS_MESH_RULE_H_
