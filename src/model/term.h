// One energy term of the model: a cost functor from costs/ bound to the nodes it acts on.
// Energy, gradient and Hessian are all derived from the functor by automatic differentiation
// (ceres::Jet, nested for the Hessian; for the finite-volume functors, nested Jets on each of the
// functor's stages chained together, src/derivatives/fast_hessian.h), so the physics is written
// once, in costs/.
//
// A functor declares
//   static constexpr int kNumNodes;      // nodes it reads, 3 coordinates each
//   static constexpr int kNumOutputs;    // outputs written by operator()
//   static constexpr EnergyForm kForm;   // how the outputs make the energy
//   template <typename T> bool operator()(const T* x0, ..., const T* x{N-1}, T* out) const;
// kSquares: out are residuals r and the energy is ½|r|² (elastic terms, the Ceres convention).
// kPotential: out[0] is the energy itself (linear potentials of gravity and loads).
// Optionally, static constexpr bool kTranslationInvariant = true; for a term of several nodes whose
// energy depends only on their differences (springs, finite-volume terms): its Hessian (and the
// gradient that comes with it) is then taken with respect to x_a − x_0 (a ≥ 1), 3 fewer
// variables, and mapped back exactly (the gradient on node 0 is minus the sum of the others; a
// spring's 6×6 Hessian is [A −A; −A A]).
#ifndef DRAPE_SRC_MODEL_TERM_H_
#define DRAPE_SRC_MODEL_TERM_H_

#include <ceres/autodiff_cost_function.h>
#include <ceres/jet.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "costs/energy_form.h"
#include "src/derivatives/fast_hessian.h"
#include "src/derivatives/psd_projection.h"

namespace drape {

class Term {
 public:
  Term(std::string type, std::vector<int> nodes)
      : type_(std::move(type)), nodes_(std::move(nodes)) {}
  virtual ~Term() = default;

  // The physical family, as counted in summary.json ("structural", "gravity", ...).
  const std::string& type() const { return type_; }
  const std::vector<int>& nodes() const { return nodes_; }
  int num_coordinates() const { return 3 * static_cast<int>(nodes_.size()); }

  // `positions` is the model's global array, 3 doubles per node. Gradient (3k) and Hessian
  // (3k×3k, row-major) are over the term's own nodes in order. False: undefined here.
  virtual bool Energy(const double* positions, double* energy) const = 0;
  virtual bool EnergyGradient(const double* positions, double* energy, double* gradient) const = 0;
  virtual bool EnergyHessian(const double* positions, double* energy, double* gradient,
                             double* hessian) const = 0;
  // False only where the energy, its gradient and its Hessian are all exactly zero: a contact
  // whose every point lies outside its clearance layer (its functor's Touches). The assembly skips
  // such a term (its active set, src/numerics/sparse_hessian.h); the term is asked again at every
  // state, so no contact is missed that the whole set would make.
  virtual bool Touches(const double* /*positions*/) const { return true; }
  // Whether EnergyHessianProjected is available: the term builds a semidefinite stand-in for its
  // Hessian from its functor's stages (src/derivatives/fast_hessian.h, "Projection").
  virtual bool HasStagedProjection() const { return false; }
  // What that stand-in is where the Hessian is indefinite (src/derivatives/fast_hessian.h).
  virtual StandIn StagedStandIn() const { return StandIn::kAboveHessian; }
  // EnergyHessian, and in `projected` (same layout) that semidefinite stand-in, with `*changed`
  // whether it differs from `hessian`. False if not evaluable, or if the term has none.
  virtual bool EnergyHessianProjected(const double* /*positions*/, EigenvalueFilter /*filter*/,
                                      double* /*energy*/, double* /*gradient*/, double* /*hessian*/,
                                      double* /*projected*/, bool* /*changed*/) const {
    return false;
  }
  // The same by nested Jets over the whole functor, whatever EnergyHessian uses: the reference
  // that every faster derivative path is checked against (tests/term_checks.h).
  virtual bool ReferenceHessian(const double* positions, double* energy, double* gradient,
                                double* hessian) const = 0;

