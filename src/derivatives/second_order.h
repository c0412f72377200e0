// A number that carries its gradient and Hessian over N variables (forward-mode automatic
// differentiation to second order), for the small stages of src/derivatives/fast_hessian.h.
//
// It gives what nested Jets (ceres::Jet<ceres::Jet<double, N>, N>) give — value, exact gradient,
// exact Hessian — with the Hessian stored once (its upper triangle, N(N+1)/2 numbers, where a
// nested Jet holds (N+1)² of which N(N+1)/2 are repeats) and every operation a short loop over
// fixed-size arrays that the compiler unrolls. Each operation is the chain rule of one elementary
// function f: value f(a), gradient f′ ∇a, Hessian f′ ∇²a + f″ ∇a ∇aᵀ (and for a product,
// a ∇²b + b ∇²a + ∇a ∇bᵀ + ∇b ∇aᵀ). Only what the staged functors use is defined: + − × ÷ with
// numbers and each other, comparisons with numbers (by value), sqrt, asin. The stages' results are
// checked against nested Jets over each whole functor (tests/term_checks.h).
#ifndef DRAPE_SRC_DERIVATIVES_SECOND_ORDER_H_
#define DRAPE_SRC_DERIVATIVES_SECOND_ORDER_H_

#include <cmath>

namespace drape::internal {

template <int N>
struct SecondOrder {
  static constexpr int kPacked = N * (N + 1) / 2;  // upper triangle, row by row

  double value = 0.0;
  double gradient[N] = {};
  double hessian[kPacked] = {};

  SecondOrder() = default;
  explicit SecondOrder(double constant) : value(constant) {}
  // The variable number k (0 ≤ k < N) at `at`.
  static SecondOrder Variable(double at, int k) {
    SecondOrder x(at);
    x.gradient[k] = 1.0;
    return x;
  }
  // Entry (r, c) of the Hessian, either triangle.
  double Hessian(int r, int c) const {
    if (r > c) return Hessian(c, r);
    return hessian[r * N - r * (r - 1) / 2 + (c - r)];
  }

  SecondOrder& operator+=(const SecondOrder& b) { return *this = *this + b; }
  SecondOrder& operator-=(const SecondOrder& b) { return *this = *this - b; }
  SecondOrder& operator*=(const SecondOrder& b) { return *this = *this * b; }

  friend SecondOrder operator+(const SecondOrder& a, const SecondOrder& b) {
    SecondOrder r(a.value + b.value);
    for (int i = 0; i < N; ++i) r.gradient[i] = a.gradient[i] + b.gradient[i];
    for (int i = 0; i < kPacked; ++i) r.hessian[i] = a.hessian[i] + b.hessian[i];
    return r;
  }
  friend SecondOrder operator-(const SecondOrder& a, const SecondOrder& b) {
    SecondOrder r(a.value - b.value);
    for (int i = 0; i < N; ++i) r.gradient[i] = a.gradient[i] - b.gradient[i];
    for (int i = 0; i < kPacked; ++i) r.hessian[i] = a.hessian[i] - b.hessian[i];
    return r;
  }
  friend SecondOrder operator-(const SecondOrder& a) { return Scaled(a, -1.0); }
  friend SecondOrder operator*(const SecondOrder& a, const SecondOrder& b) {
    SecondOrder r(a.value * b.value);
    for (int i = 0; i < N; ++i) r.gradient[i] = a.value * b.gradient[i] + b.value * a.gradient[i];
    int k = 0;
    for (int i = 0; i < N; ++i) {
      for (int j = i; j < N; ++j, ++k) {
        r.hessian[k] = a.value * b.hessian[k] + b.value * a.hessian[k] +
                       a.gradient[i] * b.gradient[j] + b.gradient[i] * a.gradient[j];
      }
    }
    return r;
  }
  friend SecondOrder operator/(const SecondOrder& a, const SecondOrder& b) {
    return a * Reciprocal(b);
  }

  friend SecondOrder operator+(const SecondOrder& a, double s) {
    SecondOrder r = a;
    r.value += s;
    return r;
  }
  friend SecondOrder operator+(double s, const SecondOrder& a) { return a + s; }
  friend SecondOrder operator-(const SecondOrder& a, double s) { return a + (-s); }
  friend SecondOrder operator-(double s, const SecondOrder& a) { return Scaled(a, -1.0) + s; }
  friend SecondOrder operator*(const SecondOrder& a, double s) { return Scaled(a, s); }
  friend SecondOrder operator*(double s, const SecondOrder& a) { return Scaled(a, s); }
  friend SecondOrder operator/(const SecondOrder& a, double s) { return Scaled(a, 1.0 / s); }
  friend SecondOrder operator/(double s, const SecondOrder& a) { return Scaled(Reciprocal(a), s); }

  friend bool operator<(const SecondOrder& a, double s) { return a.value < s; }
  friend bool operator>(const SecondOrder& a, double s) { return a.value > s; }
  friend bool operator<=(const SecondOrder& a, double s) { return a.value <= s; }
  friend bool operator>=(const SecondOrder& a, double s) { return a.value >= s; }

  friend SecondOrder sqrt(const SecondOrder& a) {
    const double root = std::sqrt(a.value);
    return Compose(a, root, 0.5 / root, -0.25 / (root * a.value));
  }

  friend SecondOrder asin(const SecondOrder& a) {
    const double complement = 1.0 - a.value * a.value;  // cos² of the angle
    const double first = 1.0 / std::sqrt(complement);
    return Compose(a, std::asin(a.value), first, a.value * first / complement);
  }

  // f(a) for f(a.value) = `value`, f′ = `first`, f″ = `second`.
  static SecondOrder Compose(const SecondOrder& a, double value, double first, double second) {
    SecondOrder r(value);
    for (int i = 0; i < N; ++i) r.gradient[i] = first * a.gradient[i];
    int k = 0;
    for (int i = 0; i < N; ++i) {
      for (int j = i; j < N; ++j, ++k) {
        r.hessian[k] = first * a.hessian[k] + second * a.gradient[i] * a.gradient[j];
      }
    }
    return r;
  }
  static SecondOrder Reciprocal(const SecondOrder& a) {
    const double inverse = 1.0 / a.value;
    return Compose(a, inverse, -inverse * inverse, 2.0 * inverse * inverse * inverse);
  }
  static SecondOrder Scaled(const SecondOrder& a, double s) {
    SecondOrder r(s * a.value);
    for (int i = 0; i < N; ++i) r.gradient[i] = s * a.gradient[i];
    for (int i = 0; i < kPacked; ++i) r.hessian[i] = s * a.hessian[i];
    return r;
  }
};

}  // namespace drape::internal

#endif  // DRAPE_SRC_DERIVATIVES_SECOND_ORDER_H_
