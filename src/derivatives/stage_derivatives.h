// Closed-form first and second derivatives of the bending functors' small stages
// (costs/fv_bending.h): the curvature binormal (3 nodes), the unit tangent (2 nodes) and
// FvBending's section (a binormal and a tangent). src/derivatives/fast_hessian.h chains them into
// each term's gradient and Hessian.
//
// Each stage's value is the functor's own stage function evaluated in doubles; only its
// derivatives are written here, as the formulas below. Every derivative is checked against
// second-order automatic differentiation of the same stage function at random and at straight
// (flat) states (tests/stage_derivatives_test.cc), and each term's assembled result against the
// nested-Jet Hessian of the whole functor (tests/term_checks.h). They replace second-order
// forward differentiation of the stages, which carried a packed Hessian through every operation:
// the finite-volume terms' local derivatives fell from 5.5 to 3.4 CPU µs per node
// (docs/benchmarks.md, session 14).
//
// A weighted Hessian Σ_i w_i ∇²q_i (the stage's outputs q weighted by w) is what the chain rule
// needs (fast_hessian.h), so each stage gives that and never its outputs' Hessians one by one.
#ifndef DRAPE_SRC_DERIVATIVES_STAGE_DERIVATIVES_H_
#define DRAPE_SRC_DERIVATIVES_STAGE_DERIVATIVES_H_

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "costs/fv_bending.h"

namespace drape::internal {

// [a]×, the matrix of a × ·.
inline Eigen::Matrix3d CrossMatrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

// The curvature binormal of a → p → b over the relative coordinates (u, v) = (a − p, b − p).
// With the functor's arms e0 = p − a = −u and e1 = b − p = v:
//   κb = 2c/d,   c = e0×e1 = v×u,   d = |e0||e1| + e0·e1 = |u||v| − u·v,
//   ∂κb/∂(u, v) = (2/d) [ [v]×  −[u]× ] − κb ∇dᵀ/d,   ∇d = (|v| û − v, |u| v̂ − u),
//   ∇²d = [ |v|/|u| (I − ûûᵀ)   ûv̂ᵀ − I ;  v̂ûᵀ − I   |u|/|v| (I − v̂v̂ᵀ) ]   (û = u/|u|),
// and for weights w, with γ = w·c (∇γ = (w×v, u×w), ∇²γ = [0 [w]×; −[w]× 0]),
//   Σ w_i ∇²κb_i = (2/d) ∇²γ − (2/d²)(∇d ∇γᵀ + ∇γ ∇dᵀ) − (2γ/d²) ∇²d + (4γ/d³) ∇d ∇dᵀ.
// Not finite where an arm has zero length or the arms fold back (d = 0), as the functor.
class BinormalDerivatives {
 public:
  BinormalDerivatives(const double* a, const double* p, const double* b)
      : u_(a[0] - p[0], a[1] - p[1], a[2] - p[2]),
        v_(b[0] - p[0], b[1] - p[1], b[2] - p[2]),
        length_u_(u_.norm()),
        length_v_(v_.norm()),
        denominator_(length_u_ * length_v_ - u_.dot(v_)) {
    CurvatureBinormal(a, p, b, value.data());
    grad_denominator_ << length_v_ / length_u_ * u_ - v_, length_u_ / length_v_ * v_ - u_;
    const double scale = 2.0 / denominator_;
    jacobian << scale * CrossMatrix(v_), -scale * CrossMatrix(u_);
    jacobian -= value * grad_denominator_.transpose() / denominator_;
  }

  Eigen::Matrix<double, 6, 6> WeightedHessian(const double* weights) const {
    const Eigen::Vector3d w(weights);
    const double d = denominator_;
    const double gamma = w.dot(v_.cross(u_));
    Eigen::Matrix<double, 6, 1> grad_gamma;
    grad_gamma << w.cross(v_), u_.cross(w);
    const Eigen::Matrix<double, 6, 1> grad_d = grad_denominator_;
    Eigen::Matrix<double, 6, 6> h =
        (4.0 * gamma / (d * d * d)) * grad_d * grad_d.transpose() -
        (2.0 / (d * d)) * (grad_d * grad_gamma.transpose() + grad_gamma * grad_d.transpose());
    const Eigen::Matrix3d w_cross = (2.0 / d) * CrossMatrix(w);
    h.topRightCorner<3, 3>() += w_cross;
    h.bottomLeftCorner<3, 3>() -= w_cross;
    const double curvature_weight = -2.0 * gamma / (d * d);
    const Eigen::Vector3d unit_u = u_ / length_u_, unit_v = v_ / length_v_;
    const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
    h.topLeftCorner<3, 3>() +=
        curvature_weight * length_v_ / length_u_ * (identity - unit_u * unit_u.transpose());
    h.bottomRightCorner<3, 3>() +=
        curvature_weight * length_u_ / length_v_ * (identity - unit_v * unit_v.transpose());
    const Eigen::Matrix3d mixed = curvature_weight * (unit_u * unit_v.transpose() - identity);
    h.topRightCorner<3, 3>() += mixed;
    h.bottomLeftCorner<3, 3>() += mixed.transpose();
    return h;
  }

