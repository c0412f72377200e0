#include "src/cli/cli.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>

#include "src/analysis/levels.h"
#include "src/analysis/mesh_rule.h"
#include "src/cli/progress.h"
#include "src/cli/usage.h"
#include "src/commands/commands.h"
#include "src/compare/compare.h"
#include "src/fit/fit_file.h"
#include "src/fit/fit_methods.h"
#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"
#include "src/fit/fit_writer.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/output/command_output.h"
#include "src/output/json.h"
#include "src/output/result_folder.h"
#include "src/output/scene_json.h"
#include "src/output/scene_json_schema.h"
#include "src/output/version.h"
#include "src/output/writers.h"
#include "src/parallel/process_group.h"
#include "src/parallel/task_farm.h"
#include "src/run/run.h"
#include "src/run/state_text.h"
#include "src/scene/calibration.h"
#include "src/scene/drape_tester.h"
#include "src/scene/file_paths.h"
#include "src/scene/material_models.h"
#include "src/scene/output_kinds.h"
#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "src/scene/yaml_reader.h"
#include "src/solvers/solver.h"
#include "src/sweep/drops.h"
#include "src/sweep/drops_report.h"
#include "src/sweep/fabrics.h"
#include "src/sweep/sweep.h"
#include "src/sweep/sweep_file.h"

