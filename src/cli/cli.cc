#include "src/cli/cli.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <functional>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>

#include "src/analysis/levels.h"
#include "src/cli/progress.h"
#include "src/compare/compare.h"
#include "src/fit/fit_file.h"
#include "src/fit/fit_methods.h"
#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"
#include "src/fit/fit_writer.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/output/result_folder.h"
#include "src/output/writers.h"
#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/run.h"
#include "src/solvers/solver.h"

namespace drape {

namespace {

constexpr char kUsage[] =
    "usage: drape solve SCENE.yaml [--solver NAME] [--out DIR] [--set key.path=value ...]\n"
    "       drape check SCENE.yaml [--set key.path=value ...]\n"
    "       drape solvers\n"
    "       drape compare SCENE.yaml... [--solvers all|a,b,...] [--out DIR] [--repeat N]\n"
    "                     [--time-limit S] [--set key.path=value ...] [--no-plots]\n"
    "       drape fit FIT.yaml [--out DIR] [--method NAME]\n"
    "       drape help\n";

constexpr char kHelp[] =
    "drape finds the equilibrium shape of fabric by minimising its total potential energy.\n"
    "\n"
    "  solve    load the scene, solve it, write the results into output.directory\n"
    "           --solver NAME        use this method instead of solver.method\n"
    "           --out DIR            write into DIR instead of output.directory\n"
    "           --set key.path=value override a scene key (repeatable; value is YAML)\n"
    "  check    load and build the scene, print what it contains, write nothing\n"
    "  solvers  list the methods and their options (solver.<method>.<key>)\n"
    "  compare  SCENE.yaml... [--solvers all|a,b] [--out DIR] [--repeat N] [--time-limit S]\n"
    "           [--set k=v] [--no-plots]: solver comparison report (speed against error)\n"
    "  fit      FIT.yaml [--out DIR] [--method NAME]: fit scene parameters (stiffnesses) to\n"
    "           measurements; writes fit.json, history.csv, sensitivity.csv, fit.png, report.md\n";

constexpr char kExitStatus[] =
    "\n"
    "exit status: 0 converged to a stable minimum; 1 ran but did not reach the tolerance\n"
    "(results written, converged: false; also after SIGINT or SIGTERM, which save the last\n"
    "iterate); 2 bad input, bad usage or an unwritable output folder (nothing written);\n"
    "3 converged to a saddle, not a minimum (results written, saddle: true).\n";

// Bad usage of the command itself (not of the scene): the message and the usage lines.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Arguments {
  std::string scene;
  std::optional<std::string> solver;
  std::optional<std::string> out;
  std::optional<std::string> method;  // fit
  std::vector<std::string> overrides;
  bool help = false;
};

void AssignFlag(const std::string& flag, const std::string& value, Arguments* parsed) {
  if (flag == "--solver") parsed->solver = value;
  if (flag == "--out") parsed->out = value;
  if (flag == "--set") parsed->overrides.push_back(value);
  if (flag == "--method") parsed->method = value;
}

// Parses `args` after the subcommand. `flags`: the options this subcommand accepts, each taking a
// value, given as `--flag value` or `--flag=value`.
Arguments ParseArguments(const std::vector<std::string>& args, const std::set<std::string>& flags) {
  Arguments parsed;
  std::vector<std::string> positional;
  for (size_t k = 1; k < args.size(); ++k) {
    const std::string& arg = args[k];
    if (arg == "--help" || arg == "-h") {
      parsed.help = true;
      continue;
    }
    if (arg.rfind('-', 0) != 0 || arg == "-") {
      positional.push_back(arg);
      continue;
    }
    const size_t equals = arg.find('=');
    const std::string flag = arg.substr(0, equals);
    if (!flags.count(flag)) throw UsageError("unknown option '" + flag + "' for " + args[0]);
    std::string value;
    if (equals != std::string::npos) {
      value = arg.substr(equals + 1);
    } else if (k + 1 < args.size()) {
      value = args[++k];
    } else {
      throw UsageError("option " + flag + " needs a value");
    }
    AssignFlag(flag, value, &parsed);
  }
  if (parsed.help) return parsed;
  if (positional.empty()) {
    throw UsageError(args[0] + (args[0] == "fit" ? " needs a fit file" : " needs a scene file"));
  }
  if (positional.size() > 1) throw UsageError("unexpected argument '" + positional[1] + "'");
  parsed.scene = positional[0];
  return parsed;
}

std::string SolverNames() {
  std::string names;
  for (const auto& info : AllSolvers()) names += (names.empty() ? "" : ", ") + info.name;
  return names;
}

// The scene's method must exist before anything is built (a typo should not cost a model build).
void RequireKnownSolver(const Scene& scene) {
  if (!FindSolver(scene.solver.method)) {
    throw InputError(scene.solver.where,
                     "unknown solver '" + scene.solver.method + "' (known: " + SolverNames() + ")");
  }
}

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
  return scene.output.directory.empty() ? "out/" + scene.name : scene.output.directory;
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

// What the certificate says of the state: a stable minimum, a saddle (with the most negative
// eigenvalue of the free Hessian), or why it cannot be certified.
std::string StabilityText(const RunResult& result) {
  if (!result.certificate.unsound.empty()) return "not certified: " + result.certificate.unsound;
  const Stability& stability = result.stability;
  if (!stability.computed) return "stability not computed";
  if (stability.stable) return "stable minimum";
  char text[120];
  std::snprintf(text, sizeof text, "saddle: most negative eigenvalue %.3g N/m",
                stability.min_eigenvalue);
  return text;
}

std::string ResultLine(const RunResult& result, const std::string& directory) {
  const SolverSummary& summary = result.summary;
  char text[200];
  std::snprintf(text, sizeof text,
                "%s: converged %s, %d iterations, %.3g s, relative residual %.3g, ",
                summary.solver.c_str(), result.converged ? "yes" : "no", summary.iterations,
                summary.wall_time_s, result.certificate.relative_residual);
  return std::string(text) + StabilityText(result) + " (" + summary.termination + "); results in " +
         directory;
}

// 0 converged to a stable minimum (or stability not computed), 3 converged to a saddle, 1 not
// converged.
int ExitStatus(const RunResult& result) {
  if (!result.converged) return kExitNotConverged;
  return result.Saddle() ? kExitSaddle : kExitConverged;
}

// The stdout summary of a `solver.levels` run: the extrapolated drape coefficient (else energy)
// with its error estimate and observed order, or why there is none.
std::string LevelsLine(const LevelsReport& report) {
  const Extrapolation& e = report.extrapolations.front();
  char text[200];
  if (e.available) {
    std::snprintf(
        text, sizeof text, "; %zu levels: extrapolated %s %.6g ± %.2g (observed order %.2f)",
        report.levels.size(), e.quantity.c_str(), e.value, e.error_estimate, e.observed_order);
    return text;
  }
  std::snprintf(text, sizeof text, "; %zu levels: no extrapolated %s (", report.levels.size(),
                e.quantity.c_str());
  return text + e.reason + ")";
}

int Solve(const Arguments& arguments, std::ostream& out, std::ostream& err,
          const CommandOptions& options) {
  if (arguments.solver && !FindSolver(*arguments.solver)) {
    err << "drape: unknown solver '" << *arguments.solver << "' (known: " << SolverNames() << ")\n";
    return kExitBadInput;
  }
  Scene scene = LoadScene(arguments.scene, arguments.overrides);
  if (arguments.solver) scene.solver.method = *arguments.solver;
  if (arguments.out) scene.output.directory = *arguments.out;
  RequireKnownSolver(scene);
  const std::string directory = OutputDirectory(scene);
  try {  // before the model is built and solved: an unwritable folder costs nothing
    CheckOutputWritable(directory);
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
    return kExitBadInput;
  }
  Model model = BuildModel(scene);
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
    WriteOutputs(scene, model, report, directory);
    lock->KeepFolder();
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
    return kExitBadInput;
  }
  out << ResultLine(report.result, directory) << (report.levels ? LevelsLine(*report.levels) : "")
      << std::endl;
  return ExitStatus(report.result);
}

