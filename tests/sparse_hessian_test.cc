// FreeHessian (the free Hessian assembled from the terms into a pattern built once, and its
// per-term positive semidefinite projection) and SparseCholesky (CHOLMOD on it).
#include "src/numerics/sparse_hessian.h"

#include <SuiteSparse_config.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "tests/assembled_hessian.h"
#include "tests/hand_built_models.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

using testing::AssembledHessian;
using testing::Dense;
using testing::Sheet;
using testing::SheetSpec;

// A small sheet, two corners fixed, shrunk by `scale` about its centre and shaken, so that its
// springs are stretched and compressed in all directions.
Model ShakenSheet(double scale) {
  SheetSpec spec;
  spec.nu = 4;
  spec.nv = 3;
  spec.fixed = {0, 3};
  Model model = Sheet(spec);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (!model.fixed[k]) model.positions[k] = scale * model.positions[k] + noise(random);
  }
  return model;
}

// The 30 cm cotton drape tester at `spacing`, its free coordinates shaken by up to `amplitude` (m)
// so that some of its finite-volume terms are indefinite and need projecting.
Model ShakenDrape(const std::string& spacing, unsigned seed, double amplitude) {
  Model model = BuildModel(
      testing::LoadConfig("configs/fv/drape_tester_cotton_30.yaml", {"mesh.spacing=" + spacing}));
  const DofMap dofs(model);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> noise(-amplitude, amplitude);
  for (int k = 0; k < dofs.num_free(); ++k)
    model.positions[dofs.free_to_global()[k]] += noise(random);
  return model;
}

Eigen::VectorXd FreeGradient(const Model& model, const DofMap& dofs,
                             const std::vector<double>& positions) {
  double energy;
  std::vector<double> gradient;
  EXPECT_TRUE(EvaluateEnergy(model, positions.data(), &energy, &gradient));
  Eigen::VectorXd free(dofs.num_free());
  dofs.Gather(gradient.data(), free.data());
  return free;
}

TEST(FreeHessian, EqualsFiniteDifferencesOfTheAssembledGradient) {
  const Model model = ShakenSheet(0.9);
  const AssembledHessian assembled(model, /*project=*/false);
  const DofMap& dofs = assembled.dofs;
  const FreeHessian::Assembly& assembly = assembled.assembly;
  const std::vector<double>& gradient = assembled.gradient;
  const Eigen::MatrixXd exact = Dense(assembled.hessian, assembled.hessian.values());

  const double h = 1e-6;
  Eigen::MatrixXd differences(dofs.num_free(), dofs.num_free());
  for (int f = 0; f < dofs.num_free(); ++f) {
    std::vector<double> plus = model.positions, minus = model.positions;
    plus[dofs.free_to_global()[f]] += h;
    minus[dofs.free_to_global()[f]] -= h;
    differences.col(f) =
        (FreeGradient(model, dofs, plus) - FreeGradient(model, dofs, minus)) / (2.0 * h);
  }
  EXPECT_LT((exact - differences).cwiseAbs().maxCoeff(), 1e-6 * exact.cwiseAbs().maxCoeff());
  // The gradient is the model's, and the energy too.
  double energy;
  std::vector<double> reference;
  ASSERT_TRUE(EvaluateEnergy(model, model.positions.data(), &energy, &reference));
  EXPECT_NEAR(assembly.energy, energy, 1e-12 * assembly.energy_magnitude);
  for (size_t k = 0; k < reference.size(); ++k) EXPECT_NEAR(gradient[k], reference[k], 1e-10);
}

TEST(FreeHessian, ProjectedHessianIsPositiveSemidefiniteWhereTheTrueOneIsNot) {
  const Model model = ShakenSheet(0.8);  // many springs compressed
  const AssembledHessian assembled(model, /*project=*/true);
  EXPECT_GT(assembled.assembly.projected_terms, 0);
  const Eigen::MatrixXd exact = Dense(assembled.hessian, assembled.hessian.values());
  const Eigen::MatrixXd projected = Dense(assembled.hessian, assembled.hessian.projected_values());
  const double scale = exact.cwiseAbs().maxCoeff();
  EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact).eigenvalues().minCoeff(),
            -1e-3 * scale);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(projected).eigenvalues().minCoeff(),
            -1e-12 * scale);
}

