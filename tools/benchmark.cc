// benchmark: drape's speed, in four modes (docs/benchmarks.md, "How to run", says what each
// prints):
//   benchmark [--scenes a,b] [--cap s] [--baseline BINARY] [--baseline-cap s] [--drape build/drape]
//             [--repeats n] [--probe-only]
//     the scenes of AllScenes: an assembly probe in this process, then one `drape solve` per scene
//     in a child process (its peak memory is that run's alone), against an older build's binary;
//   benchmark solvers [--sizes 50,100,256] [--solvers newton,ceres-lbfgs,...] [--cap s]
//             [--newton-cap s] [--scene configs/hard/two_corner_sheet.yaml]
//     every method on the hanging sheet at several sizes, one child process per run, to relative
//     residual 1e-8 or its cap; times relative to newton's;
//   benchmark starts [--scenes limp2.6,drape2.6] [--noise m]
//     newton from the flat start and from starts made of the answer (seen through the lattice of
//     twice the spacing; with noise), in this process.
//   benchmark pareto [--fabrics cotton,polyester,limp] [--cap s] [--baseline BINARY]
//             [--chart docs/pareto.svg]
//     each shipped tester fabric by each strategy (uniform lattices, levels with Richardson's
//     extrapolation, the accuracy key), the drape coefficient's error against the fabric's
//     reference over the command's wall time, one `drape solve` per run; a table and a chart.
// Paths are relative to the current folder (the repository's root).
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/levels.h"
#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/numerics/sparse_hessian.h"
#include "src/run/run.h"
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

// Runs work() in a forked child and passes its result (trivially copyable) back through a pipe;
// the child's peak resident memory (MB) into *peak_mb. False where the child threw, failed or
// wrote no result.
template <typename Result, typename Work>
bool RunInChild(Work work, Result* result, double* peak_mb) {
  static_assert(std::is_trivially_copyable_v<Result>);
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return false;
  std::fflush(stdout);  // or the child's copy of the buffer is printed twice
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_ends[0]);
    Result child_result;
    try {
      child_result = work();
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s\n", error.what());
      _exit(2);
    }
    _exit(write(pipe_ends[1], &child_result, sizeof child_result) == sizeof child_result ? 0 : 3);
  }
  close(pipe_ends[1]);
  const bool read_ok = read(pipe_ends[0], result, sizeof *result) == sizeof *result;
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

// The options of `benchmark solvers`; false (after the usage line) on an unknown one.
struct SolverComparisonOptions {
  std::vector<int> sizes = {50, 100, 256};
  std::vector<std::string> solvers;
  double cap = 600.0, newton_cap = -1.0;
  std::string scene_file = "configs/hard/two_corner_sheet.yaml";  // run from the repository root
};

bool ReadSolverComparisonOptions(int argc, char** argv, SolverComparisonOptions* options) {
  for (const auto& info : AllSolvers()) options->solvers.push_back(info.name);
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--sizes") {
      options->sizes.clear();
      for (const auto& part : Split(value)) options->sizes.push_back(std::atoi(part.c_str()));
    } else if (key == "--solvers") {
      options->solvers = Split(value);
    } else if (key == "--scene") {
      options->scene_file = value;
    } else if (key == "--cap") {
      options->cap = std::atof(value.c_str());
    } else if (key == "--newton-cap") {
      options->newton_cap = std::atof(value.c_str());
    } else {
      std::fprintf(stderr,
                   "usage: benchmark [--sizes 50,100] [--solvers a,b] [--cap s] [--newton-cap s] "
                   "[--scene file]\n");
      return false;
    }
  }
  return true;
}

