#include "src/compare/compare.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "src/compare/compare_report.h"
#include "src/model/equilibrium.h"
#include "src/output/writers.h"
#include "src/run/run.h"
#include "src/run/solve_report.h"
#include "src/run/state_text.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solver.h"

namespace drape {

namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A value of /proc/self/status in kB ("VmHWM", "VmRSS"); -1 if unreadable.
long ReadStatusKb(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.compare(0, key.size() + 1, key + ":") == 0) {
      return std::strtol(line.c_str() + key.size() + 1, nullptr, 10);
    }
  }
  return -1;
}

// Resets the process's peak resident size (VmHWM) to its current size (Linux >= 4.0).
bool ResetPeakResidentSize() {
  std::FILE* file = std::fopen("/proc/self/clear_refs", "w");
  if (!file) return false;
  const bool written = std::fputs("5", file) >= 0;
  return std::fclose(file) == 0 && written;
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

Scene WithLimits(Scene scene, const std::string& method, double tolerance,
                 const CompareOptions& options) {
  scene.solver.tolerance = tolerance;
  scene.solver.time_limit = std::min(EffectiveTimeLimit(scene.solver, method), options.time_limit);
  return scene;
}

// One timed solve. Curve points are measured in the callback, against `reference` when given.
struct TimedSolve {
  RunResult result;
  double corrected_time_s = 0.0;
  double callback_time_s = 0.0;
  double peak_memory_mb = 0.0;
  std::vector<CurvePoint> curve;
  std::vector<double> positions;
  bool curve_positions_valid = true;
  double drape_coefficient = std::nan("");  // at the final positions; NaN where there is none
};

TimedSolve Solve(const Scene& scene, const std::string& method, const SceneReference* reference) {
  Model model = BuildModel(scene);
  TimedSolve timed;
  std::vector<double> first_iterate;  // positions at the first callback
  bool iterates_move = false;         // model.positions changed between callbacks
  auto on_iteration = [&](const IterationRecord& record) {
    const Clock::time_point start = Clock::now();
    if (first_iterate.empty()) {
      first_iterate = model.positions;
    } else if (!iterates_move) {
      iterates_move = model.positions != first_iterate;
    }
    if (reference) {
      CurvePoint point;
      point.iteration = record.iteration;
      point.time_s = record.time_s - timed.callback_time_s;
      point.relative_residual = record.relative_residual;
      point.energy_gap = record.energy - reference->energy;
      point.error = MeasurePositionError(model.positions, reference->positions);
      timed.curve.push_back(point);
    }
    timed.callback_time_s += SecondsSince(start);
    return true;
  };
  const long resident_kb = ReadStatusKb("VmRSS");
  const bool peak_reset = ResetPeakResidentSize();
  timed.result = RunSolve(scene, model, method, on_iteration);
  timed.drape_coefficient = ReportedDrapeCoefficient(ReportOf(scene, model, timed.result));
  const long peak_kb = ReadStatusKb("VmHWM");
  if (peak_reset && resident_kb >= 0 && peak_kb >= 0) {
    timed.peak_memory_mb = std::max(0L, peak_kb - resident_kb) / 1024.0;
  } else {
    timed.peak_memory_mb = std::numeric_limits<double>::quiet_NaN();
  }
  timed.corrected_time_s = timed.result.summary.wall_time_s - timed.callback_time_s;
  timed.positions = model.positions;
  // A solver that iterates on its own copy leaves model.positions at the start during the
  // callbacks: its curve has no position errors then (residual and energy stay valid).
  timed.curve_positions_valid =
      iterates_move || first_iterate.empty() || timed.positions == first_iterate;
  if (!timed.curve_positions_valid) {
    for (CurvePoint& point : timed.curve) {
      point.error.max_m = point.error.rms_m = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return timed;
}

std::string Describe(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

void Classify(const RunResult& result, const SceneReference& reference, RunRecord* run) {
  run->reason = result.summary.termination;
  if (!result.certificate.evaluable || !std::isfinite(result.certificate.energy)) {
    run->status = RunStatus::kFailed;
    run->reason = "energy or forces not finite at the end (" + run->reason + ")";
  } else if (result.PassesThrough()) {
    run->status = RunStatus::kPassesThrough;
    run->reason = StateText(result);
  } else if (!result.converged) {
    run->status = RunStatus::kNotConverged;
  } else if (std::abs(run->energy_gap) > reference.energy_tolerance) {
    run->status = RunStatus::kDifferentEquilibrium;
    run->reason = std::string(run->energy_gap < 0 ? "lower" : "higher") + " energy by " +
                  Describe(std::abs(run->energy_gap)) + " J, " +
                  (!result.stability.computed ? "stability unknown"
                   : result.stability.stable  ? "stable"
                                              : "unstable");
  } else {
    run->status = RunStatus::kConverged;
  }
}

RunRecord CompareRun(const Scene& scene, const std::string& method, const SceneReference& reference,
                     const CompareOptions& options) {
  RunRecord run;
  run.scene = scene.name;
  run.solver = method;
  const Scene limited = WithLimits(scene, method, scene.solver.tolerance, options);
  for (int repeat = 0; repeat < std::max(1, options.repeat); ++repeat) {
    TimedSolve timed;
    try {
      timed = Solve(limited, method, repeat == 0 ? &reference : nullptr);
    } catch (const InputError& refusal) {
      run.status = RunStatus::kRefused;
      run.reason = refusal.what();
      return run;
    } catch (const std::exception& failure) {
      run.status = RunStatus::kFailed;
      run.reason = std::string("threw: ") + failure.what();
      return run;
    }
    run.times_s.push_back(timed.corrected_time_s);
    if (repeat > 0) continue;
    const RunResult& result = timed.result;
    run.iterations = result.summary.iterations;
    run.callback_time_s = timed.callback_time_s;
    run.relative_residual = result.certificate.relative_residual;
    run.max_node_force = result.certificate.max_node_force;
    run.energy = result.certificate.energy;
    run.energy_gap = run.energy - reference.energy;
    run.drape_coefficient_gap = timed.drape_coefficient - reference.drape_coefficient;
    run.error = MeasurePositionError(timed.positions, reference.positions);
    run.stability_computed = result.stability.computed;
    run.stable = result.stability.stable;
    run.peak_memory_mb = timed.peak_memory_mb;
    run.curve = std::move(timed.curve);
    run.curve_positions_valid = timed.curve_positions_valid;
    run.positions = std::move(timed.positions);
    Classify(result, reference, &run);
  }
  run.time_s = Median(run.times_s);
  return run;
}

void FillReference(const TimedSolve& timed, const std::string& method, double tolerance,
                   double size, SceneReference* reference) {
  const RunResult& result = timed.result;
  reference->method = method;
  reference->tolerance = tolerance;
  reference->converged = result.converged;
  reference->termination = result.summary.termination;
  reference->iterations = result.summary.iterations;
  reference->time_s = timed.corrected_time_s;
  reference->energy = result.certificate.energy;
  reference->drape_coefficient = timed.drape_coefficient;
  reference->relative_residual = result.certificate.relative_residual;
  reference->max_node_force = result.certificate.max_node_force;
  reference->stable = result.stability.stable;
  reference->stability_computed = result.stability.computed;
  // A converged run whose energy differs by more than this is another equilibrium: a millionth
  // of the energy scale (|E_ref|, or the applied force times the size when E_ref is near zero).
  reference->energy_tolerance = 1e-6 * std::max({std::abs(reference->energy),
                                                 result.certificate.reference_force * size, 1e-12});
  reference->positions = timed.positions;
}

// newton to options.reference_tolerance; if that does not reach even the scene's tolerance, the
// converged run with the smallest residual among the selected solvers at the scene's tolerance.
SceneReference ComputeReference(const Scene& scene, double size,
                                const std::vector<std::string>& solvers,
                                const CompareOptions& options, std::ostream& log) {
  SceneReference reference;
  double best_residual = std::numeric_limits<double>::infinity();
  auto consider = [&](const std::string& method, double tolerance) {
    Scene limited = WithLimits(scene, method, tolerance, options);
    limited.solver.max_iterations = std::max(EffectiveMaxIterations(limited.solver, method), 1000);
    try {
      const TimedSolve timed = Solve(limited, method, nullptr);
      const Certificate& certificate = timed.result.certificate;
      if (!certificate.evaluable || !(certificate.relative_residual < best_residual)) return;
      best_residual = certificate.relative_residual;
      FillReference(timed, method, tolerance, size, &reference);
    } catch (const std::exception& failure) {
      log << "  reference candidate " << method << " failed: " << failure.what() << '\n';
    }
  };
  consider("newton", options.reference_tolerance);
  reference.scene_tolerance = scene.solver.tolerance;
  if (best_residual <= scene.solver.tolerance) return reference;
  log << "  newton did not reach the scene's tolerance; trying the other solvers\n";
  for (const std::string& method : solvers) {
    if (method != "newton") consider(method, scene.solver.tolerance);
  }
  return reference;
}

}  // namespace

PositionError MeasurePositionError(const std::vector<double>& positions,
                                   const std::vector<double>& reference) {
  assert(positions.size() == reference.size());
  PositionError error;
  const size_t nodes = positions.size() / 3;
  if (nodes == 0) return error;
  double sum_squares = 0.0;
  for (size_t node = 0; node < nodes; ++node) {
    double squared = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double difference = positions[3 * node + c] - reference[3 * node + c];
      squared += difference * difference;
    }
    sum_squares += squared;
    error.max_m = std::max(error.max_m, std::sqrt(squared));
  }
  error.rms_m = std::sqrt(sum_squares / nodes);
  return error;
}

const char* RunStatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kConverged:
      return "converged";
    case RunStatus::kNotConverged:
      return "not converged";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kRefused:
      return "refused";
    case RunStatus::kDifferentEquilibrium:
      return "different equilibrium";
    case RunStatus::kPassesThrough:
      return "passes through";
  }
  return "?";
}

