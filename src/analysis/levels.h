// Nested lattices (`solver.levels: N`): the scene solved on N lattices of spacing 2^(N-1) h, ...,
// 2h, h (h the scene's own spacing), coarse to fine, each solve started from the previous level's
// answer interpolated onto the finer lattice (grid sequencing), then the drape coefficient and
// the energy extrapolated to h → 0 (Richardson) from the three finest levels.
//
// Coarser scenes keep the fabric per unit area: each material model's row says how its
// parameters change with the spacing (MaterialModelRow::rescale_for_spacing,
// src/scene/material_models.cc: finite-volume rigidities and areal densities are per unit area
// already; spring stiffnesses stay but flexion, which scales as h⁻⁴). Node selectors by position
// (edge, corner, box, within, all) select the same places; `ids` and `ij` are mapped through the
// lattice index: fine index i lands at i h/H on the coarse lattice and the coarse nodes on either
// side are selected (a clamp on the first two nodes stays the first two; a node between coarse
// nodes selects both). What cannot be scaled is refused at solver.levels: meshes other than a
// uniform grid or a circle, per-node forces and masses given per node.
#ifndef DRAPE_SRC_ANALYSIS_LEVELS_H_
#define DRAPE_SRC_ANALYSIS_LEVELS_H_

#include <optional>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

struct LevelRecord {
  double spacing = 0.0;  // m, lattice step along the warp
  int nodes = 0;
  int iterations = 0;
  double wall_time_s = 0.0;
  double energy = 0.0;  // J, total at the level's answer
  bool converged = false;
  bool stable = false;
  std::optional<double> drape_coefficient;  // where the scene has one
  std::optional<int> folds;
  // The fabric's edges through a support disk (ContactReport::edges_through_disk): the fabric
  // passed through it. Such an answer is not used to start the next level.
  int edges_through_disk = 0;
  // The fabric's edges through a mesh obstacle's surface (ContactReport::edges_through_body).
  int edges_through_body = 0;
  // Crossings of a triangle's side and a triangle (SelfIntersections::crossings): the fabric
  // passed through itself. Neither is such an answer used to start the next level.
  int self_crossings = 0;
  // The coarser level's answer passed through a disk or itself, so this level started flat.
  bool started_flat = false;
  // The interpolated start led through a disk or through itself, so the level was solved again
  // from the flat start (iterations and time count both solves).
  bool restarted_flat = false;
  // The level's answer is no drape: the fabric passes through a disk, a mesh obstacle or itself.
  bool PassesThrough() const {
    return edges_through_disk > 0 || edges_through_body > 0 || self_crossings > 0;
  }
};

// q(h) = q₀ + C h^p fitted through the three finest levels.
struct Extrapolation {
  std::string quantity;  // "drape_coefficient" or "energy"
  bool available = false;
  std::string reason;           // why not, when not available
  double value = 0.0;           // q₀
  double error_estimate = 0.0;  // |q(h) − q₀| of the finest level
  double observed_order = 0.0;  // p
};

// The finest level's drape coefficient with an estimate of its discretisation error, |DC(h) −
// DC(0)|: Richardson's (the drape_coefficient Extrapolation) where three levels give an observed
// order, else the change from the next coarser level, |DC(h) − DC(2h)|, which is the error of a
// quantity that converges at first order, as the drape coefficient does (docs/drape-tester.md:
// the hinge where the fabric leaves the disc's rim is placed to within a spacing).
//
// Levels this coarse can be outside the asymptotic range (the 2 cm level of a limp fabric has 4
// folds where 1 cm has 10, and their change, 0.018, is a seventeenth of the 1 cm error):
// WidenToMeshRule (src/analysis/mesh_rule.h) then adds the refinement study's rule, and the bar
// is the larger of the two.
struct DrapeErrorBar {
  double value = 0.0;         // the finest level's drape coefficient
  double levels_error = 0.0;  // the levels' own estimate
  std::string levels_basis;   // "Richardson, observed order 1.27" or "change from the 2 cm level"
  // The mesh rule's expected error and the bending length it is for, where the rule applies.
  std::optional<double> mesh_rule_error;
  double mesh_rule_bending_length = 0.0;  // m
  std::vector<int> folds;                 // per level, coarsest first (0 where a level has none)
  bool folds_differ = false;              // the two finest levels' fold counts differ

  // The estimate of |DC(h) − DC(0)|: the larger of the levels' and the rule's.
  double error() const;
  // Its basis: the levels', or where the rule is larger, the rule's and the levels' figure
  // ("mesh rule for a 9.6 mm bending length; change from the 2 cm level 0.018").
  std::string basis() const;
  bool MeshRuleIsLarger() const { return mesh_rule_error && *mesh_rule_error > levels_error; }
};

struct LevelsReport {
  std::vector<LevelRecord> levels;  // coarsest first; the last is the scene's own mesh
  std::vector<Extrapolation> extrapolations;
  // With two levels or more whose two finest converged with no fabric through a support disk.
  std::optional<DrapeErrorBar> drape_error;
};

// A length as drape's messages name it: "2 cm" (`cm_digits` significant digits) from 1 cm up,
// "5.2 mm" (2 digits) below.
std::string LengthText(double metres, int cm_digits);

// The lattice step along the warp of a grid or circle mesh, m (0 for a mesh of another kind).
double LatticeSpacing(const MeshSpec& mesh);

// The scene for lattice spacing `factor` × the scene's own (factor a power of 2). Throws
// InputError at solver.levels if the scene cannot be coarsened that far.
Scene CoarsenedScene(const Scene& scene, int factor);

// Fills `fine.positions` (free coordinates only) by bilinear interpolation of `coarse`'s positions
// over the lattice of `coarse_scene`, extrapolated linearly beyond its outline; then moves nodes
// out of the support disks they started above and shortens every lattice edge stretched by more
// than 1 % (where the interpolation cut across a disk's rim) to that. Exact for an affine
// deformation that stretches no edge by more than 1 %.
void ProlongPositions(const Scene& coarse_scene, const Model& coarse, const Scene& fine_scene,
                      Model* fine);

// The DrapeErrorBar of `levels` (coarsest first) given their extrapolations; none where the two
// finest levels have no drape coefficient, did not converge or passed through a support disk.
std::optional<DrapeErrorBar> DrapeErrorOf(const std::vector<LevelRecord>& levels,
                                          const std::vector<Extrapolation>& extrapolations);

// Richardson extrapolation through (h, q) pairs, coarsest first (uses the last three).
Extrapolation Extrapolate(const std::string& quantity, const std::vector<double>& spacing,
                          const std::vector<double>& values);

// The spacing a level reports: the lattice step along the warp (along the weft where the warp
// has a single node), m.
double LevelSpacing(const MeshSpec& mesh);

// The extrapolations and the drape coefficient's error bar of `report->levels` (coarsest first).
// With the fabric's bending length (m; a drape test's, MeshAdvice::bending_length), no
// extrapolation is made through three levels of which one is coarser than it. A lattice that coarse
// cannot carry the folds (their width is a few bending lengths), so the three levels are not in the
// asymptotic range whatever their observed order says: the cotton tester's 2 cm, 1 cm and 5 mm
// levels (bending length 1.9 cm) extrapolated its DC to 0.059 from its 1.3 mm solve, with an
// estimate of 0.046 (docs/benchmarks.md, the Pareto table's Richardson rows).
void AnalyseLevels(LevelsReport* report, std::optional<double> bending_length = std::nullopt);

}  // namespace drape

#endif  // DRAPE_SRC_ANALYSIS_LEVELS_H_
