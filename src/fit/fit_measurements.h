// The residual of each measurement kind of `drape fit`: (model − measured) / sigma × √weight, as a
// function of the positions of one equilibrium. Also the virtual Peirce test's strip scene.
#ifndef DRAPE_SRC_FIT_FIT_MEASUREMENTS_H_
#define DRAPE_SRC_FIT_FIT_MEASUREMENTS_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/fit/fit_file.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

// What a measurement is compared with, computed from a model at `positions` (3 per node).
struct MeasuredValue {
  std::vector<double> residuals;  // normalised: (model − measured) / sigma × √weight
  double model_value = 0.0;       // scalar kinds: the model's drape coefficient / bending length
};

// The number of residuals a measurement contributes.
int ResidualCount(const FitMeasurement& measurement);

// What a measurement needs of its specimen besides the positions.
struct MeasurementContext {
  double disc_radius = 0.0;  // m, the specimen scene's support disc (0 if none)
  double flat_area = 0.0;    // m², the shadow of the flat specimen (0: computed here)
};

// The flat specimen's shadow area (m²), the denominator of the drape coefficient.
double FlatShadowArea(const Model& model);

// `model` is the equilibrium's model (reactions are its energy gradient at the fixed nodes). For a
// bending length, `model` is the Peirce strip of PeirceStripScene().
MeasuredValue EvaluateMeasurement(const FitMeasurement& measurement, const Model& model,
                                  const double* positions, const MeasurementContext& context);

// The virtual Peirce cantilever (Peirce 1930; ASTM D1388) for a bending-length measurement c_m:
// a 2-D finite-volume strip of the specimen's material (D and E of the measured direction,
// ν = 0, its density and gravity), 25 mm wide, clamped on a platform by its first two nodes,
// with an overhang l = 2 c_m (the standard instrument's geometry: a 41.5° chord angle at l = 2c).
// The strip's bending length follows from the chord angle θ from clamp to tip by Peirce's
// formula c = l (cos(θ/2) / (8 tan θ))^(1/3). Throws InputError at the measurement if the scene
// is not a finite-volume fabric with a density.
Scene PeirceStripScene(const Scene& specimen, const FitMeasurement& measurement);
constexpr int kPeirceStripNodes = 41;

// Peirce's bending length (m) of a strip with overhang `overhang` (m) whose chord from the clamp
// to the tip falls at `chord_angle` (rad) below the horizontal.
double PeirceBendingLength(double overhang, double chord_angle);

// The closest point to `p` on the triangle (a, b, c) (Voronoi regions of its vertices, edges and
// face).
Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_MEASUREMENTS_H_
