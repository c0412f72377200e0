#include "src/analysis/drape_analysis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "src/model/mesh.h"
#include "tests/folded_skirt.h"

namespace drape {
namespace {

// A regular polygon of `sides` around the origin, as a fan of triangles (node 0 = centre).
void Fan(int sides, double radius, double z, std::vector<double>* positions,
         std::vector<std::array<int, 3>>* triangles) {
  positions->assign({0.0, 0.0, z});
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * M_PI * k / sides;
    positions->insert(positions->end(), {radius * std::cos(angle), radius * std::sin(angle), z});
    triangles->push_back({0, 1 + k, 1 + (k + 1) % sides});
  }
}

TEST(ProjectedArea, FlatSquareOfTwoTriangles) {
  const std::vector<double> positions = {0, 0, 0, 0.3, 0, 0, 0.3, 0.3, 0, 0, 0.3, 0};
  const Shadow shadow = ProjectedArea(positions, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_NEAR(shadow.area, 0.09, shadow.error_bound);
  EXPECT_LT(shadow.error_bound, 1e-3 * 0.09);  // 4 × 0.3 m × (0.3 m / 2048) / 2
}

TEST(ProjectedArea, FlatDiscIsThePolygonsArea) {
  std::vector<double> positions;
  std::vector<std::array<int, 3>> triangles;
  const int sides = 256;
  Fan(sides, 0.15, 0.0, &positions, &triangles);
  const double exact = 0.5 * sides * 0.15 * 0.15 * std::sin(2.0 * M_PI / sides);
  const Shadow shadow = ProjectedArea(positions, triangles);
  EXPECT_NEAR(shadow.area, exact, shadow.error_bound);
  // The bound is honest but not loose by orders of magnitude.
  EXPECT_LT(std::abs(shadow.area - exact), shadow.error_bound);
  EXPECT_LT(shadow.error_bound, 2e-3 * exact);
}

TEST(ProjectedArea, OverlappingTrianglesCountOnce) {
  // Triangle A (0,0) (2,0) (0,2), area 2; triangle B (1,0) (3,0) (1,2) lies above it, area 2,
  // wound the other way. Their intersection is (1,0) (2,0) (1,1), area 1/2: the union is 3.5.
  const std::vector<double> positions = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 1, 1, 2, 1, 3, 0, 1};
  const Shadow shadow = ProjectedArea(positions, {{0, 1, 2}, {3, 4, 5}});
  EXPECT_NEAR(shadow.area, 3.5, shadow.error_bound);
  EXPECT_GT(std::abs(shadow.area - 4.0), 10 * shadow.error_bound);  // not the sum of the areas
}

TEST(ProjectedArea, VerticalTrianglesAndNoTrianglesCastNoShadow) {
  const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(ProjectedArea(positions, {{0, 1, 2}}).area, 0.0);
  EXPECT_EQ(ProjectedArea(positions, {}).area, 0.0);
}

TEST(ProjectedArea, FinerResolutionShrinksTheErrorBound) {
  std::vector<double> positions;
  std::vector<std::array<int, 3>> triangles;
  Fan(64, 1.0, 0.0, &positions, &triangles);
  const Shadow coarse = ProjectedArea(positions, triangles, {256});
  const Shadow fine = ProjectedArea(positions, triangles, {4096});
  EXPECT_NEAR(coarse.error_bound / fine.error_bound, 16.0, 1.0);
  EXPECT_NEAR(coarse.area, fine.area, coarse.error_bound);
}

TEST(DrapeCoefficient, RatioAndCusicksFormula) {
  Model model;
  std::vector<double> flat;
  Fan(128, 0.15, 0.0, &flat, &model.triangles);
  model.initial = flat;
  // The draped shape: the same disc shrunk to 0.12 m radius and lowered.
  model.positions = flat;
  for (size_t k = 0; k < flat.size(); k += 3) {
    model.positions[k] *= 0.8;
    model.positions[k + 1] *= 0.8;
    model.positions[k + 2] = -0.05;
  }
  const DrapeCoefficient dc = ComputeDrapeCoefficient(model, 0.09);
  EXPECT_NEAR(dc.ratio, 0.64, 1e-3);
  const double disc = M_PI * 0.09 * 0.09;
  EXPECT_NEAR(dc.cusick, (0.64 * dc.flat_area - disc) / (dc.flat_area - disc), 2e-3);
  EXPECT_TRUE(std::isnan(ComputeDrapeCoefficient(model).cusick));
}

// ---- radial profile ----------------------------------------------------------------------------

TEST(RadialProfile, OfARegularPolygonIsItsClosedForm) {
  // A polygon of circumradius R with a vertex at angle 0, around (0.02, −0.01): along θ the
  // outline is at R cos(π/n) / cos(θ − θ_mid), θ_mid the direction of the side's midpoint.
  const int sides = 12;
  const double radius = 0.15;
  std::vector<double> positions;
  std::vector<std::array<int, 3>> triangles;
  Fan(sides, radius, -0.1, &positions, &triangles);
  for (size_t k = 0; k < positions.size(); k += 3) {
    positions[k] += 0.02;
    positions[k + 1] -= 0.01;
  }
  const RadialProfile profile = ComputeRadialProfile(positions, triangles, {0.02, -0.01});
  ASSERT_EQ(profile.radius.size(), 360u);
  const double side = 2.0 * M_PI / sides;
  for (int k = 0; k < 360; ++k) {
    const double theta = profile.theta[k];
    EXPECT_NEAR(theta, k * M_PI / 180.0, 1e-15);
    const double middle = (std::floor(theta / side) + 0.5) * side;
    const double exact = radius * std::cos(M_PI / sides) / std::cos(theta - middle);
    EXPECT_NEAR(profile.radius[k], exact, 1e-12) << k;
  }
}

TEST(RadialProfile, KeepsTheOuterBoundaryOfOverlapsAndHoles) {
  // An annulus (0.1 m to 0.2 m, nothing inside) plus one triangle lying over it and reaching out
  // to 0.3 m along θ = 0: the profile is the outer radius, not the inner one, and 0.3 m at θ = 0.
  const int sides = 180;
  std::vector<double> positions;
  std::vector<std::array<int, 3>> triangles;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * M_PI * k / sides;
    positions.insert(positions.end(), {0.1 * std::cos(a), 0.1 * std::sin(a), 0.0});
    positions.insert(positions.end(), {0.2 * std::cos(a), 0.2 * std::sin(a), 0.0});
  }
  for (int k = 0; k < sides; ++k) {
    const int inner = 2 * k, outer = 2 * k + 1, next = (2 * k + 2) % (2 * sides);
    triangles.push_back({inner, outer, next + 1});
    triangles.push_back({inner, next + 1, next});
  }
  const int tip = static_cast<int>(positions.size() / 3);
  positions.insert(positions.end(), {0.15, -0.03, 0.01, 0.3, 0.0, 0.01, 0.15, 0.03, 0.01});
  triangles.push_back({tip, tip + 1, tip + 2});
  const RadialProfile profile = ComputeRadialProfile(positions, triangles, {0.0, 0.0}, 720);
  EXPECT_NEAR(profile.radius[0], 0.3, 1e-12);
  const double chord = 0.2 * std::cos(M_PI / sides);
  for (int k = 20; k < 700; ++k) {
    EXPECT_LE(profile.radius[k], 0.2 + 1e-12) << k;
    EXPECT_GE(profile.radius[k], chord - 1e-12) << k;
  }
}