  // A residual block for ceres::Problem whose ½|r|² equals this energy, up to a constant for
  // potentials (see ShiftedPotential). Parameter blocks: one per node, in nodes() order.
  virtual ceres::CostFunction* NewCostFunction() const = 0;

 private:
  const std::string type_;
  const std::vector<int> nodes_;
};

namespace internal {

template <typename Functor, typename T, std::size_t... I>
bool CallFunctor(const Functor& functor, const T* const* x, T* out, std::index_sequence<I...>) {
  return functor(x[I]..., out);
}

// Energy from a functor's outputs, in any scalar type.
template <typename Functor, typename T>
bool EvaluateEnergy(const Functor& functor, const T* const* x, T* energy) {
  T out[Functor::kNumOutputs];
  if (!CallFunctor(functor, x, out, std::make_index_sequence<Functor::kNumNodes>())) return false;
  if constexpr (Functor::kForm == EnergyForm::kPotential) {
    *energy = out[0];
  } else {
    T sum = T();
    for (int k = 0; k < Functor::kNumOutputs; ++k) sum += out[k] * out[k];
    *energy = 0.5 * sum;
  }
  return true;
}

// Residual of a linear potential for least squares: r = sqrt(2 (E + shift)), so ½r² = E + shift
// and the gradient of ½r² is exactly that of E. The shift keeps the root's argument positive;
// a step that would make it negative is reported as not evaluable, and Ceres rejects it.
template <typename Functor>
struct ShiftedPotential {
  template <typename T, typename... Rest>
  bool operator()(const T* x0, Rest... rest) const {
    return Apply<T>(std::forward_as_tuple(x0, rest...),
                    std::make_index_sequence<sizeof...(Rest)>());
  }
  template <typename T, typename Tuple, std::size_t... I>
  bool Apply(const Tuple& args, std::index_sequence<I...>) const {
    T energy[1];
    if (!functor(std::get<I>(args)..., energy)) return false;
    const T argument = 2.0 * (energy[0] + shift);
    if (!(argument > 0.0)) return false;
    T* residual = std::get<sizeof...(I)>(args);
    residual[0] = sqrt(argument);
    return true;
  }
  Functor functor;
  double shift;
};

// Whether a functor says on values where its energy can be nonzero: bool Touches(x0, ..., x{N-1}).
template <typename Functor, typename = void>
struct HasTouches : std::false_type {};
template <typename Functor>
struct HasTouches<Functor, std::void_t<decltype(&Functor::Touches)>> : std::true_type {};

template <typename Functor, std::size_t... I>
bool CallTouches(const Functor& functor, const double* const* x, std::index_sequence<I...>) {
  return functor.Touches(x[I]...);
}

template <typename Functor, typename = void>
struct TranslationInvariant : std::false_type {};
template <typename Functor>
struct TranslationInvariant<Functor, std::void_t<decltype(Functor::kTranslationInvariant)>>
    : std::bool_constant<Functor::kTranslationInvariant && (Functor::kNumNodes > 1)> {};

// Energy, gradient and Hessian (row-major, over all 3N coordinates) of a functor at nodes
// x[0..N−1], by nested Jets. kRelative = false: over all 3N coordinates. kRelative = true (a
// translation-invariant functor): over the 3(N−1) relative positions r_a = x_a − x_0, node 0 held
// constant, mapped back exactly with P = (∂r/∂x)ᵀ: gradient P g_r, Hessian P H_r Pᵀ. A 2-node
// term then carries 3 derivatives instead of 6, a quarter of the work.
template <bool kRelative, typename Functor>
bool NestedJetHessian(const Functor& functor, const double* const* positions, double* energy,
                      double* gradient, double* hessian) {
  constexpr int kDofs = 3 * Functor::kNumNodes;
  constexpr int kFirst = kRelative ? 3 : 0;  // the first coordinate that carries a derivative
  constexpr int kVariables = kDofs - kFirst;
  using Jet1 = ceres::Jet<double, kVariables>;
  using Jet2 = ceres::Jet<Jet1, kVariables>;
  Jet2 storage[kDofs];
  const Jet2* x[Functor::kNumNodes];
  for (int k = 0; k < kDofs; ++k) {
    const double value = positions[k / 3][k % 3];
    if (k < kFirst) {
      storage[k] = Jet2(Jet1(value));
    } else {
      storage[k].a = Jet1(value, k - kFirst);
      storage[k].v.setZero();
      storage[k].v[k - kFirst] = Jet1(1.0);
    }
  }
  for (int a = 0; a < Functor::kNumNodes; ++a) x[a] = storage + 3 * a;
  Jet2 e;
  if (!EvaluateEnergy(functor, x, &e)) return false;
  Eigen::Matrix<double, kVariables, 1> g;
  Eigen::Matrix<double, kVariables, kVariables> h;
  for (int r = 0; r < kVariables; ++r) {
    g[r] = e.a.v[r];
    h.row(r) = e.v[r].v.transpose();
  }
  *energy = e.a.a;
  Eigen::Map<Eigen::Matrix<double, kDofs, 1>> full_gradient(gradient);
  Eigen::Map<Eigen::Matrix<double, kDofs, kDofs, Eigen::RowMajor>> full_hessian(hessian);
  if constexpr (kRelative) {
    Eigen::Matrix<double, kDofs, kVariables> p = Eigen::Matrix<double, kDofs, kVariables>::Zero();
    for (int k = 0; k < kVariables; ++k) {
      p(k % 3, k) = -1.0;
      p(k + 3, k) = 1.0;
    }
    full_gradient = p * g;
    full_hessian = p * h * p.transpose();
  } else {
    full_gradient = g;
    full_hessian = h;
  }
  return std::isfinite(e.a.a) && g.allFinite() && h.allFinite();
}

template <typename Functor, std::size_t... I>
ceres::CostFunction* NewAutoDiffCost(Functor* functor, std::index_sequence<I...>) {
  return new ceres::AutoDiffCostFunction<Functor, Functor::kNumOutputs, (I * 0 + 3)...>(functor);
}

template <typename Functor, std::size_t... I>
ceres::CostFunction* NewShiftedCost(ShiftedPotential<Functor>* functor, std::index_sequence<I...>) {
  return new ceres::AutoDiffCostFunction<ShiftedPotential<Functor>, 1, (I * 0 + 3)...>(functor);
}

}  // namespace internal

// A term whose derivatives come from automatic differentiation of `Functor`.
template <typename Functor>
class AutoDiffTerm : public Term {
 public:
  static constexpr int kN = Functor::kNumNodes;
  static constexpr int kDofs = 3 * kN;
  using Jet1 = ceres::Jet<double, kDofs>;

