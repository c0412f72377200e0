// The mesh rule: how far a drape test's drape coefficient is from its converged value on a lattice
// of spacing h (docs/drape-tester.md, "How fine a mesh"), and so which spacing an accuracy needs.
// The refinement studies of the tester fabrics of configs/fv/ (1 cm to 1.3 mm, edge contact at
// the rim) and the published fabrics of docs/validation.md (1 cm to 1.3 mm) bound the error by
//   e ≈ K × h / c,   c = (D_min / (ρ g))^(1/3),
// c the fabric's bending length in its limper direction (D_min the smaller of D_warp and D_weft,
// ρ its areal density, g gravity): the fold troughs and the hinge where the fabric leaves the rim
// are placed to within a spacing, on the scale of c. K depends on how the in-plane shear is
// discretised (finite_volume.cell_shear), for the corners' shear charges a fold oblique to the
// lattice a shear the fabric does not have (shear locking, docs/drape-tester.md's ablation):
// - At the cells' centres (the default; sessions 37 to 39): K = |DC(h) − DC(1.3 mm)| c / h, each
//   fabric against its own 1.3 mm drape coefficient, at 1 cm, 5, 3.5 (or 5.2) and 2.6 mm: the
//   limp fabric (c = 9.6 mm) 0.10, 0.01, 0.02, 0.01, the cotton (18.8 mm) 0.05, 0.05, 0.08, 0.07,
//   the light polyester (13 mm) 0.06, 0.01, 0.10, 0.12 (from 5 mm down, the fold pattern's
//   scatter, |e| ≤ 0.026); the published fabrics of docs/validation.md (session 39) M1 0.13, 0.11,
//   0.09, 0.03, M2 0.19, 0.16, 0.16, 0.05, M3 0.14, 0.08, 0.12, 0.02, M4 0.09, 0.03, 0.04, 0.02, M5
//   0.08, 0.02, 0.03, 0.00, M6 0.11, 0.09, 0.03, 0.01 (1 cm, 5, 5.2 and 2.6 mm).
//   kCellShearErrorPerSpacing is the largest, M2's at 1 cm (h/c = 1.35), rounded up. The published
//   fabrics' DCs fall faster than first order from 5 to 2.6 mm (the error of M1, M2, M3 and M6 by 6
//   times or more, M4's by 3.6; docs/drape-tester.md has the runs): session 38 read their change
//   over that step as first order and took K = 0.28 from M2, which M2's own 1.3 mm solve puts at
//   0.16 there. K rises with G c² / D (about 2,200 for the tester fabrics, M4 and M5, 2,700 for M3,
//   4,000–4,400 for M1 and M6, 7,600 for M2), the weight of the lattice's shear against the
//   bending, but not steadily enough to narrow a fabric's error bar by it.
// - At the corners (Hu/Teng's, cell_shear: false; sessions 29 and 38): the tester fabrics 0.30,
//   0.24, 0.21 (limp, 1 cm to 2.6 mm, against its Richardson limit), 0.19, 0.17, 0.06 (polyester),
//   0.08, 0.05, 0.04 (cotton); the published fabrics M1–M6 0.31, 0.42, 0.41, 0.27, 0.31, 0.35.
//   kCornerShearErrorPerSpacing is M2's, the largest.
// The published fabrics converge more slowly than the tester fabrics (M2's G c² / D is 3.3 times
// the limp fabric's: the lattice's shear weighs more against its bending), so one K per model
// keeps the slowest fabric measured. The rule is linear over the studies' spacings, up to about one
// bending length. Coarser, the lattice does not resolve the folds at all, and the error stops
// growing: the same scenes at 1.5, 2, 3 and 5 cm (corners, without the twist) were off by
// 0.06–0.48 (limp 0.34, 0.30, 0.48, 0.42 at h/c 1.6–5.2; cotton 0.20, 0.16, 0.06 at 1.1–2.7),
// where K h / c says up to 2.2, beyond the drape coefficient's whole range. The expected error is
// therefore capped at kMostDrapeError: half that range, above every error measured.
//
// It lives with the scene because the scene uses it: a drape test that does not give its
// mesh.spacing gets the spacing its drape_test.accuracy needs (ChooseDrapeTestSpacing,
// src/scene/drape_tester.h); src/analysis/mesh_rule.h turns it into the advice, warnings and
// error bars of a solve.
#ifndef DRAPE_SRC_SCENE_DRAPE_MESH_RULE_H_
#define DRAPE_SRC_SCENE_DRAPE_MESH_RULE_H_

#include <optional>

#include "src/scene/scene.h"

namespace drape {

constexpr double kCellShearErrorPerSpacing = 0.20;    // K, the shear at the cells' centres
constexpr double kCornerShearErrorPerSpacing = 0.42;  // K, the shear at the corners (Hu/Teng's)
constexpr double kMostDrapeError = 0.5;  // the cap of e: a lattice that resolves no fold

// The drape coefficient's error a drape test asks for when it does not say (drape_test.accuracy):
// the ±0.05 within which a lab compares fabrics, about the spread of one fabric's repeated real
// drops (a standard deviation of 0.010–0.065, median 0.035, over 645 Cusick drapes of 25 fabrics:
// Gong, Mao & Wang, CVPR 2024). A mesh whose expected error is larger is coarse for its fabric.
constexpr double kDefaultDrapeAccuracy = 0.05;
// The finest accuracy a drape test may ask for: the smallest drop-to-drop spread of a real fabric
// (the same study's 0.010); no lattice makes one drop more repeatable than the tester.
constexpr double kFinestDrapeAccuracy = 0.01;
// The coarsest spacing drape chooses for an accuracy: the refinement study's coarsest (1 cm),
// where the rule was measured; coarser lattices leave the rule's linear range.
constexpr double kCoarsestChosenSpacing = 0.01;

// The fabric's bending length in its limper direction, c = (D_min / (ρ g))^(1/3) (m), where the
// rule applies: a finite-volume fabric with a bending rigidity, given per unit area (density),
// under gravity; none otherwise.
std::optional<double> LimperBendingLength(const Scene& scene);

// The rule's K for the scene's fabric: its shear's discretisation (finite_volume.cell_shear) sets
// how far a coarse lattice's folds are from the fabric's.
double DrapeErrorPerSpacing(const Scene& scene);

// The rule's expected error at `spacing` for a fabric of bending length `bending_length` (both
// m) and K `error_per_spacing`: K h / c, at most kMostDrapeError.
double ExpectedDrapeError(double spacing, double bending_length, double error_per_spacing);

// The largest spacing of two significant digits (m) whose expected error is at most `error`:
// a spacing a person can type (0.0031331 → 0.0031).
double SpacingForDrapeError(double error, double bending_length, double error_per_spacing);

// The accuracy the scene's drape test asks for (drape_test.accuracy), else kDefaultDrapeAccuracy.
double AskedDrapeAccuracy(const Scene& scene);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_DRAPE_MESH_RULE_H_