TEST(RadialProfile, EnclosesTheShadowAreaOfAStarShapedDrape) {
  // Where the shadow is star-shaped around the centre (no overlap: β = 0), ½ Σ r² Δθ is its area.
  SkirtShape shape;
  shape.beta = 0.0;
  const Model skirt = FoldedSkirt(shape);
  const RadialProfile profile =
      ComputeRadialProfile(skirt.positions, skirt.triangles, {0, 0}, 3600);
  double area = 0.0;
  for (double r : profile.radius) area += 0.5 * r * r * 2.0 * M_PI / 3600;
  const Shadow shadow = ProjectedArea(skirt.positions, skirt.triangles);
  // Sampling 0.1°: the polygon through the samples differs from the outline by far less than the
  // rasterisation's bound.
  EXPECT_NEAR(area, shadow.area, 2.0 * shadow.error_bound);
}

// ---- folds -------------------------------------------------------------------------------------

std::vector<double> Lobes(int n, double mean, double amplitude, double phase, double noise,
                          unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::vector<double> radius(360);
  for (int k = 0; k < 360; ++k) {
    radius[k] = mean + amplitude * std::cos(n * k * M_PI / 180.0 + phase) + gauss(random);
  }
  return radius;
}

TEST(CountFolds, ASinusoidalProfileWithNoiseHasItsNumberOfLobes) {
  for (int n = 4; n <= 12; ++n) {
    const double phase = 0.3 * n;
    // Noise of 10% of the amplitude on every sample (σ = 2 mm for 2 cm lobes on a 12 cm mean).
    const Folds folds = CountFolds(Lobes(n, 0.12, 0.02, phase, 0.002, 7 + n));
    ASSERT_EQ(folds.count, n) << n;
    // Crests at θ = (2πj − phase)/n, within 1° + 5% of the period (the noise moves the broad
    // crests of few folds more).
    const double period = 360.0 / n, offset = -phase * 180.0 / M_PI / n;
    for (double angle : folds.angles_deg) {
      EXPECT_LT(std::abs(std::remainder(angle - offset, period)), 1.0 + 0.05 * period) << n;
    }
  }
}

