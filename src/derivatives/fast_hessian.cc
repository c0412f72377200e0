// The finite-volume functors' fast exact derivatives, by their stages (fast_hessian.h explains
// the method and the projection).
#include "src/derivatives/fast_hessian.h"

#include <ceres/jet.h>

#include <Eigen/Core>
#include <cmath>

#include "costs/fv_bending.h"
#include "costs/fv_bending_friction.h"
#include "costs/fv_cell_shear.h"
#include "costs/fv_membrane.h"
#include "costs/fv_twist.h"
#include "src/derivatives/psd_projection.h"
#include "src/derivatives/second_order.h"
#include "src/derivatives/small_product.h"
#include "src/derivatives/stage_derivatives.h"

namespace drape {
namespace internal {
namespace {

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

using BendingNodes = NodeDerivatives<5>;
using TriangleNodes = NodeDerivatives<3>;

// FvBending's curvature blocks, in the order of Q = (k1, t2, k2, t1) (see FvBending below).
struct BendingCurvatures {
  Eigen::Matrix<double, 6, 6> section1, section2, k1, k2;
  Eigen::Matrix3d t1, t2;
};

// ∂Qᵀ (G + blockdiag(sections)) ∂Q + the intermediates' curvatures mapped to the nodes.
BendingNodes::Hessian CombineBending(const BendingNodes::Jacobian<12>& dq,
                                     const Eigen::Matrix<double, 12, 12>& gauss_newton,
                                     const BendingCurvatures& curvatures) {
  enum { kW, kP, kE, kS, kN };
  Eigen::Matrix<double, 12, 12> h_q = gauss_newton;
  h_q.block<6, 6>(0, 0) += curvatures.section1;
  h_q.block<6, 6>(6, 6) += curvatures.section2;
  BendingNodes::Hessian h = SymmetricCongruence(dq, h_q);
  BendingNodes::AddRelativeToCentre(curvatures.k1, kW, kP, kE, &h);
  BendingNodes::AddDifference(curvatures.t2, kS, kN, &h);
  BendingNodes::AddRelativeToCentre(curvatures.k2, kS, kP, kN, &h);
  BendingNodes::AddDifference(curvatures.t1, kW, kE, &h);
  return h;
}

// Whether FvBending's Hessian h is semidefinite, tested on its 12×12 block without P's rows and
// columns: the energy is a function of x_a − x_P (a = W, E, S, N), whose Hessian that block is, and
// h = Tᵀ (block) T with T onto, so the two are semidefinite together (a 12×12 Cholesky costs half a
// 15×15 one).
template <typename Matrix>
bool BendingIsSemidefinite(const Eigen::MatrixBase<Matrix>& h) {
  enum { kW, kP, kE, kS, kN };
  constexpr int kOthers[4] = {kW, kE, kS, kN};
  Eigen::Matrix<double, 12, 12> relative;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      relative.block<3, 3>(3 * i, 3 * j) = h.template block<3, 3>(3 * kOthers[i], 3 * kOthers[j]);
    }
  }
  return IsSemidefinite(relative);
}

// A 3-node term's H₊ into `projection`: its exact Hessian `h` where that is semidefinite, else
// the stand-in that `blockwise()` builds from its curvature blocks (fast_hessian.h, "Projection").
template <typename Blockwise>
void StoreTriangleProjection(bool semidefinite, const TriangleNodes::Hessian& h,
                             StagedProjection* projection, const Blockwise& blockwise) {
  Eigen::Map<TriangleNodes::Hessian> projected(projection->hessian);
  projection->changed = !semidefinite;
  if (semidefinite) {
    projected = h;
  } else {
    projected = blockwise();
  }
}

// A term of one binormal k (nodes A, P, B = 0..2): writes its energy `value`, its gradient
// dqᵀ g_q (dq = ∂k/∂x, g_q = ∂E/∂k) and its Hessian h; whether all are finite.
bool StoreBinormalTermResults(double value, const TriangleNodes::Jacobian<3>& dq,
                              const Eigen::Vector3d& g_q, const TriangleNodes::Hessian& h,
                              double* energy, double* gradient, double* hessian) {
  Eigen::Map<Eigen::Matrix<double, 9, 1>> full_gradient(gradient);
  Eigen::Map<TriangleNodes::Hessian> full_hessian(hessian);
  full_hessian = h;
  full_gradient = dq.transpose() * g_q;
  *energy = value;
  return std::isfinite(*energy) && full_gradient.allFinite() && h.allFinite();
}

// Jᵀ H J + M ⊗ I₃ over (u, v).
Eigen::Matrix<double, 6, 6> MembraneRelative(const Eigen::Matrix<double, 3, 6>& j,
                                             const Eigen::Matrix3d& h_q, const Eigen::Matrix2d& m) {
  Eigen::Matrix<double, 6, 6> h = SymmetricCongruence(j, h_q);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) h.block<3, 3>(3 * a, 3 * b).diagonal().array() += m(a, b);
  }
  return h;
}

}  // namespace

