// Checks every obstacle contact functor passes: its distance to the surface at probe points worked
// out by hand, the cubic penalty energy (k/3) g³ inside the clearance only (and Touches there
// only), derivatives against
// central differences, and a force pushing outward with magnitude k g².
#ifndef DRAPE_TESTS_CONTACT_CHECKS_H_
#define DRAPE_TESTS_CONTACT_CHECKS_H_

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/term_checks.h"

namespace drape::testing {

struct Probe {
  std::vector<double> x;
  double distance;  // expected signed distance to the surface, m
};

template <typename Contact>
void ExpectDistances(const Contact& obstacle, const std::vector<Probe>& probes) {
  for (const Probe& probe : probes) {
    EXPECT_NEAR(obstacle.Distance(probe.x.data()), probe.distance, 1e-14);
  }
}

template <typename Contact>
void ExpectCubicPenaltyInsideClearanceOnly(const Contact& obstacle,
                                           const std::vector<Probe>& probes, double clearance,
                                           double stiffness) {
  const auto term = MakeTerm("contact", {0}, obstacle);
  for (const Probe& probe : probes) {
    double energy;
    ASSERT_TRUE(term->Energy(probe.x.data(), &energy));
    const double gap = std::max(0.0, clearance - probe.distance);
    EXPECT_NEAR(energy, stiffness / 3.0 * gap * gap * gap, 1e-12 * (1.0 + energy));
    // The assembly's active set: Touches exactly inside the clearance, and outside it the
    // energy and every derivative are zero (the assembly skips it there).
    EXPECT_EQ(term->Touches(probe.x.data()), probe.distance < clearance) << probe.distance;
    if (term->Touches(probe.x.data())) continue;
    double gradient[3], hessian[9];
    ASSERT_TRUE(term->ReferenceHessian(probe.x.data(), &energy, gradient, hessian));
    EXPECT_EQ(energy, 0.0);
    for (double g : gradient) EXPECT_EQ(g, 0.0);
    for (double h : hessian) EXPECT_EQ(h, 0.0);
  }
}

template <typename Contact>
void ExpectDerivativesMatchDifferencesAtProbes(const Contact& obstacle,
                                               const std::vector<Probe>& probes) {
  const auto term = MakeTerm("contact", {0}, obstacle);
  for (const Probe& probe : probes) {
    SCOPED_TRACE(probe.distance);
    ExpectDerivativesMatchDifferences(*term, probe.x);
  }
}

// The force pushes the node out, along the distance's gradient, with magnitude k g².
template <typename Contact>
void ExpectForcePushesOutward(const Contact& obstacle, const std::vector<Probe>& probes,
                              double clearance, double stiffness) {
  const auto term = MakeTerm("contact", {0}, obstacle);
  for (const Probe& probe : probes) {
    const double gap = clearance - probe.distance;
    if (gap <= 0.0) continue;
    std::vector<double> x = probe.x;
    double energy, gradient[3];
    ASSERT_TRUE(term->EnergyGradient(x.data(), &energy, gradient));
    const double force = std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] +
                                   gradient[2] * gradient[2]);
    EXPECT_NEAR(force, stiffness * gap * gap, 1e-9 * force);
    // Moving along the force increases the distance.
    for (int c = 0; c < 3; ++c) x[c] -= 1e-7 * gradient[c] / force;
    EXPECT_GT(obstacle.Distance(x.data()), probe.distance);
  }
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_CONTACT_CHECKS_H_
