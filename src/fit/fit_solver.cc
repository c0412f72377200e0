#include "src/fit/fit_solver.h"

#include <ceres/ceres.h>

#include <Eigen/SVD>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlopt.hpp>
#include <sstream>

#include "src/fit/fit_methods.h"
#include "src/solvers/solver.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

// Counts and records every objective evaluation, keeps the best point.
class Recorder {
 public:
  Recorder(FitProblem& problem, const FitOptions& options, FitResult* result)
      : problem_(problem), options_(options), result_(result), start_(Clock::now()) {}

  FitEvaluation Evaluate(const std::vector<double>& u, bool with_jacobian,
                         Eigen::MatrixXd* jacobian) {
    FitEvaluation evaluation = problem_.Evaluate(u);
    if (with_jacobian) {
      if (!problem_.ImplicitJacobian(jacobian)) {
        *jacobian = problem_.FiniteDifferenceJacobian(u, 1e-4);
        result_->jacobian_implicit = false;
      }
      ++result_->jacobian_evaluations;
    }
    FitIterationRecord record;
    record.evaluation = ++result_->evaluations;
    record.time_s = std::chrono::duration<double>(Clock::now() - start_).count();
    record.objective = evaluation.objective;
    if (evaluation.converged && evaluation.objective < best_objective_) {
      best_objective_ = evaluation.objective;
      best_u_ = u;
      best_evaluation_ = evaluation;
    }
    record.best_objective = best_objective_;
    record.parameters = problem_.ToParameters(u);
    record.inner_iterations = evaluation.inner_iterations;
    record.inner_converged = evaluation.converged;
    record.with_jacobian = with_jacobian;
    result_->history.push_back(record);
    if (options_.on_evaluation) options_.on_evaluation(record);
    return evaluation;
  }

  // A stop asked for here or on another rank (the same answer on every rank).
  bool StopRequested() const { return problem_.StopRequested(); }
  const std::vector<double>& best_u() const { return best_u_; }
  double best_objective() const { return best_objective_; }
  const FitEvaluation& best_evaluation() const { return best_evaluation_; }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  FitProblem& problem_;
  const FitOptions& options_;
  FitResult* result_;
  Clock::time_point start_;
  double best_objective_ = std::numeric_limits<double>::infinity();
  std::vector<double> best_u_;
  FitEvaluation best_evaluation_;
};

// An unconverged inner solve makes the point unusable: the objective there is replaced by a large
// value so that the outer method backs away.
double Penalised(const FitEvaluation& evaluation) {
  return evaluation.converged && std::isfinite(evaluation.objective) ? evaluation.objective : 1e30;
}

struct NloptContext {
  Recorder* recorder = nullptr;
  bool with_gradient = false;
};

double NloptObjective(unsigned n, const double* x, double* gradient, void* data) {
  auto* context = static_cast<NloptContext*>(data);
  if (context->recorder->StopRequested()) throw nlopt::forced_stop();
  const std::vector<double> u(x, x + n);
  Eigen::MatrixXd jacobian;
  const FitEvaluation evaluation = context->recorder->Evaluate(u, gradient != nullptr, &jacobian);
  if (gradient) {
    const Eigen::Map<const Eigen::VectorXd> r(evaluation.residuals.data(),
                                              static_cast<int>(evaluation.residuals.size()));
    const Eigen::VectorXd g = jacobian.transpose() * r;
    for (unsigned j = 0; j < n; ++j) gradient[j] = evaluation.converged ? g[j] : 0.0;
  }
  return Penalised(evaluation);
}

std::string NloptOutcome(nlopt::result result, bool* converged) {
  *converged = result == nlopt::SUCCESS || result == nlopt::FTOL_REACHED ||
               result == nlopt::XTOL_REACHED || result == nlopt::STOPVAL_REACHED;
  switch (result) {
    case nlopt::SUCCESS:
      return "converged";
    case nlopt::XTOL_REACHED:
      return "parameter change below the tolerance";
    case nlopt::FTOL_REACHED:
      return "objective change below the tolerance";
    case nlopt::MAXEVAL_REACHED:
      return "max_evaluations reached";
    case nlopt::STOPVAL_REACHED:
      return "objective reached zero";
    default:
      return "stopped (NLopt result " + std::to_string(static_cast<int>(result)) + ")";
  }
}