int Check(const Arguments& arguments, std::ostream& out) {
  const Scene scene = LoadScene(arguments.scene, arguments.overrides);
  RequireKnownSolver(scene);
  const Model model = BuildModel(scene);
  out << scene.name << ": " << model.num_nodes << " nodes, " << model.num_free_dofs()
      << " free dofs, " << TermSummary(model) << "; solver " << scene.solver.method << std::endl;
  return kExitConverged;
}

// `drape fit`: load the fit file (every input checked before any solve), run the outer loop with
// a progress line per evaluation on `err`, write the outputs. Exit 0 converged, 1 not converged.
int Fit(const Arguments& arguments, std::ostream& out, std::ostream& err) {
  FitSpec spec = LoadFitFile(arguments.scene);
  if (arguments.method) {
    if (!FindFitMethod(*arguments.method)) {
      throw UsageError("unknown fit method '" + *arguments.method + "' (known: " + FitMethodList() +
                       ")");
    }
    spec.method = *arguments.method;
  }
  if (arguments.out) spec.output_directory = *arguments.out;
  FitProblem problem(spec);
  FitOptions options;
  options.on_evaluation = [&](const FitIterationRecord& record) {
    char text[120];
    std::snprintf(text, sizeof text, "fit %s: evaluation %d, %.2f s, objective %.6g (best %.6g)",
                  spec.method.c_str(), record.evaluation, record.time_s, record.objective,
                  record.best_objective);
    err << text;
    for (size_t j = 0; j < record.parameters.size(); ++j) {
      std::snprintf(text, sizeof text, ", %s=%.8g", spec.parameters[j].key.c_str(),
                    record.parameters[j]);
      err << text;
    }
    err << (record.inner_converged ? "" : " (an equilibrium did not converge)") << "\n";
  };
  EnableInterrupt();
  const FitResult result = RunFit(problem, options);
  if (result.parameters.empty()) {
    err << "drape fit: " << result.termination << "; nothing written\n";
    return kExitNotConverged;
  }
  try {
    WriteFitOutputs(problem, result, spec.output_directory);
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
    return kExitBadInput;
  }
  out << "fit " << spec.method << ": converged " << (result.converged ? "yes" : "no") << ", "
      << result.evaluations << " evaluations, objective " << result.objective << " ("
      << result.termination << "); results in " << spec.output_directory << std::endl;
  return result.converged ? kExitConverged : kExitNotConverged;
}

