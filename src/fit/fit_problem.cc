#include "src/fit/fit_problem.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/analysis/drape_analysis.h"
#include "src/model/equilibrium.h"
#include "src/numerics/round_off_floor.h"
#include "src/output/json.h"
#include "src/parallel/byte_codec.h"
#include "src/parallel/shared_work.h"
#include "src/run/run.h"
#include "src/run/sensitivity.h"
#include "src/scene/scene_loader.h"
#include "src/scene/scene_size.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solver.h"

namespace drape {
namespace {

constexpr double kParameterStep = 1e-4;  // in u, for ∂g/∂u
constexpr double kMeshFileCost = 1e4;    // nodes, for the owners of equilibria on mesh files

std::string BlockLabel(const FitMeasurement& measurement) {
  switch (measurement.kind) {
    case FitMeasurement::Kind::kDrapeCoefficient:
      return "drape_coefficient";
    case FitMeasurement::Kind::kBendingLength:
      return "bending_length (" + measurement.direction + ")";
    case FitMeasurement::Kind::kPositions:
      return "positions " + measurement.file;
    case FitMeasurement::Kind::kReactions:
      return "reactions " + measurement.file;
  }
  return "";
}

// The displacement (as a fraction of the model's size) of the central differences that carry a
// direction dx*/du through a measurement function: the rasterised shadow needs a step of a few
// pixels, the smooth kinds a small one.
double DirectionStep(const FitMeasurement& measurement) {
  return measurement.kind == FitMeasurement::Kind::kDrapeCoefficient ? 2e-3 : 1e-6;
}

}  // namespace

FitProblem::FitProblem(const FitSpec& spec, int local_threads)
    : spec_(spec), local_threads_(local_threads) {
  for (size_t s = 0; s < spec_.specimens.size(); ++s) {
    FitEquilibrium main;
    main.specimen = static_cast<int>(s);
    equilibria_.push_back(std::move(main));
    const int main_index = static_cast<int>(equilibria_.size()) - 1;
    const auto& measurements = spec_.specimens[s].measurements;
    for (size_t k = 0; k < measurements.size(); ++k) {
      ResidualBlock block;
      block.specimen = static_cast<int>(s);
      block.measurement = static_cast<int>(k);
      block.equilibrium = main_index;
      if (measurements[k].kind == FitMeasurement::Kind::kBendingLength) {
        FitEquilibrium strip;
        strip.specimen = static_cast<int>(s);
        strip.strip_of = static_cast<int>(k);
        equilibria_.push_back(std::move(strip));
        block.equilibrium = static_cast<int>(equilibria_.size()) - 1;
      }
      block.offset = num_residuals_;
      block.count = ResidualCount(measurements[k]);
      block.label = BlockLabel(measurements[k]);
      if (spec_.specimens.size() > 1) block.label += " @ " + spec_.specimens[s].scene_file;
      num_residuals_ += block.count;
      blocks_.push_back(block);
      equilibria_[block.equilibrium].measured = true;
    }
  }
  const std::vector<double> theta = [&] {
    std::vector<double> initial;
    for (const auto& parameter : spec_.parameters) initial.push_back(parameter.initial);
    return initial;
  }();
  for (const int e : MeasuredEquilibria()) {
    // A mesh file's size is known once it is read: counted as a large mesh.
    const double nodes = EstimatedNodes(SceneAt(equilibria_[e], theta).mesh);
    unit_costs_.push_back(nodes > 0.0 ? nodes : kMeshFileCost);
  }
}

std::vector<double> FitProblem::ToParameters(const std::vector<double>& u) const {
  std::vector<double> theta(u.size());
  for (size_t j = 0; j < u.size(); ++j) {
    const FitParameter& p = spec_.parameters[j];
    theta[j] = p.log ? std::exp(u[j]) : u[j] * (p.upper - p.lower);
  }
  return theta;
}

std::vector<double> FitProblem::ToUnknowns(const std::vector<double>& theta) const {
  std::vector<double> u(theta.size());
  for (size_t j = 0; j < theta.size(); ++j) {
    const FitParameter& p = spec_.parameters[j];
    u[j] = p.log ? std::log(theta[j]) : theta[j] / (p.upper - p.lower);
  }
  return u;
}

std::vector<double> FitProblem::ParameterDerivatives(const std::vector<double>& u) const {
  const std::vector<double> theta = ToParameters(u);
  std::vector<double> derivative(u.size());
  for (size_t j = 0; j < u.size(); ++j) {
    const FitParameter& p = spec_.parameters[j];
    derivative[j] = p.log ? theta[j] : p.upper - p.lower;
  }
  return derivative;
}

std::vector<double> FitProblem::LowerUnknowns() const {
  std::vector<double> lower;
  for (const auto& p : spec_.parameters) lower.push_back(p.lower);
  return ToUnknowns(lower);
}

std::vector<double> FitProblem::UpperUnknowns() const {
  std::vector<double> upper;
  for (const auto& p : spec_.parameters) upper.push_back(p.upper);
  return ToUnknowns(upper);
}

const FitMeasurement& FitProblem::MeasurementOf(const ResidualBlock& block) const {
  return spec_.specimens[block.specimen].measurements[block.measurement];
}

Scene FitProblem::SceneAt(const FitEquilibrium& equilibrium,
                          const std::vector<double>& theta) const {
  Scene scene = SpecimenSceneAt(spec_, spec_.specimens[equilibrium.specimen], theta);
  if (equilibrium.strip_of < 0) return scene;
  return PeirceStripScene(scene,
                          spec_.specimens[equilibrium.specimen].measurements[equilibrium.strip_of]);
}

// The stored equilibrium solved at the u nearest to `u` (Euclidean in u) if it lies within
// kWarmStartRadius, or null.
static const std::vector<double>* NearestStart(const FitEquilibrium& equilibrium,
                                               const std::vector<double>& u) {
  const std::vector<double>* start = nullptr;
  double best = kWarmStartRadius * kWarmStartRadius;
  for (size_t k = 0; k < equilibrium.solved_u.size(); ++k) {
    double distance = 0.0;
    for (size_t j = 0; j < u.size(); ++j) {
      distance += std::pow(equilibrium.solved_u[k][j] - u[j], 2);
    }
    if (distance <= best) {
      best = distance;
      start = &equilibrium.solved_positions[k];
    }
  }
  return start;
}

MeasurementContext FitProblem::ContextOf(const ResidualBlock& block) const {
  const FitEquilibrium& equilibrium = equilibria_[block.equilibrium];
  MeasurementContext context;
  context.disc_radius = DiscRadius(equilibrium.scene);
  context.flat_area = equilibrium.flat_area;
  return context;
}

namespace {

struct InnerRun {
  int iterations = 0;
  double residual = INFINITY;  // relative, recomputed at the final positions
  bool stagnated = false;      // stopped at its roundoff floor (`best`) before the tolerance
  double best = INFINITY;
};

// One newton solve from model.positions, stopped at `tolerance`, at `max_iterations`, or when
// the residual, already acceptable, has not halved in kStagnationIterations iterations.
InnerRun RunNewton(Model& model, double tolerance, int max_iterations, double time_limit) {
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  options.time_limit = time_limit;
  InnerRun run;
  int best_iteration = 0;
  options.on_iteration = [&](const IterationRecord& record) {
    if (record.relative_residual < 0.5 * run.best) {
      run.best = record.relative_residual;
      best_iteration = record.iteration;
    }
    // Only where the current iterate is acceptable: newton leaves a saddle point (as acceptable a
    // residual as a minimum's) along negative curvature, through iterates that are not.
    run.stagnated = run.best <= kAcceptedResidual &&
                    record.relative_residual <= kAcceptedResidual &&
                    record.iteration - best_iteration >= kStagnationIterations;
    return !run.stagnated;
  };
  run.iterations = FindSolver("newton")->make()->Solve(model, options).iterations;
  double energy = 0.0;
  std::vector<double> gradient;
  if (EvaluateEnergy(model, model.positions.data(), &energy, &gradient)) {
    run.residual = RelativeResidual(model, gradient);
  }
  return run;
}

// Whether a solve reached equilibrium: the fit's residual, or, where double precision cannot reach
// that, twice the round-off floor at its positions (as RunSolve accepts: a short stiff strip with
// a friction moment stops at about 4e-8).
bool Accepted(const Model& model, const InnerRun& run) {
  if (run.residual <= kAcceptedResidual) return true;
  if (!std::isfinite(run.residual)) return false;
  return run.residual <= kFloorFactor * RelativeResidualFloor(model, model.positions.data());
}

}  // namespace

bool FitProblem::SolveEquilibrium(FitEquilibrium* equilibrium, const std::vector<double>& u,
                                  bool cold) {
  equilibrium->scene = SceneAt(*equilibrium, ToParameters(u));
  auto model = std::make_unique<Model>(BuildModel(equilibrium->scene));
  if (equilibrium->flat_area == 0.0 && !model->triangles.empty()) {
    equilibrium->flat_area = FlatShadowArea(*model);
  }
  if (equilibrium->tolerance == 0.0) {
    equilibrium->tolerance = std::min(equilibrium->scene.solver.tolerance, kInnerTolerance);
  }
  const int max_iterations = EffectiveMaxIterations(equilibrium->scene.solver, "newton");
  const double time_limit = EffectiveTimeLimit(equilibrium->scene.solver, "newton");
  // Warm start: the free coordinates of the nearest equilibrium (fixed ones as the scene says),
  // with a short budget; from the scene's own start if that fails.
  InnerRun run;
  const std::vector<double>* start = cold ? nullptr : NearestStart(*equilibrium, u);
  if (start && start->size() == model->positions.size()) {
    for (size_t k = 0; k < model->positions.size(); ++k) {
      if (!model->fixed[k]) model->positions[k] = (*start)[k];
    }
    run = RunNewton(*model, equilibrium->tolerance, std::min(kWarmStartIterations, max_iterations),
                    time_limit);
  }
  int iterations = run.iterations;
  bool accepted = Accepted(*model, run);
  if (!accepted) {  // from the flat state, through a friction's kink
    model->positions = model->initial;
    iterations += RunFrictionContinuation(equilibrium->scene, *model, "newton").iterations;
    run = RunNewton(*model, equilibrium->tolerance, max_iterations, time_limit);
    iterations += run.iterations;
    accepted = Accepted(*model, run);
  }
  // A floor above the tolerance: later solves of this equilibrium stop as soon as they reach it.
  if (run.stagnated) {
    equilibrium->tolerance =
        std::min(kAcceptedResidual, std::max(equilibrium->tolerance, 2 * run.best));
  }
  equilibrium->relative_residual = run.residual;
  equilibrium->converged = accepted;
  equilibrium->inner_iterations = iterations;
  equilibrium->positions = model->positions;
  equilibrium->model = std::move(model);
  if (equilibrium->converged) {
    equilibrium->solved_u.push_back(u);
    equilibrium->solved_positions.push_back(equilibrium->positions);
  }
  return equilibrium->converged;
}

std::vector<int> FitProblem::MeasuredEquilibria() const {
  std::vector<int> measured;
  for (size_t e = 0; e < equilibria_.size(); ++e) {
    // A specimen measured only through its Peirce strips is not solved.
    if (equilibria_[e].measured) measured.push_back(static_cast<int>(e));
  }
  return measured;
}

std::string FitProblem::SolveAndMeasure(int e, const std::vector<double>& u, bool cold) {
  FitEquilibrium& equilibrium = equilibria_[e];
  SolveEquilibrium(&equilibrium, u, cold);
  ByteWriter outcome;
  outcome.Int(equilibrium.converged ? 1 : 0);
  outcome.Int(equilibrium.inner_iterations);
  outcome.Double(equilibrium.relative_residual);
  outcome.Doubles(equilibrium.positions);
  for (const auto& block : blocks_) {
    if (block.equilibrium != e) continue;
    const MeasuredValue measured = EvaluateMeasurement(
        MeasurementOf(block), *equilibrium.model, equilibrium.positions.data(), ContextOf(block));
    outcome.Double(measured.model_value);
    outcome.Doubles(measured.residuals);
  }
  return outcome.bytes();
}

void FitProblem::TakeOutcome(int e, const std::string& outcome, FitEvaluation* evaluation) {
  FitEquilibrium& equilibrium = equilibria_[e];
  ByteReader reader(outcome);
  equilibrium.converged = reader.Int() != 0;
  equilibrium.inner_iterations = static_cast<int>(reader.Int());
  equilibrium.relative_residual = reader.Double();
  equilibrium.positions = reader.Doubles();
  evaluation->converged &= equilibrium.converged;
  evaluation->inner_iterations += equilibrium.inner_iterations;
  for (size_t b = 0; b < blocks_.size(); ++b) {
    if (blocks_[b].equilibrium != e) continue;
    evaluation->model_values[b] = reader.Double();
    const std::vector<double> residuals = reader.Doubles();
    std::copy(residuals.begin(), residuals.end(),
              evaluation->residuals.begin() + blocks_[b].offset);
  }
}

FitEvaluation FitProblem::Evaluate(const std::vector<double>& u, bool cold) {
  const std::vector<int> solved = MeasuredEquilibria();
  const std::vector<std::string> outcomes = ComputeOnOwners(
      unit_costs_, [&](int k) { return SolveAndMeasure(solved[k], u, cold); }, local_threads_);
  FitEvaluation evaluation;
  evaluation.residuals.assign(num_residuals_, 0.0);
  evaluation.model_values.assign(blocks_.size(), 0.0);
  for (size_t k = 0; k < solved.size(); ++k) TakeOutcome(solved[k], outcomes[k], &evaluation);
  for (double r : evaluation.residuals) evaluation.objective += 0.5 * r * r;
  if (!std::isfinite(evaluation.objective)) evaluation.converged = false;
  last_u_ = u;
  return evaluation;
}

void FitProblem::RebuildMissingModels() {
  for (const int e : MeasuredEquilibria()) {
    FitEquilibrium& equilibrium = equilibria_[e];
    if (equilibrium.model) continue;
    equilibrium.scene = SceneAt(equilibrium, ToParameters(last_u_));
    equilibrium.model = std::make_unique<Model>(BuildModel(equilibrium.scene));
    if (!equilibrium.model->triangles.empty()) {
      equilibrium.flat_area = FlatShadowArea(*equilibrium.model);
    }
  }
}

bool FitProblem::StopRequested() const { return AnyProcess(InterruptRequested()); }

bool FitProblem::EquilibriumDirections(const FitEquilibrium& equilibrium,
                                       Eigen::MatrixXd* directions,
                                       Eigen::MatrixXd* direct_gradient) const {
  const Model& model = *equilibrium.model;
  const int n = model.num_dofs(), p = num_parameters();
  std::vector<ParameterModels> parameters(p);
  for (int j = 0; j < p; ++j) {
    std::vector<double> plus = last_u_, minus = last_u_;
    plus[j] += kParameterStep;
    minus[j] -= kParameterStep;
    parameters[j].key = spec_.parameters[j].key;
    parameters[j].step = kParameterStep;  // in u: the derivatives are d/du
    parameters[j].plus = BuildModel(SceneAt(equilibrium, ToParameters(plus)));
    parameters[j].minus = BuildModel(SceneAt(equilibrium, ToParameters(minus)));
  }
  EquilibriumDerivatives derivatives;
  try {
    derivatives = DifferentiateEquilibrium(model, equilibrium.positions, parameters);
  } catch (const SensitivityError&) {
    return false;  // no Jacobian here: the caller's method goes on without it
  }
  directions->resize(n, p);
  direct_gradient->resize(n, p);
  for (int j = 0; j < p; ++j) {
    directions->col(j) = Eigen::Map<const Eigen::VectorXd>(derivatives.positions[j].data(), n);
    direct_gradient->col(j) = Eigen::Map<const Eigen::VectorXd>(derivatives.forces[j].data(), n);
  }
  return true;
}

std::string FitProblem::JacobianRowsOf(int e) const {
  const FitEquilibrium& equilibrium = equilibria_[e];
  ByteWriter rows;
  Eigen::MatrixXd directions, direct;
  if (!EquilibriumDirections(equilibrium, &directions, &direct)) {
    rows.Int(0);
    return rows.bytes();
  }
  rows.Int(1);
  const int p = num_parameters();
  const Model& model = *equilibrium.model;
  for (const auto& block : blocks_) {
    if (block.equilibrium != e) continue;
    const FitMeasurement& measurement = MeasurementOf(block);
    const MeasurementContext context = ContextOf(block);
    Eigen::MatrixXd block_rows = Eigen::MatrixXd::Zero(block.count, p);
    for (int j = 0; j < p; ++j) {
      const Eigen::VectorXd v = directions.col(j);
      const double largest = v.cwiseAbs().maxCoeff();
      if (largest > 0.0) {
        const double step = DirectionStep(measurement) * model.size / largest;
        std::vector<double> plus = equilibrium.positions, minus = equilibrium.positions;
        for (int k = 0; k < model.num_dofs(); ++k) {
          plus[k] += step * v[k];
          minus[k] -= step * v[k];
        }
        const auto r_plus = EvaluateMeasurement(measurement, model, plus.data(), context).residuals;
        const auto r_minus =
            EvaluateMeasurement(measurement, model, minus.data(), context).residuals;
        for (int i = 0; i < block.count; ++i) {
          block_rows(i, j) = (r_plus[i] - r_minus[i]) / (2.0 * step);
        }
      }
      if (measurement.kind == FitMeasurement::Kind::kReactions) {
        // The reactions depend on θ directly too: ∂R/∂u = ∂g/∂u at the fixed coordinates.
        const double scale = std::sqrt(measurement.weight) / measurement.sigma;
        const auto& ids = measurement.reactions.ids;
        for (size_t k = 0; k < ids.size(); ++k) {
          for (int c = 0; c < 3; ++c) block_rows(3 * k + c, j) += scale * direct(3 * ids[k] + c, j);
        }
      }
    }
    rows.Doubles(std::vector<double>(block_rows.data(), block_rows.data() + block_rows.size()));
  }
  return rows.bytes();
}

bool FitProblem::ImplicitJacobian(Eigen::MatrixXd* jacobian) {
  const int p = num_parameters();
  jacobian->setZero(num_residuals_, p);
  const std::vector<int> solved = MeasuredEquilibria();
  const std::vector<std::string> outcomes = ComputeOnOwners(
      unit_costs_, [&](int k) { return JacobianRowsOf(solved[k]); }, local_threads_);
  for (size_t k = 0; k < solved.size(); ++k) {
    ByteReader reader(outcomes[k]);
    if (reader.Int() == 0) return false;
    for (const auto& block : blocks_) {
      if (block.equilibrium != solved[k]) continue;
      const std::vector<double> rows = reader.Doubles();
      jacobian->middleRows(block.offset, block.count) =
          Eigen::Map<const Eigen::MatrixXd>(rows.data(), block.count, p);
    }
  }
  return true;
}

Eigen::MatrixXd FitProblem::FiniteDifferenceJacobian(const std::vector<double>& u, double step) {
  const int p = num_parameters();
  Eigen::MatrixXd jacobian(num_residuals_, p);
  for (int j = 0; j < p; ++j) {
    std::vector<double> plus = u, minus = u;
    plus[j] += step;
    minus[j] -= step;
    const std::vector<double> r_plus = Evaluate(plus).residuals;
    const std::vector<double> r_minus = Evaluate(minus).residuals;
    for (int i = 0; i < num_residuals_; ++i) {
      jacobian(i, j) = (r_plus[i] - r_minus[i]) / (2.0 * step);
    }
  }
  Evaluate(u);
  return jacobian;
}

}  // namespace drape