namespace drape {

namespace {

constexpr char kDescription[] =
    "drape finds the equilibrium shape of fabric by minimising its total potential energy.";

constexpr char kExitStatus[] =
    "\n"
    "exit status: 0 converged to a stable minimum; 1 ran but did not reach the tolerance\n"
    "(results written, converged: false; also after SIGINT or SIGTERM, which save the last\n"
    "iterate); 2 bad input, bad usage or an unwritable output folder (nothing written);\n"
    "3 converged, but to a saddle (saddle: true) or with the fabric through a support disk\n"
    "(results written).\n"
    "Results go to stdout; progress, warnings and errors to stderr.\n";

constexpr char kSetHelp[] =
    "override a scene key (repeatable; the value is YAML, e.g. mesh.nodes=[30,30])";

// Bad usage of the command itself (not of the scene): the message; Dispatch adds the usage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the command line of solve, check and fit gives.
struct Arguments {
  std::string command_line;  // the whole command, shell-quoted (summary.json)
  std::string file;          // the scene (solve, check) or the fit file (fit)
  std::optional<std::string> solver;
  std::optional<std::string> out;
  std::optional<std::string> method;  // fit
  int threads = 0;                    // fit, solve --drops: local threads (task_farm.h)
  std::optional<int> drops;           // solve: repeated drops of a drape test
  std::vector<std::string> overrides;
  bool json = false;                       // check: the resolved scene as JSON with units
  std::optional<std::string> calibration;  // solve, check: --calibration FILE
};

// The scene with its overrides and, where given, the calibration applied (src/scene/calibration.h).
Scene LoadCalibratedScene(const Arguments& arguments, Calibration* calibration) {
  Scene scene = LoadScene(arguments.file, arguments.overrides);
  if (arguments.calibration) *calibration = ReadCalibration(*arguments.calibration);
  ApplyCalibration(*calibration, &scene);
  return scene;
}

std::string CalibrationProvenance(const Calibration& calibration) {
  return calibration.empty() ? "" : calibration.Provenance();
}

// "unknown solver 'newtn' (known: newton, ...); did you mean 'newton'?"

std::string TermSummary(const Model& model) {
  std::string text;
  int total = 0;
  for (const auto& [type, count] : model.TermCounts()) {
    text += (text.empty() ? "" : ", ") + type + " " + std::to_string(count);
    total += count;
  }
  return std::to_string(total) + " terms" + (text.empty() ? "" : " (" + text + ")");
}

std::string OutputDirectory(const Scene& scene) {
  return scene.output.directory.empty() ? DefaultResultFolder(".", scene.name)
                                        : scene.output.directory;
}

// Lets a Ctrl-C (SIGINT) or a batch system's SIGTERM reach the solver's handler even if the parent
// process had blocked it (a blocked signal stays pending until here, so none sent before the solve
// is lost): the solve stops at the next iteration and its last iterate is written, interrupted.
void EnableInterrupt() {
  InstallInterruptHandler();
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  sigaddset(&interrupt, SIGTERM);
  pthread_sigmask(SIG_UNBLOCK, &interrupt, nullptr);
}

std::string ResultLine(const RunResult& result, const std::string& directory) {
  const SolverSummary& summary = result.summary;
  char text[200];
  std::snprintf(text, sizeof text,
                "%s: converged %s, %d iterations, %.3g s, relative residual %.3g, ",
                summary.solver.c_str(), result.converged ? "yes" : "no", summary.iterations,
                summary.wall_time_s, result.certificate.relative_residual);
  return std::string(text) + StateText(result) + " (" + summary.termination + "); results in " +
         directory;
}

// 0 converged to a stable minimum (or stability not computed), 3 converged to a saddle or with
// the fabric through a support disk or through itself, 1 not converged.
int ExitStatus(const RunResult& result) {
  if (!result.converged) return kExitNotConverged;
  return result.Saddle() || result.PassesThrough() ? kExitSaddle : kExitConverged;
}

// "drape coefficient 0.622 ± 0.042 (change from the 5.2 mm level), 8 folds on both finest levels".
std::string DrapeErrorText(const DrapeErrorBar& bar) {
  char text[160];
  std::snprintf(text, sizeof text, "drape coefficient %.3f ± %.2g (%s), ", bar.value, bar.error(),
                bar.basis().c_str());
  const int n = static_cast<int>(bar.folds.size());
  if (!bar.folds_differ) {
    return text + std::to_string(bar.folds[n - 1]) + " folds on both finest levels";
  }
  std::string folds;
  for (int count : bar.folds) folds += (folds.empty() ? "" : ", ") + std::to_string(count);
  return text + std::string("the fold count differs between levels (") + folds +
         ", coarsest first)";
}

// The stdout summary of a multilevel run: the iterations and time of all levels together (the
// line's own figures are the finest level's), then the drape coefficient with its error bar, else
// the extrapolated energy with its error estimate and observed order, or why there is none.
std::string LevelsLine(const LevelsReport& report) {
  int iterations = 0;
  double seconds = 0.0;
  for (const LevelRecord& level : report.levels) {
    iterations += level.iterations;
    seconds += level.wall_time_s;
  }
  const Extrapolation& e = report.extrapolations.front();
  char text[240];
  const int used = std::snprintf(text, sizeof text, "; %zu levels (%d iterations, %.3g s in all): ",
                                 report.levels.size(), iterations, seconds);
  if (report.drape_error) return text + DrapeErrorText(*report.drape_error);
  if (e.available) {
    std::snprintf(text + used, sizeof text - used,
                  "extrapolated %s %.6g ± %.2g (observed order %.2f)", e.quantity.c_str(), e.value,
                  e.error_estimate, e.observed_order);
    return text;
  }
  std::snprintf(text + used, sizeof text - used, "no extrapolated %s (", e.quantity.c_str());
  return text + e.reason + ")";
}

// "; drape coefficient 0.634, 9 folds" for a one-level solve of a scene with a support disc;
// "; drape coefficient 0.634 ± 0.041 (mesh rule for a 1.9 cm bending length), 9 folds" where the
// mesh rule applies (a finite-volume fabric on a lattice).
std::string DrapeLine(const SolveReport& report) {
  if (!report.drape || !(report.drape->disc_radius > 0.0)) return "";
  char coefficient[32];
  std::snprintf(coefficient, sizeof coefficient, "%.3f", report.drape->coefficient.cusick);
  std::string text = std::string("; drape coefficient ") + coefficient;
  if (const std::optional<double> error = ReportedDrapeCoefficientError(report)) {
    assert(report.mesh_advice && "a one-level solve's error bar is the mesh rule's");
    text += " ± " + RoundedNumber(*error, 2) + " (" +
            MeshRuleBasis(report.mesh_advice->bending_length) + ")";
  }
  return text + ", " + std::to_string(report.drape->folds.count) + " folds";
}

// How many drops `drape solve` runs: --drops, else drape_test.drops, else 1. --drops > 1 needs a
// drape_test block (the perturbations are the test's).
int DropsOf(const Arguments& arguments, const Scene& scene) {
  const int drops =
      arguments.drops ? *arguments.drops : (scene.drape_test ? scene.drape_test->drops : 1);
  if (drops > 1 && !scene.drape_test) {
    throw InputError(
        scene.root,
        "--drops " + std::to_string(drops) +
            " needs a drape test: give the scene a drape_test block (docs/reference.md, "
            "\"`drape_test`\")");
  }
  return drops;
}

int SolveDrops(const Arguments& arguments, const Scene& scene, const std::string& calibration,
               const std::string& directory, std::ostream& out, std::ostream& err) {
  DropsCommand command;
  command.drops = DropsOf(arguments, scene);
  command.threads = arguments.threads;
  command.directory = directory;
  command.overrides = arguments.overrides;
  command.calibration = calibration;
  EnableInterrupt();
  const DropsCommandResult outcome =
      RunDropsCommand(scene, command, CommandContext{err, arguments.command_line});
  if (!outcome.summary.coordinator) return kExitConverged;
  for (const std::string& line : outcome.lines) out << line << std::endl;
  if (outcome.interrupted) return kExitNotConverged;
  const DropStatistics& statistics = outcome.summary.statistics;
  return statistics.counted == statistics.drops ? kExitConverged : kExitNotConverged;
}

int Solve(const Arguments& arguments, std::ostream& out, std::ostream& err,
          const CommandOptions& options) {
  if (arguments.solver && !FindSolver(*arguments.solver)) {
    throw UsageError("--solver: " + UnknownSolverText(*arguments.solver));
  }
  Calibration calibration;
  Scene scene = LoadCalibratedScene(arguments, &calibration);
  if (arguments.solver) scene.solver.method = *arguments.solver;
  if (arguments.out) scene.output.directory = *arguments.out;
  RequireKnownSolver(scene);
  const std::string directory = OutputDirectory(scene);
  try {  // before the model is built and solved: an unwritable folder costs nothing
    CheckOutputWritable(directory, arguments.out ? Location{} : scene.output.directory_where,
                        arguments.out ? "--out" : "");
  } catch (const InputError&) {
    throw;  // the scene's output.directory names a file: located, as every bad key
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
    return kExitBadInput;
  }
  Model model = BuildModel(scene);
  if (const std::optional<MeshAdvice> advice = AdviseMesh(scene, model); advice && advice->coarse) {
    err << "drape: warning: " << CoarseMeshWarning(*advice) << "\n";
  }
  if (DropsOf(arguments, scene) > 1) {
    return SolveDrops(arguments, scene, CalibrationProvenance(calibration), directory, out, err);
  }
  // The folder's lock is held from before the solve to the end of the writing: a second run into
  // the same folder is refused here, before it solves, and nothing of either run is lost. A run
  // that fails before writing removes the folder if the lock created it.
  std::optional<ResultFolderLock> lock;
  try {
    lock.emplace(directory, /*remove_if_unused=*/true);
  } catch (const std::exception& error) {
    err << "drape: " << error.what() << "; nothing solved\n";
    return kExitBadInput;
  }

  const bool plain = !options.show_progress && options.plain_progress_interval_s > 0.0;
  ProgressLine progress(err, plain ? options.plain_progress_interval_s : 0.2, plain);
  std::function<bool(const IterationRecord&)> on_iteration;
  if (options.show_progress || plain) {
    on_iteration = [&progress](const IterationRecord& record) { return progress.Update(record); };
  }
  EnableInterrupt();
  const SolveReport report = SolveAndReport(scene, model, scene.solver.method, on_iteration);
  progress.Clear();

  try {
    WriteOutputs(scene, model, report, directory,
                 Provenance{arguments.command_line, arguments.overrides,
                            CalibrationProvenance(calibration)});
    lock->KeepFolder();
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
    return kExitBadInput;
  }
  const std::optional<AccuracyOutcome> accuracy = AccuracyOf(scene, report);
  out << ResultLine(report.result, directory)
      << (report.levels ? LevelsLine(*report.levels) : DrapeLine(report))
      << (accuracy && accuracy->binding ? AccuracyClause(*accuracy) : "") << std::endl;
  if (accuracy && accuracy->Failed(report.result.converged)) {
    err << "drape: " << AccuracyFailure(*accuracy, report.result.converged) << "\n";
    return kExitNotConverged;
  }
  return ExitStatus(report.result);
}

// drape check's line on the torsional rigidity: the value and where it came from.
std::string TwistLine(const FiniteVolumeSpec& fv) {
  std::string why;
  switch (fv.twist_source) {
    case FiniteVolumeSpec::TwistSource::kGiven:
      why = "given as D_66";
      break;
    case FiniteVolumeSpec::TwistSource::kBias:
      why = "from the bias bending rigidity, by the orthotropic plate's compliance at 45°";
      break;
    case FiniteVolumeSpec::TwistSource::kDefault:
      why =
          "the default √(D_warp·D_weft)/3, from bias bending measured on ten fabrics (Wang et "
          "al. 2011; 0.21-0.55 √(D_warp·D_weft) among them); a bias measurement, kes.B_bias or "
          "bending_length.bias, replaces it";
      break;
  }
  return "twist: D_66 " + RoundedNumber(fv.D_66, 6) + " N*m, " + why +
         " (docs/reference.md, \"Twist\")\n";
}

int Check(const Arguments& arguments, std::ostream& out) {
  Calibration calibration;
  const Scene scene = LoadCalibratedScene(arguments, &calibration);
  RequireKnownSolver(scene);
  const Model model = BuildModel(scene);
  if (arguments.json) {
    out << SceneJson(scene) << std::flush;
    return kExitConverged;
  }
  out << scene.name << ": " << model.num_nodes << " nodes, " << model.num_free_dofs()
      << " free dofs, " << TermSummary(model) << "; solver " << scene.solver.method << "\n";
  if (scene.drape_test) out << DrapeTestText(scene);
  const MaterialSpec& material = scene.material;
  std::string beside, twist;  // the springs beside the model's own terms; its twist's line
  switch (material.model) {
    case MaterialModel::kSprings:
      break;
    case MaterialModel::kFiniteVolume:
      if (material.springs.present) beside = " + springs";
      twist = TwistLine(material.finite_volume);
      break;
  }
  out << "material " << MaterialModelName(material.model) << beside
      << (material.lines.empty() ? ""
                                 : " + " + std::to_string(material.lines.size()) + " spring lines")
      << " (SI):";
  for (const MaterialValue& value : MaterialSiValues(scene.material)) {
    out << " " << value.key << " " << RoundedNumber(value.value, 6)
        << (value.unit == "1" ? "" : " " + value.unit) << ";";
  }
  out << "\n";
  if (!calibration.empty()) out << "calibration " << calibration.Provenance() << "\n";
  if (!material.finite_volume.measured.empty()) {
    out << "material as given:";
    for (const GivenMeasurement& value : material.finite_volume.measured) {
      out << " " << value.key << " " << RoundedNumber(value.value, 6)
          << (value.unit.empty() ? "" : " " + value.unit) << ";";
    }
    out << "\n";
  }
  out << twist;
  if (const std::optional<MeshAdvice> advice = AdviseMesh(scene, model); advice && advice->coarse) {
    out << "warning: " << CoarseMeshWarning(*advice) << "\n";
  }
  for (size_t r = 0; r < model.region_counts.size(); ++r) {
    const Model::RegionCount& count = model.region_counts[r];
    const std::string& name = scene.regions[r].name;
    out << "region " << r << (name.empty() ? "" : " '" + name + "'") << " (line "
        << scene.regions[r].where.line << "): " << count.selected << " nodes, " << count.last
        << " of them in no later region\n";
  }
  out << std::flush;
  return kExitConverged;
}

// `drape fit`: the fit file checked before any solve, a progress line per evaluation on `err`,
// the outputs written (src/commands/commands.h). Exit 0 converged, 1 not converged.
int Fit(const Arguments& arguments, std::ostream& out, std::ostream& err) {
  const FitCommand command{arguments.file, arguments.overrides, arguments.method, arguments.out,
                           arguments.threads};
  EnableInterrupt();
  FitCommandResult outcome;
  try {
    outcome = RunFitCommand(command, CommandContext{err, arguments.command_line});
  } catch (const CommandOptionError& error) {
    throw UsageError(error.what());
  } catch (const OutputFolderError& error) {
    err << "drape fit: cannot write the results: " << error.what() << "\n";
    AbortJobAfterError(kExitBadInput);  // under MPI: the other ranks would wait for this one
    return kExitBadInput;
  }
  const bool converged = outcome.result.converged;
  if (!outcome.written) {
    if (outcome.coordinator && !outcome.line.empty()) err << outcome.line << "\n";
    return converged ? kExitConverged : kExitNotConverged;
  }
  out << outcome.line << std::endl;
  return converged ? kExitConverged : kExitNotConverged;
}

// What the command line of `drape sweep` gives.
struct SweepArguments {
  std::string file;
  std::optional<std::string> out;
  std::optional<int> only;
  std::optional<std::string> task_id;  // --task-id: a number, or empty for $SLURM_ARRAY_TASK_ID
  int threads = 0;
  bool no_plots = false;
};

// The task --only or --task-id names (--task-id alone: $SLURM_ARRAY_TASK_ID); the command checks
// that it is one of its tasks.
std::optional<int> OnlyTask(std::optional<int> only, const std::optional<std::string>& task_id) {
  if (!task_id) return only;
  if (only) throw UsageError("give --only or --task-id, not both");
  std::string text = *task_id;
  if (text.empty()) {
    const char* slurm = std::getenv("SLURM_ARRAY_TASK_ID");
    if (!slurm) throw UsageError("--task-id without a value needs $SLURM_ARRAY_TASK_ID");
    text = slurm;
  }
  int value = -1;
  if (!CLI::detail::lexical_cast(text, value) || value < 0) {
    throw UsageError("--task-id: expected a task number >= 0, got '" + text + "'");
  }
  return value;
}

// A command of the layer (src/commands/commands.h) run for the command line: its option errors
// with the usage, an output folder or a task farm that fails as "drape NAME: …", exit 2.
template <typename Run>
int RunFarmedCommand(const std::string& name, std::ostream& err, const Run& run) {
  EnableInterrupt();
  try {
    return run();
  } catch (const CommandOptionError& error) {
    throw UsageError(error.what());
  } catch (const InputError&) {
    throw;
  } catch (const TaskFarmError& error) {
    err << "drape " << name << ": " << error.what() << "\n";
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
  }
  return kExitBadInput;
}

// `drape sweep`: every input checked before any solve; one progress line per finished task on
// `err`. Exit 0 when every task (or the --only task) converged, 1 otherwise.
int Sweep(const SweepArguments& arguments, const std::string& command_line, std::ostream& out,
          std::ostream& err) {
  SweepCommand command;
  command.file = arguments.file;
  command.only = OnlyTask(arguments.only, arguments.task_id);
  if (arguments.out) command.out = *arguments.out;
  command.threads = arguments.threads;
  command.plots = !arguments.no_plots;
  return RunFarmedCommand("sweep", err, [&] {
    const SweepCommandResult outcome = RunSweepCommand(command, CommandContext{err, command_line});
    if (!outcome.summary.coordinator) return kExitConverged;
    out << outcome.line << std::endl;
    return outcome.all_converged ? kExitConverged : kExitNotConverged;
  });
}

// What the command line of `drape fabrics` gives.
struct FabricsArguments {
  FabricsOptions options;
  std::optional<std::string> task_id;  // --task-id: a number, or empty for $SLURM_ARRAY_TASK_ID
};

// `drape fabrics`: the table and every fabric's scene checked before any solve; one progress line
// per finished fabric on `err`, the summary line on `out`. Exit 0 when every fabric has a
// prediction, 1 otherwise.
int Fabrics(FabricsArguments arguments, const std::string& command_line, std::ostream& out,
            std::ostream& err) {
  arguments.options.only = OnlyTask(arguments.options.only, arguments.task_id);
  return RunFarmedCommand("fabrics", err, [&] {
    const FabricsCommandResult outcome =
        RunFabricsCommand(arguments.options, CommandContext{err, command_line});
    if (!outcome.summary.coordinator) return kExitConverged;
    out << outcome.line << std::endl;
    return outcome.all_predicted ? kExitConverged : kExitNotConverged;
  });
}

// The catalogue (src/scene/solver_methods.h): each method, its default limits and every option
// with its default and range.
int ListSolvers(std::ostream& out) {
  for (const auto& method : SolverMethods()) {
    out << method.name << "\n    " << method.description << "\n    defaults: max_iterations "
        << method.max_iterations << ", time_limit " << method.time_limit << " s\n";
    if (method.records_trace) {
      out << "    writes its per-step trace to " << TraceFileName(method.name)
          << " (output.write: " << OutputKindOf(OutputKind::kHistory).name << " or "
          << OutputKindOf(OutputKind::kKinetic).name << ")\n";
    }
    if (method.options.empty()) continue;
    out << "    options (solver." << method.name << ".<key>):\n";
    for (const auto& option : method.options) {
      out << "      " << option.key << " = " << DescribeDefault(option) << ", "
          << DescribeRange(option) << ": " << option.doc << "\n";
    }
  }
  return kExitConverged;
}

void AddSetOption(CLI::App* command, std::vector<std::string>* overrides) {
  command->add_option("--set", *overrides, kSetHelp)
      ->allow_extra_args(false)
      ->type_name("key.path=value ...");
}

// The options shared by the commands that load a scene: the file (after `--` if it starts with a
// dash) and the repeatable --set.
// `file_name` names the file in the synopsis ("SCENE.yaml").
void AddSceneArguments(CLI::App* command, Arguments* arguments, const std::string& what,
                       const std::string& file_name = "SCENE.yaml") {
  command->add_option("file", arguments->file, what)->required()->type_name(file_name);
  AddSetOption(command, &arguments->overrides);
}

// --calibration FILE: a calibration `drape fabrics --calibrate` wrote.
template <typename Target>
void AddCalibrationOption(CLI::App* command, Target* file) {
  command
      ->add_option("--calibration", *file,
                   "apply this calibration of the fabric's inputs (calibration.yaml, written by "
                   "drape fabrics --calibrate)")
      ->type_name("FILE");
}

// --calibrate's help, naming the constants of CalibrationConstants().
std::string CalibrateHelp() {
  std::string names;
  for (const CalibrationConstant& c : CalibrationConstants()) {
    names += (names.empty() ? "" : ", ") + c.name;
  }
  return "fit these calibration constants, comma-separated or repeated (one or two of: " + names +
         "), to the table's measured drape coefficients; writes calibration.yaml";
}

// A finite number > 0 ("inf", "nan", "5s" and "0" are refused).
const CLI::Validator kFinitePositive(
    [](const std::string& text) {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !(value > 0.0)) {
        return "expected a finite number of seconds > 0, got '" + text + "'";
      }
      return std::string();
    },
    "S>0", "finite positive");

// The whole text as an integer >= 1 ("2x", "1.5" and "0" are refused).
const CLI::Validator kWholeNumber(
    [](const std::string& text) {
      int value = 0;
      if (!CLI::detail::lexical_cast(text, value) || value < 1) {
        return "expected a whole number >= 1, got '" + text + "'";
      }
      return std::string();
    },
    "N>=1", "whole number");

// The whole text as an integer >= 0 (a thread count; 0: the machine's cores).
const CLI::Validator kThreadCount(
    [](const std::string& text) {
      int value = 0;
      if (!CLI::detail::lexical_cast(text, value) || value < 0) {
        return "expected a whole number >= 0 (0: the machine's cores), got '" + text + "'";
      }
      return std::string();
    },
    "N>=0", "thread count");

// The command as a shell would take it back: "drape solve 'my scene.yaml' --set a=1".
std::string CommandLine(const std::vector<std::string>& args) {
  std::string line = "drape";
  for (const std::string& arg : args) {
    const bool plain =
        !arg.empty() && arg.find_first_not_of(
                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJ"
                            "KLMNOPQRSTUVWXYZ0123456789_-.,/=:+@%") == std::string::npos;
    if (plain) {
      line += " " + arg;
      continue;
    }
    line += " " + ShellQuoted(arg);
  }
  return line;
}

// The usage lines after a usage error: the failing command's synopsis only, where `args` name
// one; else every command's.
std::string UsageText(const CLI::App& app, const std::vector<std::string>& args) {
  if (const CLI::App* command = NamedCommand(app, args)) {
    return "usage: " + CommandSynopsis(*command) + "\n(`drape help " + command->get_name() +
           "` for its options)\n";
  }
  std::string text = Synopsis(app);
  for (size_t at = text.find('\n'); at + 1 < text.size(); at = text.find('\n', at + 1)) {
    text.insert(at + 1, "       ");
  }
  return "usage: " + text;
}

// `drape help [COMMAND]`: the command's help, or drape's.
int PrintHelp(const CLI::App& app, const std::string& name, std::ostream& out) {
  if (name.empty()) {  // app.help() would describe the selected subcommand, `help` itself
    out << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
    return kExitConverged;
  }
  const CLI::App* command = NamedCommand(app, {name});
  if (!command) throw UsageError("help: " + UnknownCommandText(app, name));
  out << command->help();
  return kExitConverged;
}

// What a command's run is given: the parser (help, completion), the whole command line
// (summary.json's command_line), the streams and the caller's options.
struct Invocation {
  const CLI::App& app;
  const std::string& command_line;
  std::ostream& out;
  std::ostream& err;
  const CommandOptions& options;
};

// Runs a command once its options are parsed; returns the exit status.
using CommandRun = std::function<int(const Invocation&)>;

// `drape solve`.
CommandRun DefineSolve(CLI::App* solve) {
  auto arguments = std::make_shared<Arguments>();
  AddSceneArguments(solve, arguments.get(), "scene file (YAML)");
  solve
      ->add_option("--solver", arguments->solver,
                   "use this method instead of the scene's solver.method (see `drape solvers`)")
      ->type_name("NAME");
  solve
      ->add_option("-o,--out", arguments->out,
                   "write into this folder instead of output.directory (default: "
                   "output.directory, else out/<scene name>)")
      ->type_name("DIR");
  solve
      ->add_option("--drops", arguments->drops,
                   "solve N drops of the scene's drape test, seeded perturbations of the "
                   "specimen's placement and waviness (default: drape_test.drops)")
      ->check(CLI::Range(1, kMostDrops))
      ->type_name("N");
  solve
      ->add_option("--threads", arguments->threads,
                   std::string("with --drops, the drops' ") + kLocalThreadsHelp)
      ->check(kThreadCount)
      ->capture_default_str()
      ->type_name("N");
  AddCalibrationOption(solve, &arguments->calibration);
  solve->footer(kExitStatus);
  return [arguments](const Invocation& call) {
    arguments->command_line = call.command_line;
    return Solve(*arguments, call.out, call.err, call.options);
  };
}

// `drape check`.
CommandRun DefineCheck(CLI::App* check) {
  auto arguments = std::make_shared<Arguments>();
  AddSceneArguments(check, arguments.get(), "scene file (YAML)");
  check->add_flag("--json", arguments->json,
                  "print the scene as solved (defaults filled in, SI) as JSON, each value "
                  "{\"value\": ..., \"unit\": ...}, instead of the summary");
  AddCalibrationOption(check, &arguments->calibration);
  return [arguments](const Invocation& call) { return Check(*arguments, call.out); };
}

// `drape solvers`.
CommandRun DefineSolvers(CLI::App*) {
  return [](const Invocation& call) { return ListSolvers(call.out); };
}

// `drape schema`: the scene schema's rows, or a JSON Schema of a scene file.
CommandRun DefineSchema(CLI::App* schema) {
  auto json_schema = std::make_shared<bool>(false);
  CLI::Option* rows = schema->add_flag("--json", "print the rows as JSON (the default)");
  schema
      ->add_flag("--json-schema", *json_schema,
                 "print a JSON Schema (draft 2020-12) of a scene file instead, for an editor's "
                 "completion and checking")
      ->excludes(rows);
  return [json_schema](const Invocation& call) {
    call.out << (*json_schema ? SceneJsonSchema() : SceneSchemaRowsJson());
    return kExitConverged;
  };
}

// `drape compare`.
CommandRun DefineCompare(CLI::App* compare) {
  struct CompareArguments {
    CompareOptions options;
    bool no_plots = false;
  };
  auto arguments = std::make_shared<CompareArguments>();
  CompareOptions& options = arguments->options;
  compare->add_option("scenes", options.scenes, "scene files (YAML)")
      ->required()
      ->type_name("SCENE.yaml...");
  compare
      ->add_option("--solvers", options.solvers,
                   "all, or a comma-separated list of methods (default: all)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->type_name("all|a,b,...");
  compare->add_option("-o,--out", options.out_dir, "report folder")
      ->capture_default_str()
      ->type_name("DIR");
  compare->add_option("--repeat", options.repeat, "timed repeats of each run (median)")
      ->check(kWholeNumber)
      ->capture_default_str()
      ->type_name("N");
  compare->add_option("--time-limit", options.time_limit, "seconds per run")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->type_name("S");
  AddSetOption(compare, &options.overrides);
  compare->add_flag("--no-plots", arguments->no_plots, "write the report without running gnuplot");
  return [arguments](const Invocation& call) {
    arguments->options.plots = !arguments->no_plots;
    arguments->options.command_line = call.command_line;
    return RunCompare(arguments->options, call.err, &call.out);
  };
}

// `drape fit`.
CommandRun DefineFit(CLI::App* fit) {
  auto arguments = std::make_shared<Arguments>();
  AddSceneArguments(fit, arguments.get(), "fit file (YAML)", "FIT.yaml");
  fit->add_option("-o,--out", arguments->out,
                  "write into this folder (default: the fit file's output.directory, else "
                  "out/<fit file name>)")
      ->type_name("DIR");
  fit->add_option("--method", arguments->method,
                  "outer method instead of the fit file's (" + FitMethodList() + ")")
      ->type_name("NAME");
  fit->add_option("--threads", arguments->threads, kLocalThreadsHelp)
      ->check(kThreadCount)
      ->capture_default_str()
      ->type_name("N");
  fit->get_option("--set")->description(
      "override a key of every scene the fit solves (repeatable; value is YAML; the fitted "
      "parameters win)");
  return [arguments](const Invocation& call) {
    arguments->command_line = call.command_line;
    return Fit(*arguments, call.out, call.err);
  };
}

// `drape sweep`.
CommandRun DefineSweep(CLI::App* sweep) {
  auto arguments = std::make_shared<SweepArguments>();
  sweep->add_option("file", arguments->file, "sweep file (YAML)")
      ->required()
      ->type_name("SWEEP.yaml");
  sweep
      ->add_option("-o,--out", arguments->out,
                   "write into this folder (default: the sweep file's output.directory, else "
                   "out/<sweep file name>)")
      ->type_name("DIR");
  sweep->add_option("--only", arguments->only, "run only this task (0-based)")->type_name("I");
  sweep
      ->add_option("--task-id", arguments->task_id,
                   "run only this task; without a value, $SLURM_ARRAY_TASK_ID (a Slurm job array)")
      ->expected(0, 1)
      ->type_name("I");
  sweep->add_option("--threads", arguments->threads, kLocalThreadsHelp)
      ->check(kThreadCount)
      ->capture_default_str()
      ->type_name("N");
  sweep->add_flag("--no-plots", arguments->no_plots, "write sweep.csv without sweep.html");
  return [arguments](const Invocation& call) {
    return Sweep(*arguments, call.command_line, call.out, call.err);
  };
}

// `drape fabrics`.
CommandRun DefineFabrics(CLI::App* fabrics) {
  auto arguments = std::make_shared<FabricsArguments>();
  FabricsOptions& options = arguments->options;
  fabrics->add_option("table", options.table, "the fabric table (CSV)")
      ->required()
      ->type_name("FABRICS.csv");
  fabrics
      ->add_option("--scene", options.scene,
                   "the base scene, a drape test whose material each row replaces (default: the "
                   "standard tester, 30 cm on the 18 cm disc, 5 mm lattice)")
      ->type_name("BASE.yaml");
  AddSetOption(fabrics, &options.overrides);
  fabrics->get_option("--set")->description(
      "override a key of every fabric's scene, after its material (repeatable; value is YAML)");
  fabrics
      ->add_option("--drops", options.drops,
                   "solve N drops of each fabric and predict their mean (default: the base "
                   "scene's drape_test.drops)")
      ->check(CLI::Range(1, kMostDrops))
      ->type_name("N");
  fabrics->add_option("--threads", options.threads, kLocalThreadsHelp)
      ->check(kThreadCount)
      ->capture_default_str()
      ->type_name("N");
  fabrics->add_option("-o,--out", options.out, "write into this folder (default: out/<table name>)")
      ->type_name("DIR");
  AddCalibrationOption(fabrics, &options.calibration_file);
  fabrics->add_option("--calibrate", options.calibrate, CalibrateHelp())
      ->allow_extra_args(false)
      ->delimiter(',')
      ->type_name("KEY[,KEY]");
  fabrics
      ->add_option("--only", options.only,
                   "run only this task (0-based: fabric × drops + drop − 1)")
      ->type_name("I");
  fabrics
      ->add_option("--task-id", arguments->task_id,
                   "run only this task; without a value, $SLURM_ARRAY_TASK_ID (a Slurm job array)")
      ->expected(0, 1)
      ->type_name("I");
  return [arguments](const Invocation& call) {
    return Fabrics(*arguments, call.command_line, call.out, call.err);
  };
}

// `drape help [COMMAND]`.
CommandRun DefineHelp(CLI::App* help) {
  auto topic = std::make_shared<std::string>();
  help->add_option("command", *topic, "the command")->type_name("COMMAND");
  return [topic](const Invocation& call) { return PrintHelp(call.app, *topic, call.out); };
}

// `drape completion SHELL`.
CommandRun DefineCompletion(CLI::App* completion) {
  auto shell = std::make_shared<std::string>();
  completion->add_option("shell", *shell, "the shell (bash)")
      ->required()
      ->check(CLI::IsMember({"bash"}))
      ->type_name("bash");
  return [shell](const Invocation& call) {  // bash, the one shell CLI11 lets through
    call.out << BashCompletion(call.app);
    return kExitConverged;
  };
}

// One subcommand: its name, its one-line help (`drape --help`, the man page), and what adds its
// options to the parser and returns its run.
struct CommandRow {
  const char* name;
  const char* help;
  CommandRun (*define)(CLI::App* command);
};

// Every subcommand, in the order `drape --help`, the usage and the completion script list them.
const CommandRow kCommands[] = {
    {"solve", "load the scene, solve it, write the results into output.directory", DefineSolve},
    {"check",
     "load and build the scene, print what it contains (and the SI material values derived from "
     "KES, FAST or Peirce inputs, and those inputs as given); write nothing",
     DefineCheck},
    {"solvers", "list the methods and their options (solver.<method>.<key>) with defaults",
     DefineSolvers},
    {"schema",
     "print the scene schema: its rows as JSON (--json), or a JSON Schema of a scene file "
     "(--json-schema) for an editor's completion and checking",
     DefineSchema},
    {"compare", "solver comparison report (speed against error) for one or more scenes",
     DefineCompare},
    {"fit",
     "fit scene parameters (stiffnesses) to measurements; writes fit.json, history.csv, "
     "sensitivity.csv, fit.png, report.md",
     DefineFit},
    {"sweep",
     "solve a base scene over a grid, zip or sample of its keys (one task per variant, each in "
     "OUT/tasks/NNNN); writes sweep.csv, sweep.html; reruns skip the finished tasks",
     DefineSweep},
    {"fabrics",
     "predict the drape coefficient of every fabric in a table (KES, FAST, Peirce or SI "
     "columns) and set it beside the measured one; writes fabrics.csv, fabrics.json, "
     "report.html; reruns solve only what is missing",
     DefineFabrics},
    {"help", "print this help, or a command's", DefineHelp},
    {"completion",
     "print the shell completion script (bash: source it, or install it as "
     "share/bash-completion/completions/drape)",
     DefineCompletion},
};

int Dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const CommandOptions& options) {
  CLI::App app(kDescription, "drape");
  app.set_version_flag("--version", DrapeVersion(), "print drape's version and exit");
  app.require_subcommand(1);
  app.get_formatter()->column_width(34);
  std::vector<std::pair<CLI::App*, CommandRun>> commands;
  for (const CommandRow& row : kCommands) {
    CLI::App* command = app.add_subcommand(row.name, row.help);
    commands.emplace_back(command, row.define(command));
  }
  app.footer("\n" + UsageText(app, {}) + kExitStatus);

  try {
    if (const auto unknown = UnknownWord(app, args)) throw UsageError(*unknown);
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses from the back
    try {
      app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
      out << app.help();
      return kExitConverged;
    } catch (const CLI::CallForAllHelp&) {
      out << app.help("", CLI::AppFormatMode::All);
      return kExitConverged;
    } catch (const CLI::CallForVersion&) {
      out << "drape " << DrapeVersion() << "\n";
      return kExitConverged;
    } catch (const CLI::ParseError& error) {
      throw UsageError(error.what());
    }
    const std::string command_line = CommandLine(args);
    for (const auto& [command, run] : commands) {
      if (command->parsed()) return run(Invocation{app, command_line, out, err, options});
    }
    throw UsageError("a command is required");  // require_subcommand(1) has refused this already
  } catch (const UsageError& error) {
    throw UsageError(std::string(error.what()) + "\n" + UsageText(app, args));
  }
}

}  // namespace