void RunNlopt(FitProblem& problem, Recorder* recorder, FitResult* result) {
  const FitSpec& spec = problem.spec();
  const int p = problem.num_parameters();
  const FitMethod& method = *FindFitMethod(spec.method);  // the loader checked the name
  NloptContext context{recorder, method.implicit};
  nlopt::opt opt(method.algorithm, static_cast<unsigned>(p));
  const std::vector<double> lower = problem.LowerUnknowns(), upper = problem.UpperUnknowns();
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  opt.set_min_objective(NloptObjective, &context);
  opt.set_xtol_abs(spec.tolerance);
  opt.set_ftol_abs(0.0);
  opt.set_stopval(0.0);
  opt.set_maxeval(spec.max_evaluations);
  std::vector<double> step(p);
  for (int j = 0; j < p; ++j) step[j] = std::min(0.25, (upper[j] - lower[j]) / 4.0);
  if (!context.with_gradient) opt.set_initial_step(step);
  if (context.with_gradient) opt.set_vector_storage(10);
  std::vector<double> u;
  for (const auto& parameter : spec.parameters) u.push_back(parameter.initial);
  u = problem.ToUnknowns(u);
  double objective = 0.0;
  try {
    const nlopt::result outcome = opt.optimize(u, objective);
    result->termination = NloptOutcome(outcome, &result->converged);
  } catch (const nlopt::roundoff_limited&) {
    result->termination = "roundoff-limited (the objective cannot be decreased further)";
    result->converged = true;
  } catch (const nlopt::forced_stop&) {
    result->termination = "interrupted";
  } catch (const std::runtime_error& error) {  // NLOPT_FAILURE (the two above derive from it)
    result->termination = std::string("NLopt stopped with a generic failure (") + error.what() +
                          "); the result is the best point it evaluated";
  }
}

// Ceres' view of the residuals: one parameter block u of size p, m residuals, J by implicit
// differentiation.
class FitCost : public ceres::CostFunction {
 public:
  FitCost(FitProblem& problem, Recorder* recorder) : problem_(problem), recorder_(recorder) {
    set_num_residuals(problem.num_residuals());
    mutable_parameter_block_sizes()->push_back(problem.num_parameters());
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    if (recorder_->StopRequested()) return false;
    const int p = problem_.num_parameters(), m = problem_.num_residuals();
    const std::vector<double> u(parameters[0], parameters[0] + p);
    Eigen::MatrixXd jacobian;
    const FitEvaluation evaluation =
        recorder_->Evaluate(u, jacobians != nullptr && jacobians[0] != nullptr, &jacobian);
    if (!evaluation.converged) return false;
    for (int i = 0; i < m; ++i) residuals[i] = evaluation.residuals[i];
    if (jacobians && jacobians[0]) {
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < p; ++j) jacobians[0][i * p + j] = jacobian(i, j);
      }
    }
    return true;
  }

 private:
  FitProblem& problem_;
  Recorder* recorder_;
};

void RunCeres(FitProblem& problem, Recorder* recorder, FitResult* result) {
  const FitSpec& spec = problem.spec();
  const int p = problem.num_parameters();
  std::vector<double> u;
  for (const auto& parameter : spec.parameters) u.push_back(parameter.initial);
  u = problem.ToUnknowns(u);
  ceres::Problem ceres_problem;
  ceres_problem.AddResidualBlock(new FitCost(problem, recorder), nullptr, u.data());
  const std::vector<double> lower = problem.LowerUnknowns(), upper = problem.UpperUnknowns();
  for (int j = 0; j < p; ++j) {
    ceres_problem.SetParameterLowerBound(u.data(), j, lower[j]);
    ceres_problem.SetParameterUpperBound(u.data(), j, upper[j]);
  }
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = spec.max_evaluations;
  options.parameter_tolerance = spec.tolerance;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &ceres_problem, &summary);
  result->converged = summary.termination_type == ceres::CONVERGENCE;
  result->termination = summary.message;
}

}  // namespace

FitResult RunFit(FitProblem& problem, const FitOptions& options) {
  FitResult result;
  Recorder recorder(problem, options, &result);
  if (FindFitMethod(problem.spec().method)->engine == FitMethod::Engine::kCeresLevenbergMarquardt) {
    RunCeres(problem, &recorder, &result);
  } else {
    RunNlopt(problem, &recorder, &result);
  }
  if (recorder.best_u().empty()) {
    result.converged = false;
    result.termination += "; no evaluation had every equilibrium converged";
    result.wall_time_s = recorder.elapsed();
    return result;
  }
  // The state at the best point, solved from a cold start (as `drape solve` would), and its
  // Jacobian (implicit; whole finite differences otherwise). A different objective than the
  // warm-started one means the drape has several equilibria there: said in the termination.
  // After a Ctrl-C the search is over but these closing solves still run to their end (a solve
  // with the interrupt set stops at once, unconverged, far from the optimum); a second Ctrl-C
  // stops them, and then the best point is reported as the search evaluated it.
  if (problem.StopRequested()) ClearInterrupt();
  result.final_evaluation = problem.Evaluate(recorder.best_u(), true);
  if (!result.final_evaluation.converged && problem.StopRequested()) {
    result.final_evaluation = recorder.best_evaluation();
    result.termination += "; interrupted again: the best point is reported as the search found it";
  }
  const double warm = recorder.best_objective(), cold = result.final_evaluation.objective;
  if (result.final_evaluation.converged &&
      std::abs(cold - warm) > 1e-6 * std::max(warm, cold) + 1e-12) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "; WARNING: solved from its initial shape the optimum's objective is %.6g, not "
                  "%.6g: several equilibria",
                  cold, warm);
    result.termination += text;
  }
  if (!problem.ImplicitJacobian(&result.jacobian)) {
    result.jacobian = problem.FiniteDifferenceJacobian(recorder.best_u(), 1e-4);
    result.jacobian_implicit = false;
  }
  problem.RebuildMissingModels();  // under MPI: every equilibrium's model here, for the writers
  result.parameters = problem.ToParameters(recorder.best_u());
  result.objective = result.final_evaluation.objective;
  result.converged = result.converged && result.final_evaluation.converged;
  ComputeStatistics(problem, &result);
  result.wall_time_s = recorder.elapsed();
  return result;
}

