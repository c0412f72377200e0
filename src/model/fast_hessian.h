// Fast exact energy, gradient and Hessian of the finite-volume bending functors, derived from the
// functors' own stages by the chain rule (the physics stays written once, in costs/).
//
// FvBending and FvBendingEdge compute their residuals in stages: curvature binormals (3 nodes
// each), unit tangents (2 nodes each), sections (FvBending only: 6 numbers each) and residuals
// linear in the last stage. Nested Jets over one whole 5-node functor carry 12 derivatives through
// every operation; here each stage is differentiated on its own with the few variables it reads
// (6 relative coordinates for a binormal, 3 for a tangent, 6 for a section), and the results are
// chained: for E = ½|r|², r = L y(Q(x)),
//   ∇E = J_Qᵀ g_Q,   ∇²E = J_Qᵀ H_Q J_Q + Σ_j g_Q,j ∇²Q_j,
// where g_Q, H_Q are the gradient and Hessian of E over the intermediate values Q (themselves from
// the chain rule through the sections and the constant matrix L, read off the functor's linear
// residual stage by a first-order Jet). Every stage function is the functor's own; the results are
// checked against the nested-Jet Hessian of the whole functor in tests/term_checks.h.
//
// FastHessian<Functor>::kAvailable says whether a functor has such a path (src/model/term.h uses
// it in place of the nested Jets).
#ifndef DRAPE_SRC_MODEL_FAST_HESSIAN_H_
#define DRAPE_SRC_MODEL_FAST_HESSIAN_H_

#include <ceres/jet.h>

#include <Eigen/Core>
#include <cmath>

#include "costs/fv_bending.h"
#include "costs/nested_jet.h"

namespace drape {
namespace internal {

template <typename Functor>
struct FastHessian {
  static constexpr bool kAvailable = false;
};

// Value, Jacobian and the Hessian of each output of a small function R^kIn → R^kOut, by nested
// Jets. `function(in, out)` is called with in[kIn] and out[kOut] of the nested Jet type.
template <int kIn, int kOut>
struct LocalExpansion {
  Eigen::Matrix<double, kOut, 1> value;
  Eigen::Matrix<double, kOut, kIn> jacobian;
  Eigen::Matrix<double, kIn, kIn> hessian[kOut];

