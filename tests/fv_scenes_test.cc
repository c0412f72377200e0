// The scenes of configs/fv/ (the drape tester, the square table, the sphere, the cantilevers):
// every one loads, and newton solves it on a coarse mesh to its tolerance at a stable equilibrium;
// the drape coefficient of a specimen that does not overhang is 1, and it is unchanged when the
// whole drape is scaled in a way that keeps its equilibrium geometrically similar.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "src/analysis/drape_analysis.h"
#include "src/run/run.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

struct CoarseScene {
  std::string file;  // in configs/fv/
  std::vector<std::string> overrides;
};

// Coarse versions of about 110–230 nodes: the circles at 2, 2.5 and 3 cm spacing for the 24, 30
// and 36 cm specimens, the squares at 15 × 15, the strips at 21 nodes.
std::vector<CoarseScene> CoarseScenes() {
  const std::vector<std::string> square = {"mesh.nodes=[15, 15]"};
  const std::vector<std::string> strip = {"mesh.nodes=[21, 1]"};
  std::vector<CoarseScene> scenes = {{"cantilever.yaml", strip},
                                     {"cantilever_tip.yaml", strip},
                                     {"square_table.yaml", square},
                                     {"square_table_seam.yaml", square},
                                     {"drape_tester_cotton_30_hem.yaml", {"mesh.spacing=0.025"}},
                                     {"drape_tester_limp_30.yaml", {"mesh.spacing=0.025"}},
                                     {"sphere.yaml", square},
                                     {"sphere_mesh.yaml", square},
                                     {"corner_plate.yaml", square},
                                     {"sheet_on_slope.yaml", {}}};  // 11 × 11 already
  for (const char* fabric : {"cotton", "polyester"}) {
    for (const auto& [size, spacing] :
         {std::pair<const char*, const char*>{"24", "0.02"}, {"30", "0.025"}, {"36", "0.03"}}) {
      scenes.push_back({std::string("drape_tester_") + fabric + "_" + size + ".yaml",
                        {std::string("mesh.spacing=") + spacing}});
    }
  }
  return scenes;
}

TEST(FvScenes, EverySceneHasACoarseVersionAndBuilds) {
  std::set<std::string> listed;
  for (const auto& scene : CoarseScenes()) listed.insert(scene.file);
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::SourcePath("configs/fv"))) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string file = entry.path().filename().string();
    EXPECT_EQ(listed.count(file), 1u) << file << " has no coarse version in this test";
    const Scene scene = LoadScene(entry.path().string());
    EXPECT_EQ(scene.material.model, MaterialModel::kFiniteVolume) << file;
    EXPECT_GT(BuildModel(scene).num_nodes, 20) << file;
    ++count;
  }
  EXPECT_EQ(count, static_cast<int>(listed.size()));
}

class FvSceneCoarse : public ::testing::TestWithParam<CoarseScene> {};