int SolverComparisonMain(int argc, char** argv) {
  SolverComparisonOptions options;
  if (!ReadSolverComparisonOptions(argc, argv, &options)) return 2;
  const std::vector<int>& sizes = options.sizes;
  const std::vector<std::string>& solvers = options.solvers;
  const double cap = options.cap;
  double newton_cap = options.newton_cap;
  const std::string& scene_file = options.scene_file;
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
      const bool ok =
          RunInChild([&] { return RunOne(scene_file, n, solver, limit); }, &row, &peak_mb);
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

// ---- The scene benchmark (the default mode) ----

// One benchmark scene: a scene file and the overrides that set its size.
struct BenchScene {
  std::string name, file;
  std::vector<std::string> overrides;
};

const std::vector<BenchScene>& AllScenes() {
  static const std::vector<BenchScene> scenes = {
      // One level each (a drape test is otherwise solved on two, for its error bar), so that a
      // baseline from before that default solves the same.
      {"drape10",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.01", "solver.levels=1"}},
      {"drape5",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.005", "solver.levels=1"}},
      {"drape2.6",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.0026", "solver.levels=1"}},
      {"drape1.3",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.0013", "solver.levels=1"}},
      {"limp10", "configs/fv/drape_tester_limp_30.yaml", {"mesh.spacing=0.01", "solver.levels=1"}},
      {"limp5", "configs/fv/drape_tester_limp_30.yaml", {"mesh.spacing=0.005", "solver.levels=1"}},
      {"limp2.6",
       "configs/fv/drape_tester_limp_30.yaml",
       {"mesh.spacing=0.0026", "solver.levels=1"}},
      {"limp1.3",
       "configs/fv/drape_tester_limp_30.yaml",
       {"mesh.spacing=0.0013", "solver.levels=1"}},
      // The friction cotton of docs/benchmarks.md ("Current"): 2HB = 0.124 gf·cm/cm both ways.
      {"friction4",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.004", "solver.levels=1", "material.finite_volume.kes.2HB_warp=0.124",
        "material.finite_volume.kes.2HB_weft=0.124"}},
      {"table", "configs/fv/square_table.yaml", {"mesh.nodes=[101,101]"}},
      {"sphere", "configs/fv/sphere.yaml", {"mesh.nodes=[101,101]"}},
      {"sheet50", "configs/hard/two_corner_sheet.yaml", {"mesh.nodes=[50,50]"}},
      {"sheet100", "configs/hard/two_corner_sheet.yaml", {"mesh.nodes=[100,100]"}},
      {"sheet256", "configs/hard/two_corner_sheet.yaml", {"mesh.nodes=[256,256]"}},
      // Grid sequencing (solver.levels): the same scenes solved coarse to fine.
      {"drape5-L2",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.005", "solver.levels=2"}},
      {"drape2.6-L2",
       "configs/fv/drape_tester_cotton_30.yaml",
       {"mesh.spacing=0.0026", "solver.levels=2"}},
      {"table-L3", "configs/fv/square_table.yaml", {"mesh.nodes=[101,101]", "solver.levels=3"}},
      {"sphere-L3", "configs/fv/sphere.yaml", {"mesh.nodes=[101,101]", "solver.levels=3"}},
      {"sheet100-L3",
       "configs/hard/two_corner_sheet.yaml",
       {"mesh.nodes=[100,100]", "solver.levels=3"}},
      {"sheet256-L3",
       "configs/hard/two_corner_sheet.yaml",
       {"mesh.nodes=[256,256]", "solver.levels=3"}},
  };
  return scenes;
}

// The scenes of AllScenes by name, in the order given; nothing (after saying which) if a name
// is not one of them.
std::optional<std::vector<BenchScene>> NamedScenes(const std::vector<std::string>& names) {
  std::vector<BenchScene> scenes;
  for (const auto& name : names) {
    const auto& all = AllScenes();
    const auto it = std::find_if(all.begin(), all.end(),
                                 [&name](const BenchScene& s) { return s.name == name; });
    if (it == all.end()) {
      std::fprintf(stderr, "unknown scene %s\n", name.c_str());
      return std::nullopt;
    }
    scenes.push_back(*it);
  }
  return scenes;
}

// What one `drape solve` run reported in its summary.json, and its peak memory.
struct SolveRun {
  bool ran = false, converged = false, capped = false;
  bool refused = false;  // exit status 2: the binary did not accept the scene or its settings
  int nodes = 0, iterations = 0, folds = -1;
  int all_iterations = 0;  // with solver.levels, of every level (iterations: the finest's)
  double wall = 0, assembly = 0, factorization = 0, factorizations = 0, peak_mb = 0;
  double drape_coefficient = -1, energy = 0;
  // summary.json's contact: nodes under a support disk, the fabric's edges through it (-1: not
  // in the summary, as before edge contact) and how far inside its rim the farthest one is (m).
  int nodes_under_disk = -1, edges_through_disk = -1;
  double under_disk_inside = 0;
  double command_wall = 0;   // s, the whole command: start-up, build, every level, writing
  double error_bar = -1;     // summary.json's drape_coefficient_error.estimate, else the rule's
  double extrapolated = -1;  // the levels' Richardson drape coefficient, where available
  double spacing = 0;        // m, the finest lattice's (mesh_rule.spacing_m)
};

// Runs `binary solve` on the scene file with its overrides in a child process with the time limit
// `cap` (s), writing only summary.json (and scene.yaml) into a fresh folder, and reads that
// summary back.
SolveRun RunDrape(const std::string& binary, const std::string& file,
                  const std::vector<std::string>& overrides, double cap, const std::string& out) {
  std::vector<std::string> args = {binary, "solve", file, "--out", out};
  std::vector<std::string> sets = overrides;
  sets.push_back("solver.time_limit=" + std::to_string(cap));
  sets.push_back("solver.max_iterations=100000");
  sets.push_back("output.write=[summary]");
  for (const auto& set : sets) {
    args.push_back("--set");
    args.push_back(set);
  }
  SolveRun run;
  std::system(("rm -rf '" + out + "'").c_str());
  std::fflush(stdout);  // or the child's copy of the buffer is printed twice
  const auto started = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) {
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (auto& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    if (!freopen("/dev/null", "w", stdout)) _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  struct rusage usage {};
  wait4(child, &status, 0, &usage);
  run.command_wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  run.peak_mb = usage.ru_maxrss / 1024.0;
  run.refused = WIFEXITED(status) && WEXITSTATUS(status) == 2;
  if (!WIFEXITED(status) || WEXITSTATUS(status) > 1) return run;
  YAML::Node summary;
  try {
    summary = YAML::LoadFile(out + "/summary.json");  // JSON is YAML
  } catch (const std::exception&) {
    return run;
  }
  run.ran = true;
  run.converged = summary["converged"].as<bool>();
  run.nodes = summary["nodes"].as<int>();
  run.iterations = run.all_iterations = summary["iterations"].as<int>();
  run.wall = summary["wall_time_s"].as<double>();
  if (summary["levels"]) {  // the top-level figures are the finest level's: time all levels
    run.wall = 0.0, run.all_iterations = 0;
    for (const auto& level : summary["levels"]) {
      run.wall += level["wall_time_s"].as<double>();
      run.all_iterations += level["iterations"].as<int>();
    }
  }
  run.capped = !run.converged && run.wall >= 0.98 * cap;
  run.energy = summary["energy"]["total"].as<double>();
  if (summary["drape_coefficient"])
    run.drape_coefficient = summary["drape_coefficient"].as<double>();
  if (summary["drape"] && summary["drape"]["folds"])
    run.folds = summary["drape"]["folds"].as<int>();
  if (const YAML::Node contact = summary["contact"]) {
    if (contact["nodes_under_disk"]) run.nodes_under_disk = contact["nodes_under_disk"].as<int>();
    if (contact["edges_through_disk"])
      run.edges_through_disk = contact["edges_through_disk"].as<int>();
    if (contact["under_disk_inside_m"])
      run.under_disk_inside = contact["under_disk_inside_m"].as<double>();
  }
  if (const YAML::Node bar = summary["drape_coefficient_error"]) {
    run.error_bar = bar["estimate"].as<double>();
  } else if (const YAML::Node rule = summary["mesh_rule"]) {
    run.error_bar = rule["expected_drape_coefficient_error"].as<double>();
  }
  if (summary["mesh_rule"]) run.spacing = summary["mesh_rule"]["spacing_m"].as<double>();
  const YAML::Node extrapolation = summary["extrapolation"];
  if (extrapolation && extrapolation["drape_coefficient"] &&
      extrapolation["drape_coefficient"]["available"].as<bool>()) {
    run.extrapolated = extrapolation["drape_coefficient"]["value"].as<double>();
  }
  const YAML::Node statistics = summary["statistics"];
  auto statistic = [&statistics](const char* key) {
    return statistics && statistics[key] ? statistics[key].as<double>() : 0.0;
  };
  run.assembly = statistic("assembly_s");
  run.factorization = statistic("factorization_s");
  run.factorizations = statistic("factorizations");
  return run;
}

// One assembly (energy, gradient, Hessian, projection) and one numeric factorisation of the same
// Hessian, timed in this process at a perturbed flat state, as the median of `repeats`.
struct AssemblyProbe {
  int nodes = 0, terms = 0;
  double assembly = 0, factorization = 0;          // wall s
  double assembly_cpu = 0, factorization_cpu = 0;  // CPU s (all threads)
  // CPU s of an assembly of the true Hessian alone (no H₊: what newton assembles at an iteration
  // whose H factorises).
  double exact_only_cpu = 0;
  // CPU s of the terms' local derivatives alone, one thread: EnergyHessian (the fast path where a
  // functor has one) and ReferenceHessian (nested Jets over every whole functor, as before).
  double derivatives_cpu = 0, reference_cpu = 0;
  // Wall s of the certificate's self-intersection check (src/model/self_intersection.h) at the
  // probe state, and the crossings it found there.
  double self_intersection = 0;
  int self_crossings = 0;
};

double CpuSeconds(clockid_t clock) {
  timespec time{};
  clock_gettime(clock, &time);
  return time.tv_sec + 1e-9 * time.tv_nsec;
}

// One-thread CPU time of every term's local energy, gradient and Hessian.
double LocalDerivativesCpu(const Model& model, bool reference) {
  std::vector<double> gradient(64), hessian(64 * 64);
  double energy = 0.0;
  const double start = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
  for (const auto& term : model.terms) {
    const int n = term->num_coordinates();
    gradient.resize(n);
    hessian.resize(n * n);
    if (reference) {
      term->ReferenceHessian(model.positions.data(), &energy, gradient.data(), hessian.data());
    } else {
      term->EnergyHessian(model.positions.data(), &energy, gradient.data(), hessian.data());
    }
  }
  return CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - start;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

AssemblyProbe ProbeAssembly(const BenchScene& scene, int repeats) {
  const Scene loaded = LoadScene(scene.file, scene.overrides);
  Model model = BuildModel(loaded);
  const DofMap dofs(model);
  // A fixed pseudo-random displacement of every free coordinate by up to ±1 mm, so that no term
  // sits at its rest state (where some second-derivative parts vanish).
  unsigned state = 12345u;
  for (int k = 0; k < dofs.num_free(); ++k) {
    state = state * 1664525u + 1013904223u;
    model.positions[dofs.free_to_global()[k]] += 1e-3 * (2.0 * (state >> 8) / 16777216.0 - 1.0);
  }
  FreeHessian hessian(model, dofs);
  SparseCholesky cholesky(hessian);
  AssemblyProbe probe;
  probe.nodes = static_cast<int>(model.positions.size() / 3);
  probe.terms = static_cast<int>(model.terms.size());
  FreeHessian::Assembly assembly;
  std::vector<double> gradient;
  std::vector<double> assembly_times, factorization_times, assembly_cpu, factorization_cpu;
  std::vector<double> derivatives_cpu, reference_cpu, exact_only_cpu, self_intersection;
  for (int r = 0; r < repeats; ++r) {
    const auto check_start = std::chrono::steady_clock::now();
    probe.self_crossings = FindSelfIntersections(model, model.positions).crossings;
    self_intersection.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - check_start).count());
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    if (!hessian.Assemble(model.positions.data(), true, &assembly, &gradient)) {
      std::fprintf(stderr, "%s: assembly failed at the probe state\n", scene.name.c_str());
      return probe;
    }
    assembly_cpu.push_back(CpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu_start);
    assembly_times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const double exact_start = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    hessian.Assemble(model.positions.data(), false, &assembly, &gradient);
    exact_only_cpu.push_back(CpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - exact_start);
    derivatives_cpu.push_back(LocalDerivativesCpu(model, false));
    reference_cpu.push_back(LocalDerivativesCpu(model, true));
    double largest = 0.0;
    for (int d : hessian.diagonal()) largest = std::max(largest, hessian.projected_values()[d]);
    std::vector<double> shift(hessian.size(), 1e-6 * largest);
    double factorization_start = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    while (!cholesky.Factorize(hessian.projected_values(), &shift)) {
      for (double& s : shift) s *= 10.0;
      factorization_start = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    }
    factorization_cpu.push_back(CpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - factorization_start);
    factorization_times.push_back(cholesky.last_factorization_seconds());
  }
  probe.assembly = Median(assembly_times);
  probe.factorization = Median(factorization_times);
  probe.assembly_cpu = Median(assembly_cpu);
  probe.factorization_cpu = Median(factorization_cpu);
  probe.exact_only_cpu = Median(exact_only_cpu);
  probe.derivatives_cpu = Median(derivatives_cpu);
  probe.reference_cpu = Median(reference_cpu);
  probe.self_intersection = Median(self_intersection);
  return probe;
}

// ProbeAssembly in a child process, so that this process stays small: a solve's child inherits
// its parent's peak resident memory through fork and exec (ru_maxrss), and the 1.3 mm probe's
// 150 MB would otherwise be every later solve's peak. Nodes 0 where the child failed.
AssemblyProbe ProbeAssemblyInChild(const BenchScene& scene, int repeats) {
  AssemblyProbe probe;
  double peak_mb = 0.0;
  if (!RunInChild([&] { return ProbeAssembly(scene, repeats); }, &probe, &peak_mb)) {
    probe = AssemblyProbe();
  }
  return probe;
}

std::string Ratio(double mine, double theirs, bool lower_bound) {
  if (!(mine > 0.0) || !(theirs > 0.0)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%s%.1f", lower_bound ? "> " : "", theirs / mine);
  return text;
}

std::string OrBlank(double value, const char* format) {
  if (value < 0.0) return "";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// "nodes, edges (mm inside the rim)" of the fabric under a support disk; blank without one.
std::string UnderDiskText(const SolveRun& run) {
  if (run.nodes_under_disk < 0) return "";
  std::string text = std::to_string(run.nodes_under_disk) + ", " +
                     (run.edges_through_disk < 0 ? std::string("not counted")
                                                 : std::to_string(run.edges_through_disk));
  if (run.under_disk_inside > 0.0)
    text += " (" + OrBlank(1e3 * run.under_disk_inside, "%.1f") + " mm)";
  return text;
}

void PrintRun(const BenchScene& scene, const char* binary, const SolveRun& run,
              const std::string& ratios) {
  if (!run.ran) {
    std::printf("| %s | %s | failed to run | | | | | | | | | | | %.0f | |\n", scene.name.c_str(),
                binary, run.peak_mb);
    return;
  }
  const double iterations = std::max(1, run.iterations);
  const double per_factorization = run.factorization / std::max(1.0, run.factorizations);
  const std::string iterations_text =
      std::to_string(run.iterations) +
      (run.all_iterations != run.iterations
           ? " (" + std::to_string(run.all_iterations) + " all levels)"
           : "");
  std::printf(
      "| %s | %s | %d | %s | %.2f%s | %s | %.6e | %.4f | %.4f | %s | %s | %s | %s | %.0f | %s |\n",
      scene.name.c_str(), binary, run.nodes, iterations_text.c_str(), run.wall,
      run.converged ? "" : (run.capped ? " (cap)" : " (not converged)"),
      run.converged ? "yes" : "no", run.energy, run.assembly / iterations, per_factorization,
      OrBlank(per_factorization > 0 ? run.assembly / iterations / per_factorization : -1, "%.2f")
          .c_str(),
      OrBlank(run.drape_coefficient, "%.4f").c_str(),
      run.folds >= 0 ? std::to_string(run.folds).c_str() : "", UnderDiskText(run).c_str(),
      run.peak_mb, ratios.c_str());
  std::fflush(stdout);
}

int ScenesMain(int argc, char** argv) {
  std::vector<std::string> names = {"drape10", "drape5",   "drape2.6", "limp10",
                                    "limp5",   "limp2.6",  "table",    "sphere",
                                    "sheet50", "sheet100", "sheet256"};
  double cap = 1200.0, baseline_cap = 300.0;
  int repeats = 5;
  std::string drape = "build/drape", baseline;
  bool probe_only = false;
  for (int a = 1; a < argc; ++a) {
    const std::string key = argv[a];
    if (key == "--probe-only") {
      probe_only = true;
      continue;
    }
    if (a + 1 >= argc) {
      std::fprintf(stderr, "%s needs a value\n", key.c_str());
      return 2;
    }
    const std::string value = argv[++a];
    if (key == "--scenes") {
      names = Split(value);
    } else if (key == "--cap") {
      cap = std::atof(value.c_str());
    } else if (key == "--baseline") {
      baseline = value;
    } else if (key == "--baseline-cap") {
      baseline_cap = std::atof(value.c_str());
    } else if (key == "--drape") {
      drape = value;
    } else if (key == "--repeats") {
      repeats = std::max(1, std::atoi(value.c_str()));
    } else {
      std::fprintf(stderr,
                   "usage: benchmark [--scenes a,b] [--cap s] [--baseline BINARY] "
                   "[--baseline-cap s] [--drape build/drape] [--repeats n] [--probe-only]\n"
                   "       benchmark solvers [--sizes 50,100] [--solvers a,b] [--cap s] ...\n"
                   "       benchmark starts [--scenes limp2.6,drape2.6] [--noise m]\n");
      return 2;
    }
  }
  const std::optional<std::vector<BenchScene>> named = NamedScenes(names);
  if (!named) return 2;
  const std::vector<BenchScene>& scenes = *named;
  std::printf(
      "Assembly probe (this build, %u hardware threads, OpenBLAS kernels %s; median of %d):\n\n",
      std::thread::hardware_concurrency(), BlasKernelsText().c_str(), repeats);
  std::printf(
      "| scene | nodes | terms | assembly wall s | factorisation wall s | assembly ÷ "
      "factorisation, wall | same, CPU | assembly CPU µs per node | without H₊: CPU µs per node "
      "| ÷ factorisation, CPU | local derivatives CPU µs per node: this path | nested Jets "
      "| self-intersection check wall s (crossings) | ÷ factorisation, wall "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& scene : scenes) {
    const AssemblyProbe probe = ProbeAssemblyInChild(scene, repeats);
    if (probe.nodes == 0 || !(probe.factorization > 0.0)) {
      std::printf("| %s | failed | | | | | | | | | | | | |\n", scene.name.c_str());
      continue;
    }
    std::printf(
        "| %s | %d | %d | %.4f | %.4f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f "
        "| %.4f (%d) | %.3f |\n",
        scene.name.c_str(), probe.nodes, probe.terms, probe.assembly, probe.factorization,
        probe.assembly / probe.factorization, probe.assembly_cpu / probe.factorization_cpu,
        1e6 * probe.assembly_cpu / probe.nodes, 1e6 * probe.exact_only_cpu / probe.nodes,
        probe.exact_only_cpu / probe.factorization_cpu, 1e6 * probe.derivatives_cpu / probe.nodes,
        1e6 * probe.reference_cpu / probe.nodes, probe.self_intersection, probe.self_crossings,
        probe.self_intersection / probe.factorization);
    std::fflush(stdout);
  }
  if (probe_only) return 0;
  std::printf(
      "\nSolves (`drape solve`, cap %.0f s%s):\n\n| scene | binary | nodes | iterations | wall s | "
      "converged | energy J | assembly s/iteration | s/factorisation | assembly ÷ factorisation | "
      "drape coefficient | folds | under the disc: nodes, edges through (mm inside the rim) | "
      "peak MB | baseline ÷ this: time, iterations |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      cap,
      baseline.empty() ? ""
                       : (", baseline cap " + std::to_string(int(baseline_cap)) + " s").c_str());
  const std::string out = "/tmp/drape_benchmark_" + std::to_string(getpid());
  const std::string baseline_out = out + "_baseline";
  for (const auto& scene : scenes) {
    const SolveRun run = RunDrape(drape, scene.file, scene.overrides, cap, out);
    PrintRun(scene, "this", run, "");
    if (baseline.empty()) continue;
    SolveRun old = RunDrape(baseline, scene.file, scene.overrides, baseline_cap, baseline_out);
    const char* label = "baseline";
    if (old.refused && run.ran) {
      // An older build that does not know a key of today's scene file (e372ef7 and `drape_test`,
      // KES inputs) solves the scene as this build expanded it: scene.yaml, the same model in
      // the scene file's older keys (SI values, every default filled in by this build).
      old = RunDrape(baseline, out + "/scene.yaml", {}, baseline_cap, baseline_out);
      label = "baseline (scene.yaml)";
    }
    std::string ratios;
    if (run.ran && old.ran && run.converged) {
      ratios = Ratio(run.wall, old.wall, !old.converged) + ", " +
               Ratio(run.iterations, old.iterations, !old.converged);
    }
    PrintRun(scene, label, old, ratios);
  }
  std::system(("rm -rf '" + out + "' '" + baseline_out + "'").c_str());
  return 0;
}

// ---- Speed against error (`benchmark pareto`) ----

// A shipped tester fabric and its reference drape coefficients: each build's own converged value
// (the 1.3 mm lattice, 41,825 nodes; docs/drape-tester.md, "How fine a mesh", has the runs and
// their commands), for this build's model (the twist, and the shear at the cells' centres:
// session 38) and for the baseline's (4be9ccd, before the twist: the table "Before the twist
// term").
struct ParetoFabric {
  std::string name, file;
  double reference = 0, baseline_reference = 0;
};

const std::vector<ParetoFabric>& ParetoFabrics() {
  static const std::vector<ParetoFabric> fabrics = {
      {"cotton", "configs/fv/drape_tester_cotton_30.yaml", 0.708, 0.630},
      {"polyester", "configs/fv/drape_tester_polyester_30.yaml", 0.458, 0.367},
      {"limp", "configs/fv/drape_tester_limp_30.yaml", 0.237, 0.183},
  };
  return fabrics;
}

// One way to get a drape coefficient: its label and the overrides that ask for it. `extrapolate`:
// the figure is the levels' Richardson extrapolation, not the finest level's.
struct ParetoStrategy {
  std::string label;
  std::vector<std::string> overrides;
  bool extrapolate = false;
  bool this_build_only = false;  // keys the baseline does not have
};

std::vector<ParetoStrategy> ParetoStrategies() {
  std::vector<ParetoStrategy> strategies;
  for (const char* spacing : {"0.01", "0.005", "0.0035", "0.0026"}) {
    strategies.push_back({std::string("uniform ") + spacing + " m",
                          {std::string("mesh.spacing=") + spacing, "solver.levels=1"}});
  }
  strategies.push_back({"3 levels to 0.005 m, Richardson",
                        {"mesh.spacing=0.005", "solver.levels=3"},
                        /*extrapolate=*/true});
  for (const char* accuracy : {"0.1", "0.05"}) {
    strategies.push_back({std::string("accuracy ") + accuracy,
                          {"mesh={}", std::string("drape_test.accuracy=") + accuracy},
                          /*extrapolate=*/false,
                          /*this_build_only=*/true});
  }
  return strategies;
}

struct ParetoPoint {
  std::string fabric, build, strategy;
  SolveRun run;
  double drape_coefficient = -1, error = 0;
};

void PrintParetoRow(const ParetoPoint& point) {
  const SolveRun& run = point.run;
  if (!run.ran) {
    std::printf("| %s | %s | %s | failed to run | | | | | | | |\n", point.fabric.c_str(),
                point.build.c_str(), point.strategy.c_str());
    return;
  }
  const bool covers = run.error_bar >= 0 && std::abs(point.error) <= run.error_bar;
  std::printf("| %s | %s | %s | %d | %.1f | %d | %s | %.4f | %+.4f | %s | %s |\n",
              point.fabric.c_str(), point.build.c_str(), point.strategy.c_str(), run.nodes,
              run.command_wall, run.all_iterations,
              run.converged ? "yes" : (run.capped ? "no (cap)" : "no"), point.drape_coefficient,
              point.error, OrBlank(run.error_bar, "%.3f").c_str(),
              run.error_bar < 0 ? "" : (covers ? "yes" : "no"));
  std::fflush(stdout);
}

// The chart: |error| against the command's wall time, a point per converged run, a series per
// fabric and build, drawn by gnuplot into `chart` (SVG); the target's box is the lower left.
void DrawParetoChart(const std::vector<ParetoPoint>& points, const std::string& chart) {
  const std::string data = chart + ".dat";
  std::FILE* file = std::fopen(data.c_str(), "w");
  if (!file) return;
  std::vector<std::string> series;
  for (const ParetoPoint& point : points) {
    const std::string name = point.fabric + ", " + point.build;
    if (std::find(series.begin(), series.end(), name) == series.end()) series.push_back(name);
  }
  for (const std::string& name : series) {
    std::fprintf(file, "\"%s\"\n", name.c_str());
    for (const ParetoPoint& point : points) {
      if (point.fabric + ", " + point.build != name || !point.run.ran || !point.run.converged) {
        continue;
      }
      std::fprintf(file, "%.3f %.5f \"%s\"\n", point.run.command_wall,
                   std::max(1e-4, std::abs(point.error)), point.strategy.c_str());
    }
    std::fprintf(file, "\n\n");
  }
  std::fclose(file);
  const std::string script = chart + ".gp";
  file = std::fopen(script.c_str(), "w");
  if (!file) return;
  std::fprintf(file,
               "set terminal svg size 900,560 font 'sans,12'\nset output '%s'\n"
               "set logscale xy\nset xlabel 'wall time of the command, s (2-core machine)'\n"
               "set ylabel '|drape coefficient - reference|'\nset grid\n"
               "set key outside right\nset arrow from graph 0, first 0.03 to graph 1, first 0.03 "
               "nohead dashtype 2\nset label 'target 0.03' at graph 0.02, first 0.034\n"
               "set arrow from 10, graph 0 to 10, graph 1 nohead dashtype 2\n"
               "plot for [k=0:%zu] '%s' index k using 1:2 with points pointsize 1.4 "
               "title columnheader(1)\n",
               chart.c_str(), series.size() - 1, data.c_str());
  std::fclose(file);
  if (std::system(("gnuplot '" + script + "'").c_str()) != 0) {
    std::fprintf(stderr, "benchmark: gnuplot could not draw %s\n", chart.c_str());
  }
}

// One fabric by one strategy, on this build or the baseline's binary.
ParetoPoint RunParetoPoint(const ParetoFabric& fabric, const ParetoStrategy& strategy,
                           const std::string& binary, bool is_baseline, double cap,
                           const std::string& out) {
  ParetoPoint point{fabric.name, is_baseline ? "baseline" : "this", strategy.label, {}};
  point.run = RunDrape(binary, fabric.file, strategy.overrides, cap, out);
  const bool extrapolated = strategy.extrapolate && point.run.extrapolated >= 0;
  point.drape_coefficient = extrapolated ? point.run.extrapolated : point.run.drape_coefficient;
  point.error =
      point.drape_coefficient - (is_baseline ? fabric.baseline_reference : fabric.reference);
  return point;
}

struct ParetoOptions {
  std::string drape = "build/drape", baseline, chart;
  std::vector<std::string> fabrics;  // empty: all
  double cap = 300.0;
};

bool ReadParetoOptions(int argc, char** argv, ParetoOptions* options) {
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--drape") {
      options->drape = value;
    } else if (key == "--baseline") {
      options->baseline = value;
    } else if (key == "--chart") {
      options->chart = value;
    } else if (key == "--cap") {
      options->cap = std::atof(value.c_str());
    } else if (key == "--fabrics") {
      options->fabrics = Split(value);
    } else {
      std::fprintf(stderr,
                   "usage: benchmark pareto [--fabrics cotton,polyester,limp] [--cap s] "
                   "[--baseline BINARY] [--chart docs/pareto.svg] [--drape build/drape]\n");
      return false;
    }
  }
  return true;
}

int ParetoMain(int argc, char** argv) {
  ParetoOptions options;
  if (!ReadParetoOptions(argc, argv, &options)) return 2;
  std::printf(
      "Speed against error (`benchmark pareto`, cap %.0f s per level; error against each build's "
      "own 1.3 mm drape coefficient):\n\n| fabric | build | strategy | nodes | wall s | "
      "iterations | converged | DC | error | error bar | covers |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n",
      options.cap);
  const std::string out = "/tmp/drape_pareto_" + std::to_string(getpid());
  const std::vector<std::string>& names = options.fabrics;
  std::vector<ParetoPoint> points;
  for (const ParetoFabric& fabric : ParetoFabrics()) {
    if (!names.empty() && std::find(names.begin(), names.end(), fabric.name) == names.end()) {
      continue;
    }
    for (const ParetoStrategy& strategy : ParetoStrategies()) {
      points.push_back(RunParetoPoint(fabric, strategy, options.drape, false, options.cap, out));
      PrintParetoRow(points.back());
      if (options.baseline.empty() || strategy.this_build_only) continue;
      points.push_back(RunParetoPoint(fabric, strategy, options.baseline, true, options.cap, out));
      PrintParetoRow(points.back());
    }
  }
  std::system(("rm -rf '" + out + "'").c_str());
  if (!options.chart.empty()) DrawParetoChart(points, options.chart);
  return 0;
}

// ---- Starts near the answer (`benchmark starts`) ----

// The nodes of `fine` at the places of the nodes of `coarse` (the lattices are nested), -1 where
// none is: matched by their flat positions to 0.1 µm.
std::vector<int> NodesAtTheSamePlaces(const Model& coarse, const Model& fine) {
  const auto place = [](const Model& model, int node) {
    return std::pair{std::lround(model.initial[3 * node] * 1e7),
                     std::lround(model.initial[3 * node + 1] * 1e7)};
  };
  std::map<std::pair<long, long>, int> fine_at;
  for (int k = 0; k < fine.num_nodes; ++k) fine_at[place(fine, k)] = k;
  std::vector<int> matches(coarse.num_nodes, -1);
  for (int k = 0; k < coarse.num_nodes; ++k) {
    const auto it = fine_at.find(place(coarse, k));
    if (it != fine_at.end()) matches[k] = it->second;
  }
  return matches;
}

// The answer as a consistent coarser level could give it at best: taken at the nodes of the
// lattice of twice the spacing and interpolated back as `solver.levels` does (ProlongPositions).
// False (nothing done) where the two lattices are not nested.
bool ThroughTheCoarserLattice(const Scene& scene, const std::vector<double>& answer, Model* start) {
  const Scene coarse_scene = CoarsenedScene(scene, 2);
  Model coarse = BuildModel(coarse_scene);
  const std::vector<int> matches = NodesAtTheSamePlaces(coarse, *start);
  if (std::count(matches.begin(), matches.end(), -1) > 0) return false;
  for (int k = 0; k < coarse.num_nodes; ++k) {
    for (int c = 0; c < 3; ++c) {
      if (!coarse.fixed[3 * k + c]) coarse.positions[3 * k + c] = answer[3 * matches[k] + c];
    }
  }
  ProlongPositions(coarse_scene, coarse, scene, start);
  return true;
}

// Every free coordinate of `answer` displaced by normal noise of standard deviation `noise` (m).
void WithNoise(const std::vector<double>& answer, double noise, Model* start) {
  std::mt19937 random(1);
  std::normal_distribution<double> normal(0.0, noise);
  for (size_t i = 0; i < answer.size(); ++i) {
    if (!start->fixed[i]) start->positions[i] = answer[i] + normal(random);
  }
}

// Whether the answer is a stable minimum, and if not, why.
const char* Verdict(const RunResult& result) {
  if (!result.converged) return "no: not converged";
  if (result.contact.ThroughDisk()) return "no: through a support disc";
  if (result.self_intersections.Any()) return "no: through itself";
  return result.Saddle() ? "no: a saddle" : "yes";
}

// One row: the solve from `start`'s positions, how far they were from `answer` (the largest and
// the rms difference over every coordinate, mm) and how the iterations split by relative
// residual: the fall (≥ 10), the settling (1e-2 to 10), the end.
void SolveAndPrint(const Scene& scene, const std::string& label, Model& start,
                   const std::vector<double>& answer) {
  double largest = 0.0, squares = 0.0;
  for (size_t i = 0; i < answer.size(); ++i) {
    const double d = start.positions[i] - answer[i];
    largest = std::max(largest, std::abs(d));
    squares += d * d;
  }
  const RunResult result = RunSolve(scene, start, scene.solver.method);
  int fall = 0, settling = 0, end = 0;
  for (const IterationRecord& record : result.summary.history) {
    if (record.iteration == result.summary.iterations) continue;  // the answer, no step from it
    record.relative_residual >= 10.0   ? ++fall
    : record.relative_residual >= 1e-2 ? ++settling
                                       : ++end;
  }
  std::string coefficient, folds;  // blank for a scene without a drape coefficient
  if (HasDrapeCoefficient(scene, start)) {
    const DrapeAnalysis drape = AnalyseDrape(scene, start);
    coefficient = OrBlank(drape.coefficient.cusick, "%.4f");
    folds = std::to_string(drape.folds.count);
  }
  const std::string distance = answer.empty()
                                   ? ""
                                   : OrBlank(1e3 * largest, "%.3g") + ", " +
                                         OrBlank(1e3 * std::sqrt(squares / answer.size()), "%.2g");
  std::printf("| %s | %s | %s | %d | %d / %d / %d | %.2f | %.9e | %s | %s | %s |\n",
              scene.name.c_str(), label.c_str(), distance.c_str(), result.summary.iterations, fall,
              settling, end, result.summary.wall_time_s, result.certificate.energy,
              coefficient.c_str(), folds.c_str(), Verdict(result));
  std::fflush(stdout);
}

int StartsMain(int argc, char** argv) {
  std::vector<std::string> names = {"limp2.6", "drape2.6"};
  double noise = 1e-4;
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--scenes") {
      names = Split(value);
    } else if (key == "--noise" && std::atof(value.c_str()) > 0.0) {
      noise = std::atof(value.c_str());
    } else {
      std::fprintf(stderr, "usage: benchmark starts [--scenes limp2.6,drape2.6] [--noise m]\n");
      return 2;
    }
  }
  const std::optional<std::vector<BenchScene>> named = NamedScenes(names);
  if (!named) return 2;
  std::printf(
      "| scene | start | from the answer: largest, rms mm | iterations | fall / settling / end "
      "| wall s | energy J | DC | folds | stable |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const BenchScene& bench : *named) {
    Scene scene = LoadScene(bench.file, bench.overrides);
    scene.name = bench.name;
    Model flat = BuildModel(scene);
    SolveAndPrint(scene, "flat", flat, {});
    const std::vector<double> answer = flat.positions;
    Model coarse_start = BuildModel(scene);
    if (ThroughTheCoarserLattice(scene, answer, &coarse_start)) {
      SolveAndPrint(scene, "the answer through the 2h lattice", coarse_start, answer);
    } else {
      std::printf("| %s | the answer through the 2h lattice: the lattices are not nested |\n",
                  scene.name.c_str());
    }
    Model noisy_start = BuildModel(scene);
    WithNoise(answer, noise, &noisy_start);
    SolveAndPrint(scene, "the answer + noise " + OrBlank(1e3 * noise, "%.2g") + " mm", noisy_start,
                  answer);
  }
  return 0;
}

}  // namespace
}  // namespace drape

int main(int argc, char** argv) {
  drape::RestartWithFasterBlasKernels(argv);  // as drape does; solves it runs inherit the choice
  try {
    drape::RunLibrariesOnOneThread();  // as drape does (src/numerics/library_threads.h)
    if (argc > 1 && std::string(argv[1]) == "solvers") {
      return drape::SolverComparisonMain(argc - 1, argv + 1);
    }
    if (argc > 1 && std::string(argv[1]) == "starts") return drape::StartsMain(argc - 1, argv + 1);
    if (argc > 1 && std::string(argv[1]) == "pareto") return drape::ParetoMain(argc - 1, argv + 1);
    return drape::ScenesMain(argc, argv);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "benchmark: %s\n", error.what());
    return 1;
  }
}