// The catalogue (src/scene/solver_methods.h): each method, its default limits and every option
// with its default and range.
int ListSolvers(std::ostream& out) {
  for (const auto& method : SolverMethods()) {
    out << method.name << "\n    " << method.description << "\n    defaults: max_iterations "
        << method.max_iterations << ", time_limit " << method.time_limit << " s\n";
    if (method.options.empty()) continue;
    out << "    options (solver." << method.name << ".<key>):\n";
    for (const auto& option : method.options) {
      out << "      " << option.key << " = " << DescribeDefault(option) << ", "
          << DescribeRange(option) << ": " << option.doc << "\n";
    }
  }
  return kExitConverged;
}

int Dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const CommandOptions& options) {
  if (args.empty()) throw UsageError("no command given");
  const std::string& command = args[0];
  if (command == "help" || command == "--help" || command == "-h") {
    out << kUsage << "\n"
        << kHelp << "           (methods: " << FitMethodList() << ")\n"
        << kExitStatus;
    return kExitConverged;
  }
  if (command == "solvers") {
    if (args.size() > 1) throw UsageError("solvers takes no arguments");
    return ListSolvers(out);
  }
  if (command == "compare") {
    try {
      return RunCompare(ParseCompareArguments({args.begin() + 1, args.end()}), err);
    } catch (const std::invalid_argument& error) {
      throw UsageError(error.what());
    }
  }
  const std::map<std::string, std::set<std::string>> flags = {
      {"solve", {"--solver", "--out", "--set"}},
      {"check", {"--set"}},
      {"fit", {"--out", "--method"}}};
  const auto accepted = flags.find(command);
  if (accepted == flags.end()) throw UsageError("unknown command '" + command + "'");
  const Arguments arguments = ParseArguments(args, accepted->second);
  if (arguments.help) {
    out << kUsage;
    return kExitConverged;
  }
  if (command == "fit") return Fit(arguments, out, err);
  return command == "solve" ? Solve(arguments, out, err, options) : Check(arguments, out);
}

}  // namespace

int RunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               const CommandOptions& options) {
  RunLibrariesOnOneThread();
  try {
    return Dispatch(args, out, err, options);
  } catch (const UsageError& error) {
    err << "drape: " << error.what() << "\n" << kUsage;
  } catch (const InputError& error) {
    err << error.what() << "\n";
  } catch (const std::bad_alloc&) {
    err << "drape: out of memory (the scene's mesh or method needs more memory than this machine "
           "gives; a coarser mesh, or mesh.max_nodes, bounds it); nothing written\n";
  } catch (const std::exception& error) {
    err << "drape: error: " << error.what() << "\n";
  }
  return kExitBadInput;
}

}  // namespace drape
