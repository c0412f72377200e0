// benchmark: the hanging sheet (configs/hard/two_corner_sheet.yaml) at several sizes, solved by
// every method to relative residual 1e-8 or its own limit, one child process per run (so that the
// peak memory, ru_maxrss of the child, is that run's alone). Prints a table: nodes, dofs, solver,
// iterations, wall time, residual reached, final energy, time relative to newton, peak memory,
// and for newton the time per iteration over its mean time per numeric factorisation.
//
//   benchmark [--sizes 50,100,256] [--solvers newton,ceres-lbfgs,...] [--cap SECONDS]
//             [--newton-cap SECONDS] [--scene configs/hard/two_corner_sheet.yaml]
//   (paths relative to the current folder)
//
// --cap is each run's time limit (default 600 s); a run that hits it is reported as such.
// --newton-cap is newton's (default: --cap), so that the reference can run to 1e-8 while the
// others are held to a shorter limit. Ratios to newton are printed only where newton reached 1e-8.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "src/model/equilibrium.h"
#include "src/numerics/library_threads.h"
#include "src/model/model.h"
#include "src/scene/scene_loader.h"
#include "src/solvers/solver.h"

namespace drape {
namespace {

struct Row {
  int iterations = 0;
  int converged = 0;
  double seconds = 0, residual = 0, energy = 0, per_iteration_over_factorization = 0;
  // newton: seconds in assembly, factorisation, solves, line search; factorisations made
  double assembly = 0, factorization = 0, solve = 0, line_search = 0, factorizations = 0;
};

std::vector<std::string> Split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

// newton's wall time per iteration over its mean time per numeric factorisation, both from the
// same run (so that the load of a shared machine affects both alike).
double PerIterationOverFactorization(const SolverSummary& summary, double seconds) {
  const auto& statistics = summary.statistics;
  const auto time = statistics.find("factorization_s");
  const auto count = statistics.find("factorizations");
  if (time == statistics.end() || count == statistics.end() || !(time->second > 0.0)) return 0.0;
  return seconds / summary.iterations / (time->second / count->second);
}

Row RunOne(const std::string& scene_file, int n, const std::string& solver, double cap) {
  const std::string nodes = "mesh.nodes=[" + std::to_string(n) + "," + std::to_string(n) + "]";
  const Scene scene = LoadScene(scene_file, {nodes});
  Model model = BuildModel(scene);
  SolverOptions options;
  options.tolerance = 1e-8;
  options.max_iterations = 1000000;
  options.time_limit = cap;
  const auto start = std::chrono::steady_clock::now();
  const SolverSummary summary = FindSolver(solver)->make()->Solve(model, options);
  Row row;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Certificate certificate = ComputeCertificate(model, model.positions.data());
  row.iterations = summary.iterations;
  row.converged = certificate.relative_residual <= 1e-8;
  row.residual = certificate.relative_residual;
  row.energy = certificate.energy;
  if (solver == "newton" && summary.iterations > 0) {
    row.per_iteration_over_factorization = PerIterationOverFactorization(summary, row.seconds);
    auto statistic = [&summary](const char* key) {
      const auto it = summary.statistics.find(key);
      return it == summary.statistics.end() ? 0.0 : it->second;
    };
    row.assembly = statistic("assembly_s");
    row.factorization = statistic("factorization_s");
    row.solve = statistic("solve_s");
    row.line_search = statistic("line_search_s");
    row.factorizations = statistic("factorizations");
  }
  return row;
}

// Runs in a child; returns the row and the child's peak resident memory (MB).
bool RunInChild(const std::string& scene_file, int n, const std::string& solver, double cap,
                Row* row, double* peak_mb) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return false;
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_ends[0]);
    Row result;
    try {
      result = RunOne(scene_file, n, solver, cap);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s\n", error.what());
      _exit(2);
    }
    if (write(pipe_ends[1], &result, sizeof result) != sizeof result) _exit(3);
    _exit(0);
  }
  close(pipe_ends[1]);
  const bool read_ok = read(pipe_ends[0], row, sizeof *row) == sizeof *row;
  close(pipe_ends[0]);
  int status = 0;
  struct rusage usage {};
  wait4(child, &status, 0, &usage);
  *peak_mb = usage.ru_maxrss / 1024.0;
  return read_ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// newton's wall time between the smallest and each larger size, as an exponent of the node
