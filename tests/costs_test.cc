// One typed test over every functor in costs/: its derivatives (energy, gradient, Hessian, and the
// fast path against the nested-Jet reference) at a generic state and at its rest or flat state, and
// Ceres' GradientChecker on the residual path the ceres-* solvers use (Term::NewCostFunction).
// Each functor's own test file checks its physics (closed forms, invariances); this one makes sure
// no functor in costs/ is left out: `Costs.EveryFunctorIsListed` reads costs/ and fails for a
// functor without a Sample below.
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "costs/box_contact.h"
#include "costs/constant_force_potential.h"
#include "costs/cylinder_contact.h"
#include "costs/disk_contact.h"
#include "costs/edge_contact.h"
#include "costs/edge_edge_contact.h"
#include "costs/fv_bending.h"
#include "costs/fv_bending_friction.h"
#include "costs/fv_bending_friction_step.h"
#include "costs/fv_cell_shear.h"
#include "costs/fv_membrane.h"
#include "costs/fv_shear_friction.h"
#include "costs/fv_twist.h"
#include "costs/mesh_contact.h"
#include "costs/obstacle_friction.h"
#include "costs/plane_contact.h"
#include "costs/point_triangle_contact.h"
#include "costs/pressure_potential.h"
#include "costs/sphere_contact.h"
#include "costs/spring_stretch.h"
#include "costs/stretch_limit_barrier.h"
#include "costs/tension_only_spring.h"
#include "costs/zero_length_spring.h"
#include "src/geometry/triangle_surface.h"
#include "src/model/term.h"
#include "tests/term_checks.h"
#include "tests/test_meshes.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

// Tolerances, relative to the largest entry.
constexpr double kDifferenceTolerance = 1e-6;  // central differences, step 1e-6 × the state's size
constexpr double kCeresTolerance = 1e-6;       // GradientChecker's relative precision
// GradientChecker's first finite-difference step (Ridders' extrapolation shrinks it), relative to
// each coordinate: within the smooth part of every sample (a contact's node stays inside the
// clearance layer, ~5 mm deep; a finite volume's arms are ~1 cm).
constexpr double kCeresInitialStep = 1e-4;
// The least-squares shift of potentials (src/model/term.h), J: above any sample's |energy|, so
// that the residual √(2 (E + shift)) is smooth at every state below.
constexpr double kShift = 10.0;

// A functor with the states its checks run at (3 coordinates per node, nodes 0, 1, ...): a
// generic one, and its rest (flat, unstretched) state or, for contacts, a node inside the
// clearance layer.
template <typename Functor>
struct Sample;

constexpr double kClearance = 0.01, kContactStiffness = 1e4;
const double kOrigin[3] = {0, 0, 0}, kUp[3] = {0, 0, 1};

template <>
struct Sample<SpringStretch> {
  static constexpr const char* kName = "SpringStretch";
  static SpringStretch Make() { return SpringStretch::Create(100.0, 1.0); }
  static std::vector<std::vector<double>> States() {
    return {{0.1, -0.2, 0.3, 1.0, 0.4, -0.2}, {0, 0, 0, 1, 0, 0}};
  }
};

template <>
struct Sample<TensionOnlySpring> {
  static constexpr const char* kName = "TensionOnlySpring";
  static TensionOnlySpring Make() { return TensionOnlySpring::Create(100.0, 1.0); }
  static std::vector<std::vector<double>> States() {
    return {{0.1, -0.2, 0.3, 1.2, 0.4, -0.2}, {0, 0, 0, 0.5, 0, 0}};
  }
};

template <>
struct Sample<ZeroLengthSpring> {
  static constexpr const char* kName = "ZeroLengthSpring";
  static ZeroLengthSpring Make() { return ZeroLengthSpring::Create(50.0); }
  static std::vector<std::vector<double>> States() {
    return {{0.1, -0.2, 0.3, 1.2, 0.4, -0.2}, {0.3, 0.3, 0.3, 0.3, 0.3, 0.3}};
  }
};