  // Σ_i weights_i ∇²out_i.
  Eigen::Matrix<double, kIn, kIn> WeightedHessian(const double* weights) const {
    Eigen::Matrix<double, kIn, kIn> sum = weights[0] * hessian[0];
    for (int i = 1; i < kOut; ++i) sum += weights[i] * hessian[i];
    return sum;
  }
};

template <int kIn, int kOut, typename Function>
void Expand(const Function& function, const double* input, LocalExpansion<kIn, kOut>* expansion) {
  using Jet1 = ceres::Jet<double, kIn>;
  using Jet2 = ceres::Jet<Jet1, kIn>;
  Jet2 in[kIn], out[kOut];
  for (int k = 0; k < kIn; ++k) {
    in[k].a = Jet1(input[k], k);
    in[k].v.setZero();
    in[k].v[k] = Jet1(1.0);
  }
  function(in, out);
  for (int i = 0; i < kOut; ++i) {
    expansion->value[i] = out[i].a.a;
    expansion->jacobian.row(i) = out[i].a.v.transpose();
    for (int r = 0; r < kIn; ++r) expansion->hessian[i].row(r) = out[i].v[r].v.transpose();
  }
}

// The curvature binormal of a → p → b over the relative coordinates (a − p, b − p).
inline void ExpandBinormal(const double* a, const double* p, const double* b,
                           LocalExpansion<6, 3>* expansion) {
  const double relative[6] = {a[0] - p[0], a[1] - p[1], a[2] - p[2],
                              b[0] - p[0], b[1] - p[1], b[2] - p[2]};
  Expand<6, 3>(
      [](const auto* in, auto* out) {
        using T = std::remove_const_t<std::remove_reference_t<decltype(in[0])>>;
        const T origin[3] = {T(), T(), T()};
        CurvatureBinormal(in, origin, in + 3, out);
      },
      relative, expansion);
}

// The unit vector along b − a over the coordinates of b − a.
inline void ExpandUnitDirection(const double* a, const double* b, LocalExpansion<3, 3>* expansion) {
  const double relative[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  Expand<3, 3>(
      [](const auto* in, auto* out) {
        using T = std::remove_const_t<std::remove_reference_t<decltype(in[0])>>;
        const T origin[3] = {T(), T(), T()};
        UnitDirection(origin, in, out);
      },
      relative, expansion);
}

// The constant matrix L of a functor's residual stage r = L y, read off by a first-order Jet.
template <int kIn, int kOut, typename Function>
Eigen::Matrix<double, kOut, kIn> LinearStage(const Function& function) {
  using Jet = ceres::Jet<double, kIn>;
  Jet in[kIn], out[kOut];
  for (int k = 0; k < kIn; ++k) in[k] = Jet(0.0, k);
  function(in, out);
  Eigen::Matrix<double, kOut, kIn> matrix;
  for (int i = 0; i < kOut; ++i) matrix.row(i) = out[i].v.transpose();
  return matrix;
}

// Local derivatives over the coordinates of a term's kNodes nodes (3 each).
template <int kNodes>
struct NodeDerivatives {
  static constexpr int kDofs = 3 * kNodes;
  using Hessian = Eigen::Matrix<double, kDofs, kDofs, Eigen::RowMajor>;
  template <int kRows>
  using Jacobian = Eigen::Matrix<double, kRows, kDofs>;

  // Rows of ∂q/∂x for q a function of (x_a − x_p, x_b − x_p) with Jacobian `relative` (m × 6).
  template <int kRows>
  static void AddRelativeToCentre(const Eigen::Matrix<double, kRows, 6>& relative, int a, int p,
                                  int b, Eigen::Ref<Jacobian<kRows>> jacobian) {
    jacobian.template middleCols<3>(3 * a) += relative.template leftCols<3>();
    jacobian.template middleCols<3>(3 * b) += relative.template rightCols<3>();
    jacobian.template middleCols<3>(3 * p) -=
        relative.template leftCols<3>() + relative.template rightCols<3>();
  }
  // Rows of ∂q/∂x for q a function of x_b − x_a with Jacobian `relative` (m × 3).
  template <int kRows>
  static void AddDifference(const Eigen::Matrix<double, kRows, 3>& relative, int a, int b,
                            Eigen::Ref<Jacobian<kRows>> jacobian) {
    jacobian.template middleCols<3>(3 * b) += relative;
    jacobian.template middleCols<3>(3 * a) -= relative;
  }
  // H += Pᵀ A P for A over (x_a − x_p, x_b − x_p).
  static void AddRelativeToCentre(const Eigen::Matrix<double, 6, 6>& second, int a, int p, int b,
                                  Hessian* hessian) {
    const int node[2] = {a, b};
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        const Eigen::Matrix3d block = second.template block<3, 3>(3 * i, 3 * j);
        hessian->template block<3, 3>(3 * node[i], 3 * node[j]) += block;
        hessian->template block<3, 3>(3 * node[i], 3 * p) -= block;
        hessian->template block<3, 3>(3 * p, 3 * node[j]) -= block;
        hessian->template block<3, 3>(3 * p, 3 * p) += block;
      }
    }
  }
  // H += Pᵀ A P for A over x_b − x_a.
  static void AddDifference(const Eigen::Matrix3d& second, int a, int b, Hessian* hessian) {
    hessian->template block<3, 3>(3 * a, 3 * a) += second;
    hessian->template block<3, 3>(3 * b, 3 * b) += second;
    hessian->template block<3, 3>(3 * a, 3 * b) -= second;
    hessian->template block<3, 3>(3 * b, 3 * a) -= second;
  }
};

// FvBending (nodes W, P, E, S, N = 0..4). Intermediates Q = (k1, t2, k2, t1), 12 values; the
// sections y1 = Section(k1, t2), y2 = Section(k2, t1); residuals r = L (y1, y2).
template <>
struct FastHessian<FvBending> {
  static constexpr bool kAvailable = true;
  using Nodes = NodeDerivatives<5>;