  // `least_squares_shift` (J) is used only for potentials in NewCostFunction().
  AutoDiffTerm(std::string type, std::vector<int> nodes, const Functor& functor,
               double least_squares_shift = 0.0)
      : Term(std::move(type), std::move(nodes)),
        functor_(functor),
        least_squares_shift_(least_squares_shift) {}

  const Functor& functor() const { return functor_; }

  bool Energy(const double* positions, double* energy) const override {
    const double* x[kN];
    for (int a = 0; a < kN; ++a) x[a] = positions + 3 * nodes()[a];
    return internal::EvaluateEnergy(functor_, x, energy);
  }

  bool Touches(const double* positions) const override {
    if constexpr (internal::HasTouches<Functor>::value) {
      const double* x[kN];
      for (int a = 0; a < kN; ++a) x[a] = positions + 3 * nodes()[a];
      return internal::CallTouches(functor_, x, std::make_index_sequence<kN>());
    } else {
      return true;
    }
  }

  bool EnergyGradient(const double* positions, double* energy, double* gradient) const override {
    Jet1 storage[kDofs];
    const Jet1* x[kN];
    for (int a = 0; a < kN; ++a) {
      for (int c = 0; c < 3; ++c)
        storage[3 * a + c] = Jet1(positions[3 * nodes()[a] + c], 3 * a + c);
      x[a] = storage + 3 * a;
    }
    Jet1 e;
    if (!internal::EvaluateEnergy(functor_, x, &e)) return false;
    *energy = e.a;
    for (int k = 0; k < kDofs; ++k) gradient[k] = e.v[k];
    return std::isfinite(e.a) && e.v.allFinite();
  }