// FvBending (nodes W, P, E, S, N = 0..4). Intermediates Q = (k1, t2, k2, t1), 12 values; the
// sections y1 = Section(k1, t2), y2 = Section(k2, t1); residuals r = L (y1, y2). The Hessian is
//   ∇²E = Jᵀ J  +  ∂Qᵀ (Σ_i c_i ∇²y_i) ∂Q  +  Σ_j g_Q,j ∇²Q_j,   J = L ∂y/∂Q ∂Q/∂x, c = Lᵀ r,
// a Gauss–Newton part (semidefinite by construction) and six small curvature blocks: two sections
// (6×6 over (k, t)), two binormals (6×6 over their relative coordinates), two tangents (3×3).
// Its stand-in, where ∇²E is indefinite, is the Gauss–Newton part (fast_hessian.h, "Projection").
bool FastHessian<FvBending>::Evaluate(const FvBending& functor, const double* const* x,
                                      double* energy, double* gradient, double* hessian,
                                      StagedProjection* projection) {
  enum { kW, kP, kE, kS, kN };
  const BinormalDerivatives k1(x[kW], x[kP], x[kE]), k2(x[kS], x[kP], x[kN]);
  const UnitDirectionDerivatives t1(x[kW], x[kE]), t2(x[kS], x[kN]);
  const SectionDerivatives y1(k1.value, t2.value, functor.size1);
  const SectionDerivatives y2(k2.value, t1.value, functor.size2);

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
  const Eigen::Matrix<double, 12, 1> g_q = SmallProduct(dy.transpose(), c);
  const Eigen::Matrix<double, 8, 12> ldy = SmallProduct(l, dy);
  const Eigen::Matrix<double, 12, 12> gauss_newton = SymmetricProduct(ldy, ldy);
  BendingCurvatures curvatures;
  curvatures.section1 = y1.WeightedHessian(c.data());
  curvatures.section2 = y2.WeightedHessian(c.data() + 4);
  curvatures.k1 = k1.WeightedHessian(g_q.data());
  curvatures.t2 = t2.WeightedHessian(g_q.data() + 3);
  curvatures.k2 = k2.WeightedHessian(g_q.data() + 6);
  curvatures.t1 = t1.WeightedHessian(g_q.data() + 9);

  BendingNodes::Jacobian<12> dq = BendingNodes::Jacobian<12>::Zero();
  BendingNodes::AddRelativeToCentre<3>(k1.jacobian, kW, kP, kE, dq.middleRows<3>(0));
  BendingNodes::AddDifference<3>(t2.jacobian, kS, kN, dq.middleRows<3>(3));
  BendingNodes::AddRelativeToCentre<3>(k2.jacobian, kS, kP, kN, dq.middleRows<3>(6));
  BendingNodes::AddDifference<3>(t1.jacobian, kW, kE, dq.middleRows<3>(9));

  Eigen::Map<Eigen::Matrix<double, 15, 1>> full_gradient(gradient);
  Eigen::Map<BendingNodes::Hessian> full_hessian(hessian);
  full_hessian = CombineBending(dq, gauss_newton, curvatures);
  full_gradient = SmallProduct(dq.transpose(), g_q);
  *energy = 0.5 * r.squaredNorm();
  const bool finite =
      std::isfinite(*energy) && full_gradient.allFinite() && full_hessian.allFinite();
  if (finite && projection) {  // H where semidefinite, else Jᵀ J (fast_hessian.h, "Projection")
    Eigen::Map<BendingNodes::Hessian> projected(projection->hessian);
    projection->changed = !BendingIsSemidefinite(full_hessian);
    if (projection->changed) {  // Jᵀ J with J = L ∂y/∂Q ∂Q/∂x (8×15)
      const Eigen::Matrix<double, 8, 15> j = SmallProduct(ldy, dq);
      projected = SymmetricProduct(j, j);
    } else {
      projected = full_hessian;
    }
  }
  return finite;
}