template <>
struct Sample<StretchLimitBarrier> {
  static constexpr const char* kName = "StretchLimitBarrier";
  static StretchLimitBarrier Make() { return StretchLimitBarrier::Create(1e3, 1.1); }
  static std::vector<std::vector<double>> States() {
    return {{0.1, -0.2, 0.3, 1.3, 0.4, -0.2}, {0, 0, 0, 1, 0, 0}};
  }
};

template <>
struct Sample<ConstantForcePotential> {
  static constexpr const char* kName = "ConstantForcePotential";
  static ConstantForcePotential Make() {
    const double force[3] = {0.5, -1.0, 2.0}, reference[3] = {0.1, 0.2, 0.3};
    return ConstantForcePotential::Create(force, reference);
  }
  static std::vector<std::vector<double>> States() { return {{0.4, -0.3, 0.9}, {0.1, 0.2, 0.3}}; }
};

template <>
struct Sample<PressurePotential> {
  static constexpr const char* kName = "PressurePotential";
  static PressurePotential Make() { return PressurePotential::Create(3.0, 0.2, -0.1); }
  static std::vector<std::vector<double>> States() {
    return {{0.1, -0.2, 0.3, 1.2, 0.4, -0.2}, {1, 0, 0, 0, 0, 1}};
  }
};

template <>
struct Sample<SphereContact> {
  static constexpr const char* kName = "SphereContact";
  static SphereContact Make() {
    return SphereContact::Create(kOrigin, 1.0, kClearance, kContactStiffness);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.3, 0.4, 0.87}, {0.0, 0.0, 1.004}};  // inside the layer
  }
};

template <>
struct Sample<PlaneContact> {
  static constexpr const char* kName = "PlaneContact";
  static PlaneContact Make() {
    return PlaneContact::Create(kOrigin, kUp, kClearance, kContactStiffness);
  }
  static std::vector<std::vector<double>> States() { return {{0.3, 0.4, 0.006}, {0, 0, 0.002}}; }
};

// A node slipped 3 mm across a tilted normal (in the smooth part, |u| ≫ ε), and at its start x0,
// the kink's centre (the smoothed state where a step begins).
template <>
struct Sample<ObstacleFriction> {
  static constexpr const char* kName = "ObstacleFriction";
  static ObstacleFriction Make() {
    const double normal[3] = {0.6, 0.0, 0.8}, start[3] = {0.1, 0.2, 0.3};
    return ObstacleFriction::Create(0.4, 2.0, normal, start, 0.001);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.1, 0.203, 0.301}, {0.1, 0.2, 0.3}};
  }
};

template <>
struct Sample<DiskContact> {
  static constexpr const char* kName = "DiskContact";
  static DiskContact Make() {
    return DiskContact::Create(kOrigin, 1.0, kClearance, kContactStiffness);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.3, 0.4, 0.005}, {1.003, 0.002, 0.004}};  // over the disc, beyond its rim
  }
};

// An edge over the rim of a disc (R = 1 m, t = 1 cm) at 8 points, cutting the rim's corner as in
// tests/edge_contact_test.cc (no point within 1 mm of the rim circle or of the clearance layer's
// boundary, where the energy is less smooth than a difference needs), and an edge lying flat on the
// disc's top. The disc lies at z = −1 m so that Ceres's relative difference steps are not tiny.
template <>
struct Sample<EdgeContact<DiskContact>> {
  static constexpr const char* kName = "EdgeContact";
  static EdgeContact<DiskContact> Make() {
    const double centre[3] = {0.0, 0.0, -1.0};
    return EdgeContact(DiskContact::Create(centre, 1.0, kClearance, kContactStiffness), 8);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.96, 0.0, -0.9882, 1.0588, 0.0, -1.015}, {0.3, 0.4, -0.995, 0.5, 0.4, -0.994}};
  }
};