TEST(CountFolds, ACircleHasNone) {
  EXPECT_EQ(CountFolds(std::vector<double>(360, 0.15)).count, 0);
  // A circle with mesh-like noise (σ = 0.5 mm on 15 cm, i.e. 0.3%).
  EXPECT_EQ(CountFolds(Lobes(1, 0.15, 0.0, 0.0, 0.0005, 3)).count, 0);
  // Facets of a 64-gon (bumps of 0.12% of the radius, 5.6° apart).
  std::vector<double> polygon(360);
  for (int k = 0; k < 360; ++k) {
    const double side = 360.0 / 64, middle = (std::floor(k / side) + 0.5) * side;
    polygon[k] = 0.15 * std::cos(M_PI / 64) / std::cos((k - middle) * M_PI / 180.0);
  }
  EXPECT_EQ(CountFolds(polygon).count, 0);
}

TEST(CountFolds, KeepsMinorFoldsOfAnIrregularDrapeAndDropsRipples) {
  // Six folds (crests every 60°), the one at θ = 0 a third as high as the others.
  std::vector<double> radius(360);
  for (int k = 0; k < 360; ++k) {
    const double from_zero = std::min(k, 360 - k);
    const double envelope = 1.0 - 2.0 / 3.0 * std::exp(-0.5 * std::pow(from_zero / 25.0, 2));
    radius[k] = 0.12 + 0.02 * envelope * std::pow(std::cos(3.0 * k * M_PI / 180.0), 2);
  }
  const Folds irregular = CountFolds(radius);
  ASSERT_EQ(irregular.count, 6);
  EXPECT_NEAR(std::remainder(irregular.angles_deg[0], 360.0), 0.0, 1e-6);
  // Five folds with flat troughs (range 4 cm) and a ripple 2 mm (5% of the range) high in the
  // middle of a trough: a local maximum, but not a fold.
  std::vector<double> ripple(360);
  for (int k = 0; k < 360; ++k) {
    const double crest = std::max(0.0, std::cos(5.0 * k * M_PI / 180.0));
    ripple[k] =
        0.12 + 0.04 * crest * crest * crest + 0.002 * std::exp(-0.5 * std::pow((k - 36) / 4.0, 2));
  }
  EXPECT_EQ(CountFolds(ripple).count, 5);
  FoldOptions no_rule;
  no_rule.relative_prominence = no_rule.absolute_prominence = 0.0;
  EXPECT_EQ(CountFolds(ripple, no_rule).count, 6);
}

TEST(CountFolds, OfAHandBuiltFoldedSkirt) {
  // The projection of a skirt hanging in n lobes, folding over itself in the troughs (β = 1.5).
  for (int n = 4; n <= 12; n += 2) {
    SkirtShape shape;
    shape.lobes = n;
    const Model skirt = FoldedSkirt(shape);
    const RadialProfile profile = ComputeRadialProfile(skirt.positions, skirt.triangles, {0, 0});
    EXPECT_NEAR(profile.radius[0], SkirtCrestRadius(shape), 1e-12) << n;  // a crest on θ = 0
    const Folds folds = CountFolds(profile.radius);
    EXPECT_EQ(folds.count, n);
    const auto [low, high] = std::minmax_element(profile.radius.begin(), profile.radius.end());
    EXPECT_NEAR(*high, SkirtCrestRadius(shape), 1e-12);
    EXPECT_GT(*low, shape.disc_radius);
  }
}

// A scene whose only content is the drape tester's 18 cm support disc.
Scene SceneWithSupportDisc() {
  Scene scene;
  ObstacleSpec disk;
  disk.kind = "disk";
  disk.radius = 0.09;
  scene.obstacles.push_back(disk);
  return scene;
}

TEST(AnalyseDrape, CentresTheProfileOnTheDiskAndFindsTheFolds) {
  const Scene scene = SceneWithSupportDisc();
  SkirtShape shape;
  shape.lobes = 7;
  const Model skirt = FoldedSkirt(shape);
  ASSERT_TRUE(HasDrapeCoefficient(scene, skirt));
  const DrapeAnalysis analysis = AnalyseDrape(scene, skirt);
  EXPECT_EQ(analysis.disc_radius, 0.09);
  EXPECT_EQ(analysis.folds.count, 7);
  EXPECT_NEAR(analysis.radius_max, SkirtCrestRadius(shape), 1e-12);
  // The overhang fraction on the crest θ = 0: 0.8 of the flat overhang shows.
  EXPECT_NEAR(analysis.overhang[0], 0.8, 1e-9);
  EXPECT_NEAR(analysis.flat_profile.radius[90], shape.specimen_radius, 1e-12);
  EXPECT_GT(analysis.coefficient.cusick, 0.0);
  EXPECT_LT(analysis.coefficient.cusick, 1.0);
  // Without a disk the centre is the flat specimen's centroid.
  Model moved = FoldedSkirt(shape);
  for (size_t k = 0; k < moved.initial.size(); k += 3) moved.initial[k] += 0.5;
  const auto centre = ProfileCentre(Scene{}, moved);
  EXPECT_NEAR(centre[0], 0.5, 1e-12);
  EXPECT_NEAR(centre[1], 0.0, 1e-12);
}

