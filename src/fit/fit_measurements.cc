#include "src/fit/fit_measurements.h"

#include <cmath>
#include <limits>

#include "src/analysis/drape_analysis.h"
#include "src/model/equilibrium.h"
#include "src/scene/fabric_parameters.h"
#include "src/scene/material_models.h"

namespace drape {
namespace {

constexpr double kStripWidth = 0.025;  // m, ASTM D1388's 25 mm strip

Eigen::Vector3d Node(const double* positions, int id) {
  return Eigen::Vector3d(positions[3 * id], positions[3 * id + 1], positions[3 * id + 2]);
}

double Scale(const FitMeasurement& measurement) {
  return std::sqrt(measurement.weight) / measurement.sigma;
}

// Drape coefficient: Cusick's (A_shadow − π r²) / (A_flat − π r²) with the support disc radius r,
// or A_shadow / A_flat without one (Rusinko & Swan). Areas by src/analysis/drape_analysis.h.
ShadowOptions FitShadowOptions() {
  ShadowOptions options;
  options.resolution = 4096;
  return options;
}

double DrapeCoefficientAt(const Model& model, const double* positions, double disc_radius,
                          double flat) {
  const SpecimenSurface draped =
      SurfaceAt(model, std::vector<double>(positions, positions + model.num_dofs()));
  const double shadow = ProjectedArea(draped.points, draped.triangles, FitShadowOptions()).area;
  if (flat <= 0.0) flat = FlatShadowArea(model);
  if (disc_radius <= 0.0) return shadow / flat;
  return CusickCoefficient(shadow, flat, disc_radius);
}

// Each measured point against the model: by node id, the 3 coordinate differences; as a cloud, the
// 3 components of (point − closest point on the model's surface), whose norm is the distance.
std::vector<double> PositionResiduals(const FitMeasurement& measurement, const Model& model,
                                      const double* positions) {
  const PositionData& data = measurement.positions;
  std::vector<double> residuals;
  residuals.reserve(3 * data.points.size());
  for (size_t k = 0; k < data.points.size(); ++k) {
    Eigen::Vector3d difference;
    if (!data.cloud) {
      difference = Node(positions, data.ids[k]) - data.points[k];
    } else {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& t : model.triangles) {
        const Eigen::Vector3d closest = ClosestPointOnTriangle(
            data.points[k], Node(positions, t[0]), Node(positions, t[1]), Node(positions, t[2]));
        const double squared = (closest - data.points[k]).squaredNorm();
        if (squared < best) {
          best = squared;
          difference = closest - data.points[k];
        }
      }
    }
    for (int c = 0; c < 3; ++c) residuals.push_back(difference[c]);
  }
  return residuals;
}

// Reactions R = ∂E/∂x at the fixed coordinates (src/model/equilibrium.cc), against the measured
// forces.
std::vector<double> ReactionResiduals(const FitMeasurement& measurement, const Model& model,
                                      const double* positions) {
  double energy = 0.0;
  std::vector<double> gradient;
  std::vector<double> residuals;
  const bool evaluable = EvaluateEnergy(model, positions, &energy, &gradient);
  for (size_t k = 0; k < measurement.reactions.ids.size(); ++k) {
    const int id = measurement.reactions.ids[k];
    for (int c = 0; c < 3; ++c) {
      const double force =
          evaluable ? gradient[3 * id + c] : std::numeric_limits<double>::quiet_NaN();
      residuals.push_back(force - measurement.reactions.forces[k][c]);
    }
  }
  return residuals;
}

// The strip's chord angle: from the clamp (midway between the two fixed nodes 0 and 1, the face of
// the first free control volume) to the tip (the last node), below the horizontal.
double ChordAngle(const Model& model, const double* positions) {
  const Eigen::Vector3d clamp = 0.5 * (Node(positions, 0) + Node(positions, 1));
  const Eigen::Vector3d tip = Node(positions, model.num_nodes - 1);
  return std::atan2(clamp.z() - tip.z(), tip.x() - clamp.x());
}

}  // namespace

double FlatShadowArea(const Model& model) {
  const SpecimenSurface flat = SurfaceAt(model, model.initial);
  return ProjectedArea(flat.points, flat.triangles, FitShadowOptions()).area;
}