// count (the target: at most 1.5). Only sizes where newton reached 1e-8 give an exponent; a
// larger size where it stopped short gives a lower bound.
struct NewtonTime {
  int nodes;
  double seconds;
  bool converged;
};
void PrintGrowth(const std::vector<NewtonTime>& times) {
  if (times.empty()) return;
  if (!times[0].converged) {
    std::printf("\nnewton did not reach 1e-8 at %d nodes: no growth exponent\n", times[0].nodes);
    return;
  }
  for (size_t k = 1; k < times.size(); ++k) {
    const double exponent = std::log(times[k].seconds / times[0].seconds) /
                            std::log(static_cast<double>(times[k].nodes) / times[0].nodes);
    std::printf("\nnewton, %d to %d nodes: time grows as nodes^%.2f%s\n", times[0].nodes,
                times[k].nodes, exponent,
                times[k].converged ? "" : " at least (newton stopped before 1e-8 there)");
  }
}

// Where newton's time went, from its own statistics.
void PrintSplits(const std::vector<std::pair<int, Row>>& splits) {
  for (const auto& [nodes, row] : splits) {
    const double other =
        row.seconds - row.assembly - row.factorization - row.solve - row.line_search;
    std::printf(
        "\nnewton, %d nodes: %.0f factorisations of %.3f s each; time in assembly %.0f%%, "
        "factorisation %.0f%%, solves %.0f%%, line search %.0f%%, other %.0f%%\n",
        nodes, row.factorizations, row.factorization / std::max(1.0, row.factorizations),
        100 * row.assembly / row.seconds, 100 * row.factorization / row.seconds,
        100 * row.solve / row.seconds, 100 * row.line_search / row.seconds,
        100 * other / row.seconds);
  }
}

int Main(int argc, char** argv) {
  RunLibrariesOnOneThread();  // as drape does (src/numerics/library_threads.h)
  std::vector<int> sizes = {50, 100, 256};
  std::vector<std::string> solvers;
  for (const auto& info : AllSolvers()) solvers.push_back(info.name);
  double cap = 600.0, newton_cap = -1.0;
  std::string scene_file = "configs/hard/two_corner_sheet.yaml";  // run from the repository root
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--sizes") {
      sizes.clear();
      for (const auto& part : Split(value)) sizes.push_back(std::atoi(part.c_str()));
    } else if (key == "--solvers") {
      solvers = Split(value);
    } else if (key == "--scene") {
      scene_file = value;
    } else if (key == "--cap") {
      cap = std::atof(value.c_str());
    } else if (key == "--newton-cap") {
      newton_cap = std::atof(value.c_str());
    } else {
      std::fprintf(stderr,
                   "usage: benchmark [--sizes 50,100] [--solvers a,b] [--cap s] [--newton-cap s] "
                   "[--scene file]\n");
      return 2;
    }
  }
  if (newton_cap <= 0.0) newton_cap = cap;
  std::printf(
      "| nodes | dofs | solver | iterations | wall s | rel. residual | energy J | "
      "÷ newton | peak MB | newton s/iteration ÷ s/factorisation |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<NewtonTime> newton_times;
  std::vector<std::pair<int, Row>> newton_splits;
  for (int n : sizes) {
    double newton_seconds = 0.0;
    for (const auto& solver : solvers) {
      Row row;
      double peak_mb = 0.0;
      const double limit = solver == "newton" ? newton_cap : cap;
      const bool ok = RunInChild(scene_file, n, solver, limit, &row, &peak_mb);
      if (!ok) {
        std::printf("| %d | %d | %s | failed to run | | | | | %.0f | |\n", n * n, 3 * n * n - 6,
                    solver.c_str(), peak_mb);
        continue;
      }
      if (solver == "newton") {
        // Times are compared with newton's only where it reached 1e-8 itself.
        newton_seconds = row.converged ? row.seconds : 0.0;
        newton_times.push_back({n * n, row.seconds, row.converged != 0});
        newton_splits.push_back({n * n, row});
      }
      char ratio[32] = "";
      if (newton_seconds > 0.0) {  // a run stopped before 1e-8 gives only a lower bound
        std::snprintf(ratio, sizeof ratio, "%s%.1f", row.converged ? "" : "> ",
                      row.seconds / newton_seconds);
      }
      char factor[32] = "";
      if (row.per_iteration_over_factorization > 0.0) {
        std::snprintf(factor, sizeof factor, "%.2f", row.per_iteration_over_factorization);
      }
      std::printf("| %d | %d | %s | %d | %.2f%s | %.2e%s | %.9g | %s | %.0f | %s |\n", n * n,
                  3 * n * n - 6, solver.c_str(), row.iterations, row.seconds,
                  row.seconds >= limit ? " (cap)" : "", row.residual,
                  row.converged ? "" : " (not reached)", row.energy, ratio, peak_mb, factor);
      std::fflush(stdout);
    }
  }
  PrintGrowth(newton_times);
  PrintSplits(newton_splits);
  return 0;
}

}  // namespace
}  // namespace drape

int main(int argc, char** argv) { return drape::Main(argc, argv); }
