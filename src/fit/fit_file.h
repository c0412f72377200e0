// The fit file of `drape fit`: which scene keys to fit, to which measurements, by which
// method. Read with located errors ("file:line:column: key.path: what is wrong"); measurement
// data files (csv, xyz, and ply/stl/obj through src/scene/mesh_file.h) are read here too, so that
// every bad input is reported before a single equilibrium is solved.
#ifndef DRAPE_SRC_FIT_FIT_FILE_H_
#define DRAPE_SRC_FIT_FIT_FILE_H_

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"

namespace drape {

// One fitted scene key. The outer optimiser works on u = log θ when `log`, on θ otherwise.
struct FitParameter {
  std::string key;  // a numeric scene key by path, e.g. material.finite_volume.D_warp
  double initial = 0.0;
  double lower = 0.0, upper = 0.0;  // bounds on θ
  bool log = false;
  Location where;
};

// Measured node positions: `id,x,y,z` rows (chosen nodes), or a point cloud (`x,y,z` csv, .xyz,
// .ply) compared by the distance of each point to the nearest point of the model's surface.
struct PositionData {
  bool cloud = false;
  std::vector<int> ids;                 // node ids (not a cloud)
  std::vector<Eigen::Vector3d> points;  // m
  std::vector<int> lines;               // the file line of each point
};

// Measured support reactions: `id,fx,fy,fz` rows for fixed nodes, N.
struct ReactionData {
  std::vector<int> ids;
  std::vector<Eigen::Vector3d> forces;
  std::vector<int> lines;  // the file line of each row
};

struct FitMeasurement {
  enum class Kind { kDrapeCoefficient, kPositions, kBendingLength, kReactions };
  Kind kind = Kind::kPositions;
  double value = 0.0;   // drape coefficient (dimensionless) or bending length (m)
  double weight = 1.0;  // multiplies the squared, normalised residuals
  // The measurement's standard uncertainty, in its own unit: the residuals are (model −
  // measured) / sigma. Defaults: drape coefficient 0.01, positions 1 mm, bending length 1 mm,
  // reactions 1% of the largest measured force.
  double sigma = 0.0;
  // drape_coefficient: the support disc radius (m) for Cusick's DC; 0 = the scene's disk
  // obstacle, and without one the ratio A_shadow / A_flat.
  double disc_radius = 0.0;
  // bending_length: the yarn direction of the virtual Peirce strip ("warp" or "weft").
  std::string direction = "warp";
  std::string file;  // the data file (positions, reactions), resolved
  PositionData positions;
  ReactionData reactions;
  Location where;
};

// A specimen: one scene solved with the fitted parameters, and what was measured on it. The first
// is the fit file's `scene`; `- scene: {file: other.yaml, measurements: [...]}` adds more.
struct FitSpecimen {
  std::string scene_file;  // resolved against the fit file's folder
  // The scene file, read and parsed once by LoadFitFile: every evaluation loads its scene from it.
  std::shared_ptr<const SceneDocument> scene;
  std::vector<FitMeasurement> measurements;
  // A drape test without mesh.spacing: the lattice its accuracy chose at the initial parameters
  // (src/scene/drape_tester.h). Every evaluation keeps it, so that the objective does not jump
  // where other parameters (another bending length) would choose another lattice.
  std::optional<double> chosen_spacing;
  Location where;
};

struct FitSpec {
  std::string file;  // the fit file as given
  std::string name;  // its stem
  std::vector<FitParameter> parameters;
  std::vector<FitSpecimen> specimens;  // [0] is the main scene
  std::string method = "bobyqa";       // a name in FitMethodTable() (src/fit/fit_methods.h)
  int max_evaluations = 200;           // outer objective evaluations
  double tolerance = 1e-8;  // relative change of the (log-)parameters that stops the outer loop
  // Resolved against the fit file's folder (as a scene's output.directory); default out/<name>.
  std::string output_directory;
  // `drape fit --set key.path=value`: applied to every specimen's scene before the fitted
  // parameters (which win where both name a key).
  std::vector<std::string> scene_overrides;
  Location method_where;
  Location root;
  // What the checks found worth saying but not refusing (FitMeshWarning): `drape fit` prints
  // them on stderr and fit.json lists them.
  std::vector<std::string> warnings;
};

// The warning for a drape coefficient measured on `scene` (a specimen's, at the initial
// parameters) whose mesh rule (src/analysis/mesh_rule.h) expects a discretisation error above
// the measurement's sigma: the fitted parameters would absorb it as a bias. Empty otherwise.
std::string FitMeshWarning(const Scene& scene, const Model& model,
                           const FitMeasurement& measurement);

// Loads and checks `path` and the files it names (scenes are loaded once with every parameter at
// its initial value, which checks the keys). `scene_overrides` become FitSpec::scene_overrides.
// Throws InputError on any bad input.
FitSpec LoadFitFile(const std::string& path, const std::vector<std::string>& scene_overrides = {});

// The specimen's scene with every parameter at `theta`: loaded from the document read once, with
// spec.scene_overrides and then each parameter set as a number (SceneValue), not as text.
Scene SpecimenSceneAt(const FitSpec& spec, const FitSpecimen& specimen,
                      const std::vector<double>& theta);

// Reads a positions file (`id,x,y,z`, or `x,y,z` / .xyz / .ply as a point cloud); `where` locates
// the key that names it. Throws InputError located in the data file for a bad row.
PositionData ReadPositionFile(const std::string& path, const Location& where);
ReactionData ReadReactionFile(const std::string& path, const Location& where);

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_FILE_H_