  static bool Evaluate(const FvBending& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian) {
    enum { kW, kP, kE, kS, kN };
    LocalExpansion<6, 3> k1, k2;
    LocalExpansion<3, 3> t1, t2;
    ExpandBinormal(x[kW], x[kP], x[kE], &k1);
    ExpandBinormal(x[kS], x[kP], x[kN], &k2);
    ExpandUnitDirection(x[kW], x[kE], &t1);
    ExpandUnitDirection(x[kS], x[kN], &t2);
    LocalExpansion<6, 4> y1, y2;
    ExpandSection(k1, t2, functor.size1, &y1);
    ExpandSection(k2, t1, functor.size2, &y2);

    const Eigen::Matrix<double, 8, 8> l =
        LinearStage<8, 8>([&functor](const auto* y, auto* r) { functor.Residuals(y, y + 4, r); });
    Eigen::Matrix<double, 8, 1> y;
    y << y1.value, y2.value;
    const Eigen::Matrix<double, 8, 1> r = l * y;
    const Eigen::Matrix<double, 8, 1> c = l.transpose() * r;  // ∂E/∂y

    // Over Q = (k1, t2, k2, t1): ∂y/∂Q is block diagonal.
    Eigen::Matrix<double, 8, 12> dy = Eigen::Matrix<double, 8, 12>::Zero();
    dy.block<4, 6>(0, 0) = y1.jacobian;
    dy.block<4, 6>(4, 6) = y2.jacobian;
    const Eigen::Matrix<double, 12, 1> g_q = dy.transpose() * c;
    Eigen::Matrix<double, 12, 12> h_q = dy.transpose() * (l.transpose() * l) * dy;
    h_q.block<6, 6>(0, 0) += y1.WeightedHessian(c.data());
    h_q.block<6, 6>(6, 6) += y2.WeightedHessian(c.data() + 4);

    Nodes::Jacobian<12> dq = Nodes::Jacobian<12>::Zero();
    Nodes::AddRelativeToCentre<3>(k1.jacobian, kW, kP, kE, dq.middleRows<3>(0));
    Nodes::AddDifference<3>(t2.jacobian, kS, kN, dq.middleRows<3>(3));
    Nodes::AddRelativeToCentre<3>(k2.jacobian, kS, kP, kN, dq.middleRows<3>(6));
    Nodes::AddDifference<3>(t1.jacobian, kW, kE, dq.middleRows<3>(9));

    Eigen::Map<Eigen::Matrix<double, 15, 1>> full_gradient(gradient);
    Eigen::Map<Nodes::Hessian> full_hessian(hessian);
    Nodes::Hessian h = dq.transpose() * h_q * dq;
    Nodes::AddRelativeToCentre(k1.WeightedHessian(g_q.data()), kW, kP, kE, &h);
    Nodes::AddDifference(t2.WeightedHessian(g_q.data() + 3), kS, kN, &h);
    Nodes::AddRelativeToCentre(k2.WeightedHessian(g_q.data() + 6), kS, kP, kN, &h);
    Nodes::AddDifference(t1.WeightedHessian(g_q.data() + 9), kW, kE, &h);
    full_hessian = h;
    full_gradient = dq.transpose() * g_q;
    *energy = 0.5 * r.squaredNorm();
    return std::isfinite(*energy) && full_gradient.allFinite() && h.allFinite();
  }

  // The section of binormal k and tangent t (both with their values) over (k, t).
  template <int kTangentIn>
  static void ExpandSection(const LocalExpansion<6, 3>& k, const LocalExpansion<kTangentIn, 3>& t,
                            double size, LocalExpansion<6, 4>* section) {
    const double input[6] = {k.value[0], k.value[1], k.value[2],
                             t.value[0], t.value[1], t.value[2]};
    Expand<6, 4>([size](const auto* in, auto* out) { FvBending::Section(in, in + 3, size, out); },
                 input, section);
  }
};

// FvBendingEdge (nodes A, P, B = 0..2): Q = k, the binormal; r = L k.
template <>
struct FastHessian<FvBendingEdge> {
  static constexpr bool kAvailable = true;
  using Nodes = NodeDerivatives<3>;

  static bool Evaluate(const FvBendingEdge& functor, const double* const* x, double* energy,
                       double* gradient, double* hessian) {
    LocalExpansion<6, 3> k;
    ExpandBinormal(x[0], x[1], x[2], &k);
    const Eigen::Matrix3d l =
        LinearStage<3, 3>([&functor](const auto* q, auto* r) { functor.Residuals(q, r); });
    const Eigen::Vector3d r = l * k.value;
    const Eigen::Vector3d g_q = l.transpose() * r;
    Nodes::Jacobian<3> dq = Nodes::Jacobian<3>::Zero();
    Nodes::AddRelativeToCentre<3>(k.jacobian, 0, 1, 2, dq);
    Nodes::Hessian h = dq.transpose() * (l.transpose() * l) * dq;
    Nodes::AddRelativeToCentre(k.WeightedHessian(g_q.data()), 0, 1, 2, &h);
    Eigen::Map<Eigen::Matrix<double, 9, 1>> full_gradient(gradient);
    Eigen::Map<Nodes::Hessian> full_hessian(hessian);
    full_hessian = h;
    full_gradient = dq.transpose() * g_q;
    *energy = 0.5 * r.squaredNorm();
    return std::isfinite(*energy) && full_gradient.allFinite() && h.allFinite();
  }
};

}  // namespace internal
}  // namespace drape

#endif  // DRAPE_SRC_MODEL_FAST_HESSIAN_H_