  // By the functor's staged chain rule where it has one (src/derivatives/fast_hessian.h), else by
  // nested Jets.
  bool EnergyHessian(const double* positions, double* energy, double* gradient,
                     double* hessian) const override {
    const double* x[kN];
    for (int a = 0; a < kN; ++a) x[a] = positions + 3 * nodes()[a];
    if constexpr (internal::FastHessian<Functor>::kAvailable) {
      return internal::FastHessian<Functor>::Evaluate(functor_, x, energy, gradient, hessian);
    } else {
      return internal::NestedJetHessian<internal::TranslationInvariant<Functor>::value>(
          functor_, x, energy, gradient, hessian);
    }
  }

  bool HasStagedProjection() const override { return internal::FastHessian<Functor>::kAvailable; }

  StandIn StagedStandIn() const override {
    if constexpr (internal::FastHessian<Functor>::kAvailable) {
      return internal::FastHessian<Functor>::kStandIn;
    } else {
      return StandIn::kAboveHessian;
    }
  }

  bool EnergyHessianProjected(const double* positions, EigenvalueFilter filter, double* energy,
                              double* gradient, double* hessian, double* projected,
                              bool* changed) const override {
    if constexpr (internal::FastHessian<Functor>::kAvailable) {
      const double* x[kN];
      for (int a = 0; a < kN; ++a) x[a] = positions + 3 * nodes()[a];
      internal::StagedProjection projection{filter, projected, false};
      const bool ok = internal::FastHessian<Functor>::Evaluate(functor_, x, energy, gradient,
                                                               hessian, &projection);
      *changed = projection.changed;
      return ok;
    } else {
      return false;
    }
  }

  bool ReferenceHessian(const double* positions, double* energy, double* gradient,
                        double* hessian) const override {
    const double* x[kN];
    for (int a = 0; a < kN; ++a) x[a] = positions + 3 * nodes()[a];
    return internal::NestedJetHessian<internal::TranslationInvariant<Functor>::value>(
        functor_, x, energy, gradient, hessian);
  }

  ceres::CostFunction* NewCostFunction() const override {
    if constexpr (Functor::kForm == EnergyForm::kPotential) {
      auto* shifted = new internal::ShiftedPotential<Functor>{functor_, least_squares_shift_};
      return internal::NewShiftedCost<Functor>(shifted, std::make_index_sequence<kN>());
    } else {
      return internal::NewAutoDiffCost(new Functor(functor_), std::make_index_sequence<kN>());
    }
  }

 private:
  const Functor functor_;
  const double least_squares_shift_;
};

// The functor of `term` if it is an AutoDiffTerm<Functor>, else null: how a solver that needs a
// term's rest-state data (a spring's stiffness and rest length) reads it.
template <typename Functor>
const Functor* FunctorOf(const Term& term) {
  const auto* typed = dynamic_cast<const AutoDiffTerm<Functor>*>(&term);
  return typed ? &typed->functor() : nullptr;
}

template <typename Functor>
std::unique_ptr<Term> MakeTerm(std::string type, std::vector<int> nodes, const Functor& functor,
                               double least_squares_shift = 0.0) {
  return std::make_unique<AutoDiffTerm<Functor>>(std::move(type), std::move(nodes), functor,
                                                 least_squares_shift);
}

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_TERM_H_
