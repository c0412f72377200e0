// The outputs of `drape fit`: fit.json, history.csv, sensitivity.csv, fit.png and report.md, each
// written to a temporary name and renamed (no half-written file is left).
#ifndef DRAPE_SRC_FIT_FIT_WRITER_H_
#define DRAPE_SRC_FIT_FIT_WRITER_H_

#include <Eigen/Core>
#include <string>

#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"

namespace drape {

// One row of the sensitivity table: how a measurement moves with a parameter at the optimum.
// For a vector measurement (positions, reactions) the root-mean-square over its components.
struct Sensitivity {
  std::string measurement, parameter, unit;
  double per_parameter = 0.0;      // ∂measurement/∂θ, measurement unit per parameter unit
  double per_log_parameter = 0.0;  // ∂measurement/∂ln θ = θ ∂measurement/∂θ
};
std::vector<Sensitivity> SensitivityTable(const FitProblem& problem, const FitResult& result);

void WriteFitOutputs(const FitProblem& problem, const FitResult& result,
                     const std::string& directory);

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_WRITER_H_