const std::vector<double>& AccuracyLevels() {
  static const std::vector<double> levels = {1e-2, 1e-4, 1e-6, 1e-8};
  return levels;
}

double TimeToReach(const RunRecord& run, double level) {
  if (!run.curve_positions_valid) return kTimeUnknown;
  if (run.status == RunStatus::kDifferentEquilibrium || run.status == RunStatus::kPassesThrough) {
    return -1.0;
  }
  for (const CurvePoint& point : run.curve) {
    if (point.error.rms_m / run.size <= level) return std::max(0.0, point.time_s);
  }
  return -1.0;
}

SceneComparison CompareScene(const std::string& scene_file, const CompareOptions& options,
                             std::ostream& log) {
  SceneComparison comparison;
  comparison.file = scene_file;
  comparison.name = std::filesystem::path(scene_file).stem().string();
  Scene scene;
  try {
    scene = LoadScene(scene_file, options.overrides);
    comparison.name = scene.name;
    const Model model = BuildModel(scene);
    comparison.num_nodes = model.num_nodes;
    comparison.free_dofs = model.num_free_dofs();
    comparison.size = model.size;
  } catch (const std::exception& error) {
    comparison.error = error.what();
    log << scene_file << ": " << comparison.error << '\n';
    return comparison;
  }
  std::vector<std::string> solvers = options.solvers;
  if (solvers.empty() || (solvers.size() == 1 && solvers[0] == "all")) {
    solvers.clear();
    for (const SolverInfo& info : AllSolvers()) solvers.push_back(info.name);
  }
  log << comparison.name << " (" << comparison.free_dofs << " free dofs): reference...\n";
  comparison.reference = ComputeReference(scene, comparison.size, solvers, options, log);
  const SceneReference& reference = comparison.reference;
  log << "  reference " << reference.method << ": residual " << reference.relative_residual
      << ", energy " << reference.energy << " J, " << reference.time_s << " s\n";
  if (reference.positions.empty()) {
    comparison.error = "no solver gave an evaluable reference";
    return comparison;
  }
  for (const std::string& method : solvers) {
    RunRecord run = CompareRun(scene, method, reference, options);
    run.size = comparison.size;
    log << "  " << method << ": " << RunStatusName(run.status) << ", " << run.iterations
        << " iterations, " << run.time_s << " s, residual " << run.relative_residual
        << (run.reason.empty() ? "" : " (" + run.reason + ")") << '\n';
    comparison.runs.push_back(std::move(run));
  }
  return comparison;
}