std::vector<CommandHelp> CommandList() {
  std::vector<CommandHelp> list;
  for (const CommandRow& row : kCommands) list.push_back({row.name, row.help});
  return list;
}

int RunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               const CommandOptions& options) {
  RunLibrariesOnOneThread();
  try {
    return Dispatch(args, out, err, options);
  } catch (const UsageError& error) {
    err << "drape: " << error.what();
  } catch (const InputError& error) {
    err << error.what() << "\n";
  } catch (const std::bad_alloc&) {
    err << "drape: out of memory (the scene's mesh or method needs more memory than this machine "
           "gives; a coarser mesh, or mesh.max_nodes, bounds it); nothing written\n";
  } catch (const std::exception& error) {
    err << "drape: error: " << error.what() << "\n";
  }
  err << std::flush;
  AbortJobAfterError(kExitBadInput);  // under MPI: the other ranks may wait for this one
  return kExitBadInput;
}

std::string UnknownSolverText(const std::string& name) {
  std::vector<std::string> names;
  std::string list;
  for (const auto& info : AllSolvers()) {
    names.push_back(info.name);
    list += (list.empty() ? "" : ", ") + info.name;
  }
  return "unknown solver '" + name + "' (known: " + list + ")" + SuggestionText(name, names);
}

void RequireKnownSolver(const Scene& scene) {
  if (!FindSolver(scene.solver.method)) {
    throw InputError(scene.solver.where, UnknownSolverText(scene.solver.method));
  }
}

}  // namespace drape