// Each term's stand-in, summed over the free coordinates: what FreeHessian's projection must give,
// whatever shortcut it takes (the 3×3 block of a spring). A term with a staged projection gives its
// own (Term::EnergyHessianProjected, src/derivatives/fast_hessian.h); any other its Hessian
// projected by a full eigen-decomposition (negative eigenvalues replaced by their magnitudes, or by
// zero).
Eigen::MatrixXd ProjectedTermByTerm(const Model& model, const DofMap& dofs,
                                    EigenvalueFilter filter) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(dofs.num_free(), dofs.num_free());
  for (const auto& term : model.terms) {
    const int n = term->num_coordinates();
    std::vector<double> gradient(n), values(n * n), stand_in(n * n);
    double energy;
    Eigen::MatrixXd projected;
    if (term->HasStagedProjection()) {
      bool changed;
      EXPECT_TRUE(term->EnergyHessianProjected(model.positions.data(), filter, &energy,
                                               gradient.data(), values.data(), stand_in.data(),
                                               &changed));
      projected = Eigen::Map<Eigen::MatrixXd>(stand_in.data(), n, n);
    } else {
      EXPECT_TRUE(
          term->EnergyHessian(model.positions.data(), &energy, gradient.data(), values.data()));
      const Eigen::MatrixXd local = Eigen::Map<Eigen::MatrixXd>(values.data(), n, n);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(local);
      const Eigen::VectorXd filtered = filter == EigenvalueFilter::kAbsolute
                                           ? Eigen::VectorXd(eigen.eigenvalues().cwiseAbs())
                                           : Eigen::VectorXd(eigen.eigenvalues().cwiseMax(0.0));
      projected = eigen.eigenvectors() * filtered.asDiagonal() * eigen.eigenvectors().transpose();
    }
    for (int r = 0; r < n; ++r) {
      const int row = dofs.global_to_free()[3 * term->nodes()[r / 3] + r % 3];
      for (int c = 0; c < n; ++c) {
        const int column = dofs.global_to_free()[3 * term->nodes()[c / 3] + c % 3];
        if (row >= 0 && column >= 0) sum(row, column) += projected(r, c);
      }
    }
  }
  return sum;
}

TEST(FreeHessian, ProjectsEachSpringAsItsFullEigenDecompositionWould) {
  const Model model = ShakenSheet(0.8);
  const DofMap dofs(model);
  for (EigenvalueFilter filter : {EigenvalueFilter::kAbsolute, EigenvalueFilter::kClamp}) {
    const AssembledHessian assembled(model, /*project=*/true, filter);
    ASSERT_GT(assembled.assembly.projected_terms, 0);
    const Eigen::MatrixXd expected = ProjectedTermByTerm(model, dofs, filter);
    const Eigen::MatrixXd projected =
        Dense(assembled.hessian, assembled.hessian.projected_values());
    EXPECT_LT((projected - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
  }
}

// A shaken finite-volume drape: its terms build their stand-ins from their stages
// (src/derivatives/fast_hessian.h, checked term by term in tests/term_checks.h); the assembled H₊
// is their sum, and semidefinite where the true Hessian is not.
TEST(FreeHessian, FiniteVolumeStandInIsTheSumOfTheTermsAndSemidefinite) {
  const Model model = ShakenDrape("0.03", 5, 0.008);
  for (EigenvalueFilter filter : {EigenvalueFilter::kClamp, EigenvalueFilter::kAbsolute}) {
    const AssembledHessian assembled(model, /*project=*/true, filter);
    EXPECT_GT(assembled.assembly.projected_terms, 0);
    const Eigen::MatrixXd exact = Dense(assembled.hessian, assembled.hessian.values());
    const Eigen::MatrixXd projected =
        Dense(assembled.hessian, assembled.hessian.projected_values());
    const double scale = exact.cwiseAbs().maxCoeff();
    EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact).eigenvalues().minCoeff(),
              -1e-3 * scale);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(projected).eigenvalues().minCoeff(),
              -1e-10 * scale);
    const Eigen::MatrixXd expected = ProjectedTermByTerm(model, assembled.dofs, filter);
    EXPECT_LT((projected - expected).cwiseAbs().maxCoeff(), 1e-12 * scale);
  }
}

// The assembly's threads split the terms' local work only: energy, gradient, Hessian and its
// projection are bit-for-bit the same on 1, 2 and 3 threads (a finite-volume drape, shaken so that
// terms need projecting).
TEST(FreeHessian, AssemblyIsBitIdenticalForAnyThreadCount) {
  const Model model = ShakenDrape("0.015", 11, 0.004);
  const DofMap dofs(model);
  std::vector<double> reference_gradient;
  FreeHessian::Assembly reference;
  FreeHessian one(model, dofs);
  one.set_threads(1);
  ASSERT_TRUE(one.Assemble(model.positions.data(), true, &reference, &reference_gradient));
  EXPECT_GT(reference.projected_terms, 0);
  for (int threads : {2, 3}) {
    FreeHessian many(model, dofs);
    many.set_threads(threads);
    FreeHessian::Assembly assembly;
    std::vector<double> gradient;
    ASSERT_TRUE(many.Assemble(model.positions.data(), true, &assembly, &gradient));
    EXPECT_EQ(assembly.energy, reference.energy);
    EXPECT_EQ(assembly.projected_terms, reference.projected_terms);
    EXPECT_TRUE(gradient == reference_gradient) << threads << " threads";
    EXPECT_TRUE(many.values() == one.values()) << threads << " threads";
    EXPECT_TRUE(many.projected_values() == one.projected_values()) << threads << " threads";
  }
}

