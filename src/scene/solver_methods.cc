// The catalogue of solver methods (see solver_methods.h). Adding a method: one entry here, one
// factory under the same name in src/solvers/solver_registry.cc, one row per option in
// docs/reference.md.
#include "src/scene/solver_methods.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <sstream>

namespace drape {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

MethodOption Real(const std::string& key, std::optional<double> default_value, double min,
                  double max, const std::string& doc) {
  MethodOption option;
  option.key = key;
  option.default_value = default_value;
  option.min = min;
  option.max = max;
  option.doc = doc;
  return option;
}

MethodOption Integer(const std::string& key, double default_value, double min, double max,
                     const std::string& doc) {
  MethodOption option = Real(key, default_value, min, max, doc);
  option.integer = true;
  return option;
}

MethodOption Positive(MethodOption option) {
  option.min_exclusive = true;
  return option;
}

MethodOption BelowMax(MethodOption option) {
  option.max_exclusive = true;
  return option;
}

MethodOption Derived(MethodOption option, const std::string& default_text) {
  option.default_value.reset();
  option.default_text = default_text;
  return option;
}

// The options every NLopt method shares.
MethodOption NloptMemory() {
  return Integer("memory", 10, 1, 1000, "vectors kept by the limited-memory update");
}
MethodOption NloptLocalEnergy() {
  return Integer("local_energy", 1, 0, 1,
                 "1: minimise the energy relative to the best point (sums of term changes, "
                 "no round-off stall); 0: the total energy");
}

std::vector<SolverMethod> BuildCatalogue() {
  return {
      {"newton",
       "Newton on the exact energy: exact Hessians (nested Jets, or the finite-volume terms' "
       "staged chain rule), per-term PSD projection far from the "
       "solution, CHOLMOD supernodal Cholesky, pseudo-time regularisation M/dt^2 and an Armijo "
       "line search; quadratic near the end (the default)",
       1000,
       600.0,
       {Real("regularization", 1e-4, 1e-12, 1e16, "initial pseudo-time regularisation mu"),
        Integer("max_line_search", 30, 1, 1000, "energy evaluations per line search"),
        Integer("max_expansions", 4, 0, 60,
                "doublings of an accepted full step (0 unless given where the fabric has a "
                "bending friction)"),
        Real("exact_hessian_residual", kInf, 0, kInf,
             "try the unprojected Hessian only below this relative residual"),
        Real("absolute_projection_above", 1e-4, 0, kInf,
             "negative term eigenvalues take their magnitude above this relative residual, "
             "zero below (0: magnitudes always; the finite-volume bending term's stand-in is its "
             "Gauss-Newton part either way)"),
        Integer("exact_retry_steps", 10, 1, 1e6,
                "after the Hessian fails to factorise, steps before it is tried again"),
        Integer("escape_saddles", 1, 0, 1,
                "1: where the residual meets the tolerance at a saddle, leave it along the most "
                "negative curvature; 0: stop there")}},
      {"ceres-lbfgs",
       "L-BFGS on the exact energy (ceres::GradientProblemSolver, per-term autodiff gradients)",
       20000,
       600.0,
       {Integer("memory", 20, 1, 1000, "rank of the L-BFGS approximation")}},
      {"ceres-lm",
       "Levenberg-Marquardt on the terms as least squares (linear potentials shifted); fails on "
       "taut drapes (no geometric stiffness)",
       1000,
       600.0,
       {}},
      {"ceres-dogleg",
       "Powell's dogleg on the terms as least squares (linear potentials shifted)",
       1000,
       600.0,
       {}},
      {"puiseux-fixed-point",
       "Puiseux's fixed point: A0 x(n+1) = A(xn) xn + f with A0 factorised once; springs and "
       "constant forces only; the reference solver of the mass-spring model",
       20000,
       600.0,
       {Positive(Real("relaxation", 1.0, 0, 2, "step relaxation omega: x += omega * step"))}},
      {"puiseux-dynamic",
       "Puiseux's implicit dynamic scheme (A0 + M/dt^2 + beta/2dt) x(n+1) = ...; stops at rest, "
       "at t_max or on the residual",
       20000,
       600.0,
       {Positive(Real("dt", 0.01, 0, 100, "time step, s")),
        Real("beta", 0.0, 0, 1e12, "viscous damping, N s/m"),
        Positive(Real("t_max", kInf, 0, kInf, "simulated time after which it stops, s")),
        Derived(Positive(Real("epsilon", 0, 0, kInf,
                              "at rest when the kinetic energy is below epsilon^2, J")),
                "solver.tolerance")},
       true},
      {"explicit-euler",
       "Rusinko & Swan's explicit Euler with friction: v <- (1-f)v + a dt, x <- x + v dt, and "
       "Provot's stretch-limit constraint breadth-first from the fixed nodes; stops at rest",
       200000,
       600.0,
       {Derived(Positive(Real("dt", 0, 0, 100, "time step, s")),
                "1/omega_max of the springs and masses"),
        BelowMax(Real("friction", 0.01, 0, 1, "fraction of the velocity lost per step")),
        [] {
          MethodOption limit =
              Derived(Positive(Real("stretch_limit", 0, 1, kInf, "Provot's maximum stretch ratio")),
                      "springs.stretch_limit (0: none)");
          limit.zero_means_none = true;
          return limit;
        }()},
       true},
      {"nlopt-lbfgs",
       "NLopt LD_LBFGS on the exact energy; stops on the relative residual; iterations = energy "
       "evaluations",
       20000,
       600.0,
       {NloptMemory(), NloptLocalEnergy()}},
      {"nlopt-tnewton",
       "NLopt LD_TNEWTON_PRECOND_RESTART (preconditioned truncated Newton) on the exact energy",
       20000,
       600.0,
       {NloptMemory(), NloptLocalEnergy()}},
      {"nlopt-var2",
       "NLopt LD_VAR2 (shifted limited-memory variable metric) on the exact energy",
       20000,
       600.0,
       {NloptMemory(), NloptLocalEnergy()}},
      {"nlopt-mma",
       "NLopt LD_MMA (method of moving asymptotes) on the exact energy",
       20000,
       600.0,
       {NloptLocalEnergy()}},
      {"nlopt-slsqp",
       "NLopt LD_SLSQP (dense SQP) on the exact energy; refused above 1,000 free dofs",
       20000,
       600.0,
       {NloptLocalEnergy()}},
  };
}

std::string Number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

const std::vector<SolverMethod>& SolverMethods() {
  static const std::vector<SolverMethod> methods = BuildCatalogue();
  return methods;
}

const SolverMethod* FindSolverMethod(const std::string& name) {
  for (const auto& method : SolverMethods()) {
    if (method.name == name) return &method;
  }
  return nullptr;
}

const MethodOption* FindMethodOption(const SolverMethod& method, const std::string& key) {
  for (const auto& option : method.options) {
    if (option.key == key) return &option;
  }
  return nullptr;
}

std::string DescribeRange(const MethodOption& option) {
  std::string range = (option.min_exclusive ? "(" : "[") + Number(option.min) + ", " +
                      Number(option.max) +
                      (option.max_exclusive || std::isinf(option.max) ? ")" : "]");
  if (option.integer) range = "integer in " + range;
  if (option.zero_means_none) range = "0 (none) or " + range;
  return range;
}

std::string DescribeDefault(const MethodOption& option) {
  return option.default_value ? Number(*option.default_value) : option.default_text;
}

std::string CheckMethodOption(const MethodOption& option, double value) {
  if (!std::isfinite(value) && !(std::isinf(option.max) && value == option.max)) {
    return "must be a finite number, got " + Number(value);
  }
  if (option.zero_means_none && value == 0.0) return "";
  const bool below = option.min_exclusive ? !(value > option.min) : !(value >= option.min);
  const bool above = option.max_exclusive ? !(value < option.max) : !(value <= option.max);
  if (below || above || (option.integer && value != std::floor(value))) {
    const bool bracket = !option.integer && !option.zero_means_none;
    return "must be " +
           std::string(option.integer ? "an "
                       : bracket      ? "in "
                                      : "") +
           DescribeRange(option) + ", got " + Number(value);
  }
  return "";
}

std::optional<double> MethodOptionValue(const std::string& method,
                                        const std::map<std::string, double>& given,
                                        const std::string& key) {
  const SolverMethod* registered = FindSolverMethod(method);
  assert(registered && "an unregistered method reads an option");
  const MethodOption* option = registered ? FindMethodOption(*registered, key) : nullptr;
  assert(option && "a method reads an option it does not register");
  if (const auto found = given.find(key); found != given.end()) return found->second;
  return option ? option->default_value : std::nullopt;
}

int EffectiveMaxIterations(const SolverSpec& spec, const std::string& method) {
  const SolverMethod* registered = FindSolverMethod(method);
  assert(registered);
  return spec.max_iterations.value_or(registered ? registered->max_iterations : 1);
}

double EffectiveTimeLimit(const SolverSpec& spec, const std::string& method) {
  const SolverMethod* registered = FindSolverMethod(method);
  assert(registered);
  return spec.time_limit.value_or(registered ? registered->time_limit : 0.0);
}

}  // namespace drape
