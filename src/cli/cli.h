// The `drape` command: its arguments, subcommands and exit status (docs/reference.md,
// "The command line"). Kept apart from main() so tests can drive it without a process.
#ifndef DRAPE_SRC_CLI_CLI_H_
#define DRAPE_SRC_CLI_CLI_H_

#include <ostream>
#include <string>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

// Exit status of the command.
enum ExitStatus {
  kExitConverged = 0,     // solved to the tolerance (or another subcommand succeeded)
  kExitNotConverged = 1,  // ran, results written, but the tolerance was not reached
  kExitBadInput = 2,      // bad scene, bad usage, or results that could not be written
  kExitSaddle = 3,        // converged, results written, but not a stable minimum (a saddle, or
                          // the fabric through a support disk or through itself)
};

struct CommandOptions {
  // Show the one-line progress report on `err` (the caller decides: stderr is a terminal).
  bool show_progress = false;
  // Without a terminal: print a plain progress line on `err` every this many seconds (0: never).
  double plain_progress_interval_s = 0.0;
};

// "unknown solver 'newtn' (known: newton, …); did you mean 'newton'?"
std::string UnknownSolverText(const std::string& name);

// The scene's method must exist before anything is built (a typo should not cost a model build):
// InputError at solver.method, "unknown solver 'newtn' (known: …); did you mean 'newton'?".
void RequireKnownSolver(const Scene& scene);

// A subcommand of `drape` and its one-line help, as `drape --help` lists them.
struct CommandHelp {
  std::string name;
  std::string help;
};

// Every subcommand, in the order `drape --help` lists them: the rows of the table that the
// parser, the usage, the completion script and the man page are all made from.
std::vector<CommandHelp> CommandList();

// Runs `drape args...` (args without the program name): prints results on `out`, errors, usage
// and progress on `err`, and returns the exit status. Input errors are caught here and printed as
// their located message; nothing is written unless a solve ran.
int RunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               const CommandOptions& options = {});

}  // namespace drape

#endif  // DRAPE_SRC_CLI_CLI_H_
