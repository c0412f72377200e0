// The spacing a drape test's mesh needs for its drape coefficient (docs/drape-tester.md, "How fine
// a mesh"). The refinement study of the limp fabric and the cotton of configs/fv/ (1 cm to 1.3 mm,
// edge contact at the rim) finds the drape coefficient converging at first order in the lattice
// spacing h, with an error of about
//   e ≈ kDrapeErrorPerSpacing × h / c,   c = (D_min / (ρ g))^(1/3),
// c the fabric's bending length in its limper direction (D_min the smaller of D_warp and D_weft,
// ρ its areal density, g gravity): the fold troughs and the hinge where the fabric leaves the rim
// are placed to within a spacing, on the scale of c. Measured K = e c / h with the bending's twist
// (costs/fv_twist.h, its default D66; session 29): limp (c = 9.6 mm) 0.30, 0.24, 0.21 at 1 cm,
// 5 mm, 2.6 mm against Richardson's limit from 5, 2.6 and 1.3 mm (0.176); cotton (c = 18.8 mm)
// 0.08, 0.05, 0.04 against its 1.3 mm DC (0.708); the light polyester (c = 13 mm) 0.19, 0.17,
// 0.06 against its 1.3 mm DC (0.434). Without the twist (D66 = 0) the same study gave 0.30, 0.23,
// 0.18; 0.23, 0.13, 0.06; 0.31, 0.24, 0.12: the twist cut the cotton's and the polyester's errors,
// not the limp fabric's. kDrapeErrorPerSpacing is the largest measured, the polyester's at 1 cm
// without the twist, above every error measured with it (the limp fabric's 0.30 at 1 cm).
// The rule is linear over the study's spacings, up to about one bending length. Coarser, the
// lattice does not resolve the folds at all, and the error stops growing: the same scenes at 1.5,
// 2, 3 and 5 cm (without the twist) were off by 0.06–0.48 (limp 0.34, 0.30, 0.48, 0.42 at
// h/c 1.6–5.2; cotton 0.20, 0.16, 0.06 at 1.1–2.7), where K h / c says up to 1.6, beyond the drape
// coefficient's whole range. The expected error is therefore capped at kMostDrapeError: half that
// range, above every error measured.
#ifndef DRAPE_SRC_ANALYSIS_MESH_RULE_H_
#define DRAPE_SRC_ANALYSIS_MESH_RULE_H_

#include <optional>
#include <string>

#include "src/analysis/levels.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

constexpr double kDrapeErrorPerSpacing = 0.31;  // K
constexpr double kCoarseDrapeError = 0.05;      // e above which a mesh is coarse for its fabric
constexpr double kMostDrapeError = 0.5;         // the cap of e: a lattice that resolves no fold

struct MeshAdvice {
  double spacing = 0.0;         // h, m
  double bending_length = 0.0;  // c, m
  double expected_error = 0.0;  // K h / c, at most kMostDrapeError
  double spacing_needed = 0.0;  // the largest h of two digits with e ≤ kCoarseDrapeError, m
  bool coarse = false;          // expected_error > kCoarseDrapeError
  bool unresolved = false;      // K h / c reached kMostDrapeError: the lattice resolves no fold
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