// FvBendingEdge (nodes A, P, B = 0..2): Q = k, the binormal; r = L k. ∇²E = Jᵀ J + Σ_j g_j ∇²k_j
// (J = L ∂k/∂x, g = Lᵀ r): a Gauss–Newton part and one 6×6 curvature block over (a − p, b − p).
bool FastHessian<FvBendingEdge>::Evaluate(const FvBendingEdge& functor, const double* const* x,
                                          double* energy, double* gradient, double* hessian,
                                          StagedProjection* projection) {
  const BinormalDerivatives k(x[0], x[1], x[2]);
  const Eigen::Matrix3d l =
      LinearStage<3, 3>([&functor](const auto* q, auto* r) { functor.Residuals(q, r); });
  const Eigen::Vector3d r = l * k.value;
  const Eigen::Vector3d g_q = l.transpose() * r;
  TriangleNodes::Jacobian<3> dq = TriangleNodes::Jacobian<3>::Zero();
  TriangleNodes::AddRelativeToCentre<3>(k.jacobian, 0, 1, 2, dq);
  const TriangleNodes::Jacobian<3> j = SmallProduct(l, dq);
  const TriangleNodes::Hessian gauss_newton = SymmetricProduct(j, j);
  Eigen::Matrix<double, 6, 6> curvature = k.WeightedHessian(g_q.data());
  TriangleNodes::Hessian h = gauss_newton;
  TriangleNodes::AddRelativeToCentre(curvature, 0, 1, 2, &h);
  const bool finite =
      StoreBinormalTermResults(0.5 * r.squaredNorm(), dq, g_q, h, energy, gradient, hessian);
  if (finite && projection) {
    StoreTriangleProjection(IsSemidefinite(h), h, projection, [&] {
      ProjectSymmetric(projection->filter, &curvature);
      TriangleNodes::Hessian sum = gauss_newton;
      TriangleNodes::AddRelativeToCentre(curvature, 0, 1, 2, &sum);
      return sum;
    });
  }
  return finite;
}

// FvBendingFriction (nodes A, P, B = 0..2): Q = k, the binormal; E = φ(k) by the functor's
// OfBinormal stage, differentiated over the 3 values of k. Over the relative coordinates
// (a − p, b − p), ∇²E = Kᵀ ∇²φ K + Σ_j φ_j ∇²k_j (K = ∂k/∂(a − p, b − p), 3×6), mapped to the nodes
// by H = Tᵀ B T (T: x ↦ (a − p, b − p)). Its stand-in is B's eigenvalues filtered, mapped the same
// way: semidefinite, H₊ − H = Tᵀ (B₊ − B) T ⪰ 0, translations in its null space; a 6×6
// decomposition in place of the whole 9×9 Hessian's: the friction cotton of docs/benchmarks.md
// assembles H₊ in 0.78 of the CPU time (benchmark scene friction4); at 3 to 5 mm (seven spacings)
// 3,108 newton iterations against 2,926, fewer on four, to the same drape coefficients (1,518
// against 1,270 at 3.8 mm: the paths through the folds scatter with the rounding alone). Projecting
// only the curvature block (∇²φ is semidefinite, φ being convex in k), as FvBendingEdge's, took the
// friction cotton of docs/benchmarks.md 392 newton iterations against 303, to the same minimum.
bool FastHessian<FvBendingFriction>::Evaluate(const FvBendingFriction& functor,
                                              const double* const* x, double* energy,
                                              double* gradient, double* hessian,
                                              StagedProjection* projection) {
  using Number = SecondOrder<3>;
  const BinormalDerivatives k(x[0], x[1], x[2]);
  Number q[3];
  for (int c = 0; c < 3; ++c) q[c] = Number::Variable(k.value[c], c);
  const Number e = functor.OfBinormal(q);
  Eigen::Vector3d g_q;
  Eigen::Matrix3d h_q;
  for (int r = 0; r < 3; ++r) {
    g_q[r] = e.gradient[r];
    for (int c = 0; c < 3; ++c) h_q(r, c) = e.Hessian(r, c);
  }
  TriangleNodes::Jacobian<3> dq = TriangleNodes::Jacobian<3>::Zero();
  TriangleNodes::AddRelativeToCentre<3>(k.jacobian, 0, 1, 2, dq);
  Eigen::Matrix<double, 6, 6> relative = SymmetricCongruence(k.jacobian, h_q);
  relative += k.WeightedHessian(g_q.data());
  TriangleNodes::Hessian h = TriangleNodes::Hessian::Zero();
  TriangleNodes::AddRelativeToCentre(relative, 0, 1, 2, &h);
  const bool finite = StoreBinormalTermResults(e.value, dq, g_q, h, energy, gradient, hessian);
  if (finite && projection) {
    StoreTriangleProjection(IsSemidefinite(relative), h, projection, [&] {
      ProjectSymmetric(projection->filter, &relative);
      TriangleNodes::Hessian stand_in = TriangleNodes::Hessian::Zero();
      TriangleNodes::AddRelativeToCentre(relative, 0, 1, 2, &stand_in);
      return stand_in;
    });
  }
  return finite;
}

