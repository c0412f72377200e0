// The classical fourth-order Runge–Kutta scheme, for the shooting references of the cantilever
// tests (tests/cantilever_test.cc, tests/fv_bending_friction_test.cc).
#ifndef DRAPE_TESTS_RK4_H_
#define DRAPE_TESTS_RK4_H_

namespace drape::testing {

// Integrates y' = derivative(s, y, dy) from s = 0 to `length` in `steps` equal steps; y has N
// components and holds the start on entry, the end on return.
template <int N, typename Derivative>
void IntegrateRk4(const Derivative& derivative, double length, int steps, double* y) {
  const double h = length / steps;
  for (int k = 0; k < steps; ++k) {
    const double s = k * h;
    double k1[N], k2[N], k3[N], k4[N], t[N];
    derivative(s, y, k1);
    for (int i = 0; i < N; ++i) t[i] = y[i] + 0.5 * h * k1[i];
    derivative(s + 0.5 * h, t, k2);
    for (int i = 0; i < N; ++i) t[i] = y[i] + 0.5 * h * k2[i];
    derivative(s + 0.5 * h, t, k3);
    for (int i = 0; i < N; ++i) t[i] = y[i] + h * k3[i];
    derivative(s + h, t, k4);
    for (int i = 0; i < N; ++i) y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_RK4_H_
