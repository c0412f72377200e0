// newton: Newton's method on the total energy over the free coordinates, with exact Hessians.
//
// Each iteration assembles the energy, its gradient and its Hessian from the terms' nested-Jet
// derivatives (FreeHessian), in two versions: the true Hessian H and H₊, whose every term is made
// positive semidefinite (the finite-volume terms by their own stand-ins,
// src/derivatives/fast_hessian.h: the bending term's is its Gauss–Newton part). Far from
// equilibrium (relative residual above 1e-4) H₊ replaces a term's negative eigenvalues with their
// magnitudes: clamping them to zero, the usual projection, leaves a compressed spring no sideways
// curvature, and the steps then crawl through the slack, wrinkled parts of a hanging sheet
// (docs/benchmarks.md). Near equilibrium it clamps them: there the energy is flat to rounding,
// steps are judged by the residual force alone, and the magnitudes can hold the iterates at a
// saddle (configs/fit/drape_fv.yaml with D_warp = 4e-5 stalled at a residual of 5e-7 with
// magnitudes throughout).
//
// The step p solves (A + λ D) p = −g with CHOLMOD (symbolic analysis once), where
//   A = H when H + λD factorises (only H gives quadratic convergence), else H₊ (H₊ ≠ H where a
//       term is indefinite, e.g. a compressed spring); after H fails, H₊ is used until the
//       residual has fallen tenfold;
//   D = the lumped masses over their mean (1 for a massless coordinate), so λ D = M/dt² is an
//       implicit pseudo-time step of length dt = √(M̄/λ): far from equilibrium the sheet falls
//       like a damped body instead of jumping along a near-singular Newton direction;
//   λ = μ · s · min(1, r): s the mean diagonal of H₊ at the start (the stiffness scale, so every
//       setting is dimensionless and the iterates do not depend on the units), r the relative
//       residual, μ adapted by Nielsen's rule on the gain ratio of the full step, and multiplied
//       by 10 when the matrix does not factorise or no step decreases the energy. As steps
//       succeed, μ and r fall, dt grows without bound and the method becomes Newton's, with
//       quadratic convergence (λ = O(‖g‖) keeps it quadratic even where H is singular, as for a
//       sheet turning freely about one support).
// H₊ is assembled only where it is used: at the start (for s), with H where H is blocked above the
// last residual (the step will be H₊'s unless the residual fell below the block in one step:
// 18 of 418 on the 2,821-node drape tester), and otherwise for a step whose H failed to factorise:
// the iterate is then assembled again, with H₊. The iterates are the same as with H₊ assembled at
// every iteration, and an iteration whose H factorises skips the terms' projections (statistics:
// projected_assemblies, and projected_assemblies_unused for those whose step then used H).
// The step is accepted by a backtracking (Armijo) line search on the true energy; a trial point
// whose energy is not finite is never accepted, the step is shortened instead. When the full step
// is accepted, it is doubled (up to 4 times) while the energy keeps falling: H₊ overstates the
// curvature where terms are indefinite, and an energy evaluation costs about 1/300 of a
// factorisation (not where the fabric has a bending friction: a doubled step carries control
// volumes past the friction's kink; src/run/run.cc, SolveMethodOptions). Near the end,
// where the energy changes by less than its own rounding (64 ulps of Σ|term energy|), it cannot
// judge a step; there the step is accepted if it lowers the norm of the free residual force, both
// norms computed by one path (EvaluateEnergy), not the iterate's from the assembly's fast
// derivatives: their rounding differs, and that difference alone once accepted step after step at
// a saddle (a sheet on a sphere crawled 1,900 iterations at a relative residual of 2e-8, its
// energy unchanged to 17 digits, without reaching the saddle escape).
#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/model/mesh.h"
#include "src/model/self_contact.h"
#include "src/numerics/sparse_hessian.h"
#include "src/numerics/stability.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solvers.h"