template <>
struct Sample<CylinderContact> {
  static constexpr const char* kName = "CylinderContact";
  static CylinderContact Make() {
    return CylinderContact::Create(kOrigin, 1.0, 1.0, kClearance, kContactStiffness);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.3, 0.4, 0.005}, {0.6, 0.8 + 0.004, -0.5}};  // over the top, beside the side
  }
};

template <>
struct Sample<BoxContact> {
  static constexpr const char* kName = "BoxContact";
  static BoxContact Make() {
    const double min[3] = {-1, -1, -1}, max[3] = {1, 1, 0};
    return BoxContact::Create(min, max, kClearance, kContactStiffness);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.3, 0.4, 0.006}, {1.002, 1.003, 0.004}};  // over the top, near a corner
  }
};

// The box of Sample<BoxContact> as 12 triangles (each face split along a diagonal, normals
// outward): over its top away from the diagonals, near a corner.
template <>
struct Sample<MeshContact<TriangleSurface>> {
  static constexpr const char* kName = "MeshContact";
  static MeshContact<TriangleSurface> Make() {
    return MeshContact<TriangleSurface>(
        testing::Cuboid(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 0)), kClearance,
        kContactStiffness);
  }
  static std::vector<std::vector<double>> States() {
    return {{0.3, -0.4, 0.006}, {1.002, 1.003, 0.004}};
  }
};

template <>
struct Sample<FvMembrane> {
  static constexpr const char* kName = "FvMembrane";
  static FvMembrane Make() { return FvMembrane::Create(80.0, 60.0, 15.0, 5.0, 0.01, 0.012); }
  static std::vector<std::vector<double>> States() {  // nodes P, A, B
    return {{0.001, -0.002, 0.001, 0.011, 0.001, 0.003, -0.001, 0.013, -0.002},
            {0, 0, 0, 0.01, 0, 0, 0, 0.012, 0}};
  }
};

template <>
struct Sample<FvBendingEdge> {
  static constexpr const char* kName = "FvBendingEdge";
  static FvBendingEdge Make() { return FvBendingEdge::Create(2e-5, 0.01, 1e-4); }
  static std::vector<std::vector<double>> States() {  // nodes a, P, b
    return {{-0.01, 0.001, 0.002, 0, 0, 0, 0.0098, -0.001, 0.003},
            {-0.01, 0, 0, 0, 0, 0, 0.01, 0, 0}};
  }
};

template <>
struct Sample<FvBending> {
  static constexpr const char* kName = "FvBending";
  static FvBending Make() { return FvBending::Create(2e-5, 1.5e-5, 5e-6, 0.01, 0.012, 1.2e-4); }
  static std::vector<std::vector<double>> States() {  // nodes W, P, E, S, N
    return {{-0.01, 0.001, 0.002, 0, 0, 0, 0.0098, -0.001, 0.003, 0.001, -0.012, 0.002, -0.001,
             0.0118, 0.003},
            {-0.01, 0, 0, 0, 0, 0, 0.01, 0, 0, 0, -0.012, 0, 0, 0.012, 0}};
  }
};

template <>
struct Sample<FvTwist> {
  static constexpr const char* kName = "FvTwist";
  // D66 A = 1e-5 N·m × 1.2e-4 m² on a 1 cm × 1.2 cm cell.
  static FvTwist Make() { return FvTwist::Create(1.2e-9, 0.01, 0.012); }
  static std::vector<std::vector<double>> States() {  // nodes P, E, N, C
    return {{0.0003, 0.0002, 0.0004, 0.0101, 0.0005, -0.0003, 0.0012, 0.0118, 0.0009, 0.0098,
             0.0123, 0.0021},
            {0, 0, 0, 0.01, 0, 0, 0, 0.012, 0, 0.01, 0.012, 0}};
  }
};

