// A small program for tests/task_farm_mpi_test.cc, run as `mpirun -np N task_farm_mpi_probe
// TASKS [--fail T] [--die T]` or alone: a task farm of TASKS tasks whose results are computed
// from the task number alone. The coordinator prints `task <t> value <v> rank <r>` per collected
// result (r: the rank that ran it), every process one `summary ...` line; `--fail T` makes task T
// throw, `--die T` makes the process running task T exit at once, without finalising MPI,
// `--throw-on-rank R` makes rank R throw before the farm (the others wait for it: the probe then
// aborts the job as drape's commands do).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/parallel/process_group.h"
#include "src/parallel/task_farm.h"

namespace {

// A few milliseconds of arithmetic whose value depends only on the task.
double TaskValue(int task) {
  double sum = 0.0;
  for (int k = 1; k <= 200000; ++k) sum += std::sin(task + 1e-3 * k) / k;
  return sum;
}

int Probe(int task_count, int fail_task, int die_task, int throwing_rank) {
  if (drape::Processes().rank == throwing_rank) throw std::runtime_error("the probe's rank fails");
  std::vector<int> tasks(task_count);
  std::iota(tasks.begin(), tasks.end(), 0);
  const auto run = [&](int task) {
    if (task == fail_task) throw std::runtime_error("the probe's failing task");
    if (task == die_task) std::_Exit(7);
    char text[100];
    std::snprintf(text, sizeof text, "value %.17g rank %d", TaskValue(task),
                  drape::Processes().rank);
    return std::string(text);
  };
  const auto collect = [](int task, const std::string& result) {
    std::printf("task %d %s\n", task, result.c_str());
    std::fflush(stdout);
  };
  const drape::TaskFarmSummary summary = drape::RunTaskFarm(tasks, run, collect, {2});
  std::printf("summary rank %d coordinator %d tasks %d workers %d mpi %d\n",
              drape::Processes().rank, summary.coordinator ? 1 : 0, summary.tasks, summary.workers,
              drape::MpiStarted() ? 1 : 0);
  return 0;
}

int FlagValue(int argc, char** argv, const std::string& flag) {
  for (int k = 2; k + 1 < argc; ++k) {
    if (argv[k] == flag) return std::atoi(argv[k + 1]);
  }
  return -1;
}

// The probe, its errors reported as drape reports a command's: the job is aborted when another
// rank may be waiting (before ProcessGroupScope, in main, would wait for the other ranks).
int ProbeReportingErrors(int argc, char** argv) {
  try {
    return Probe(std::atoi(argv[1]), FlagValue(argc, argv, "--fail"),
                 FlagValue(argc, argv, "--die"), FlagValue(argc, argv, "--throw-on-rank"));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "task_farm_mpi_probe: %s\n", error.what());
  } catch (...) {
    std::fprintf(stderr, "task_farm_mpi_probe: an unknown exception\n");
  }
  drape::AbortJobAfterError(3);
  return 3;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: task_farm_mpi_probe TASKS [--fail T] [--die T] [--throw-on-rank R]\n");
    return 2;
  }
  const drape::ProcessGroupScope processes;
  return ProbeReportingErrors(argc, argv);
}
