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

#include "src/cli/progress.h"
#include "src/compare/compare.h"
#include "src/fit/fit_file.h"
#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"
#include "src/fit/fit_writer.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
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
    "           measurements; writes fit.json, history.csv, sensitivity.csv, fit.png, report.md\n"
    "           (methods: bobyqa, nelder-mead, sbplx, cobyla, implicit-lbfgs, implicit-lm)\n"
    "\n"
    "exit status: 0 converged; 1 ran but did not reach the tolerance (results written,\n"
    "converged: false); 2 bad input or usage (nothing written).\n";

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
    if (arg.rfind("-", 0) != 0 || arg == "-") {
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
    if (flag == "--solver") parsed.solver = value;
    if (flag == "--out") parsed.out = value;
    if (flag == "--set") parsed.overrides.push_back(value);
    if (flag == "--method") parsed.method = value;
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

// Lets a Ctrl-C reach the solver's handler even if the parent process had blocked SIGINT (a
// blocked signal stays pending until here, so none sent before the solve is lost).
void EnableInterrupt() {
  InstallInterruptHandler();
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  pthread_sigmask(SIG_UNBLOCK, &interrupt, nullptr);
}

std::string ResultLine(const RunResult& result, const std::string& directory) {
  const SolverSummary& summary = result.summary;
  char text[160];
  std::snprintf(text, sizeof text,
                "%s: converged %s, %d iterations, %.3g s, relative residual %.3g",
                summary.solver.c_str(), result.converged ? "yes" : "no", summary.iterations,
                summary.wall_time_s, result.certificate.relative_residual);
  return std::string(text) + " (" + summary.termination + "); results in " + directory;
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
  Model model = BuildModel(scene);

  ProgressLine progress(err);
  std::function<bool(const IterationRecord&)> on_iteration;
  if (options.show_progress) {
    on_iteration = [&progress](const IterationRecord& record) { return progress.Update(record); };
  }
  EnableInterrupt();
  const RunResult result = RunSolve(scene, model, scene.solver.method, on_iteration);
  progress.Clear();

  const std::string directory = OutputDirectory(scene);
  try {
    WriteOutputs(scene, model, result, directory);
  } catch (const std::exception& error) {
    err << "drape: cannot write the results: " << error.what() << "\n";
    return kExitBadInput;
  }
  out << ResultLine(result, directory) << std::endl;
  return result.converged ? kExitConverged : kExitNotConverged;
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
    const auto& methods = FitMethods();
    if (std::find(methods.begin(), methods.end(), *arguments.method) == methods.end()) {
      throw UsageError(
          "unknown fit method '" + *arguments.method +
          "' (known: bobyqa, nelder-mead, sbplx, cobyla, implicit-lbfgs, implicit-lm)");
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
    out << kUsage << "\n" << kHelp;
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