template <>
struct Sample<FvCellShear> {
  static constexpr const char* kName = "FvCellShear";
  // G A_c = 50 N/m × 1.2e-4 m² on a 1 cm × 1.2 cm cell.
  static FvCellShear Make() { return FvCellShear::Create(50.0, 1.2e-4); }
  static std::vector<std::vector<double>> States() {  // nodes P, E, N, C
    return Sample<FvTwist>::States();
  }
};

template <>
struct Sample<FvBendingFriction> {
  static constexpr const char* kName = "FvBendingFriction";
  // δ = 5 1/m: the generic state's κ ≈ 50 1/m is far beyond it, the flat state at its kink.
  // H = 600 N (not a fabric's): energies of a few J, so that Ceres' differences of the shifted
  // residual √(2 (E + 10 J)) are not lost in round-off.
  static FvBendingFriction Make() { return FvBendingFriction::Create(600.0, 0.01, 1e-4, 5.0); }
  static std::vector<std::vector<double>> States() {  // nodes a, P, b
    // P off the origin: Ceres' steps are relative to each coordinate (at 0, a 1e-4 m step on 1 cm
    // arms leaves Ridders' extrapolation 4e-4 off the z derivative).
    return {{-0.01, 0.0003, 0.0008, 0.0004, 0.0003, 0.0005, 0.0099, -0.0003, 0.001},
            {-0.01, 0, 0, 0, 0, 0, 0.01, 0, 0}};
  }
};

template <>
struct Sample<FvBendingFrictionStep> {
  static constexpr const char* kName = "FvBendingFrictionStep";
  // As FvBendingFriction's, with the kink at κ0 = 20 1/m: the generic state's κ ≈ 50 1/m is 30
  // from it, the flat state 20 (both beyond δ = 5 1/m); d across along y.
  static FvBendingFrictionStep Make() {
    return FvBendingFrictionStep::Create(600.0, 0.01, 1e-4, 5.0, 20.0, 1.0);
  }
  static std::vector<std::vector<double>> States() {  // nodes a, P, b, d
    return {{-0.01, 0.0003, 0.0008, 0.0004, 0.0003, 0.0005, 0.0099, -0.0003, 0.001, 0.0006, 0.0102,
             0.0007},
            {-0.01, 0, 0, 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0}};
  }
};

template <>
struct Sample<FvShearFriction> {
  static constexpr const char* kName = "FvShearFriction";
  // δ = 0.01 rad: the generic state's γ ≈ 0.1 rad is beyond it, the rest state at its kink.
  // HG = 4e5 N/m (not a fabric's): energies of a few J, as FvBendingFriction's sample.
  static FvShearFriction Make() { return FvShearFriction::Create(4e5, 0.01, 0.012, 0.01); }
  static std::vector<std::vector<double>> States() {  // nodes P, A, B; P off the origin
    return {{0.0003, 0.0002, 0.0004, 0.0101, 0.0005, -0.0003, 0.0012, 0.0118, 0.0009},
            {0.0003, 0.0002, 0, 0.0103, 0.0002, 0, 0.0003, 0.0122, 0}};
  }
};

// The fabric's contact with itself (C = 1 cm): a node and a tilted triangle of 2 cm sides, the
// node 4–6 mm from the triangle's inside, from its side a–b and from its corner a (the three
// distance types, each away from where the nearest part changes).
template <>
struct Sample<PointTriangleContact> {
  static constexpr const char* kName = "PointTriangleContact";
  static PointTriangleContact Make() { return PointTriangleContact(kClearance, kContactStiffness); }
  static std::vector<std::vector<double>> States() {
    const std::vector<double> triangle = {0.0003,  0.0002, 0.0004, 0.0201, 0.0005,
                                          -0.0003, 0.0012, 0.0198, 0.0009};
    std::vector<std::vector<double>> states = {
        {0.005, 0.004, 0.006}, {0.012, -0.004, 0.003}, {-0.004, -0.003, 0.002}};
    for (auto& state : states) state.insert(state.end(), triangle.begin(), triangle.end());
    return states;
  }
};

