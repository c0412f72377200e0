#include "src/model/equilibrium.h"

#include <gtest/gtest.h>

#include <cmath>

#include "costs/constant_force_potential.h"
#include "costs/spring_stretch.h"
#include "src/model/contact.h"

namespace drape {
namespace equilibrium_test {

constexpr double kStiffness = 40.0, kRest = 0.1, kMass = 0.05, kGravity = 9.81;

// A mass hanging under a fixed node by one spring; node 0 also has its own weight.
Model HangingMass(double hang_length) {
  Model model;
  model.num_nodes = 2;
  model.positions = {0, 0, 0, 0, 0, -hang_length};
  model.initial = model.positions;
  model.mass = {kMass, kMass};
  model.fixed = {1, 1, 1, 0, 0, 0};
  model.applied = {0, 0, -kMass * kGravity, 0, 0, -kMass * kGravity};
  model.terms.push_back(MakeTerm("structural", {0, 1}, SpringStretch::Create(kStiffness, kRest)));
  for (int node = 0; node < 2; ++node) {
    const double weight[3] = {0, 0, -kMass * kGravity};
    model.terms.push_back(MakeTerm(
        "gravity", {node}, ConstantForcePotential::Create(weight, &model.initial[3 * node])));
  }
  return model;
}

TEST(DofMap, NumbersFreeCoordinatesInOrderAndRoundTrips) {
  const Model model = HangingMass(0.1);
  const DofMap dofs(model);
  ASSERT_EQ(dofs.num_free(), 3);
  EXPECT_EQ(dofs.free_to_global(), (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(dofs.global_to_free()[0], -1);
  EXPECT_EQ(dofs.global_to_free()[5], 2);
  std::vector<double> free(3), global(6, 7.0);
  dofs.Gather(model.positions.data(), free.data());
  dofs.Scatter(free.data(), global.data());
  EXPECT_EQ(global[0], 7.0);
  for (int k = 3; k < 6; ++k) EXPECT_EQ(global[k], model.positions[k]);
}

TEST(Certificate, ZeroResidualAndBalancedReactionAtTheExactEquilibrium) {
  const double stretched = kRest + kMass * kGravity / kStiffness;
  const Model model = HangingMass(stretched);
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  ASSERT_TRUE(certificate.evaluable);
  EXPECT_LT(certificate.relative_residual, 1e-14);
  EXPECT_LT(certificate.max_node_force, 1e-14);
  // The support carries both weights.
  EXPECT_NEAR(certificate.reaction_sum.z(), 2 * kMass * kGravity, 1e-14);
  EXPECT_NEAR(certificate.node_forces[2], 2 * kMass * kGravity, 1e-14);
  EXPECT_NEAR(certificate.reference_force, std::sqrt(2.0) * kMass * kGravity, 1e-15);
  // Energies per type: spring ½kδ², weight −m g Δz measured from the start (zero here).
  const double delta = stretched - kRest;
  EXPECT_NEAR(certificate.energy_by_type.at("structural"), 0.5 * kStiffness * delta * delta, 1e-15);
  EXPECT_NEAR(certificate.energy_by_type.at("gravity"), 0.0, 1e-15);
}

TEST(Certificate, ResidualIsTheUnbalancedForceOverTheWeight) {
  const Model model = HangingMass(kRest);  // the spring is slack, the mass unsupported
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  EXPECT_NEAR(certificate.node_forces[5], -kMass * kGravity, 1e-15);
  EXPECT_NEAR(certificate.max_node_force, kMass * kGravity, 1e-15);
  EXPECT_NEAR(certificate.relative_residual, 1.0 / std::sqrt(2.0), 1e-14);
}

TEST(Certificate, WithoutLoadsTheReactionsSetTheScale) {
  Model model = HangingMass(0.15);
  model.terms.resize(1);  // the spring only: its ends are pulled apart by a prescribed move
  std::fill(model.applied.begin(), model.applied.end(), 0.0);
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  const double tension = kStiffness * 0.05;
  EXPECT_NEAR(certificate.reference_force, tension, 1e-12);
  EXPECT_NEAR(certificate.relative_residual, 1.0, 1e-12);
}

TEST(Certificate, NotEvaluableWhereTheEnergyIsNot) {
  Model model = HangingMass(0.1);
  model.positions[5] = NAN;
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  EXPECT_FALSE(certificate.evaluable);
  EXPECT_FALSE(certificate.relative_residual <= 1.0);
}

// A state that has run away, is not finite, or has a node inside an obstacle's
// body is not certified, whatever its residual.
TEST(Certificate, RefusesAStateThatHasRunAway) {
  Model model = HangingMass(0.1);
  model.size = 0.1;
  EXPECT_EQ(ComputeCertificate(model, model.positions.data()).unsound, "");
  model.positions[5] = -2.7e11;  // where newton's first long steps took a sheet past a pin
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  EXPECT_NE(certificate.unsound.find("run away"), std::string::npos) << certificate.unsound;
}

TEST(Certificate, RefusesAStateThatIsNotFinite) {
  Model model = HangingMass(0.1);
  model.positions[3] = INFINITY;
  EXPECT_NE(ComputeCertificate(model, model.positions.data()).unsound, "");
}

TEST(Certificate, RefusesANodeInsideAnObstacle) {
  Model model = HangingMass(0.1);
  ObstacleSpec floor;
  floor.kind = "plane";
  floor.center = {0, 0, -0.05};
  floor.normal = {0, 0, 1};
  model.obstacles = {floor};
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  EXPECT_NE(certificate.unsound.find("inside obstacle 1"), std::string::npos)
      << certificate.unsound;
}

// Reactions + contact (+ constraint) = −(weight + loads), checked.
TEST(Certificate, BalanceCountsReactionsAndTheGivenConstraintForces) {
  Model model = HangingMass(kRest + kMass * kGravity / kStiffness);
  Certificate certificate = ComputeCertificate(model, model.positions.data());
  EXPECT_TRUE(certificate.balanced) << certificate.balance_error;
  EXPECT_NEAR(certificate.applied_sum.z(), -2 * kMass * kGravity, 1e-12);
  // A constraint holding the lower node (a force on it equal to its weight): the spring is then
  // too long, and the support carries one weight less.
  const std::vector<double> holding = {0, 0, 0, 0, 0, kMass * kGravity};
  model.positions[5] = -kRest;
  certificate = ComputeCertificate(model, model.positions.data(), &holding);
  EXPECT_LT(certificate.relative_residual, 1e-12);
  EXPECT_NEAR(certificate.reaction_sum.z(), kMass * kGravity, 1e-12);
  EXPECT_NEAR(certificate.constraint_sum.z(), kMass * kGravity, 1e-12);
  EXPECT_TRUE(certificate.balanced) << certificate.balance_error;
}

}  // namespace equilibrium_test
}  // namespace drape