// A lattice specimen (mesh kind circle: a staircase outline, 1 cm spacing on a 30 cm specimen).
Model LatticeSkirt(const SkirtShape& shape, bool draped) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kCircle;
  spec.radius = shape.specimen_radius;
  spec.spacing = 0.01;
  const Mesh mesh = BuildMesh(spec);
  Model model = SkirtModel(shape, mesh.nodes, mesh.triangles);
  if (!draped) model.positions = model.initial;
  return model;
}

// The same with its fringe out to the circle (src/model/mesh.h), as BuildModel gives it.
Model LatticeSkirtWithFringe(const SkirtShape& shape, bool draped) {
  Model model = LatticeSkirt(shape, draped);
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kCircle;
  spec.radius = shape.specimen_radius;
  spec.spacing = 0.01;
  model.fringe = BuildMesh(spec).fringe;
  return model;
}

TEST(AnalyseDrape, CountsTheFoldsOfTheDrapeNotTheStaircaseOfALatticeOutline) {
  const Scene scene = SceneWithSupportDisc();
  SkirtShape shape;
  shape.lobes = 7;
  const Model flat = LatticeSkirt(shape, false);
  const DrapeAnalysis undraped = AnalyseDrape(scene, flat);
  EXPECT_EQ(undraped.folds.count, 0);
  // The outline itself has false "folds" when counted on r(θ): the analysis must not use it so.
  EXPECT_GT(CountFolds(undraped.profile.radius).count, 0);
  EXPECT_EQ(AnalyseDrape(scene, LatticeSkirt(shape, true)).folds.count, 7);
}

// With its fringe, the lattice specimen's flat area is the disc's, πR², to 0.1 % (the target;
// finely rasterised, 4096 pixels across, so that the raster's error bound is below it), its
// outline no longer shows the staircase (0 folds on r(θ) itself), its drape keeps its 7 folds,
// and its drape coefficient comes nearer to the fine polar mesh's (120 spokes, whose outline
// holds πR² to 0.05 %). Without the fringe the 1 cm staircase leaves 5.8 % of the disc out of
// the flat area, and a different share out of the shadow: DC 0.6175 against the polar mesh's
// 0.6346 (measured at 8192 pixels across). With it, 0.6333: the test asks for at least a
// fivefold smaller error.
TEST(AnalyseDrape, ALatticeSpecimenWithItsFringeIsTheDisc) {
  const Scene scene = SceneWithSupportDisc();
  SkirtShape shape;
  shape.lobes = 7;
  ShadowOptions fine;
  fine.resolution = 4096;
  const double disc = M_PI * shape.specimen_radius * shape.specimen_radius;
  const DrapeCoefficient flat =
      ComputeDrapeCoefficient(LatticeSkirtWithFringe(shape, false), shape.disc_radius, fine);
  ASSERT_LT(flat.shadow.error_bound, 1e-3 * disc);
  EXPECT_NEAR(flat.flat_area, disc, 1e-3 * disc);
  EXPECT_NEAR(flat.cusick, 1.0, 1e-12);
  const DrapeAnalysis undraped = AnalyseDrape(scene, LatticeSkirtWithFringe(shape, false));
  EXPECT_EQ(undraped.folds.count, 0);
  EXPECT_EQ(CountFolds(undraped.profile.radius).count, 0);
  EXPECT_EQ(AnalyseDrape(scene, LatticeSkirtWithFringe(shape, true)).folds.count, 7);

  const double polar = ComputeDrapeCoefficient(FoldedSkirt(shape), shape.disc_radius, fine).cusick;
  const double with_fringe =
      ComputeDrapeCoefficient(LatticeSkirtWithFringe(shape, true), shape.disc_radius, fine).cusick;
  const double staircase =
      ComputeDrapeCoefficient(LatticeSkirt(shape, true), shape.disc_radius, fine).cusick;
  EXPECT_LT(5.0 * std::abs(with_fringe - polar), std::abs(staircase - polar));
}

}  // namespace
}  // namespace drape