namespace drape {

namespace {

// The options' defaults and ranges are in the catalogue (src/scene/solver_methods.cc).
struct NewtonSettings {
  double regularization;  // μ at the start (dimensionless)
  double min_regularization = 1e-12;
  double max_regularization = 1e16;
  int max_line_search;  // energy evaluations per step
  int max_expansions;   // doublings of an accepted full step
  // H₊ takes the magnitudes of negative eigenvalues above this relative residual, and clamps
  // them to zero below it (0: always magnitudes, ∞: always clamped).
  double absolute_projection_above;
  // Try the unprojected H first below this relative residual (by default always; after H fails to
  // factorise, H₊ is used until the residual has fallen tenfold).
  double exact_hessian_residual;
  // After H fails, H is tried again once the residual has fallen tenfold or after this many steps.
  int exact_retry_steps;
  double armijo = 1e-4;
  // 1: where the residual is met at a saddle, leave it along the most negative curvature (issue
  // 14); 0: stop there (the certificate then reports the saddle).
  bool escape_saddles = true;
};

NewtonSettings ReadSettings(const std::map<std::string, double>& options) {
  auto read = [&options](const char* key) { return *MethodOptionValue("newton", options, key); };
  NewtonSettings settings;
  settings.regularization = read("regularization");
  settings.exact_hessian_residual = read("exact_hessian_residual");
  settings.max_line_search = static_cast<int>(read("max_line_search"));
  settings.max_expansions = static_cast<int>(read("max_expansions"));
  settings.absolute_projection_above = read("absolute_projection_above");
  settings.exact_retry_steps = static_cast<int>(read("exact_retry_steps"));
  settings.escape_saddles = read("escape_saddles") != 0.0;
  return settings;
}

class Stopwatch {
 public:
  explicit Stopwatch(double* total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() {
    *total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  double* total_;
  std::chrono::steady_clock::time_point start_;
};

struct Counters {
  int factorizations = 0, failed_factorizations = 0, energy_evaluations = 0;
  int exact_hessian_steps = 0, line_search_failures = 0, projected_terms = 0;
  int saddle_escapes = 0, projected_assemblies = 0, projected_unused = 0, contact_rebuilds = 0;
  int filtered_steps = 0;
  double assembly_s = 0.0, factorization_s = 0.0, solve_s = 0.0, line_search_s = 0.0;
  // Of those: finding the self-contact pairs again (in assembly_s) and the step filter of the line
  // search and its expansions (in line_search_s).
  double self_contact_s = 0.0, step_filter_s = 0.0;
};

// Weights D of the pseudo-time term: lumped masses over their mean, 1 where there is no mass.
std::vector<double> PseudoTimeWeights(const Model& model, const DofMap& dofs) {
  std::vector<double> weights(dofs.num_free(), 1.0);
  double sum = 0.0;
  int count = 0;
  for (int f = 0; f < dofs.num_free(); ++f) {
    const double mass = model.mass.empty() ? 0.0 : model.mass[dofs.free_to_global()[f] / 3];
    if (mass > 0.0) sum += mass, ++count;
  }
  if (count == 0) return weights;
  const double mean = sum / count;
  for (int f = 0; f < dofs.num_free(); ++f) {
    const double mass = model.mass[dofs.free_to_global()[f] / 3];
    if (mass > 0.0) weights[f] = mass / mean;
  }
  return weights;
}

double StiffnessScale(const FreeHessian& hessian) {
  double projected = 0.0, exact = 0.0;
  for (int k : hessian.diagonal()) {
    projected += hessian.projected_values()[k];
    exact += std::abs(hessian.values()[k]);
  }
  if (projected > 0.0 && std::isfinite(projected)) return projected / hessian.size();
  if (exact > 0.0 && std::isfinite(exact)) return exact / hessian.size();
  return 1.0;
}

// The diagonal of the bounding box of the model's nodes, m (1 if they coincide).
double BoundingBoxDiagonal(const Model& model) {
  const double diagonal = BoundingDiagonal(
      Eigen::Map<const Eigen::Matrix3Xd>(model.positions.data(), 3, model.num_nodes));
  return diagonal > 0.0 && std::isfinite(diagonal) ? diagonal : 1.0;
}

class NewtonIteration {
 public:
  NewtonIteration(Model& model, const SolverOptions& options, SolverSummary* summary)
      : model_(model),
        settings_(ReadSettings(options.method_options)),
        monitor_(model, options, summary),
        own_workspace_(options.workspace ? nullptr : std::make_unique<HessianWorkspace>(model)),
        workspace_(options.workspace ? options.workspace : own_workspace_.get()),
        dofs_(workspace_->dofs),
        weights_(PseudoTimeWeights(model, dofs_)),
        mu_(settings_.regularization),
        model_size_(BoundingBoxDiagonal(model)) {}

  void Run();
  const Counters& counters() const { return counters_; }
  double factor_nonzeros() const { return workspace_->cholesky.factor_nonzeros(); }

 private:
  bool Step(double residual);
  bool ResidualFalls(const double* trial);
  double FreeSquaredNorm(const std::vector<double>& gradient) const;
  void AdaptRegularization();
  bool EnsureProjected();
  bool ExactBlocked(double residual) const;
  bool ExpectsProjectedStep() const;
  bool ComputeStep(bool exact, double residual, std::vector<double>* step);
  bool LineSearch(const std::vector<double>& step, double* alpha);
  bool EscapeSaddle();
  void Expand(const std::vector<double>& step, double energy, double* alpha);
  void SetTrial(const std::vector<double>& step, double alpha, std::vector<double>* trial) const;

  Model& model_;
  const NewtonSettings settings_;
  IterationMonitor monitor_;
  // The free Hessian's pattern and its analysis: the caller's, or this solve's own when the caller
  // gave none or when the fabric's contact with itself changed the model's terms (RefreshModel).
  std::unique_ptr<HessianWorkspace> own_workspace_;
  HessianWorkspace* workspace_;
  const DofMap dofs_;  // the free coordinates, which no change of terms moves
  FreeHessian& hessian() { return workspace_->hessian; }
  SparseCholesky& cholesky() { return workspace_->cholesky; }
  bool RefreshModel();
  const std::vector<double> weights_;
  double mu_;
  const double model_size_;
  double last_lambda_ = 0.0;
  double full_step_gain_ = 0.0;
  double growth_ = 2.0;
  double last_residual_ = std::numeric_limits<double>::infinity();
  bool projected_ready_ = false;            // H₊ assembled at the current iterate
  double iterate_squared_residual_ = -1.0;  // for ResidualFalls, at the iterate (-1: not yet)
  double WeightedSquaredNorm(const std::vector<double>& v) const {
    double sum = 0.0;
    for (size_t k = 0; k < v.size(); ++k) sum += v[k] * v[k] * weights_[k];
    return sum;
  }
  double stiffness_scale_ = 1.0;
  double exact_blocked_above_ = std::numeric_limits<double>::infinity();
  int steps_since_exact_failed_ = 0;
  FreeHessian::Assembly assembly_;
  std::vector<double> gradient_, free_gradient_, trial_, trial_gradient_, expanded_;
  Counters counters_;
};

// The fabric's contact with itself at the iterate (UpdateSelfContact): where its terms changed,
// a pattern of the new terms and its analysis. Returns whether they changed.
bool NewtonIteration::RefreshModel() {
  bool changed = false;
  {
    Stopwatch watch(&counters_.self_contact_s);
    changed = UpdateSelfContact(&model_, model_.positions.data());
  }
  if (!changed) return false;
  own_workspace_ = std::make_unique<HessianWorkspace>(model_);
  workspace_ = own_workspace_.get();
  ++counters_.contact_rebuilds;
  return true;
}

void NewtonIteration::Run() {
  for (int iteration = 0;; ++iteration) {
    bool evaluable;
    {
      Stopwatch watch(&counters_.assembly_s);
      RefreshModel();
      hessian().set_eigenvalue_filter(last_residual_ > settings_.absolute_projection_above
                                          ? EigenvalueFilter::kAbsolute
                                          : EigenvalueFilter::kClamp);
      // H₊ with H where it is used: at the start (the stiffness scale) and where H is blocked
      // (ExpectsProjectedStep); otherwise ComputeStep assembles it for a step that needs it (H
      // failed to factorise), so that no H₊ is assembled for an iteration whose exact step
      // succeeds unless the residual fell below the block in one step.
      projected_ready_ = iteration == 0 || ExpectsProjectedStep();
      iterate_squared_residual_ = -1.0;
      evaluable =
          hessian().Assemble(model_.positions.data(), projected_ready_, &assembly_, &gradient_);
    }
    if (!evaluable) {
      monitor_.Stop("energy, gradient or Hessian not finite at the iterate");
      return;
    }
    if (projected_ready_) counters_.projected_terms = assembly_.projected_terms;
    counters_.projected_assemblies += projected_ready_;
    const double residual = RelativeResidual(model_, gradient_);
    last_residual_ = residual;
    // A saddle is not an answer: where the residual is met but the true Hessian is indefinite,
    // leave along its most negative curvature and go on.
    if (settings_.escape_saddles && monitor_.Reached(residual) && EscapeSaddle()) {
      if (monitor_.Record(iteration, assembly_.energy, residual, /*may_converge=*/false)) return;
      continue;
    }
    if (monitor_.Record(iteration, assembly_.energy, residual)) return;
    if (iteration == 0) stiffness_scale_ = StiffnessScale(hessian());
    if (!Step(residual)) return;
  }
}

// One accepted step from model.positions, raising μ until the factorisation and the line search
// succeed. False (after Stop) if no step can be found.
bool NewtonIteration::Step(double residual) {
  free_gradient_.resize(dofs_.num_free());
  dofs_.Gather(gradient_.data(), free_gradient_.data());
  std::vector<double> step;
  if (++steps_since_exact_failed_ > settings_.exact_retry_steps) {
    exact_blocked_above_ = std::numeric_limits<double>::infinity();
  }
  while (true) {
    const bool exact = !ExactBlocked(residual);
    double alpha = 0.0;
    if (ComputeStep(exact, residual, &step) && LineSearch(step, &alpha)) {
      if (exact) ++counters_.exact_hessian_steps;
      if (exact && projected_ready_) ++counters_.projected_unused;
      AdaptRegularization();
      return true;
    }
    if (exact) {  // H is not positive definite here (or gives no descent): use H₊ until closer
      exact_blocked_above_ = residual / 10.0;
      steps_since_exact_failed_ = 0;
      continue;
    }
    mu_ = std::max(mu_ * 10.0, 1e-6);
    if (mu_ > settings_.max_regularization) {
      if (EscapeSaddle()) return true;
      monitor_.StopStalled(residual, "no step decreases the energy (regularisation limit reached)");
      return false;
    }
  }
}

// Nielsen's rule on the gain ratio ρ of the full step: μ shrinks (by up to 3) when the quadratic
// model predicted the energy well, grows when it did not, and grows faster after each failure.
void NewtonIteration::AdaptRegularization() {
  const double rho = full_step_gain_;
  if (rho > 0.0) {
    const double factor = std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
    mu_ = std::max(mu_ * factor, settings_.min_regularization);
    growth_ = 2.0;
  } else {
    mu_ = std::max(mu_ * growth_, 1e-9);
    growth_ *= 2.0;
  }
}

// Whether a step at `residual` may not use H: at or above exact_hessian_residual, or above the
// block set where H last failed.
bool NewtonIteration::ExactBlocked(double residual) const {
  return !(residual < settings_.exact_hessian_residual && residual < exact_blocked_above_);
}

// Whether the next step will be H₊'s: H is blocked at the last residual, and the block stays for
// the next step (Step lifts it after exact_retry_steps).
bool NewtonIteration::ExpectsProjectedStep() const {
  return ExactBlocked(last_residual_) &&
         steps_since_exact_failed_ + 1 <= settings_.exact_retry_steps;
}

// Assembles H₊ at the iterate if this iteration's assembly left it out (the same energy and
// gradient come again). False if not evaluable.
bool NewtonIteration::EnsureProjected() {
  if (projected_ready_) return true;
  Stopwatch watch(&counters_.assembly_s);
  projected_ready_ = hessian().Assemble(model_.positions.data(), true, &assembly_, &gradient_);
  counters_.projected_terms = assembly_.projected_terms;
  ++counters_.projected_assemblies;
  return projected_ready_;
}

bool NewtonIteration::ComputeStep(bool exact, double residual, std::vector<double>* step) {
  if (!exact && !EnsureProjected()) return false;
  const double lambda = mu_ * stiffness_scale_ * std::min(1.0, residual);
  last_lambda_ = lambda;
  std::vector<double> shift(weights_.size());
  for (size_t k = 0; k < shift.size(); ++k) shift[k] = lambda * weights_[k];
  ++counters_.factorizations;
  bool factorized;
  {
    Stopwatch watch(&counters_.factorization_s);
    factorized =
        cholesky().Factorize(exact ? hessian().values() : hessian().projected_values(), &shift);
  }
  if (!factorized) {
    ++counters_.failed_factorizations;
    return false;
  }
  Stopwatch watch(&counters_.solve_s);
  cholesky().Solve(free_gradient_, step);
  for (double& value : *step) value = -value;
  return std::all_of(step->begin(), step->end(), [](double v) { return std::isfinite(v); });
}

bool NewtonIteration::ResidualFalls(const double* trial) {
  // Both residuals by the same path (EvaluateEnergy): the assembly's gradient comes from the fast
  // derivatives, whose rounding differs, and at the round-off floor that difference alone would
  // make a step that changes nothing look like progress.
  if (!(iterate_squared_residual_ >= 0.0)) {
    double energy;
    ++counters_.energy_evaluations;
    if (!EvaluateEnergy(model_, model_.positions.data(), &energy, &trial_gradient_)) return false;
    iterate_squared_residual_ = FreeSquaredNorm(trial_gradient_);
  }
  double trial_energy;
  ++counters_.energy_evaluations;
  if (!EvaluateEnergy(model_, trial, &trial_energy, &trial_gradient_)) return false;
  return FreeSquaredNorm(trial_gradient_) < iterate_squared_residual_;
}

double NewtonIteration::FreeSquaredNorm(const std::vector<double>& gradient) const {
  double sum = 0.0;
  for (int global : dofs_.free_to_global()) sum += gradient[global] * gradient[global];
  return sum;
}

bool NewtonIteration::LineSearch(const std::vector<double>& step, double* alpha) {
  Stopwatch watch(&counters_.line_search_s);
  const double energy = assembly_.energy;
  const double slope = std::inner_product(step.begin(), step.end(), free_gradient_.begin(), 0.0);
  if (!(slope < 0.0)) return false;
  // The rounding error of a sum of term energies: a few ulps of the sum of their magnitudes.
  const double rounding =
      64.0 * std::numeric_limits<double>::epsilon() * assembly_.energy_magnitude;
  trial_ = model_.positions;
  // No node may pass through an obstacle (src/model/contact.h) and no piece of the fabric through
  // another (src/model/self_contact.h): the step starts at most there.
  SetTrial(step, 1.0, &trial_);
  double a = 1.0;
  {
    Stopwatch filter(&counters_.step_filter_s);
    a = StepSafeFraction(model_, model_.positions.data(), trial_.data());
  }
  if (!(a > 0.0)) return false;
  counters_.filtered_steps += a < 1.0;
  for (int evaluation = 0; evaluation < settings_.max_line_search; ++evaluation) {
    SetTrial(step, a, &trial_);
    double trial_energy;
    ++counters_.energy_evaluations;
    const bool finite = EvaluateEnergy(model_, trial_.data(), &trial_energy);
    // Where the energy is flat to rounding it cannot judge the step: the residual force does.
    const bool flat = finite && std::abs(trial_energy - energy) <= rounding;
    const bool accepted = flat ? ResidualFalls(trial_.data())
                               : finite && trial_energy <= energy + settings_.armijo * a * slope;
    if (evaluation == 0) {
      // Gain ratio of the full step against its quadratic model (A + λD) p = −g:
      // predicted decrease −g·p − ½ pᵀA p = −½ g·p + ½ λ pᵀD p.
      // For a step limited to a < 1 by the step filter: −a g·p − ½ a² pᵀA p.
      const double predicted =
          -a * slope + 0.5 * a * a * (slope + last_lambda_ * WeightedSquaredNorm(step));
      full_step_gain_ = flat     ? (accepted ? 1.0 : 0.0)
                        : finite ? (energy - trial_energy) / predicted
                                 : -1.0;
    }
    if (accepted) {
      if (evaluation == 0 && !flat) Expand(step, trial_energy, &a);
      model_.positions.swap(trial_);
      *alpha = a;
      return true;
    }
    if (!finite) {
      a *= 0.1;
      continue;
    }
    // Minimum of the quadratic through E(0), E'(0) and E(a), kept within [0.1a, 0.5a].
    const double curvature = trial_energy - energy - slope * a;
    const double minimizer = curvature > 0.0 ? -slope * a * a / (2.0 * curvature) : 0.5 * a;
    a = std::clamp(minimizer, 0.1 * a, 0.5 * a);
  }
  ++counters_.line_search_failures;
  return false;
}

void NewtonIteration::SetTrial(const std::vector<double>& step, double alpha,
                               std::vector<double>* trial) const {
  const std::vector<int>& free_to_global = dofs_.free_to_global();
  for (size_t f = 0; f < step.size(); ++f) {
    (*trial)[free_to_global[f]] = model_.positions[free_to_global[f]] + alpha * step[f];
  }
}

// Doubles the accepted step alpha·p (in trial_, of energy `energy`) while that lowers the energy.
// (Refining the last doubling by the minimum of a parabola was tried: more iterations, 188
// against 83 on the 50×50 sheet, as the path through the folds changes.)
void NewtonIteration::Expand(const std::vector<double>& step, double energy, double* alpha) {
  expanded_ = trial_;
  for (int k = 0; k < settings_.max_expansions; ++k) {
    SetTrial(step, 2.0 * *alpha, &expanded_);
    double safe = 1.0;
    {
      Stopwatch filter(&counters_.step_filter_s);
      safe = StepSafeFraction(model_, model_.positions.data(), expanded_.data());
    }
    if (safe < 1.0) return;
    double expanded_energy;
    ++counters_.energy_evaluations;
    if (!EvaluateEnergy(model_, expanded_.data(), &expanded_energy) ||
        !(expanded_energy < energy)) {
      return;
    }
    energy = expanded_energy;
    *alpha *= 2.0;
    trial_.swap(expanded_);
  }
}

// Near a saddle no step of (A + λD) p = −g lowers the energy, but a step along the true Hessian's
// most negative eigenvector v does. Tries ±t v for t from a tenth of the model's size down to
// 1e-7 of it and keeps the lowest energy; then Newton resumes with μ at its initial value.
bool NewtonIteration::EscapeSaddle() {
  constexpr int kMaxEscapes = 20;
  if (counters_.saddle_escapes >= kMaxEscapes) return false;
  double eigenvalue;
  std::vector<double> direction;
  if (!NegativeCurvature(hessian(), &eigenvalue, &direction, &cholesky())) return false;
  const double rounding =
      64.0 * std::numeric_limits<double>::epsilon() * assembly_.energy_magnitude;
  double best_energy = assembly_.energy - rounding;
  std::vector<double> best;
  trial_ = model_.positions;
  for (double t = 0.1 * model_size_; t > 1e-7 * model_size_; t *= 0.3) {
    for (double sign : {1.0, -1.0}) {
      SetTrial(direction, sign * t, &trial_);
      if (StepSafeFraction(model_, model_.positions.data(), trial_.data()) < 1.0) continue;
      double energy;
      ++counters_.energy_evaluations;
      if (EvaluateEnergy(model_, trial_.data(), &energy) && energy < best_energy) {
        best_energy = energy;
        best = trial_;
      }
    }
  }
  if (best.empty()) return false;
  model_.positions.swap(best);
  ++counters_.saddle_escapes;
  mu_ = settings_.regularization;
  exact_blocked_above_ = std::numeric_limits<double>::infinity();
  return true;
}

class NewtonSolver : public Solver {
 public:
  SolverSummary Solve(Model& model, const SolverOptions& options) const override {
    SolverSummary summary;
    if (model.num_free_dofs() == 0) return SolveWithoutFreeDofs(model, options);
    NewtonIteration newton(model, options, &summary);
    newton.Run();
    const Counters& c = newton.counters();
    summary.statistics = {
        {"factorizations", c.factorizations},
        {"failed_factorizations", c.failed_factorizations},
        {"energy_evaluations", c.energy_evaluations},
        {"exact_hessian_steps", c.exact_hessian_steps},
        {"saddle_escapes", c.saddle_escapes},
        {"self_contact_rebuilds", c.contact_rebuilds},
        {"filtered_steps", c.filtered_steps},
        {"line_search_failures", c.line_search_failures},
        {"projected_terms_last", c.projected_terms},
        {"projected_assemblies", c.projected_assemblies},
        {"projected_assemblies_unused", c.projected_unused},
        {"factor_nonzeros", newton.factor_nonzeros()},
        {"assembly_s", c.assembly_s},
        {"factorization_s", c.factorization_s},
        {"solve_s", c.solve_s},
        {"line_search_s", c.line_search_s},
        {"self_contact_s", c.self_contact_s},
        {"step_filter_s", c.step_filter_s},
    };
    return summary;
  }

 private:
  static SolverSummary SolveWithoutFreeDofs(Model& model, const SolverOptions& options) {
    SolverSummary summary;
    IterationMonitor monitor(model, options, &summary);
    double energy = 0.0;
    std::vector<double> gradient;
    if (!EvaluateEnergy(model, model.positions.data(), &energy, &gradient)) {
      monitor.Stop("energy not finite at the start");
    } else {
      monitor.Record(0, energy, RelativeResidual(model, gradient));
    }
    return summary;
  }
};

}  // namespace

std::unique_ptr<Solver> NewNewtonSolver() { return std::make_unique<NewtonSolver>(); }

}  // namespace drape