namespace {

// E = φ(Q) = ½|r(Q)|² over the Gram entries Q = (u·u, v·v, u·v) of two arms u, v (FvMembrane's
// and FvCellShear's Residuals stage), differentiated over the 3 values of Q. With J = ∂Q/∂(u, v)
// (rows (2u, 0), (0, 2v), (v, u)) and the constant second derivatives of Q,
//   ∇²E = Jᵀ ∇²φ J + M ⊗ I₃,   M = [2 φ_uu  φ_uv; φ_uv  2 φ_vv]   (φ_Q = ∂φ/∂Q),
// over (u, v). Its stand-in: ∇²φ and M each made semidefinite (fast_hessian.h, "Projection").
class GramStage {
 public:
  template <typename Functor>
  bool Evaluate(const Functor& functor, const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    using Number = SecondOrder<3>;
    const double gram[3] = {u.dot(u), v.dot(v), u.dot(v)};
    Number q[3], r[Functor::kNumOutputs];
    for (int k = 0; k < 3; ++k) q[k] = Number::Variable(gram[k], k);
    if (!functor.Residuals(q, r)) return false;
    Number sum;
    for (const Number& residual : r) sum += residual * residual;
    const Number e = 0.5 * sum;
    Eigen::Vector3d g_q;
    for (int k = 0; k < 3; ++k) {
      g_q[k] = e.gradient[k];
      for (int c = 0; c < 3; ++c) h_q_(k, c) = e.Hessian(k, c);
    }
    j_ << 2.0 * u.transpose(), Eigen::RowVector3d::Zero(), Eigen::RowVector3d::Zero(),
        2.0 * v.transpose(), v.transpose(), u.transpose();
    m_ << 2.0 * g_q[0], g_q[2], g_q[2], 2.0 * g_q[1];
    hessian = MembraneRelative(j_, h_q_, m_);
    gradient = j_.transpose() * g_q;
    energy = e.value;
    return std::isfinite(energy) && gradient.allFinite() && hessian.allFinite();
  }

  Eigen::Matrix<double, 6, 6> StandIn(EigenvalueFilter filter) const {
    Eigen::Matrix3d h_q = h_q_;
    Eigen::Matrix2d m = m_;
    ProjectSymmetric(filter, &h_q);
    ProjectSymmetric(filter, &m);
    return MembraneRelative(j_, h_q, m);
  }

  double energy = 0.0;
  Eigen::Matrix<double, 6, 1> gradient;  // over (u, v)
  Eigen::Matrix<double, 6, 6> hessian;

 private:
  Eigen::Matrix<double, 3, 6> j_;
  Eigen::Matrix3d h_q_;
  Eigen::Matrix2d m_;
};

// A 4-node term's Hessian over the relative positions x_a − x_P (a = 1..3, 9×9) mapped to its
// nodes (12×12, row-major): node P's rows and columns are minus the sums of the others'.
void FourNodesFromRelative(const Eigen::Matrix<double, 9, 9>& relative, double* out) {
  Eigen::Map<NodeDerivatives<4>::Hessian> h(out);
  // The sum of the relative Hessian's three block rows: P's row (negated), and by symmetry its
  // column; P's own block is the sum of that row's three blocks.
  const Eigen::Matrix<double, 3, 9> row_sum =
      relative.middleRows<3>(0) + relative.middleRows<3>(3) + relative.middleRows<3>(6);
  h.bottomRightCorner<9, 9>() = relative;
  h.block<3, 9>(0, 3) = -row_sum;
  h.block<9, 3>(3, 0) = -row_sum.transpose();
  h.block<3, 3>(0, 0) =
      row_sum.middleCols<3>(0) + row_sum.middleCols<3>(3) + row_sum.middleCols<3>(6);
}

// A 4-node term's gradient over the relative positions mapped to its nodes.
void FourNodesFromRelative(const Eigen::Matrix<double, 9, 1>& relative, double* out) {
  Eigen::Map<Eigen::Matrix<double, 12, 1>> g(out);
  g << -(relative.segment<3>(0) + relative.segment<3>(3) + relative.segment<3>(6)), relative;
}

}  // namespace

