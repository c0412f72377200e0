// The scene: every setting of a YAML scene file, typed, in SI units, each with the place in the
// file it came from so that errors found later (while building the model) are still located.
// The contract is docs/reference.md's scene reference (docs/architecture.md, "The scene format is a
// contract").
#ifndef DRAPE_SRC_SCENE_SCENE_H_
#define DRAPE_SRC_SCENE_SCENE_H_

#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/geometry/triangle_surface.h"
#include "src/scene/material_models.h"
#include "src/scene/output_kinds.h"

namespace drape {

// Where a value stands in a scene file (1-based line and column) and its dotted key path.
struct Location {
  std::string file;
  int line = 0;
  int column = 0;
  std::string key;  // e.g. "material.springs.structural"
};

// A user-input error: the message is "file:line:column: key.path: what is wrong".
// The location and the problem are kept apart (where(), problem()) for a caller that relocates
// the error (a fit file's parameter that names a bad scene key).
class InputError : public std::runtime_error {
 public:
  InputError(const Location& where, const std::string& what);
  explicit InputError(const std::string& message)
      : std::runtime_error(message), problem_(message) {}
  const Location& where() const { return where_; }  // line 0 when it has no location
  const std::string& problem() const { return problem_; }

 private:
  Location where_;
  std::string problem_;
};

// The largest mesh.max_nodes accepted: node ids and coordinate indices stay within int.
constexpr int kLargestMaxNodes = 100000000;

struct MeshSpec {
  enum class Kind { kGrid, kCircle, kArc, kChain, kFile };
  Kind kind = Kind::kGrid;
  // grid
  Eigen::Vector2d size{1.0, 1.0};
  std::array<int, 2> nodes{15, 15};  // node counts along u and v
  std::vector<double> u, v;          // explicit coordinates (non-uniform), empty if size/nodes
  std::string plane = "xy";          // "xy" (flat) or "xz" (vertical, v along +z)
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  // circle
  double radius = 0.15;
  double spacing = 0.01;
  // arc
  int rings = 15;
  int spokes = 64;
  // chain
  double length = 1.0;
  int chain_nodes = 11;
  Eigen::Vector3d direction{1.0, 0.0, 0.0};
  std::vector<Eigen::Vector3d> points;  // explicit chain nodes (replace length/nodes/direction)
  bool closed = false;                  // chain: a link from the last node back to the first
  // file
  std::string path;  // resolved against the scene file's folder
  // Or the surface given as arrays instead of a file (Python's `mesh=(vertices, faces)`): built
  // and checked as a file's, its errors located at the array's row (`faces[2]`), counted from 0.
  struct Arrays {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::vector<int>> faces;
  };
  std::shared_ptr<const Arrays> arrays;
  int max_nodes =
      1000000;  // the loader refuses a larger mesh (mesh.max_nodes, src/scene/scene_size.h)
  Location where;
};

// A set of nodes, as written under `nodes:` in `fixed`, `loads.forces`, `material.lines` and
// `regions`.
struct NodeSelector {
  enum class Kind { kEdge, kCorner, kIds, kIj, kRow, kColumn, kBox, kWithin, kOutside, kAll };
  Kind kind = Kind::kAll;
  std::string name;  // edge: top|bottom|left|right; corner: top-left|top-right|bottom-left|...
  std::vector<int> ids;
  std::vector<std::array<int, 2>> ij;
  int index = 0;  // row: the lattice index j; column: the lattice index i
  Eigen::Vector3d min = Eigen::Vector3d::Zero(), max = Eigen::Vector3d::Zero();  // box
  Eigen::Vector3d center = Eigen::Vector3d::Zero();                              // within, outside
  double radius = 0.0;                                                           // within, outside
  // `{region: NAME}`: the named region's own selection. The loader replaces such a selector by a
  // copy of that region's selection, so `region` is empty in a loaded Scene.
  std::string region;
  Location where;
};

// A stiffness given for both yarn directions: `structural: 1000` or `{warp: 1000, weft: 800}`.
struct SpringFamilySpec {
  bool present = false;
  double warp = 0.0;  // N/m
  double weft = 0.0;  // N/m
  Location where;
};

struct SpringsSpec {
  bool present = false;  // material.springs is given (required by model springs, optional beside
                         // finite_volume)
  SpringFamilySpec structural, shear, flexion;
  enum class RestLength { kInitial, kZero, kGiven };
  RestLength rest_length = RestLength::kInitial;
  double rest_length_value = 0.0;  // m, for kGiven
  bool tension_only = false;
  std::optional<double> stretch_limit;  // maximum stretch ratio, > 1
  Location where;
};

// A fabric measurement as the scene gave it, in a laboratory's units (kes.B_warp 0.12 gf·cm²/cm):
// what `drape check` and summary.json report beside the SI values it was converted to.
struct GivenMeasurement {
  std::string key;  // below material.finite_volume: "kes.B_warp", "fast.EB5", "bending_length.warp"
  double value = 0;
  std::string unit;  // the schema's: "gf·cm²/cm", "%", "cm"
};

struct FiniteVolumeSpec {
  bool present = false;
  double E_warp = 0, E_weft = 0, nu_warp = 0, nu_weft = 0, G = 0;  // N/m
  double D_warp = 0, D_weft = 0, D_12 = 0;                         // N·m
  // The torsional rigidity D66 (N·m; M12 = D66 · 2κ12, costs/fv_twist.h) and how the loader set
  // it: given as D_66, converted from a bias bending measurement (kes.B_bias,
  // bending_length.bias), or the default rule of src/scene/fabric_parameters.h from D_warp and
  // D_weft, which a region that changes those re-applies (src/model/regions.cc).
  double D_66 = 0;
  enum class TwistSource { kGiven, kBias, kDefault };
  TwistSource twist_source = TwistSource::kGiven;
  // Fibre friction in bending (KES 2HB/2), N·m/m = N: 0 is the elastic fabric
  // (costs/fv_bending_friction.h), and δ, the curvature (1/m) below which its kink is smoothed.
  double bending_friction_warp = 0, bending_friction_weft = 0;
  double bending_friction_smoothing = 0.1;
  // Yarn friction in shear (KES 2HG/2), N/m: 0 is the elastic fabric
  // (costs/fv_shear_friction.h), and δ, the shear angle (rad) below which its kink is smoothed.
  double shear_friction = 0;
  double shear_friction_smoothing = 0.001;
  // How the frictions follow the load: 0, the monotone (deformation-theory) form, loads applied at
  // once; N ≥ 1, the incremental form, loads ramped in N equal steps, each a minimisation with the
  // frictions' kinks at the previous step's state (costs/fv_bending_friction_step.h).
  int friction_load_steps = 0;
  // The in-plane shear taken once per whole lattice cell, at its centre (costs/fv_cell_shear.h),
  // or, false, at each control volume's corners (Hu/Teng's quarters); the same for the whole
  // fabric.
  bool cell_shear = true;
  std::vector<GivenMeasurement> measured;  // the kes, fast and bending_length keys given
  Location where;
};

// A spring line (material.lines): springs on the structural links (lattice neighbours along the
// warp or the weft) both of whose nodes are selected, added to whatever the material model has.
struct SpringLineSpec {
  NodeSelector nodes;
  double stiffness = 0.0;  // N/m per link (`structural`)
  bool tension_only = false;
  Location where;
};

struct MaterialSpec {
  // src/scene/material_models.h. A finite_volume material may have springs beside it (`springs`).
  MaterialModel model = MaterialModel::kSprings;
  enum class MassKind { kDensity, kNodeMass, kTotalMass };
  MassKind mass_kind = MassKind::kDensity;
  double mass_value = 0.0;  // kg/m², kg per node, or kg
  SpringsSpec springs;
  FiniteVolumeSpec finite_volume;
  std::vector<SpringLineSpec> lines;
  Location where;
};

// A region (`regions:`): material values overriding the scene's material for the selected nodes
// (src/model/regions.h). Only what is given overrides; a later region overrides an earlier one.
struct RegionSpec {
  std::string name;  // optional; loads, supports and lines select the region by `{region: name}`
  NodeSelector nodes;
  std::optional<double> density;                // kg/m² (material.density)
  std::map<std::string, double> finite_volume;  // E_warp, E_weft, nu_warp, nu_weft, G, D_* (SI)
  SpringFamilySpec structural, shear, flexion;  // present when given
  std::optional<bool> tension_only;
  std::map<std::string, Location> given;  // each key written, with where its value is
  Location where;
};

struct FixedSpec {
  NodeSelector nodes;
  std::array<bool, 3> dofs{true, true, true};  // x, y, z
  Eigen::Vector3d move = Eigen::Vector3d::Zero();
  Location where;
};

struct ForceSpec {
  NodeSelector nodes;
  // kTotal: `value` shared equally; kEach: `value` on every node; kValues: `values[k]` on the k-th
  // selected node in id order; kRamp: from `value` (first node) to `ramp_to` (last node), linear
  // in the node's position along the selection; kTraction: `value` (Pa) times each node's lumped
  // area; kPressure: `pressure` (Pa) times each node's lumped area along its initial normal.
  enum class Kind { kTotal, kEach, kValues, kRamp, kTraction, kPressure };
  Kind kind = Kind::kTotal;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();    // N
  std::vector<Eigen::Vector3d> values;                // N, kValues
  Eigen::Vector3d ramp_to = Eigen::Vector3d::Zero();  // N, kRamp
  double pressure = 0.0;                              // Pa, kPressure
  Location values_where;                              // the `values` list (kValues)
  Location where;
};

// Pressure on a closed 2-D chain: the potential −p × (area enclosed in the x–z plane).
struct PressureSpec {
  double pressure = 0.0;  // N/m (force per unit length of the profile, per unit depth)
  Location where;
};

struct LoadsSpec {
  std::optional<Eigen::Vector3d> gravity;  // m/s²
  std::vector<ForceSpec> forces;
  std::optional<PressureSpec> pressure;
  Location where;
};

// One rigid body. Its kinds, and which keys each takes, are the registry's
// (src/model/obstacle_kinds.h), checked when the model is built; the loader reads each key with
// its range.
struct ObstacleSpec {
  std::string kind;  // "sphere", "disk", ... (a row of ObstacleKinds())
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // sphere, disk, cylinder; pin `position`
  double radius = 0.0;
  double height = 0.0;                                                           // cylinder
  Eigen::Vector3d min = Eigen::Vector3d::Zero(), max = Eigen::Vector3d::Zero();  // box
  Eigen::Vector3d normal{0.0, 0.0, 1.0};  // plane (its `point` in `center`), normalised
  // mesh: the file (resolved against the scene file's folder) and its placement, x' = R (s x) + t
  // (src/geometry/triangle_surface.h, PlaceVertex); the loader reads the file into `surface`.
  std::string file;
  double scale = 1.0;
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     // degrees about x, then y, then z
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // m
  std::shared_ptr<const TriangleSurface> surface;
  double friction = 0.0;
  std::map<std::string, Location> given;  // the keys written, with where each value is
  Location where;
};

struct ContactSpec {
  double thickness = 0.001;  // m
  bool self = true;          // the fabric's contact with itself (src/model/self_contact.h)
  Location where;
};

// The most nested lattices a solve takes (solver.levels): each halves the spacing.
constexpr int kMostLevels = 8;

struct SolverSpec {
  std::string method = "newton";
  double tolerance = 1e-8;  // relative equilibrium residual
  // As given; when not, the method's own defaults (src/scene/solver_methods.h; see
  // MaxIterations, TimeLimit below).
  std::optional<int> max_iterations;
  std::optional<double> time_limit;  // s
  // Nested lattices to solve on (grid and circle meshes): 1 = the scene's mesh only; N > 1 solves
  // on spacings 2^(N-1) h, ..., 2h, h, each started from the previous one, and extrapolates.
  // 0: not given; LevelsToSolve (src/run/solve_report.h) decides.
  int levels = 0;
  Location levels_where;
  // Method-specific keys: solver.<method>.<key>: number (checked against the catalogue of
  // src/scene/solver_methods.h).
  std::map<std::string, std::map<std::string, double>> method_options;
  Location where;
};

struct OutputSpec {
  std::string directory;  // resolved: absolute or relative to the current directory
  std::vector<std::string> write = DefaultOutputWrite(false);  // names of src/scene/output_kinds.h
  // mesh.obj's up axis: "z" (as solved) or "y": a quarter turn about x, (x, y, z) → (x, z, −y),
  // so drape's +z is the file's +y (right-handed; Blender's and three.js's default import).
  std::string obj_up = "z";
  Location where;
  Location directory_where;  // the output.directory key's, where the scene gives one (else line 0)
};

// A drape test (Cusick 1968; BS 5058, ISO 9073-9) given by its geometry: the scene's `drape_test`
// block, which src/scene/drape_tester.h expands into the mesh, the clamp, the support disc and
// gravity of a hand-written tester scene. Lengths in m.
struct DrapeTestSpec {
  double specimen_diameter = 0.30;
  double disc_diameter = 0.18;
  std::optional<double> clamp_diameter;  // not given: 1 cm less than the disc
  // The disc's centre seen from the specimen's (a real specimen is never centred exactly; the
  // offset also breaks the lattice's symmetry, so the folds form where they want).
  Eigen::Vector2d offset{0.0013, 0.0007};
  // Repeated drops (src/sweep/drops.h): how many, and the seeded perturbations that make them
  // differ: the specimen's placement on the disc (a uniform scatter of this radius around
  // `offset`) and an initial out-of-plane waviness of the overhang (this amplitude).
  int drops = 1;
  double placement = 0.002;
  double waviness = 0.002;
  int seed = 1;
  // The drape coefficient's error the test asks for (none: kDefaultDrapeAccuracy,
  // src/scene/drape_mesh_rule.h). Where the scene gives no mesh.spacing, the loader chooses the
  // spacing that reaches it by the mesh rule (spacing_chosen).
  std::optional<double> accuracy;
  bool spacing_chosen = false;
  Location where;
  Location accuracy_where;  // the accuracy's value, else the block
};

struct Scene {
  std::string file;       // the scene file as given
  std::string directory;  // folder of the scene file
  std::string name;       // default: the file stem
  int dimension = 3;
  MeshSpec mesh;
  MaterialSpec material;
  std::vector<RegionSpec> regions;
  std::vector<FixedSpec> fixed;
  LoadsSpec loads;
  std::vector<ObstacleSpec> obstacles;
  ContactSpec contact;
  SolverSpec solver;
  OutputSpec output;
  std::optional<DrapeTestSpec> drape_test;  // given: mesh, fixed and obstacles are its expansion
  Location root;                            // the document itself (file, line 1)
};

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_H_