// The active set skips only contacts that add nothing: at a shaken drape whose fabric crosses the
// disc's clearance layer, with edges in it whose two nodes are clear of it (the rim's corner cut),
// the assembly with it equals the whole set's bit for bit.
TEST(FreeHessian, TheActiveSetMissesNoContactTheWholeSetWouldMake) {
  const Model model = ShakenDrape("0.01", 3, 0.0015);
  const DofMap dofs(model);
  const double* x = model.positions.data();
  int edges_through_layer_between_clear_nodes = 0;
  std::vector<bool> node_touches(model.num_nodes, false);
  for (const Model::ContactTerm& contact : model.contact_terms) {
    const Term& term = *model.terms[contact.term];
    if (contact.edge_points == 0) node_touches[term.nodes()[0]] = term.Touches(x);
  }
  for (const Model::ContactTerm& contact : model.contact_terms) {
    const Term& term = *model.terms[contact.term];
    if (contact.edge_points == 0 || !term.Touches(x)) continue;
    edges_through_layer_between_clear_nodes +=
        !node_touches[term.nodes()[0]] && !node_touches[term.nodes()[1]];
  }
  EXPECT_GT(edges_through_layer_between_clear_nodes, 0);
  double contact_energy = 0.0;
  for (const Model::ContactTerm& contact : model.contact_terms) {
    double energy = 0.0;
    ASSERT_TRUE(model.terms[contact.term]->Energy(x, &energy));
    contact_energy += energy;
  }
  EXPECT_GT(contact_energy, 0.0);
  FreeHessian active(model, dofs), whole(model, dofs);
  whole.set_active_set(false);
  FreeHessian::Assembly with_set, without_set;
  std::vector<double> gradient_with_set, gradient_without_set;
  ASSERT_TRUE(active.Assemble(x, true, &with_set, &gradient_with_set));
  ASSERT_TRUE(whole.Assemble(x, true, &without_set, &gradient_without_set));
  EXPECT_GT(with_set.skipped_terms, 0);
  EXPECT_LT(with_set.skipped_terms, static_cast<int>(model.contact_terms.size()));
  EXPECT_EQ(without_set.skipped_terms, 0);
  EXPECT_EQ(with_set.energy, without_set.energy);
  EXPECT_TRUE(gradient_with_set == gradient_without_set);
  EXPECT_TRUE(active.values() == whole.values());
  EXPECT_TRUE(active.projected_values() == whole.projected_values());
}

// Terms with no free coordinate (a drape's clamped centre) are evaluated at the first assembly and
// reused while the fixed positions stay: each assembly equals one that evaluates every term, bit
// for bit, and moving a fixed coordinate makes the next one evaluate them anew. The clamped nodes
// are moved off their rest state first, so that those terms carry energy and force (at rest both
// are zero, and a stale value could not show).
TEST(FreeHessian, ConstantTermsAreReusedOnlyWhileTheFixedPositionsStay) {
  Model model = ShakenDrape("0.01", 5, 0.002);
  const DofMap dofs(model);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  std::vector<int> fixed_coordinates;
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (dofs.global_to_free()[k] >= 0) continue;
    fixed_coordinates.push_back(k);
    model.positions[k] += noise(random);
  }
  ASSERT_FALSE(fixed_coordinates.empty());
  FreeHessian reusing(model, dofs), evaluating(model, dofs);
  evaluating.set_reuse_constant_terms(false);
  std::vector<double> x = model.positions;
  auto assemble_both = [&](bool reuse_expected) {
    FreeHessian::Assembly reused, evaluated;
    std::vector<double> reused_gradient, evaluated_gradient;
    EXPECT_TRUE(reusing.Assemble(x.data(), true, &reused, &reused_gradient));
    EXPECT_TRUE(evaluating.Assemble(x.data(), true, &evaluated, &evaluated_gradient));
    EXPECT_EQ(reused.reused_terms > 0, reuse_expected);
    EXPECT_EQ(evaluated.reused_terms, 0);
    EXPECT_EQ(reused.energy, evaluated.energy);
    EXPECT_EQ(reused.energy_magnitude, evaluated.energy_magnitude);
    EXPECT_TRUE(reused_gradient == evaluated_gradient);
    EXPECT_TRUE(reusing.values() == evaluating.values());
    EXPECT_TRUE(reusing.projected_values() == evaluating.projected_values());
    return evaluated.energy;
  };
  assemble_both(/*reuse_expected=*/false);  // the first assembly evaluates every term
  x[dofs.free_to_global()[0]] += 1e-3;
  const double before = assemble_both(/*reuse_expected=*/true);
  x[fixed_coordinates[fixed_coordinates.size() / 2]] += 1e-3;  // a clamped node of the centre
  EXPECT_NE(assemble_both(/*reuse_expected=*/false), before);
  assemble_both(/*reuse_expected=*/true);
}