// Two edges of 2 cm with C = 1 cm: crossing 4.5 mm apart (both insides), one's end b 6.5 mm from
// the other's inside, and the ends b and c 5.8 mm apart.
template <>
struct Sample<EdgeEdgeContact> {
  static constexpr const char* kName = "EdgeEdgeContact";
  static EdgeEdgeContact Make() { return EdgeEdgeContact(kClearance, kContactStiffness); }
  static std::vector<std::vector<double>> States() {
    const std::vector<double> edge = {0.0002, 0.0001, -0.0003, 0.02, 0.0004, 0.0002};
    std::vector<std::vector<double>> states = {{0.01, -0.01, 0.005, 0.011, 0.01, 0.004},
                                               {0.025, -0.01, 0.004, 0.026, 0.01, 0.003},
                                               {0.024, 0.003, 0.003, 0.04, 0.01, 0.004}};
    for (auto& state : states) state.insert(state.begin(), edge.begin(), edge.end());
    return states;
  }
};

template <typename Functor>
std::unique_ptr<Term> SampleTerm() {
  std::vector<int> nodes(Functor::kNumNodes);
  for (int k = 0; k < Functor::kNumNodes; ++k) nodes[k] = k;
  return MakeTerm(Sample<Functor>::kName, nodes, Sample<Functor>::Make(), kShift);
}

template <typename Functor>
class CostsTest : public ::testing::Test {};

using Functors =
    ::testing::Types<SpringStretch, TensionOnlySpring, ZeroLengthSpring, StretchLimitBarrier,
                     ConstantForcePotential, PressurePotential, SphereContact, PlaneContact,
                     DiskContact, EdgeContact<DiskContact>, CylinderContact, BoxContact,
                     MeshContact<TriangleSurface>, PointTriangleContact, EdgeEdgeContact,
                     FvMembrane, FvBendingEdge, FvBending, FvBendingFriction, FvBendingFrictionStep,
                     FvShearFriction, FvTwist, FvCellShear, ObstacleFriction>;

class FunctorNames {
 public:
  template <typename Functor>
  static std::string GetName(int) {
    return Sample<Functor>::kName;
  }
};

TYPED_TEST_SUITE(CostsTest, Functors, FunctorNames);

TYPED_TEST(CostsTest, DerivativesMatchDifferencesAndTheNestedJetReference) {
  const auto term = SampleTerm<TypeParam>();
  for (const std::vector<double>& state : Sample<TypeParam>::States()) {
    SCOPED_TRACE(::testing::Message() << "state " << ::testing::PrintToString(state));
    testing::ExpectDerivativesMatchDifferences(*term, state, kDifferenceTolerance);
  }
}

// The residual path's Jacobian (Jets through Ceres' AutoDiffCostFunction) against central
// differences of its residuals, step `step` m, to 1e-6 of the largest entry.
void ExpectResidualJacobianMatchesDifferences(const ceres::CostFunction& cost,
                                              std::vector<double> state, int nodes,
                                              double step = 1e-8) {
  std::vector<double*> blocks(nodes);
  for (int k = 0; k < nodes; ++k) blocks[k] = state.data() + 3 * k;
  double residual = 0.0;
  std::vector<double> jacobian(3 * nodes);
  std::vector<double*> jacobians(nodes);
  for (int k = 0; k < nodes; ++k) jacobians[k] = jacobian.data() + 3 * k;
  ASSERT_TRUE(cost.Evaluate(blocks.data(), &residual, jacobians.data()));
  double largest = 0.0;
  for (double entry : jacobian) largest = std::max(largest, std::abs(entry));
  for (int i = 0; i < 3 * nodes; ++i) {
    double plus = 0.0, minus = 0.0;
    state[i] += step;
    ASSERT_TRUE(cost.Evaluate(blocks.data(), &plus, nullptr));
    state[i] -= 2 * step;
    ASSERT_TRUE(cost.Evaluate(blocks.data(), &minus, nullptr));
    state[i] += step;
    EXPECT_NEAR(jacobian[i], (plus - minus) / (2 * step), 1e-6 * largest) << "coordinate " << i;
  }
}