// Newton reaches each scene's own tolerance, and the equilibrium is a stable minimum (the drapes
// rest on their obstacles, held in-plane where the obstacle cannot hold them; the cantilevers
// droop under their weight or load).
TEST_P(FvSceneCoarse, NewtonSolvesItToAStableEquilibrium) {
  const CoarseScene& c = GetParam();
  const auto solved =
      testing::SolveConfig(std::string("configs/fv/") + c.file, "newton", c.overrides);
  ASSERT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_LE(solved.result.certificate.relative_residual, solved.scene.solver.tolerance);
  EXPECT_TRUE(solved.result.stability.computed);
  EXPECT_TRUE(solved.result.stability.stable) << solved.result.stability.min_eigenvalue;
  if (DiscRadius(solved.scene) > 0.0) {  // a drape tester: the fabric hangs, 0 < DC < 1
    const DrapeCoefficient dc = ComputeDrapeCoefficient(solved.model, DiscRadius(solved.scene));
    EXPECT_GT(dc.cusick, 0.0);
    EXPECT_LT(dc.cusick, 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(FvScenes, FvSceneCoarse, ::testing::ValuesIn(CoarseScenes()),
                         [](const auto& test) {
                           std::string name = test.param.file;
                           name = name.substr(0, name.find('.'));
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

// The square table with a tension-only seam across it (material.lines on a finite-volume fabric):
// newton reaches a certified stable minimum; the seam's own energy is reported; no seam spring
// pushes (each one's tension dE/dl is ≥ 0, and zero wherever the seam is shorter than it was);
// and without its line terms the model is exactly the plain square table's: the same solution,
// bitwise.
TEST(FvScenes, TensionOnlySeamOnAFiniteVolumeTablecloth) {
  const std::vector<std::string> square = {"mesh.nodes=[15, 15]"};
  auto seam = testing::SolveConfig("configs/fv/square_table_seam.yaml", "newton", square);
  ASSERT_TRUE(seam.result.converged) << seam.result.summary.termination;
  EXPECT_TRUE(seam.result.stability.computed);
  EXPECT_TRUE(seam.result.stability.stable) << seam.result.stability.min_eigenvalue;
  ASSERT_EQ(seam.result.certificate.energy_by_type.count("line"), 1u);
  EXPECT_GT(seam.result.certificate.energy_by_type.at("line"), 0.0);
  EXPECT_EQ(seam.model.TermCounts().at("line"), 14);  // the 14 warp links of the middle row
  int compressed = 0, stretched = 0;
  for (const auto& term : seam.model.terms) {
    if (term->type() != "line") continue;
    const int a = term->nodes()[0], b = term->nodes()[1];
    const Eigen::Vector3d d = seam.model.position(b) - seam.model.position(a);
    const double rest = (seam.model.initial_position(b) - seam.model.initial_position(a)).norm();
    double energy = 0.0, gradient[6];
    ASSERT_TRUE(term->EnergyGradient(seam.model.positions.data(), &energy, gradient));
    const double tension =
        Eigen::Vector3d(gradient[3], gradient[4], gradient[5]).dot(d.normalized());
    EXPECT_GE(tension, 0.0);
    if (d.norm() < rest) {
      ++compressed;
      EXPECT_EQ(tension, 0.0);
      EXPECT_EQ(energy, 0.0);
    } else {
      ++stretched;
    }
  }
  std::printf("seam: %d links stretched, %d shorter than at rest (slack)\n", stretched, compressed);
  EXPECT_GT(stretched, 0);

  auto plain = testing::SolveConfig("configs/fv/square_table.yaml", "newton", square);
  Model without = BuildModel(seam.scene);
  std::vector<std::unique_ptr<Term>> kept;
  std::vector<int> new_index;  // of each old term (the contact terms are listed by index)
  for (auto& term : without.terms) {
    new_index.push_back(static_cast<int>(kept.size()));
    if (term->type() != "line") kept.push_back(std::move(term));
  }
  without.terms = std::move(kept);
  for (auto& contact : without.contact_terms) contact.term = new_index[contact.term];
  ASSERT_EQ(without.TermCounts(), plain.model.TermCounts());
  const RunResult run = RunSolve(plain.scene, without, "newton");
  ASSERT_TRUE(run.converged) << run.summary.termination;
  EXPECT_EQ(without.positions, plain.model.positions);
  EXPECT_EQ(run.certificate.energy, plain.result.certificate.energy);
}

// The override the issue quotes — tension-only structural springs beside the finite volumes of
// the drape tester — builds one energy of both that newton takes to a certified stable minimum,
// reporting the springs' energy apart from the fabric's.
TEST(FvScenes, TensionOnlySpringsBesideFiniteVolumes) {
  const auto solved = testing::SolveConfig(
      "configs/fv/drape_tester_cotton_30.yaml", "newton",
      {"mesh.spacing=0.025", "material.springs={structural: 100, tension_only: true}"});
  ASSERT_TRUE(solved.result.converged) << solved.result.summary.termination;
  EXPECT_LE(solved.result.certificate.relative_residual, solved.scene.solver.tolerance);
  EXPECT_TRUE(solved.result.stability.computed);
  EXPECT_TRUE(solved.result.stability.stable) << solved.result.stability.min_eigenvalue;
  const auto& energy = solved.result.certificate.energy_by_type;
  ASSERT_EQ(energy.count("structural"), 1u);
  ASSERT_EQ(energy.count("fv_bending"), 1u);
  EXPECT_GE(energy.at("structural"), 0.0);
  EXPECT_GT(solved.model.TermCounts().at("structural"), 0);
}

// The drape tester with a hem (a region at the rim): the hem's nodes, and only they, carry twice
// the density, and their bending terms four times the rigidity.
TEST(FvScenes, HemRegionDoublesTheRimsDensity) {
  const std::vector<std::string> coarse = {"mesh.spacing=0.025"};
  const Scene hem = testing::LoadConfig("configs/fv/drape_tester_cotton_30_hem.yaml", coarse);
  const Scene plain = testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml", coarse);
  const Model with = BuildModel(hem), without = BuildModel(plain);
  ASSERT_EQ(with.num_nodes, without.num_nodes);
  ASSERT_EQ(with.region_counts.size(), 1u);
  int rim = 0;
  for (int k = 0; k < with.num_nodes; ++k) {
    const double r = std::hypot(with.position(k).x(), with.position(k).y());
    const double factor = r >= 0.14 - 1e-9 ? 2.0 : 1.0;
    rim += factor > 1.0 ? 1 : 0;
    EXPECT_DOUBLE_EQ(with.mass[k], factor * without.mass[k]) << k;
  }
  EXPECT_EQ(rim, with.region_counts[0].selected);
  EXPECT_GT(rim, 10);
  EXPECT_DOUBLE_EQ(hem.regions[0].finite_volume.at("D_warp"),
                   4 * plain.material.finite_volume.D_warp);
}

// Cusick's DC = (A_shadow − A_disc)/(A_specimen − A_disc) is defined for a specimen that overhangs
// the disc. A specimen no larger than the disc cannot hang: it lies flat, its shadow is its flat
// area, and DC = 1 (the stiff limit) — for a smaller specimen the ratio of two equal negative
// numbers, for A_specimen = A_disc by convention (ComputeDrapeCoefficient; no 0/0).
TEST(FvScenes, SpecimenNoLargerThanTheDiscHasDrapeCoefficientOne) {
  // 16 cm specimen on the 18 cm disc: every node lies within the clamped region. (A drape_test
  // block refuses a specimen no larger than its disc: the radius is set past the loader.)
  testing::Solved solved{
      testing::LoadConfig("configs/fv/drape_tester_polyester_24.yaml", {"mesh.spacing=0.02"}),
      Model{}, RunResult{}};
  solved.scene.mesh.radius = 0.08;
  solved.model = BuildModel(solved.scene);
  solved.result = RunSolve(solved.scene, solved.model, "newton");
  ASSERT_TRUE(solved.result.converged) << solved.result.summary.termination;
  const double disc = DiscRadius(solved.scene);
  ASSERT_DOUBLE_EQ(disc, 0.09);
  const DrapeCoefficient smaller = ComputeDrapeCoefficient(solved.model, disc);
  EXPECT_LT(smaller.flat_area, M_PI * disc * disc);
  EXPECT_NEAR(smaller.cusick, 1.0, 1e-12);
  EXPECT_NEAR(smaller.ratio, 1.0, 1e-12);
  // A disc of exactly the specimen's (flat) area.
  const double equal_radius = std::sqrt(smaller.flat_area / M_PI);
  EXPECT_DOUBLE_EQ(ComputeDrapeCoefficient(solved.model, equal_radius).cusick, 1.0);
}

// Geometric similarity. Scale every length by λ (mesh, disc, the held region, the contact
// thickness), keep the areal density ρ and gravity g, and scale D by λ³ and E, G by λ. For the
// configuration x' = λx every energy then scales by λ³:
//   bending  ½ D κ² A:        κ' = κ/λ, A' = λ² A, D' = λ³ D        → λ³;
//   membrane ½ E ε² A:        ε' = ε (strains are ratios), E' = λ E  → λ³;
//   gravity  ρ g z A:         z' = λ z, A' = λ² A                    → λ³;
//   contact  (k/3) g_c³ with k = F_ref/(f t)²: F_ref (the weight, ∝ ρ g A) → λ² F_ref,
//            t' = λ t, so k' = k, and the depth g_c' = λ g_c          → λ³.
// So Π'(λx) = λ³ Π(x): equilibria map to equilibria with the same stability, and the shadow
// (an area, × λ²) over A_specimen − A_disc (× λ²) gives the same DC. Equivalently the drape
// depends on lengths only through ratios to the bending length c = (D/ρg)^(1/3), which scales
// by λ. The shadow is rasterised on a pixel grid that scales with the extent, so both runs see
// the same pixels; what differs is rounding and the solver's tolerance.
TEST(FvScenes, DrapeCoefficientIsInvariantUnderGeometricScaling) {
  const std::vector<std::string> coarse = {"mesh.spacing=0.02"};
  Scene scene = testing::LoadConfig("configs/fv/drape_tester_polyester_24.yaml", coarse);
  const double lambda = 2.5;
  Scene scaled = scene;
  scaled.mesh.radius *= lambda;
  scaled.mesh.spacing *= lambda;
  scaled.mesh.origin *= lambda;
  FiniteVolumeSpec& fv = scaled.material.finite_volume;
  for (double* d : {&fv.D_warp, &fv.D_weft, &fv.D_12, &fv.D_66}) *d *= lambda * lambda * lambda;
  for (double* e : {&fv.E_warp, &fv.E_weft, &fv.G}) *e *= lambda;
  for (FixedSpec& fixed : scaled.fixed) {
    fixed.nodes.center *= lambda;
    fixed.nodes.radius *= lambda;
  }
  for (ObstacleSpec& obstacle : scaled.obstacles) {
    obstacle.center *= lambda;
    obstacle.radius *= lambda;
  }
  scaled.contact.thickness *= lambda;
  double dc[2];
  int k = 0;
  for (const Scene* s : {&scene, &scaled}) {
    Model model = BuildModel(*s);
    const RunResult run = RunSolve(*s, model, "newton");
    ASSERT_TRUE(run.converged) << run.summary.termination;
    dc[k++] = ComputeDrapeCoefficient(model, DiscRadius(*s)).cusick;
  }
  EXPECT_GT(dc[0], 0.05);
  EXPECT_LT(dc[0], 0.95);
  EXPECT_NEAR(dc[1], dc[0], 1e-6);
}

}  // namespace
}  // namespace drape