TEST(SparseCholesky, SolvesAPositiveDefiniteSystemAndRefusesAnIndefiniteOne) {
  const Model model = ShakenSheet(0.8);
  const AssembledHessian assembled(model, /*project=*/true);
  const FreeHessian& hessian = assembled.hessian;
  SparseCholesky cholesky(hessian);
  EXPECT_FALSE(cholesky.Factorize(hessian.values(), nullptr));

  const std::vector<double> shift(hessian.size(), 1.0);
  ASSERT_TRUE(cholesky.Factorize(hessian.projected_values(), &shift));
  std::vector<double> b(hessian.size()), x, product(hessian.size());
  for (int k = 0; k < hessian.size(); ++k) b[k] = std::cos(k);
  cholesky.Solve(b, &x);
  hessian.Multiply(hessian.projected_values(), x.data(), product.data());
  for (int k = 0; k < hessian.size(); ++k) EXPECT_NEAR(product[k] + x[k], b[k], 1e-9);
}

// The flops of the factorisation of `hessian`'s pattern with the one ordering `ordering`.
double FlopsWithOrdering(const FreeHessian& hessian, int ordering) {
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.nmethods = 1;
  common.method[0].ordering = ordering;
  cholmod_sparse* matrix = cholmod_allocate_sparse(
      hessian.size(), hessian.size(), hessian.num_nonzeros(), 1, 1, 1, CHOLMOD_REAL, &common);
  std::copy(hessian.column_starts().begin(), hessian.column_starts().end(),
            static_cast<int*>(matrix->p));
  std::copy(hessian.rows().begin(), hessian.rows().end(), static_cast<int*>(matrix->i));
  cholmod_factor* factor = cholmod_analyze(matrix, &common);
  const double flops = factor ? common.fl : -1.0;
  cholmod_free_factor(&factor, &common);
  cholmod_free_sparse(&matrix, &common);
  cholmod_finish(&common);
  return flops;
}

// The analysis keeps the cheaper of AMD's and METIS's orderings: on the drape tester's lattice
// (2,821 nodes) nested dissection (CHOLMOD's default would not have tried it), on a small sheet
// AMD.
TEST(SparseCholesky, KeepsTheCheaperOfTheTwoOrderings) {
  for (const bool lattice : {true, false}) {
    const Model model = lattice ? ShakenDrape("0.005", 3, 1e-3) : ShakenSheet(0.8);
    const AssembledHessian assembled(model, /*project=*/true);
    const SparseCholesky cholesky(assembled.hessian);
    const double amd = FlopsWithOrdering(assembled.hessian, CHOLMOD_AMD);
    const double metis = FlopsWithOrdering(assembled.hessian, CHOLMOD_METIS);
    ASSERT_GT(amd, 0.0);
    ASSERT_GT(metis, 0.0);
    EXPECT_DOUBLE_EQ(cholesky.factorization_flops(), std::min(amd, metis)) << "lattice " << lattice;
    if (lattice) {
      EXPECT_LT(metis, 0.9 * amd);
    }
  }
}

// CHOLMOD's allocations fail (SuiteSparse's allocator replaced by one that always fails): the
// constructor used the NULL of cholmod_allocate_sparse unchecked and crashed; now it reports
// std::bad_alloc, which the commands turn into "out of memory", exit 2.
void* NoMemory(size_t) { return nullptr; }

TEST(SparseCholesky, ReportsOutOfMemoryInsteadOfUsingANullMatrix) {
  const Model model = ShakenSheet(0.8);
  const AssembledHessian assembled(model, /*project=*/true);
  void* (*original)(size_t) = SuiteSparse_config.malloc_func;
  SuiteSparse_config.malloc_func = NoMemory;
  bool out_of_memory = false;
  try {
    SparseCholesky cholesky(assembled.hessian);
  } catch (const std::bad_alloc&) {
    out_of_memory = true;
  }
  SuiteSparse_config.malloc_func = original;
  EXPECT_TRUE(out_of_memory);
}

}  // namespace
}  // namespace drape
