// The fit as a function of the parameters: r(u) = the normalised residuals of every measurement
// at the equilibria of the specimens (and of the virtual Peirce strips) solved with the scene keys
// set to θ(u). u = ln θ for a log parameter, θ / (upper − lower) otherwise.
//
// Inner solves: newton, warm-started from the equilibrium already solved at the nearest u (the
// previous one, in a descent) if that u is within kWarmStartRadius, from the scene's own initial
// positions (a cold start) otherwise — a drape has several equilibria (fold patterns), and a warm
// start from a distant shape can settle in another one than the cold start, which is how
// measurements are simulated and how `drape solve` starts; to a relative residual of
// kInnerTolerance (or the scene's own, if tighter), or until the residual stagnates at its roundoff
// floor (no halving in kStagnationIterations iterations; later solves then stop at twice that
// floor); a warm start that has not converged in kWarmStartIterations is restarted from the scene's
// own initial positions. The equilibrium is accepted if its relative residual is at most
// kAcceptedResidual. Rule: the position error of an equilibrium is about (relative residual) ×
// (its sag), so the objective's noise is ~1e-10 relative — far below both the outer steps
// (relative parameter changes down to the outer tolerance, 1e-8 by default, are only resolved
// where the sensitivity is > 1e-2) and the central-difference steps (1e-4 in u) of the
// derivatives.
//
// Derivatives by implicit differentiation through the equilibrium g(x*(θ), θ) = 0:
//   dx*/du = −H⁻¹ ∂g/∂u,
// H the exact Hessian over the free coordinates at x* (src/numerics/sparse_hessian.h, assembled
// once and factorised once with CHOLMOD per equilibrium, one back-solve per parameter), ∂g/∂u by
// central differences of the energy gradient at fixed x* between models built at u ± 1e-4 (the
// energies are linear in the stiffnesses, so these differences are exact up to roundoff). The
// residuals' dependence on x is then differentiated along each direction dx*/du_j by a central
// difference of the measurement function alone (no re-solve).
//
// In parallel (src/parallel/shared_work.h): the equilibria of an evaluation, and their implicit
// derivatives, are independent; each belongs to one owner (an MPI rank; or, in a process alone,
// whichever of `local_threads` threads takes it), which alone solves it and keeps
// its warm-start history (so each equilibrium starts from its own previous one, whatever the
// number of ranks). Owners are set once, by the equilibria's node counts (the largest first, each
// to the least loaded rank). The owner sends back the equilibrium's outcome (converged, iterations,
// positions) and its measurements' residuals, or its Jacobian rows; every process then assembles
// r, J and the objective in the same order as a serial run: the same numbers, bit for bit, with
// any number of ranks or threads. Under MPI every rank runs the same outer loop on these numbers;
// a rank keeps the models of its own equilibria only (RebuildMissingModels() for the writer).
#ifndef DRAPE_SRC_FIT_FIT_PROBLEM_H_
#define DRAPE_SRC_FIT_FIT_PROBLEM_H_

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "src/fit/fit_file.h"
#include "src/fit/fit_measurements.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

constexpr double kInnerTolerance = 1e-10;
constexpr double kAcceptedResidual = 1e-8;
constexpr int kStagnationIterations = 8;
constexpr int kWarmStartIterations = 40;  // then a cold start from the scene's own positions
constexpr double kWarmStartRadius = 0.2;  // in u: a 22% change of a log parameter

// Where each measurement's residuals lie in r.
struct ResidualBlock {
  int specimen = 0;
  int measurement = 0;  // index in the specimen's measurements
  int equilibrium = 0;  // index in FitProblem::equilibria()
  int offset = 0, count = 0;
  std::string label;  // e.g. "drape_coefficient", "positions scan.csv", "bending_length (warp)"
};

// One equilibrium solved per evaluation: a specimen, or a bending-length measurement's strip.
struct FitEquilibrium {
  int specimen = 0;
  int strip_of = -1;      // the bending-length measurement whose strip this is, -1 for the specimen
  bool measured = false;  // some measurement uses it (otherwise it is not solved)
  Scene scene;            // at the last evaluated θ
  std::unique_ptr<Model> model;
  std::vector<double> positions;  // the last equilibrium, 3 per node
  bool converged = false;
  int inner_iterations = 0;
  double relative_residual = 0.0;
  double flat_area = 0.0;  // m², the flat specimen's shadow (computed once, if needed)
  double tolerance = 0.0;  // the inner tolerance, raised to a roundoff floor once one is met
  // Every converged equilibrium so far and its u: the next solve starts from the one whose u is
  // nearest, so that a drape with several equilibria (folds) follows one branch continuously.
  std::vector<std::vector<double>> solved_u, solved_positions;
};