TYPED_TEST(CostsTest, CeresGradientCheckerAcceptsTheResidualPath) {
  const auto term = SampleTerm<TypeParam>();
  const std::unique_ptr<ceres::CostFunction> cost(term->NewCostFunction());
  if constexpr (std::is_same_v<TypeParam, FvBendingFriction> ||
                std::is_same_v<TypeParam, FvBendingFrictionStep> ||
                std::is_same_v<TypeParam, FvShearFriction> ||
                std::is_same_v<TypeParam, EdgeEdgeContact>) {
    // Ceres' GradientChecker (Ridders' differences) reports some coordinates 1e-4 to 0.8 off for
    // the frictions, whose residual is √(2 (E + shift)), scaling with H, where plain central
    // differences of the same cost function agree with its Jets to 1e-9: checked that way. So for
    // the edge–edge contact's end-to-inside state: Ridders gives 0.02484 for ∂r/∂b_x where the
    // Jets give 0.0246159, as do central differences of the exact segment distance at steps 2e-6,
    // 1e-5 and 1e-4 m (0.0246159, 0.0246159, 0.0246170).
    // The edge contact's Jacobian entries are ~1e-2 of r ≈ 4.5: at 1e-8 m the differences' round-
    // off (ε r / 1e-8 ≈ 5e-8) is the tolerance itself; at 1e-6 m it is 100 times smaller, and
    // the truncation error (1e-12 of the third derivative) smaller still.
    const double step = std::is_same_v<TypeParam, EdgeEdgeContact> ? 1e-6 : 1e-8;
    for (const std::vector<double>& state : Sample<TypeParam>::States()) {
      ExpectResidualJacobianMatchesDifferences(*cost, state, TypeParam::kNumNodes, step);
    }
    return;
  }
  ceres::NumericDiffOptions difference;
  difference.ridders_relative_initial_step_size = kCeresInitialStep;
  const ceres::GradientChecker checker(
      cost.get(), static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), difference);
  for (std::vector<double> state : Sample<TypeParam>::States()) {
    std::vector<const double*> blocks(TypeParam::kNumNodes);
    for (int k = 0; k < TypeParam::kNumNodes; ++k) blocks[k] = state.data() + 3 * k;
    // No ProbeResults unless it fails: its inline destructor frees Eigen storage that Ceres
    // allocated, which AddressSanitizer builds of this file read as a heap overflow (Eigen's
    // alignment bookkeeping differs between this translation unit and Debian's libceres there).
    if (!checker.Probe(blocks.data(), kCeresTolerance, nullptr)) {
      ceres::GradientChecker::ProbeResults results;
      checker.Probe(blocks.data(), kCeresTolerance, &results);
      ADD_FAILURE() << "state " << ::testing::PrintToString(state) << "\n" << results.error_log;
    }
  }
}

template <typename... Functor>
std::set<std::string> NamesOf(::testing::Types<Functor...>*) {
  return {Sample<Functor>::kName...};
}

// Every struct in costs/ with a kNumNodes (a functor a Term wraps) has a Sample above.
TEST(Costs, EveryFunctorIsListed) {
  std::set<std::string> in_costs;
  const std::regex functor(R"(^struct (\w+) \{$)");
  for (const auto& entry : std::filesystem::directory_iterator(testing::SourcePath("costs"))) {
    std::ifstream file(entry.path());
    std::string line, current;
    while (std::getline(file, line)) {
      std::smatch match;
      if (std::regex_match(line, match, functor)) current = match[1];
      if (!current.empty() && line.find("static constexpr int kNumNodes") != std::string::npos) {
        in_costs.insert(current);
      }
    }
  }
  EXPECT_EQ(in_costs, NamesOf(static_cast<Functors*>(nullptr)));
}

}  // namespace
}  // namespace drape
