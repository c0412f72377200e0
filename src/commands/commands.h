// The commands that run many solves — fit, repeated drops, sweep, a table of fabrics — as one
// layer that both faces call: the command line (src/cli/cli.cc) and the Python module
// (python/drape_module.cc). Each takes its inputs as data and a CommandContext (where progress and
// warnings go, one line each, and the command line for the files' provenance); it checks what it
// is given before any solve, checks the output folder, runs, writes its files and returns what it
// did with the line the command line prints. What stays with each face: parsing its arguments,
// its signals (the CLI's handler, Python's restored afterwards), its exit status or exception.
#ifndef DRAPE_SRC_COMMANDS_COMMANDS_H_
#define DRAPE_SRC_COMMANDS_COMMANDS_H_

#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/fit/fit_solver.h"
#include "src/run/solve_report.h"
#include "src/scene/scene.h"
#include "src/sweep/calibrate.h"
#include "src/sweep/drops.h"
#include "src/sweep/fabrics.h"
#include "src/sweep/sweep.h"

namespace drape {

struct CommandContext {
  std::ostream& log;         // progress lines, and warnings ("drape fit: warning: …")
  std::string command_line;  // for summary.json, fit.json, … (`drape fit x.yaml`, `python: …`)
};

// An option that is not one the command knows (a fit method): the CLI says it with its usage,
// Python as an InputError.
class CommandOptionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The output folder cannot be written: found before any solve, nothing written.
class OutputFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Worker threads as --threads takes them: a whole number ≥ 0 (0: the machine's cores). Throws
// CommandOptionError otherwise.
void RequireThreadCount(int threads);

// ---- drape fit ----------------------------------------------------------------------------------
struct FitCommand {
  std::string file;                    // the fit file
  std::vector<std::string> overrides;  // --set on every scene the fit solves
  std::optional<std::string> method;   // instead of the fit file's
  std::optional<std::string> out;      // instead of the fit file's output.directory
  int threads = 1;
};
struct FitCommandResult {
  FitResult result;
  std::string directory;
  bool written = false;      // the outputs were written (the coordinator, with parameters)
  bool coordinator = true;   // false on MPI ranks that only worked
  bool interrupted = false;  // stopped by a signal: the best point so far
  std::string line;          // "fit bobyqa: converged yes, 31 evaluations, …; results in …"
};
FitCommandResult RunFitCommand(const FitCommand& command, const CommandContext& context);

// ---- repeated drops -----------------------------------------------------------------------------
struct DropsCommand {
  int drops = 0;  // ≥ 1; 0: the scene's drape_test.drops
  int threads = 0;
  std::string directory;
  std::vector<std::string> overrides;  // the scene's, for the provenance
  std::string calibration;             // the calibration applied to the scene, for the provenance
};
struct DropsCommandResult {
  DropsSummary summary;
  bool interrupted = false;
  std::vector<std::string> lines;  // the statistics line, and the specimen-size advice if any
};
// Throws InputError when the scene has no drape test (for more than one drop) or `drops` is out of
// range.
DropsCommandResult RunDropsCommand(const Scene& scene, const DropsCommand& command,
                                   const CommandContext& context);

// ---- drape sweep --------------------------------------------------------------------------------
struct SweepCommand {
  std::string file;
  std::string out;  // empty: the sweep file's output folder
  std::optional<int> only;
  int threads = 0;
  bool plots = true;
};
struct SweepCommandResult {
  SweepSummary summary;
  bool all_converged = false;  // every task (or the --only task), not interrupted
  std::string line;
};
SweepCommandResult RunSweepCommand(const SweepCommand& command, const CommandContext& context);

// ---- drape fabrics ------------------------------------------------------------------------------
struct FabricsCommandResult {
  FabricsSummary summary;
  std::optional<CalibrateSummary> calibration;  // with --calibrate
  bool all_predicted = false;                   // every fabric has a prediction, not interrupted
  std::string line;
};
// `options.command_line` is taken from the context. With `options.calibrate`, the calibration
// (src/sweep/calibrate.h); with `options.calibration_file`, that calibration applied to every
// fabric.
FabricsCommandResult RunFabricsCommand(FabricsOptions options, const CommandContext& context);

// What a drape test asked of its drape coefficient's error bar and what the solve reached
// (AccuracyOf, src/run/solve_report.h), as both faces say it: the result line's clause ("; accuracy
// ±0.05 asked, ±0.043 reached (mesh.spacing 2.7 mm chosen for it)"), and why a run whose accuracy
// binds did not reach it (`drape solve` on stderr with exit 1, Python as a DrapeWarning).
std::string AccuracyClause(const AccuracyOutcome& accuracy);
std::string AccuracyFailure(const AccuracyOutcome& accuracy, bool converged);

}  // namespace drape

#endif  // DRAPE_SRC_COMMANDS_COMMANDS_H_