int ResidualCount(const FitMeasurement& measurement) {
  switch (measurement.kind) {
    case FitMeasurement::Kind::kPositions:
      return 3 * static_cast<int>(measurement.positions.points.size());
    case FitMeasurement::Kind::kReactions:
      return 3 * static_cast<int>(measurement.reactions.ids.size());
    default:
      return 1;
  }
}

MeasuredValue EvaluateMeasurement(const FitMeasurement& measurement, const Model& model,
                                  const double* positions, const MeasurementContext& context) {
  MeasuredValue result;
  const double scale = Scale(measurement);
  switch (measurement.kind) {
    case FitMeasurement::Kind::kDrapeCoefficient: {
      const double radius =
          measurement.disc_radius > 0 ? measurement.disc_radius : context.disc_radius;
      result.model_value = DrapeCoefficientAt(model, positions, radius, context.flat_area);
      result.residuals = {(result.model_value - measurement.value) * scale};
      return result;
    }
    case FitMeasurement::Kind::kBendingLength: {
      result.model_value =
          PeirceBendingLength(2.0 * measurement.value, ChordAngle(model, positions));
      result.residuals = {(result.model_value - measurement.value) * scale};
      return result;
    }
    case FitMeasurement::Kind::kPositions:
      result.residuals = PositionResiduals(measurement, model, positions);
      break;
    case FitMeasurement::Kind::kReactions:
      result.residuals = ReactionResiduals(measurement, model, positions);
      break;
  }
  double squared = 0.0;
  for (double& r : result.residuals) {
    squared += r * r;
    r *= scale;
  }
  // Vector kinds: the root-mean-square difference per point, in the measurement's unit.
  result.model_value = std::sqrt(3.0 * squared / std::max<size_t>(1, result.residuals.size()));
  return result;
}

double PeirceBendingLength(double overhang, double chord_angle) {
  return overhang * std::cbrt(std::cos(chord_angle / 2.0) / (8.0 * std::tan(chord_angle)));
}

Scene PeirceStripScene(const Scene& specimen, const FitMeasurement& measurement) {
  if (!MaterialModelOf(specimen.material.model).peirce_test) {
    throw InputError(measurement.where, "the virtual Peirce test needs material.model: " +
                                            MaterialModelsWith(&MaterialModelRow::peirce_test));
  }
  if (specimen.material.mass_kind != MaterialSpec::MassKind::kDensity) {
    throw InputError(measurement.where, "the virtual Peirce test needs material.density (kg/m²)");
  }
  Scene strip = specimen;
  strip.name = specimen.name + "-peirce-" + measurement.direction;
  strip.dimension = 2;
  // The clamp sits midway between the two fixed nodes: total length = overhang + h/2 with
  // h = total / (nodes − 1).
  const double overhang = 2.0 * measurement.value;
  const int nodes = kPeirceStripNodes;
  const double length = overhang * (nodes - 1) / (nodes - 1.5);
  MeshSpec mesh;
  mesh.kind = MeshSpec::Kind::kGrid;
  mesh.size = Eigen::Vector2d(length, kStripWidth);
  mesh.nodes = {nodes, 1};
  mesh.where = specimen.mesh.where;
  strip.mesh = mesh;
  FiniteVolumeSpec& fv = strip.material.finite_volume;
  if (measurement.direction == "weft") {
    fv.D_warp = fv.D_weft;
    fv.E_warp = fv.E_weft;
    fv.bending_friction_warp = fv.bending_friction_weft;
  }
  fv.D_weft = fv.D_warp;
  fv.E_weft = fv.E_warp;
  fv.bending_friction_weft = fv.bending_friction_warp;
  fv.nu_warp = fv.nu_weft = 0.0;
  fv.D_12 = 0.0;
  FixedSpec clamp;
  clamp.nodes.kind = NodeSelector::Kind::kIds;
  clamp.nodes.ids = {0, 1};
  clamp.nodes.where = measurement.where;
  clamp.where = measurement.where;
  strip.fixed = {clamp};
  const double g = specimen.loads.gravity ? specimen.loads.gravity->norm() : kStandardGravity;
  strip.loads = LoadsSpec{};
  strip.loads.gravity = Eigen::Vector3d(0.0, 0.0, -g);
  strip.loads.where = measurement.where;
  strip.obstacles.clear();
  return strip;
}

Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace drape