namespace {

// Every scene loads (with the --set overrides) and builds, before anything is solved or written;
// the first that does not is reported, located, and the comparison stops (exit 2).
bool ScenesLoad(const CompareOptions& options, std::ostream& log) {
  for (const std::string& file : options.scenes) {
    try {
      const Scene scene = LoadScene(file, options.overrides);
      BuildModel(scene);
    } catch (const InputError& error) {
      log << error.what() << "\ndrape compare: nothing compared, no report written\n";
      return false;
    }
  }
  return true;
}

}  // namespace

int RunCompare(const CompareOptions& options, std::ostream& log, std::ostream* result) {
  if (options.scenes.empty()) {
    log << "drape compare: no scene given\n";
    return 2;
  }
  for (const std::string& name : options.solvers) {
    if (name != "all" && !FindSolver(name)) {
      log << "drape compare: unknown solver '" << name << "' (see `drape solvers`)\n";
      return 2;
    }
  }
  if (options.repeat < 1 || !(options.time_limit > 0)) {
    log << "drape compare: --repeat must be at least 1 and --time-limit positive\n";
    return 2;
  }
  if (!ScenesLoad(options, log)) return 2;
  try {  // before any solve: an unwritable folder costs nothing
    CheckOutputWritable(options.out_dir);
  } catch (const std::exception& error) {
    log << "drape compare: cannot write the report: " << error.what() << "; nothing solved\n";
    return 2;
  }
  const Clock::time_point start = Clock::now();
  std::vector<SceneComparison> comparisons;
  for (const std::string& file : options.scenes) {
    comparisons.push_back(CompareScene(file, options, log));
  }
  try {
    WriteCompareReport(comparisons, options, SecondsSince(start), log);
  } catch (const std::exception& error) {
    log << "drape compare: cannot write the report: " << error.what() << '\n';
    return 1;
  }
  (result ? *result : log) << "report: "
                           << (std::filesystem::path(options.out_dir) / "report.md").string()
                           << '\n';
  return 0;
}

}  // namespace drape