// FvMembrane (nodes P, A, B = 0..2): GramStage over the arms u = A − P, v = B − P, mapped to the
// nodes.
bool FastHessian<FvMembrane>::Evaluate(const FvMembrane& functor, const double* const* x,
                                       double* energy, double* gradient, double* hessian,
                                       StagedProjection* projection) {
  const Eigen::Vector3d u(x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]);
  const Eigen::Vector3d v(x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2]);
  GramStage stage;
  if (!stage.Evaluate(functor, u, v)) return false;
  Eigen::Map<Eigen::Matrix<double, 9, 1>> full_gradient(gradient);
  full_gradient << -(stage.gradient.head<3>() + stage.gradient.tail<3>()), stage.gradient;
  Eigen::Map<TriangleNodes::Hessian> full_hessian(hessian);
  TriangleNodes::Hessian h = TriangleNodes::Hessian::Zero();
  TriangleNodes::AddRelativeToCentre(stage.hessian, 1, 0, 2, &h);
  full_hessian = h;
  *energy = stage.energy;
  if (projection) {
    StoreTriangleProjection(IsSemidefinite(stage.hessian), h, projection, [&] {
      TriangleNodes::Hessian stand_in = TriangleNodes::Hessian::Zero();
      TriangleNodes::AddRelativeToCentre(stage.StandIn(projection->filter), 1, 0, 2, &stand_in);
      return stand_in;
    });
  }
  return true;
}

// FvCellShear (nodes P, E, N, C = 0..3): GramStage over the centre tangents (u_c, v_c) = S X,
// linear in the relative positions X = (E − P, N − P, C − P): u_c = (X_E − X_N + X_C)/2,
// v_c = (X_N − X_E + X_C)/2. Over X the gradient is Sᵀ g and the Hessian Sᵀ H S, mapped to the
// nodes as FvTwist's.
bool FastHessian<FvCellShear>::Evaluate(const FvCellShear& functor, const double* const* x,
                                        double* energy, double* gradient, double* hessian,
                                        StagedProjection* projection) {
  enum { kP, kE, kN, kC };
  Eigen::Vector3d u, v;
  for (int k = 0; k < 3; ++k) {
    u[k] = 0.5 * ((x[kE][k] - x[kP][k]) + (x[kC][k] - x[kN][k]));
    v[k] = 0.5 * ((x[kN][k] - x[kP][k]) + (x[kC][k] - x[kE][k]));
  }
  GramStage stage;
  if (!stage.Evaluate(functor, u, v)) return false;
  Eigen::Matrix<double, 6, 9> s = Eigen::Matrix<double, 6, 9>::Zero();
  const Eigen::Matrix3d half = 0.5 * Eigen::Matrix3d::Identity();
  s.block<3, 3>(0, 0) = half;   // u_c: E
  s.block<3, 3>(0, 3) = -half;  //      N
  s.block<3, 3>(0, 6) = half;   //      C
  s.block<3, 3>(3, 0) = -half;  // v_c: E
  s.block<3, 3>(3, 3) = half;   //      N
  s.block<3, 3>(3, 6) = half;   //      C
  const Eigen::Matrix<double, 9, 1> g_relative = s.transpose() * stage.gradient;
  FourNodesFromRelative(g_relative, gradient);
  const Eigen::Matrix<double, 9, 9> h_relative = SymmetricCongruence(s, stage.hessian);
  FourNodesFromRelative(h_relative, hessian);
  *energy = stage.energy;
  if (projection) {
    projection->changed = !IsSemidefinite(stage.hessian);
    FourNodesFromRelative(projection->changed
                              ? SymmetricCongruence(s, stage.StandIn(projection->filter)).eval()
                              : h_relative,
                          projection->hessian);
  }
  return true;
}

