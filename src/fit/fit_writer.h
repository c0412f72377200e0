// The outputs of `drape fit`: fit.json, history.csv, sensitivity.csv, fit.png, report.md and
// report.html (the same report, fit.png embedded), each written to a temporary name and renamed
// (no half-written file is left).
#ifndef DRAPE_SRC_FIT_FIT_WRITER_H_
#define DRAPE_SRC_FIT_FIT_WRITER_H_

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"
#include "src/output/provenance.h"

namespace drape {

// One row of the sensitivity table: how a measurement moves with a parameter at the optimum.
// For a vector measurement (positions, reactions) the root-mean-square over its components.
struct Sensitivity {
  std::string measurement, parameter, unit;
  double per_parameter = 0.0;      // ∂measurement/∂θ, measurement unit per parameter unit
  double per_log_parameter = 0.0;  // ∂measurement/∂ln θ = θ ∂measurement/∂θ
};
std::vector<Sensitivity> SensitivityTable(const FitProblem& problem, const FitResult& result);

// The words and numbers fit.png shows: the two views' titles, the axis names with their unit
// (index 0 = x, 1 = y, 2 = z), and the caption under the views: one line per fitted parameter
// (its key, value at the optimum, unit — known for material keys, from the solved scene — and
// standard error), then the final residual (the
// objective ½Σr² of the normalised residuals and their RMS) and whether the fit converged.
struct FitPlotText {
  std::array<std::string, 2> titles;
  std::array<std::string, 3> axis_labels;
  std::vector<std::string> caption;
};
FitPlotText FitPlotTextOf(const FitProblem& problem, const FitResult& result);

// `provenance` (src/output/provenance.h) goes into fit.json and the reports.
void WriteFitOutputs(const FitProblem& problem, const FitResult& result,
                     const std::string& directory, const Provenance& provenance = {});

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_WRITER_H_