struct FitEvaluation {
  std::vector<double> residuals;
  double objective = 0.0;  // ½ Σ r²
  bool converged = true;   // every inner solve reached its tolerance
  int inner_iterations = 0;
  std::vector<double> model_values;  // per block (ResidualBlock order)
};

class FitProblem {
 public:
  // `local_threads`: threads that solve the equilibria when the process is alone (0: the
  // machine's cores); under MPI each rank solves its own equilibria in order.
  explicit FitProblem(const FitSpec& spec, int local_threads = 1);

  int num_parameters() const { return static_cast<int>(spec_.parameters.size()); }
  int num_residuals() const { return num_residuals_; }
  const std::vector<ResidualBlock>& blocks() const { return blocks_; }
  const FitSpec& spec() const { return spec_; }

  // θ ↔ u, and dθ/du.
  std::vector<double> ToParameters(const std::vector<double>& u) const;
  std::vector<double> ToUnknowns(const std::vector<double>& theta) const;
  std::vector<double> ParameterDerivatives(const std::vector<double>& u) const;
  std::vector<double> LowerUnknowns() const;
  std::vector<double> UpperUnknowns() const;

  // Solves every equilibrium at u (warm-started unless `cold`) and returns the residuals.
  FitEvaluation Evaluate(const std::vector<double>& u, bool cold = false);

  // dr/du at the last evaluated u, by implicit differentiation. False if a Hessian could not be
  // factorised (an equilibrium that is not a strict minimum); `jacobian` is m × p.
  bool ImplicitJacobian(Eigen::MatrixXd* jacobian);

  // dr/du by central differences of whole, re-solved equilibria (step `step` in u); leaves the
  // state at u re-evaluated.
  Eigen::MatrixXd FiniteDifferenceJacobian(const std::vector<double>& u, double step);

  const std::vector<FitEquilibrium>& equilibria() const { return equilibria_; }
  const std::vector<double>& last_unknowns() const { return last_u_; }

  // Under MPI, builds (at the last evaluated u) the model and scene of each measured equilibrium
  // that another rank owns, so that every equilibrium has its model, scene and positions here (as
  // the writers need). Does nothing in a process alone.
  void RebuildMissingModels();

  // Whether a stop was asked for (SIGINT, SIGTERM) in this process or, under MPI, in any rank: all
  // ranks get the same answer, so their outer loops stop together. A collective call under MPI.
  bool StopRequested() const;

 private:
  Scene SceneAt(const FitEquilibrium& equilibrium, const std::vector<double>& theta) const;
  bool SolveEquilibrium(FitEquilibrium* equilibrium, const std::vector<double>& u, bool cold);
  // The measured equilibria, in order: the units of the parallel work.
  std::vector<int> MeasuredEquilibria() const;
  // Solves equilibrium e at u and evaluates its measurements (on its owner); the outcome packed.
  std::string SolveAndMeasure(int e, const std::vector<double>& u, bool cold);
  // Reads SolveAndMeasure's outcome into equilibrium e (on every process) and `evaluation`.
  void TakeOutcome(int e, const std::string& outcome, FitEvaluation* evaluation);
  // dr/du's rows of equilibrium e's blocks, packed (on its owner); first a flag: 0 if its Hessian
  // could not be factorised.
  std::string JacobianRowsOf(int e) const;
  MeasurementContext ContextOf(const ResidualBlock& block) const;
  // dx*/du (3n × p, zero rows at fixed coordinates) and ∂g/∂u at x* (3n × p). False if H is not
  // positive definite.
  bool EquilibriumDirections(const FitEquilibrium& equilibrium, Eigen::MatrixXd* directions,
                             Eigen::MatrixXd* direct_gradient) const;
  const FitMeasurement& MeasurementOf(const ResidualBlock& block) const;

  FitSpec spec_;
  std::vector<Scene> base_scenes_;  // each specimen at the initial parameters (disc radius etc.)
  // Per measured equilibrium (MeasuredEquilibria() order), its expected cost: its mesh's node
  // count. Sets which rank owns it under MPI (src/parallel/shared_work.h), once for the fit.
  std::vector<double> unit_costs_;
  std::vector<FitEquilibrium> equilibria_;
  std::vector<ResidualBlock> blocks_;
  int num_residuals_ = 0;
  std::vector<double> last_u_;
  int local_threads_ = 1;
};

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_PROBLEM_H_