namespace {

// "0.98 × ln E_warp − 0.17 × ln D_warp" (components below 0.05 left out).
std::string DirectionText(const FitProblem& problem, const Eigen::VectorXd& direction) {
  const int largest = [&] {
    int index = 0;
    direction.cwiseAbs().maxCoeff(&index);
    return index;
  }();
  const double sign = direction[largest] < 0 ? -1.0 : 1.0;  // the largest component positive
  std::string text;
  for (int j = 0; j < direction.size(); ++j) {
    const double component = sign * direction[j];
    if (std::abs(component) < 0.05) continue;
    const FitParameter& parameter = problem.spec().parameters[j];
    char term[300];
    std::snprintf(term, sizeof term, "%s%.2f × %s%s",
                  text.empty() ? (component < 0 ? "−" : "") : (component < 0 ? " − " : " + "),
                  std::abs(component), parameter.log ? "ln " : "", parameter.key.c_str());
    text += term;
  }
  return text;
}

void ComputeIdentifiability(const FitProblem& problem, FitResult* result) {
  const Eigen::MatrixXd& jacobian = result->jacobian;
  const int p = static_cast<int>(jacobian.cols());
  Identifiability& out = result->identifiability;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double largest = s.size() > 0 ? s[0] : 0.0;
  out.identifiable.assign(p, true);
  for (int j = 0; j < p; ++j) out.parameter_sensitivity.push_back(jacobian.col(j).norm());
  for (int k = 0; k < p; ++k) {
    const double value = k < s.size() ? s[k] : 0.0;
    const Eigen::VectorXd v = svd.matrixV().col(k);
    const bool flat = value < 1.0 || value < 1e-8 * largest;
    out.singular_values.push_back(value);
    out.directions.push_back(v);
    out.flat.push_back(flat);
    if (!flat) continue;
    for (int j = 0; j < p; ++j) {
      if (std::abs(v[j]) > 0.3) out.identifiable[j] = false;
    }
    std::ostringstream text;
    text.precision(3);
    text << "flat direction (" << DirectionText(problem, v) << "): a unit change along it moves "
         << "the predictions by " << value << " measurement uncertainties (< 1), so the "
         << "measurements do not determine it";
    out.statements.push_back(text.str());
  }
  for (int j = 0; j < p; ++j) {
    const FitParameter& parameter = problem.spec().parameters[j];
    std::ostringstream text;
    text.precision(3);
    if (out.identifiable[j]) {
      text << parameter.key << " is identifiable";
    } else {
      text << parameter.key << " is NOT identifiable from these measurements: changing it alone by "
           << (parameter.log ? "a factor e" : "its bounds' span") << " moves the predictions by "
           << out.parameter_sensitivity[j] << " measurement uncertainties";
    }
    out.statements.push_back(text.str());
  }
}

}  // namespace

void ComputeStatistics(const FitProblem& problem, FitResult* result) {
  const Eigen::MatrixXd& jacobian = result->jacobian;
  const int m = static_cast<int>(jacobian.rows()), p = static_cast<int>(jacobian.cols());
  const std::vector<double>& r = result->final_evaluation.residuals;
  double squared = 0.0;
  for (double value : r) squared += value * value;
  result->residual_variance = m > p ? squared / (m - p) : 1.0;
  ComputeIdentifiability(problem, result);
  // Gauss–Newton covariance in u: s² (JᵀJ)⁺ over the identifiable directions; a parameter with
  // weight in a flat direction has an unbounded error.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(p, p);
  for (int k = 0; k < s.size(); ++k) {
    if (s[k] <= 1e-12 * (s.size() ? s[0] : 1.0)) continue;
    const Eigen::VectorXd v = svd.matrixV().col(k);
    covariance += v * v.transpose() / (s[k] * s[k]);
  }
  covariance *= result->residual_variance;
  const std::vector<double> dtheta =
      problem.ParameterDerivatives(problem.ToUnknowns(result->parameters));
  result->standard_errors.assign(p, std::numeric_limits<double>::infinity());
  result->correlation = Eigen::MatrixXd::Constant(p, p, std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < p; ++i) {
    if (result->identifiability.identifiable[i]) {
      result->standard_errors[i] = std::sqrt(std::max(0.0, covariance(i, i))) * dtheta[i];
    }
    for (int j = 0; j < p; ++j) {
      const double scale = std::sqrt(covariance(i, i) * covariance(j, j));
      if (scale > 0.0) result->correlation(i, j) = covariance(i, j) / scale;
    }
  }
}

}  // namespace drape
