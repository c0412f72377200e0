// The closed-form derivatives of the bending stages (src/derivatives/stage_derivatives.h) against
// second-order automatic differentiation (src/derivatives/second_order.h) of the functors' own
// stage functions (costs/fv_bending.h), at random states, at straight (flat) states and near them.
#include "src/derivatives/stage_derivatives.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <random>
#include <type_traits>

#include "costs/fv_bending.h"
#include "src/derivatives/second_order.h"

namespace drape::internal {
namespace {

// Value, Jacobian and Σ_i w_i ∇²out_i of `function(in, out)`: R^kIn → R^kOut at `input`, by
// second-order forward differentiation.
template <int kIn, int kOut>
struct Reference {
  Eigen::Matrix<double, kOut, 1> value;
  Eigen::Matrix<double, kOut, kIn> jacobian;
  Eigen::Matrix<double, kIn, kIn> weighted_hessian;
};

template <int kIn, int kOut, typename Function>
Reference<kIn, kOut> Differentiate(const Function& function, const double* input,
                                   const double* weights) {
  using Number = SecondOrder<kIn>;
  Number in[kIn], out[kOut];
  for (int k = 0; k < kIn; ++k) in[k] = Number::Variable(input[k], k);
  function(in, out);
  Reference<kIn, kOut> reference;
  reference.weighted_hessian.setZero();
  for (int i = 0; i < kOut; ++i) {
    reference.value[i] = out[i].value;
    for (int r = 0; r < kIn; ++r) {
      reference.jacobian(i, r) = out[i].gradient[r];
      for (int c = 0; c < kIn; ++c)
        reference.weighted_hessian(r, c) += weights[i] * out[i].Hessian(r, c);
    }
  }
  return reference;
}

// |a − b| ≤ 1e-10 of b's largest entry (or 1e-14 where b is zero).
template <typename A, typename B>
void ExpectClose(const A& a, const B& b, const char* what) {
  const double scale = std::max(b.cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-10 * scale) << what << "\n"
                                                          << a << "\nagainst\n"
                                                          << b;
}

Eigen::Vector3d RandomVector(std::mt19937* random, double size) {
  std::uniform_real_distribution<double> uniform(-size, size);
  return {uniform(*random), uniform(*random), uniform(*random)};
}

void CheckBinormal(const Eigen::Vector3d& a, const Eigen::Vector3d& p, const Eigen::Vector3d& b,
                   const Eigen::Vector3d& weights) {
  const BinormalDerivatives closed(a.data(), p.data(), b.data());
  const double relative[6] = {a[0] - p[0], a[1] - p[1], a[2] - p[2],
                              b[0] - p[0], b[1] - p[1], b[2] - p[2]};
  const auto reference = Differentiate<6, 3>(
      [](const auto* in, auto* out) {
        using T = std::remove_const_t<std::remove_reference_t<decltype(in[0])>>;
        const T origin[3] = {T(), T(), T()};
        CurvatureBinormal(in, origin, in + 3, out);
      },
      relative, weights.data());
  ExpectClose(closed.value, reference.value, "binormal");
  ExpectClose(closed.jacobian, reference.jacobian, "binormal Jacobian");
  ExpectClose(closed.WeightedHessian(weights.data()), reference.weighted_hessian,
              "binormal weighted Hessian");
}

void CheckUnitDirection(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& weights) {
  const UnitDirectionDerivatives closed(a.data(), b.data());
  const Eigen::Vector3d difference = b - a;
  const auto reference = Differentiate<3, 3>(
      [](const auto* in, auto* out) {
        using T = std::remove_const_t<std::remove_reference_t<decltype(in[0])>>;
        const T origin[3] = {T(), T(), T()};
        UnitDirection(origin, in, out);
      },
      difference.data(), weights.data());
  ExpectClose(closed.value, reference.value, "tangent");
  ExpectClose(closed.jacobian, reference.jacobian, "tangent Jacobian");
  ExpectClose(closed.WeightedHessian(weights.data()), reference.weighted_hessian,
              "tangent weighted Hessian");
}

void CheckSection(const Eigen::Vector3d& k, const Eigen::Vector3d& t, double size,
                  const Eigen::Vector4d& weights) {
  const SectionDerivatives closed(k, t, size);
  const double input[6] = {k[0], k[1], k[2], t[0], t[1], t[2]};
  const auto reference = Differentiate<6, 4>(
      [size](const auto* in, auto* out) { FvBending::Section(in, in + 3, size, out); }, input,
      weights.data());
  ExpectClose(closed.value, reference.value, "section");
  ExpectClose(closed.jacobian, reference.jacobian, "section Jacobian");
  ExpectClose(closed.WeightedHessian(weights.data()), reference.weighted_hessian,
              "section weighted Hessian");
}

TEST(StageDerivatives, BinormalAtRandomStates) {
  std::mt19937 random(3);
  for (int trial = 0; trial < 50; ++trial) {
    CheckBinormal(RandomVector(&random, 1.0), RandomVector(&random, 1.0),
                  RandomVector(&random, 1.0), RandomVector(&random, 10.0));
  }
}

// Straight (the flat state, κb = 0) with unequal arms, and bent by a little out of line.
TEST(StageDerivatives, BinormalAtAndNearStraight) {
  std::mt19937 random(5);
  for (const double bend : {0.0, 1e-6, 1e-3}) {
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::Vector3d p = RandomVector(&random, 1.0);
      const Eigen::Vector3d direction = RandomVector(&random, 1.0).normalized();
      const Eigen::Vector3d a = p - 0.01 * direction;
      const Eigen::Vector3d b = p + 0.013 * direction + bend * RandomVector(&random, 0.01);
      CheckBinormal(a, p, b, RandomVector(&random, 10.0));
    }
  }
}

TEST(StageDerivatives, UnitDirectionAtRandomStates) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 50; ++trial) {
    CheckUnitDirection(RandomVector(&random, 1.0), RandomVector(&random, 1.0),
                       RandomVector(&random, 10.0));
  }
}

TEST(StageDerivatives, UnitDirectionOfCoincidentPointsIsZero) {
  const Eigen::Vector3d a(0.1, 0.2, 0.3);
  const UnitDirectionDerivatives closed(a.data(), a.data());
  const double weights[3] = {1.0, 2.0, 3.0};
  EXPECT_EQ(closed.value, Eigen::Vector3d::Zero());
  EXPECT_EQ(closed.jacobian, Eigen::Matrix3d::Zero());
  EXPECT_EQ(closed.WeightedHessian(weights), Eigen::Matrix3d::Zero());
}

TEST(StageDerivatives, SectionAtRandomStatesAndFlat) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d k = trial < 10 ? Eigen::Vector3d::Zero() : RandomVector(&random, 5.0);
    const Eigen::Vector3d t = RandomVector(&random, 1.0).normalized();
    Eigen::Vector4d weights;
    weights << RandomVector(&random, 10.0), RandomVector(&random, 10.0)[0];
    CheckSection(k, t, 0.005 + 0.01 * trial / 50.0, weights);
  }
}

}  // namespace
}  // namespace drape::internal
