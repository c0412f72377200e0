// The mesh rule: how far a drape test's drape coefficient is from its converged value on a lattice
// of spacing h (docs/drape-tester.md, "How fine a mesh"), and so which spacing an accuracy needs.
// The refinement study of the limp fabric and the cotton of configs/fv/ (1 cm to 1.3 mm, edge
// contact at the rim) finds the drape coefficient converging at first order in the lattice
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

constexpr double kDrapeErrorPerSpacing = 0.31;  // K
constexpr double kMostDrapeError = 0.5;         // the cap of e: a lattice that resolves no fold

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

// The rule's expected error at `spacing` for a fabric of bending length `bending_length` (both
// m): K h / c, at most kMostDrapeError.
double ExpectedDrapeError(double spacing, double bending_length);

// The largest spacing of two significant digits (m) whose expected error is at most `error`:
// a spacing a person can type (0.0031331 → 0.0031).
double SpacingForDrapeError(double error, double bending_length);

// The accuracy the scene's drape test asks for (drape_test.accuracy), else kDefaultDrapeAccuracy.
double AskedDrapeAccuracy(const Scene& scene);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_DRAPE_MESH_RULE_H_