// FvTwist (nodes P, E, N, C = 0..3), by its stages: Q = (d, a, b), linear in the relative
// positions X = (E − P, N − P, C − P) (d = X_C − X_E − X_N, a = X_C, b = X_N − X_E: Q = T X with T
// constant); the unit normal n(a, b) (FvTwist::Normal, in SecondOrder<6> numbers over a and b);
// the residual r(d, n) (FvTwist::Residual, in SecondOrder<6> numbers over d and n). Then
//   ∇_Q r = (r_d, J_nᵀ r_n),   ∇²_Q r = [r_dd, r_dn J_n; ·, J_nᵀ r_nn J_n + Σ_k r_n,k ∇²n_k],
// ∇_X r = Tᵀ ∇_Q r, ∇²_X r = Tᵀ ∇²_Q r T, and E = ½ r²: ∇E = r ∇r, ∇²E = ∇r ∇rᵀ + r ∇²r, mapped
// back to the nodes (P's rows are minus the sum of the others'). Stand-in where ∇²E is indefinite:
// ∇r ∇rᵀ (fast_hessian.h, "Projection").
bool FastHessian<FvTwist>::Evaluate(const FvTwist& functor, const double* const* x, double* energy,
                                    double* gradient, double* hessian,
                                    StagedProjection* projection) {
  enum { kP, kE, kN, kC };
  using Number = SecondOrder<6>;
  Number a[3], b[3], normal[3];
  double d[3];
  for (int k = 0; k < 3; ++k) {
    d[k] = x[kC][k] - x[kE][k] - x[kN][k] + x[kP][k];
    a[k] = Number::Variable(x[kC][k] - x[kP][k], k);
    b[k] = Number::Variable(x[kN][k] - x[kE][k], 3 + k);
  }
  if (!FvTwist::Normal(a, b, normal)) return false;
  Number stage_in[6], r;
  for (int k = 0; k < 3; ++k) {
    stage_in[k] = Number::Variable(d[k], k);
    stage_in[3 + k] = Number::Variable(normal[k].value, 3 + k);
  }
  functor.Residual(stage_in, stage_in + 3, &r);
  // Over Q = (d, a, b).
  Eigen::Matrix<double, 3, 6> j_n;
  for (int k = 0; k < 3; ++k) {
    for (int v = 0; v < 6; ++v) j_n(k, v) = normal[k].gradient[v];
  }
  const Eigen::Vector3d r_n(r.gradient[3], r.gradient[4], r.gradient[5]);
  Eigen::Matrix<double, 9, 1> g_q;
  g_q << r.gradient[0], r.gradient[1], r.gradient[2], j_n.transpose() * r_n;
  Eigen::Matrix<double, 9, 9> h_q;
  Eigen::Matrix3d r_dd, r_dn, r_nn;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      r_dd(i, j) = r.Hessian(i, j);
      r_dn(i, j) = r.Hessian(i, 3 + j);
      r_nn(i, j) = r.Hessian(3 + i, 3 + j);
    }
  }
  Eigen::Matrix<double, 6, 6> curvature = j_n.transpose() * r_nn * j_n;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) curvature(i, j) += r_n[k] * normal[k].Hessian(i, j);
    }
  }
  h_q.topLeftCorner<3, 3>() = r_dd;
  h_q.topRightCorner<3, 6>() = r_dn * j_n;
  h_q.bottomLeftCorner<6, 3>() = h_q.topRightCorner<3, 6>().transpose();
  h_q.bottomRightCorner<6, 6>() = curvature;
  // Q = T X over X = (E − P, N − P, C − P).
  Eigen::Matrix<double, 9, 9> t = Eigen::Matrix<double, 9, 9>::Zero();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  t.block<3, 3>(0, 0) = -identity;  // d
  t.block<3, 3>(0, 3) = -identity;
  t.block<3, 3>(0, 6) = identity;
  t.block<3, 3>(3, 6) = identity;   // a
  t.block<3, 3>(6, 0) = -identity;  // b
  t.block<3, 3>(6, 3) = identity;
  const Eigen::Matrix<double, 9, 1> dr = t.transpose() * g_q;
  const Eigen::Matrix<double, 9, 9> gauss_newton = dr * dr.transpose();
  const Eigen::Matrix<double, 9, 9> h_relative = gauss_newton + r.value * (t.transpose() * h_q * t);
  const Eigen::Matrix<double, 9, 1> g_relative = r.value * dr;
  FourNodesFromRelative(g_relative, gradient);
  FourNodesFromRelative(h_relative, hessian);
  *energy = 0.5 * r.value * r.value;
  const bool finite = std::isfinite(*energy) && g_relative.allFinite() && h_relative.allFinite();
  if (finite && projection) {  // H where semidefinite, else ∇r ∇rᵀ (fast_hessian.h, "Projection")
    projection->changed = !IsSemidefinite(h_relative);
    FourNodesFromRelative(projection->changed ? gauss_newton : h_relative, projection->hessian);
  }
  return finite;
}

}  // namespace internal
}  // namespace drape
