#include "src/commands/commands.h"

#include <cstdio>
#include <functional>

#include "src/analysis/levels.h"
#include "src/fit/fit_file.h"
#include "src/fit/fit_methods.h"
#include "src/fit/fit_problem.h"
#include "src/fit/fit_writer.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/writers.h"
#include "src/parallel/process_group.h"
#include "src/scene/drape_tester.h"
#include "src/solvers/solver.h"
#include "src/sweep/drops_report.h"
#include "src/sweep/sweep_file.h"

namespace drape {
namespace {

// The progress line of each fit evaluation.
std::function<void(const FitIterationRecord&)> FitProgressPrinter(const FitSpec& spec,
                                                                  std::ostream& log) {
  return [&spec, &log](const FitIterationRecord& record) {
    char text[120];
    std::snprintf(text, sizeof text, "fit %s: evaluation %d, %.2f s, objective %.6g (best %.6g)",
                  spec.method.c_str(), record.evaluation, record.time_s, record.objective,
                  record.best_objective);
    log << text;
    for (size_t j = 0; j < record.parameters.size(); ++j) {
      std::snprintf(text, sizeof text, ", %s=%.8g", spec.parameters[j].key.c_str(),
                    record.parameters[j]);
      log << text;
    }
    log << (record.inner_converged ? "" : " (an equilibrium did not converge)") << std::endl;
  };
}

}  // namespace

void RequireThreadCount(int threads) {
  if (threads < 0) {
    throw CommandOptionError(
        "threads: expected a whole number >= 0 (0: the machine's cores), got " +
        std::to_string(threads));
  }
}

FitCommandResult RunFitCommand(const FitCommand& command, const CommandContext& context) {
  RequireThreadCount(command.threads);
  FitSpec spec = LoadFitFile(command.file, command.overrides);
  if (command.method) {
    if (!FindFitMethod(*command.method)) {
      throw CommandOptionError("unknown fit method '" + *command.method +
                               "' (known: " + FitMethodList() + ")");
    }
    spec.method = *command.method;
  }
  if (command.out) spec.output_directory = *command.out;
  FitCommandResult outcome;
  outcome.directory = spec.output_directory;
  // Under mpirun/srun every rank runs the fit in step; only the coordinator reports and writes.
  outcome.coordinator = Processes().IsCoordinator();
  if (outcome.coordinator) {
    try {  // before any solve: an unwritable folder costs nothing
      CheckOutputWritable(spec.output_directory, {}, command.out ? "out" : "");
    } catch (const std::exception& error) {
      throw OutputFolderError(std::string(error.what()) + "; nothing solved");
    }
    for (const std::string& warning : spec.warnings) {
      context.log << "drape fit: warning: " << warning << std::endl;
    }
  }
  FitProblem problem(spec, command.threads);
  FitOptions options;
  if (outcome.coordinator) options.on_evaluation = FitProgressPrinter(spec, context.log);
  outcome.result = RunFit(problem, options);
  outcome.interrupted = InterruptRequested();
  const FitResult& result = outcome.result;
  if (result.parameters.empty()) {
    outcome.line = "drape fit: " + result.termination + "; nothing written";
    return outcome;
  }
  if (!outcome.coordinator) return outcome;
  WriteFitOutputs(problem, result, spec.output_directory,
                  Provenance{context.command_line, command.overrides});
  outcome.written = true;
  char objective[32];
  std::snprintf(objective, sizeof objective, "%g", result.objective);
  outcome.line = "fit " + spec.method + ": converged " + (result.converged ? "yes" : "no") + ", " +
                 std::to_string(result.evaluations) + " evaluations, objective " + objective +
                 " (" + result.termination + "); results in " + spec.output_directory;
  return outcome;
}

DropsCommandResult RunDropsCommand(const Scene& scene, const DropsCommand& command,
                                   const CommandContext& context) {
  RequireThreadCount(command.threads);
  if (command.drops < 0 || command.drops > kMostDrops) {
    throw CommandOptionError("drops: expected a whole number from 1 to " +
                             std::to_string(kMostDrops) + ", got " + std::to_string(command.drops));
  }
  if (!scene.drape_test) {
    throw InputError(scene.root,
                     "a drop needs a drape test: give the scene a drape_test block "
                     "(docs/reference.md, \"`drape_test`\")");
  }
  DropsOptions options;
  options.drops = command.drops > 0 ? command.drops : scene.drape_test->drops;
  options.threads = command.threads;
  options.directory = command.directory;
  options.command_line = context.command_line;
  options.overrides = command.overrides;
  options.calibration = command.calibration;
  DropsCommandResult outcome;
  outcome.summary = RunDrops(scene, options, context.log);
  outcome.interrupted = InterruptRequested();
  if (!outcome.summary.coordinator) return outcome;
  const DropStatistics& statistics = outcome.summary.statistics;
  outcome.lines.push_back(DropsLine(statistics, outcome.summary.mesh_advice) + "; results in " +
                          command.directory + " (report.html)");
  if (statistics.counted > 0) {
    if (const auto advice =
            SpecimenSizeAdvice(scene.drape_test->specimen_diameter, statistics.mean)) {
      outcome.lines.push_back("specimen size: " + *advice);
    }
  }
  return outcome;
}

SweepCommandResult RunSweepCommand(const SweepCommand& command, const CommandContext& context) {
  RequireThreadCount(command.threads);
  const SweepSpec spec = LoadSweepFile(command.file);
  const int count = static_cast<int>(spec.tasks.size());
  if (command.only && (*command.only < 0 || *command.only >= count)) {
    throw CommandOptionError("task " + std::to_string(*command.only) +
                             " is not in the sweep (its tasks are 0 to " +
                             std::to_string(count - 1) + ")");
  }
  SweepOptions options;
  options.out = command.out;
  options.only = command.only;
  options.threads = command.threads;
  options.plots = command.plots;
  options.command_line = context.command_line;
  SweepCommandResult outcome;
  outcome.summary = RunSweep(spec, options, context.log);
  const SweepSummary& s = outcome.summary;
  outcome.line = "sweep: " + std::to_string(s.tasks) + " tasks; " + std::to_string(s.solved) +
                 " solved, " + std::to_string(s.skipped) + " already done (skipped); " +
                 std::to_string(s.rows) + " rows, " + std::to_string(s.converged) + " converged" +
                 (s.interrupted ? "; interrupted" : "") + "; results in " + s.directory +
                 "/sweep.csv";
  const bool all = command.only ? s.converged_tasks.count(*command.only) > 0
                                : static_cast<int>(s.converged_tasks.size()) == s.tasks;
  outcome.all_converged = all && !s.interrupted;
  return outcome;
}

FabricsCommandResult RunFabricsCommand(FabricsOptions options, const CommandContext& context) {
  RequireThreadCount(options.threads);
  options.command_line = context.command_line;
  FabricsCommandResult outcome;
  if (!options.calibrate.empty()) {
    outcome.calibration = RunCalibrate(options, context.log);
    const CalibrateSummary& s = *outcome.calibration;
    outcome.line = CalibrateLine(s);
    outcome.all_predicted = s.problem.empty() && !s.interrupted;
    return outcome;
  }
  if (!options.calibration_file.empty()) {
    options.calibration = ReadCalibration(options.calibration_file);
  }
  const FabricsSpec spec = LoadFabrics(options);
  outcome.summary = RunFabrics(spec, options, context.log);
  const FabricsSummary& s = outcome.summary;
  if (options.only) {
    outcome.line = "fabrics: task " + std::to_string(*options.only) + " done; results in " +
                   s.directory + " (run without --only to write fabrics.csv)";
    outcome.all_predicted = !s.interrupted;
  } else {
    outcome.line = FabricsLine(s) + "; results in " + s.directory + "/fabrics.csv";
    outcome.all_predicted = s.predicted == s.fabrics && !s.interrupted;
  }
  return outcome;
}

// "; accuracy ±0.05 asked, ±0.043 reached (mesh.spacing 2.7 mm chosen for it)".
std::string AccuracyClause(const AccuracyOutcome& accuracy) {
  return "; accuracy ±" + RoundedNumber(accuracy.asked, 2) + " asked, ±" +
         RoundedNumber(accuracy.reached, 2) + " reached (mesh.spacing " +
         LengthText(accuracy.spacing, 2) +
         (accuracy.spacing_chosen ? " chosen for it)" : " given)");
}

// Why a run that asked for an accuracy did not reach it (stderr, exit 1): the finest lattice
// stopped before equilibrium (with the best level that reached it), or its bar is wider.
std::string AccuracyFailure(const AccuracyOutcome& accuracy, bool converged) {
  const std::string asked = "±" + RoundedNumber(accuracy.asked, 2);
  if (!converged) {
    std::string text = "the " + LengthText(accuracy.spacing, 2) +
                       " lattice stopped before equilibrium, so no drape coefficient within " +
                       asked + " (drape_test.accuracy)";
    if (const auto& best = accuracy.best_converged) {
      char figure[64];
      std::snprintf(figure, sizeof figure, "%.3f ± %.2g", best->drape_coefficient, best->error);
      text += "; the best reached is the " + LengthText(best->spacing, 2) + " level's, " + figure +
              " (mesh rule)";
    }
    return text + "; raise solver.time_limit or solver.max_iterations, or ask for less";
  }
  const std::string head = "the drape coefficient's error bar ±" +
                           RoundedNumber(accuracy.reached, 2) + " is wider than the " + asked +
                           " asked (drape_test.accuracy)";
  if (!accuracy.spacing_chosen) {
    return head + ": mesh.spacing " + LengthText(accuracy.spacing, 2) +
           " is too coarse for it; leave mesh.spacing out and drape chooses the lattice";
  }
  return head + ": the levels changed it more than the mesh rule expects at " +
         LengthText(accuracy.spacing, 2) + "; give mesh.spacing " +
         LengthText(accuracy.spacing * accuracy.asked / accuracy.reached, 2) +
         " or finer to narrow it";
}

}  // namespace drape
