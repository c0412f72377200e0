// drape: the equilibrium shape of fabric. See README.md and `drape help`.
#include <unistd.h>

#include <iostream>
#include <string>
#include <vector>

#include "src/cli/cli.h"
#include "src/numerics/library_threads.h"
#include "src/parallel/process_group.h"

int main(int argc, char** argv) {
  // Before anything else: OpenBLAS's kernels can only be chosen by running drape again.
  drape::RestartWithFasterBlasKernels(argv);
  // Finalises MPI at the end if a command started it (only under mpirun/srun).
  const drape::ProcessGroupScope processes;
  const std::vector<std::string> args(argv + 1, argv + argc);
  drape::CommandOptions options;
  options.show_progress = ::isatty(STDERR_FILENO) == 1;
  if (!options.show_progress) options.plain_progress_interval_s = 5.0;  // batch jobs, logs
  return drape::RunCommand(args, std::cout, std::cerr, options);
}
