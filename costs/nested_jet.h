// Arithmetic between plain numbers and nested Jets (ceres::Jet<ceres::Jet<double, N>, N>), which
// Ceres 2.1 defines only for one level. With these, a functor written for `double` and `Jet` also
// compiles for the nested Jets that give exact Hessians. Functors write zero as `T()`.
#ifndef DRAPE_COSTS_NESTED_JET_H_
#define DRAPE_COSTS_NESTED_JET_H_

#include <ceres/jet.h>

#include <type_traits>

namespace ceres {

template <typename T, int N, typename S>
using EnableForNestedJet =
    std::enable_if_t<std::is_arithmetic_v<S> && internal::IsJet<T>::value, Jet<T, N>>;

template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator+(const Jet<T, N>& f, S s) {
  return f + Jet<T, N>(T(s));
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator+(S s, const Jet<T, N>& f) {
  return Jet<T, N>(T(s)) + f;
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator-(const Jet<T, N>& f, S s) {
  return f - Jet<T, N>(T(s));
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator-(S s, const Jet<T, N>& f) {
  return Jet<T, N>(T(s)) - f;
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator*(const Jet<T, N>& f, S s) {
  return f * T(s);
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator*(S s, const Jet<T, N>& f) {
  return T(s) * f;
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator/(const Jet<T, N>& f, S s) {
  return f / T(s);
}
template <typename T, int N, typename S>
EnableForNestedJet<T, N, S> operator/(S s, const Jet<T, N>& f) {
  return T(s) / f;
}

}  // namespace ceres

namespace drape {

// The value of a number, a Jet or a nested Jet, as a plain double (its derivative parts dropped):
// for a functor that decides from the value alone which branch its derivatives take.
inline double ScalarPart(double x) { return x; }
template <typename T, int N>
double ScalarPart(const ceres::Jet<T, N>& x) {
  return ScalarPart(x.a);
}

}  // namespace drape

#endif  // DRAPE_COSTS_NESTED_JET_H_