  Eigen::Vector3d value;
  Eigen::Matrix<double, 3, 6> jacobian;

 private:
  Eigen::Vector3d u_, v_;
  double length_u_, length_v_, denominator_;
  Eigen::Matrix<double, 6, 1> grad_denominator_;
};

// The unit vector t = s/|s| along s = b − a, over the coordinates of s:
//   ∂t/∂s = (I − ttᵀ)/|s|,   Σ w_i ∇²t_i = −(w tᵀ + t wᵀ + (w·t)(I − 3ttᵀ))/|s|².
// Zero, with zero derivatives, where a = b (as the functor's UnitDirection).
class UnitDirectionDerivatives {
 public:
  UnitDirectionDerivatives(const double* a, const double* b)
      : length_(Eigen::Vector3d(b[0] - a[0], b[1] - a[1], b[2] - a[2]).norm()) {
    UnitDirection(a, b, value.data());
    jacobian.setZero();
    if (length_ > 0.0) {
      jacobian = (Eigen::Matrix3d::Identity() - value * value.transpose()) / length_;
    }
  }

  Eigen::Matrix3d WeightedHessian(const double* weights) const {
    if (!(length_ > 0.0)) return Eigen::Matrix3d::Zero();
    const Eigen::Vector3d w(weights);
    const Eigen::Vector3d& t = value;
    const Eigen::Matrix3d h = w * t.transpose() + t * w.transpose() +
                              w.dot(t) * (Eigen::Matrix3d::Identity() - 3.0 * t * t.transpose());
    return -h / (length_ * length_);
  }

  Eigen::Vector3d value;
  Eigen::Matrix3d jacobian;

 private:
  double length_;
};

// FvBending's section y = (k·t/l, k/l − (k·t/l) t) of a binormal k and a unit tangent t, over
// (k, t), l the control-volume size:
//   ∂y0 = (tᵀ, kᵀ)/l,   ∂(y1..3) = ( (I − ttᵀ)/l,  −(t kᵀ/l + y0 I) ),
// and for weights (w0, w) (w over y1..3), Σ w_i ∇²y_i has the blocks
//   kk: 0,   kt: ((w0 − w·t) I − t wᵀ)/l,   tt: −(k wᵀ + w kᵀ)/l.
class SectionDerivatives {
 public:
  SectionDerivatives(const Eigen::Vector3d& k, const Eigen::Vector3d& t, double size)
      : k_(k), t_(t), size_(size) {
    FvBending::Section(k.data(), t.data(), size, value.data());
    jacobian.row(0) << t.transpose() / size, k.transpose() / size;
    jacobian.bottomLeftCorner<3, 3>() = (Eigen::Matrix3d::Identity() - t * t.transpose()) / size;
    jacobian.bottomRightCorner<3, 3>() =
        -(t * k.transpose() / size + value[0] * Eigen::Matrix3d::Identity());
  }

  Eigen::Matrix<double, 6, 6> WeightedHessian(const double* weights) const {
    const double w0 = weights[0];
    const Eigen::Vector3d w(weights + 1);
    Eigen::Matrix<double, 6, 6> h;
    h.topLeftCorner<3, 3>().setZero();
    h.topRightCorner<3, 3>() =
        ((w0 - w.dot(t_)) * Eigen::Matrix3d::Identity() - t_ * w.transpose()) / size_;
    h.bottomLeftCorner<3, 3>() = h.topRightCorner<3, 3>().transpose();
    h.bottomRightCorner<3, 3>() = -(k_ * w.transpose() + w * k_.transpose()) / size_;
    return h;
  }

  Eigen::Matrix<double, 4, 1> value;
  Eigen::Matrix<double, 4, 6> jacobian;

 private:
  Eigen::Vector3d k_, t_;
  double size_;
};

}  // namespace drape::internal

#endif  // DRAPE_SRC_DERIVATIVES_STAGE_DERIVATIVES_H_
