// The residual of each measurement kind, the closest point on a triangle, and the virtual Peirce
// test against Peirce's own geometry and the bending length (D / ρg)^⅓.
#include "src/fit/fit_measurements.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "tests/fit_test_support.h"

namespace drape::testing {
namespace {

TEST(FitMeasurementsTest, ClosestPointOnTriangleBeatsEverySample) {
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto random_point = [&] {
    return Eigen::Vector3d(uniform(generator), uniform(generator), uniform(generator));
  };
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d a = random_point(), b = random_point(), c = random_point(),
                          p = 2.0 * random_point();
    const Eigen::Vector3d closest = ClosestPointOnTriangle(p, a, b, c);
    // On the triangle: barycentric coordinates in [0, 1].
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    EXPECT_NEAR(normal.dot(closest - a), 0.0, 1e-12);
    // No sampled point of the triangle is nearer.
    const double distance = (closest - p).norm();
    for (int i = 0; i <= 40; ++i) {
      for (int j = 0; i + j <= 40; ++j) {
        const Eigen::Vector3d q = a + (b - a) * (i / 40.0) + (c - a) * (j / 40.0);
        EXPECT_LE(distance, (q - p).norm() + 1e-12);
      }
    }
  }
}

TEST(FitMeasurementsTest, PeirceFormulaAtTheStandardAngle) {
  // c = l (cos(θ/2) / (8 tan θ))^⅓; at θ = 41.5° the ratio c/l is 0.509 (ASTM D1388 takes l/2).
  const double angle = 41.5 * M_PI / 180.0;
  const double expected = std::cbrt(std::cos(angle / 2) / (8 * std::tan(angle)));
  EXPECT_NEAR(PeirceBendingLength(1.0, angle), expected, 1e-15);
  EXPECT_NEAR(PeirceBendingLength(0.1, angle), 0.05, 0.001);
}

// The virtual strip of a material with bending length c0 = (D/ρg)^⅓, with the overhang 2 c0,
// gives back c0 within Peirce's approximation (his formula is 1.9% high at 41.5°,
// tests/cantilever_test.cc; the rest is the strip's discretisation and extension).
TEST(FitMeasurementsTest, VirtualPeirceStripGivesTheBendingLength) {
  const Scene specimen = LoadConfig("configs/fit/drape_fv.yaml");
  FitMeasurement measurement;
  measurement.kind = FitMeasurement::Kind::kBendingLength;
  measurement.sigma = 0.001;
  for (const std::string direction : {"warp", "weft"}) {
    const double d = direction == "warp" ? 1.0e-4 : 5.0e-5;  // the scene's D_warp, D_weft
    const double c0 = std::cbrt(d / (0.15 * 9.81));
    measurement.value = c0;
    measurement.direction = direction;
    Scene strip = PeirceStripScene(specimen, measurement);
    strip.solver.tolerance = 1e-8;  // the strip's roundoff floor is above 1e-10
    EXPECT_EQ(strip.dimension, 2);
    EXPECT_DOUBLE_EQ(strip.material.finite_volume.D_warp, d);
    Model model = BuildModel(strip);
    // The overhang beyond the clamp (midway between nodes 0 and 1) is 2 c0.
    const double h = model.positions[3] - model.positions[0];
    EXPECT_NEAR(model.positions[3 * (model.num_nodes - 1)] - h / 2, 2 * c0, 1e-12);
    const RunResult result = RunSolve(strip, model, "newton");
    ASSERT_TRUE(result.converged);
    const MeasuredValue value = EvaluateMeasurement(measurement, model, model.positions.data(), {});
    EXPECT_NEAR(value.model_value / c0, 1.0, 0.03) << direction;
    EXPECT_NEAR(value.residuals[0], (value.model_value - c0) / 0.001, 1e-12);
  }
}

// The strip bends with the measured direction's friction moment, and reads a longer bending length
// than the elastic strip (tests/fv_bending_friction_test.cc checks the friction cantilever itself).
TEST(FitMeasurementsTest, VirtualPeirceStripCarriesTheDirectionsFriction) {
  Scene specimen = LoadConfig("configs/fit/drape_fv.yaml");
  FitMeasurement measurement;
  measurement.kind = FitMeasurement::Kind::kBendingLength;
  measurement.sigma = 0.001;
  measurement.value = std::cbrt(5.0e-5 / (0.15 * 9.81));  // the weft's c0
  measurement.direction = "weft";
  const MeasuredValue elastic = [&] {
    Scene strip = PeirceStripScene(specimen, measurement);
    Model model = BuildModel(strip);
    EXPECT_TRUE(RunSolve(strip, model, "newton").converged);
    return EvaluateMeasurement(measurement, model, model.positions.data(), {});
  }();
  specimen.material.finite_volume.bending_friction_warp = 1.0e-4;  // N
  specimen.material.finite_volume.bending_friction_weft = 2.0e-4;
  Scene strip = PeirceStripScene(specimen, measurement);
  EXPECT_EQ(strip.material.finite_volume.bending_friction_warp, 2.0e-4);
  EXPECT_EQ(strip.material.finite_volume.bending_friction_weft, 2.0e-4);
  Model model = BuildModel(strip);
  ASSERT_TRUE(RunSolve(strip, model, "newton").converged);
  const MeasuredValue frictional =
      EvaluateMeasurement(measurement, model, model.positions.data(), {});
  EXPECT_GT(frictional.model_value, elastic.model_value * 1.01);
}

TEST(FitMeasurementsTest, PositionsByIdAndAsACloud) {
  const TrueSolve solved = SolveTruth("configs/fit/drape_fv.yaml", {});
  const Model& model = solved.model;
  FitMeasurement by_id;
  by_id.kind = FitMeasurement::Kind::kPositions;
  by_id.sigma = 0.002;
  by_id.weight = 4.0;
  by_id.positions.ids = {0, 7};
  by_id.positions.points = {Position(model, 0) + Eigen::Vector3d(0.001, 0, 0),
                            Position(model, 7) - Eigen::Vector3d(0, 0, 0.003)};
  const MeasuredValue r = EvaluateMeasurement(by_id, model, model.positions.data(), {});
  ASSERT_EQ(r.residuals.size(), 6u);
  // (model − measured) / sigma × √weight.
  EXPECT_NEAR(r.residuals[0], -0.001 / 0.002 * 2.0, 1e-9);
  EXPECT_NEAR(r.residuals[5], 0.003 / 0.002 * 2.0, 1e-9);
  // A cloud: a point on a face has zero distance; a point lifted off a flat clamped face (the
  // clamped centre is flat at z = 0) by 1 mm has distance 1 mm.
  FitMeasurement cloud;
  cloud.kind = FitMeasurement::Kind::kPositions;
  cloud.sigma = 0.001;
  cloud.positions.cloud = true;
  const auto& t = model.triangles[model.triangles.size() / 3];
  const Eigen::Vector3d centroid =
      (Position(model, t[0]) + Position(model, t[1]) + Position(model, t[2])) / 3.0;
  cloud.positions.points = {centroid, Eigen::Vector3d(0.001, 0.002, 0.001)};
  const MeasuredValue d = EvaluateMeasurement(cloud, model, model.positions.data(), {});
  EXPECT_NEAR(Eigen::Vector3d(d.residuals[0], d.residuals[1], d.residuals[2]).norm(), 0.0, 1e-9);
  EXPECT_NEAR(Eigen::Vector3d(d.residuals[3], d.residuals[4], d.residuals[5]).norm(), 1.0, 1e-9);
}

TEST(FitMeasurementsTest, ReactionsBalanceTheWeight) {
  const TrueSolve solved = SolveTruth("configs/fit/sheet_springs.yaml", {});
  // Four corners of a symmetric hammock: each carries a quarter of the weight 0.2 × 0.25 × 9.81 N.
  FitMeasurement reactions;
  reactions.kind = FitMeasurement::Kind::kReactions;
  reactions.sigma = 1.0;
  reactions.reactions.ids = {0, 8, 72, 80};
  const double quarter = 0.2 * 0.25 * 9.81 / 4.0;
  reactions.reactions.forces.assign(4, Eigen::Vector3d(0, 0, 0));
  const MeasuredValue r =
      EvaluateMeasurement(reactions, solved.model, solved.model.positions.data(), {});
  ASSERT_EQ(r.residuals.size(), 12u);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(r.residuals[3 * k + 2], quarter, 1e-9);
}

TEST(FitMeasurementsTest, DrapeCoefficientOfAFlatSpecimenIsOne) {
  const Scene scene = LoadConfig("configs/fit/drape_fv.yaml");
  const Model model = BuildModel(scene);  // flat: at its initial positions
  FitMeasurement dc;
  dc.kind = FitMeasurement::Kind::kDrapeCoefficient;
  dc.sigma = 0.01;
  dc.value = 0.5;
  MeasurementContext context;
  context.disc_radius = 0.06;
  const MeasuredValue r = EvaluateMeasurement(dc, model, model.positions.data(), context);
  EXPECT_NEAR(r.model_value, 1.0, 1e-9);
  EXPECT_NEAR(r.residuals[0], 0.5 / 0.01, 1e-6);
}

}  // namespace
}  // namespace drape::testing
