// puiseux_report: regenerates docs/puiseux.md and docs/img/puiseux/*.png — every test case of
// Puiseux's paper (configs/puiseux/) solved with the paper's fixed point and with newton, the
// paper's dynamic table (test case 2) beside our numbers, and the kinetic-energy histories.
//
//   puiseux_report [REPO_ROOT] [WORK_DIR]
//
// REPO_ROOT defaults to the current folder; WORK_DIR (CSV files and gnuplot scripts, kept for a
// look) defaults to /tmp/puiseux_report. Needs gnuplot (pngcairo terminal). Takes about a minute.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

struct Paths {
  fs::path root;    // the repository
  fs::path work;    // CSV files and gnuplot scripts
  fs::path images;  // docs/img/puiseux
};

struct CaseInfo {
  std::string file;    // under configs/puiseux/
  std::string title;   // as in the paper
  std::string figure;  // the paper's figure
  bool unique;         // a unique equilibrium: compare shapes; else energies only
};

const std::vector<CaseInfo>& Cases() {
  static const std::vector<CaseInfo> cases = {
      {"piece_8x8_uniform_2d", "2-D piece, 8×8, uniform force on part of the border", "Fig. 1",
       true},
      {"piece_15x15_ramp_2d", "2-D piece, 15×15, non-uniform forces, elastic", "Fig. 2", true},
      {"piece_15x15_ramp_tension_only_2d", "2-D piece, 15×15, non-uniform forces, tension-only",
       "Fig. 3", false},
      {"paraglider_fixed_trailing_edge", "paraglider profile, fixed trailing edge", "Fig. 4", true},
      {"paraglider_free_trailing_edge", "paraglider profile, free trailing edge", "Fig. 5", true},
      {"curtain_3d", "test case 1: curtain (own weight, weighted lower border)", "Fig. 6", true},
      {"pulled_border_3d", "test case 2: pulled by a border", "Fig. 7", true},
      {"pulled_corner_3d", "test case 2: pulled by a corner", "Fig. 8", true},
      {"hammock_3d", "test case 2: own weight, two opposite borders fixed", "Fig. 9", true},
      {"hung_by_corner_3d", "test case 5: hung by one corner", "Fig. 10", false},
      {"dynamic_pulled_3d", "dynamic test case 2 (its equilibrium)", "Fig. 11", true},
      {"tombe1_3d", "tombe 1: a falling piece (its equilibrium)", "Fig. 12b", false},
  };
  return cases;
}

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void RunGnuplot(const fs::path& script) {
  const std::string command = "gnuplot '" + script.string() + "'";
  if (std::system(command.c_str()) != 0) std::cerr << "gnuplot failed on " << script << "\n";
}

// The structural springs as line segments (x y z, a blank line after each) at `positions`.
void WriteSegments(const Model& model, const std::vector<double>& positions, const fs::path& file) {
  std::ofstream out(file);
  for (const auto& term : model.terms) {
    if (term->type() != "structural") continue;
    for (int node : term->nodes()) {
      out << positions[3 * node] << " " << positions[3 * node + 1] << " " << positions[3 * node + 2]
          << "\n";
    }
    out << "\n";
  }
}

// The picture of a solved case: the final shape over the initial one (grey).
void DrawShape(const Paths& paths, const std::string& name, const Model& model,
               const std::string& title) {
  const fs::path start = paths.work / (name + "_start.dat");
  const fs::path final = paths.work / (name + "_final.dat");
  WriteSegments(model, model.initial, start);
  WriteSegments(model, model.positions, final);
  const fs::path script = paths.work / (name + ".gp");
  std::ofstream gp(script);
  gp << "set terminal pngcairo size 640,520 font 'sans,10'\n"
     << "set output '" << (paths.images / (name + ".png")).string() << "'\n"
     << "set title \"" << title << "\"\nunset key\n";
  if (model.dimension == 2) {
    gp << "set size ratio -1\nset xlabel 'x (m)'\nset ylabel 'z (m)'\n"
       << "plot '" << start.string() << "' using 1:3 with lines lc rgb '#bbbbbb', '"
       << final.string() << "' using 1:3 with lines lw 1.5 lc rgb '#1f4e99'\n";
  } else {
    gp << "set view 60,35\nset view equal xyz\nset xlabel 'x'\nset ylabel 'y'\nset zlabel 'z'\n"
       << "set ticslevel 0\n"
       << "splot '" << start.string() << "' with lines lc rgb '#cccccc', '" << final.string()
       << "' with lines lw 1.2 lc rgb '#1f4e99'\n";
  }
  gp.close();
  RunGnuplot(script);
}

struct Solution {
  Model model;
  RunResult result;
};

Solution Solve(const Scene& scene, const std::string& method) {
  Solution solution{BuildModel(scene), RunResult{}};
  solution.result = RunSolve(scene, solution.model, method);
  return solution;
}

double PositionGap(const Model& a, const Model& b) {
  double gap = 0.0;
  for (int k = 0; k < a.num_nodes; ++k) {
    double squared = 0.0;
    for (int c = 0; c < 3; ++c)
      squared += std::pow(a.positions[3 * k + c] - b.positions[3 * k + c], 2);
    gap = std::max(gap, std::sqrt(squared));
  }
  return gap / a.size;
}

double ReactionGap(const Model& model, const Certificate& a, const Certificate& b) {
  double difference = 0.0, norm = 0.0;
  for (int k = 0; k < model.num_dofs(); ++k) {
    if (!model.fixed[k]) continue;
    difference += std::pow(a.node_forces[k] - b.node_forces[k], 2);
    norm += std::pow(b.node_forces[k], 2);
  }
  return norm > 0.0 ? std::sqrt(difference / norm) : 0.0;
}

std::string Outcome(const RunResult& result) { return result.converged ? "yes" : "**no**"; }

// One row of the static table; draws the case.
std::string StaticRow(const Paths& paths, const CaseInfo& info) {
  const Scene scene = LoadScene((paths.root / "configs/puiseux" / (info.file + ".yaml")).string());
  Scene static_scene = scene;
  static_scene.solver.tolerance = 1e-8;  // the scene's own tolerance is the paper's for dynamics
  static_scene.solver.max_iterations = 100000;
  const Solution fixed_point = Solve(static_scene, "puiseux-fixed-point");
  const Solution newton = Solve(static_scene, "newton");
  std::cerr << info.file << ": fixed point " << fixed_point.result.summary.iterations
            << " it, newton " << newton.result.summary.iterations << " it\n";
  DrawShape(paths, info.file, newton.model, info.title + " (newton)");
  const auto& fp = fixed_point.result;
  const auto& nt = newton.result;
  std::ostringstream row;
  row << "| " << info.figure << " | [" << info.file << "](../configs/puiseux/" << info.file
      << ".yaml) | " << fp.summary.iterations << " | " << Format("%.2f", fp.summary.wall_time_s)
      << " | " << Format("%.1e", fp.certificate.relative_residual) << " | " << Outcome(fp) << " | "
      << nt.summary.iterations << " | " << Format("%.2f", nt.summary.wall_time_s) << " | "
      << Format("%.1e", nt.certificate.relative_residual) << " | "
      << (nt.stability.stable ? "stable" : "**saddle**") << " | "
      << Format("%.3e",
                (fp.certificate.energy - nt.certificate.energy) / std::abs(nt.certificate.energy))
      << " | ";
  if (info.unique) {
    row << Format("%.1e", PositionGap(fixed_point.model, newton.model)) << " | "
        << Format("%.1e", ReactionGap(newton.model, fp.certificate, nt.certificate)) << " |";
  } else {
    row << "(not unique) | (not unique) |";
  }
  return row.str();
}

// ------------------------------------------------------------------------------ dynamics

struct DynamicRun {
  double dt = 0, beta = 0;
  int iterations = 0;
  double residual = 0, t_final = 0, w_c = 0, w_cg = 0;
  std::string termination;
  fs::path trace;  // t, w_c
};

DynamicRun RunDynamic(const Paths& paths, const std::string& file, double dt, double beta,
                      double tolerance) {
  Scene scene = LoadScene((paths.root / "configs/puiseux" / (file + ".yaml")).string());
  scene.solver.tolerance = tolerance;
  scene.solver.max_iterations = 1000000;
  scene.solver.method_options["puiseux-dynamic"] = {
      {"dt", dt}, {"beta", beta}, {"t_max", 25.0}, {"epsilon", 1e-5}};
  Solution solution = Solve(scene, "puiseux-dynamic");
  DynamicRun run;
  run.dt = dt;
  run.beta = beta;
  const SolverSummary& summary = solution.result.summary;
  run.iterations = summary.iterations;
  run.residual = solution.result.certificate.relative_residual;
  run.termination = summary.termination;
  if (!summary.trace.empty()) {
    run.t_final = summary.trace.back()[1];
    run.w_c = summary.trace.back()[2];
    run.w_cg = summary.trace.back()[3];
  }
  run.trace =
      paths.work / (file + "_dt" + Format("%g", dt) + "_beta" + Format("%g", beta) + ".csv");
  std::ofstream out(run.trace);
  for (const auto& row : summary.trace) {
    if (row[2] > 0.0) out << row[1] << " " << row[2] << "\n";
  }
  std::cerr << file << " dt=" << dt << " beta=" << beta << ": " << run.iterations << " steps, "
            << summary.termination << "\n";
  return run;
}

void PlotKinetic(const Paths& paths, const std::vector<DynamicRun>& runs, const std::string& name,
                 const std::string& title) {
  const fs::path script = paths.work / (name + ".gp");
  std::ofstream gp(script);
  gp << "set terminal pngcairo size 760,520 font 'sans,10'\n"
     << "set output '" << (paths.images / (name + ".png")).string() << "'\n"
     << "set title \"" << title << "\"\nset logscale y\nset format y '%.0e'\n"
     << "set xlabel 't (s)'\nset ylabel 'w_c (J)'\nset key outside right\nplot ";
  for (size_t k = 0; k < runs.size(); ++k) {
    gp << (k ? ", " : "") << "'" << runs[k].trace.string() << "' using 1:2 with lines title 'dt "
       << runs[k].dt << ", beta " << runs[k].beta << "'";
  }
  gp << "\n";
  gp.close();
  RunGnuplot(script);
}

// The paper's table (§4.3.1), copied as printed.
struct PaperRow {
  const char *dt, *beta, *it, *r, *t_final, *w_c, *w_cg;
};
const std::vector<PaperRow>& PaperTable() {
  static const std::vector<PaperRow> rows = {
      {"5.0", "0", "5", "1.5e-2", "25", "3.5e-06", "2.7e-06"},
      {"0.5", "0", "50", "3.0e-3", "25", "5.0e-07", "5.1e-08"},
      {"0.05", "0", "500", "1.9e-4", "25", "5.2e-9", "2.8e-11"},
      {"0.01", "0", "1868", "3.13e-5", "18.7", "1.0e-12", "4.9e-15"},
      {"0.005", "0", "3140", "1.0e-5", "18", "2.2e-08", "2.7e-11"},
      {"0.001", "0", "12474", "9.9e-06", "12.5", "7.6e-06", "5.6e-06"},
      {"5.0", "1e-3", "5", "1.5e-2", "25", "3.5e-6", "2.7e-06"},
      {"0.5", "1e-3", "50", "3.0e-3", "25", "5.1e-7", "5.2e-8"},
      {"0.05", "1e-3", "500", "1.9e-4", "25", "5.3e-9", "2.9e-11"},
      {"0.01", "1e-3", "1656", "2.1e-5", "16.6", "1.0e-10", "1.5e-14"},
      {"0.05", "1e-6", "500", "1.9e-4", "25.0", "5.2e-09", "2.7e-11"},
      {"0.01", "1e-6", "1868", "2.1e-05", "18.7", "1.0e-10", "4.9e-15"},
  };
  return rows;
}

std::string DynamicTable(const Paths& paths, std::vector<DynamicRun>* runs) {
  std::ostringstream table;
  table << "| dt (s) | β | paper: it | r | t_final | w_c | w_cg | ours: it | r | t_final | w_c "
           "| w_cg | stopped by |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const PaperRow& paper : PaperTable()) {
    const DynamicRun run =
        RunDynamic(paths, "dynamic_pulled_3d", std::atof(paper.dt), std::atof(paper.beta), 1e-5);
    runs->push_back(run);
    std::string stop = run.termination.substr(0, run.termination.find(" ("));
    table << "| " << paper.dt << " | " << paper.beta << " | " << paper.it << " | " << paper.r
          << " | " << paper.t_final << " | " << paper.w_c << " | " << paper.w_cg << " | "
          << run.iterations << " | " << Format("%.2g", run.residual) << " | "
          << Format("%.4g", run.t_final) << " | " << Format("%.2g", run.w_c) << " | "
          << Format("%.2g", run.w_cg) << " | " << stop << " |\n";
  }
  return table.str();
}

std::string Read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace
}  // namespace drape

int main(int argc, char** argv) {
  using namespace drape;
  Paths paths;
  paths.root = fs::absolute(argc > 1 ? argv[1] : ".");
  paths.work = argc > 2 ? fs::path(argv[2]) : fs::path("/tmp/puiseux_report");
  paths.images = paths.root / "docs/img/puiseux";
  fs::create_directories(paths.work);
  fs::create_directories(paths.images);
  const auto start = std::chrono::steady_clock::now();
  try {
    std::ostringstream statics;
    statics << "| paper | scene | fixed point: it | s | residual | converged | newton: it | s | "
               "residual | stability | ΔE/|E| | max Δx / size | ‖ΔR‖/‖R‖ |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::ostringstream pictures;
    for (const CaseInfo& info : Cases()) {
      statics << StaticRow(paths, info) << "\n";
      pictures << "| " << info.figure << ": " << info.title << " |\n|---|\n| ![" << info.file
               << "](img/puiseux/" << info.file << ".png) |\n\n";
    }
    std::vector<DynamicRun> runs;
    const std::string dynamic = DynamicTable(paths, &runs);
    PlotKinetic(paths, runs, "kinetic_test_case_2",
                "Test case 2: kinetic energy w_c against time (cf. the paper's Figure 12)");
    std::vector<DynamicRun> falling;
    for (double dt : {0.05, 0.01, 0.005}) {
      falling.push_back(RunDynamic(paths, "tombe1_3d", dt, 0.01, 1e-5));
    }
    PlotKinetic(paths, falling, "kinetic_tombe1", "tombe 1: kinetic energy w_c against time");
    std::ostringstream falling_table;
    falling_table << "| dt (s) | β | steps | t_final | r | w_c | stopped by |\n"
                     "|---|---|---|---|---|---|---|\n";
    for (const DynamicRun& run : falling) {
      falling_table << "| " << run.dt << " | " << run.beta << " | " << run.iterations << " | "
                    << Format("%.4g", run.t_final) << " | " << Format("%.2g", run.residual) << " | "
                    << Format("%.2g", run.w_c) << " | "
                    << run.termination.substr(0, run.termination.find(" (")) << " |\n";
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string text = Read(paths.root / "tools/puiseux_report.md.in");
    auto substitute = [&text](const std::string& key, const std::string& value) {
      const std::string marker = "@" + key + "@";
      for (auto at = text.find(marker); at != std::string::npos; at = text.find(marker)) {
        text.replace(at, marker.size(), value);
      }
    };
    substitute("STATIC_TABLE", statics.str());
    substitute("PICTURES", pictures.str());
    substitute("DYNAMIC_TABLE", dynamic);
    substitute("TOMBE1_TABLE", falling_table.str());
    substitute("RUN_SECONDS", Format("%.0f", seconds));
    std::ofstream(paths.root / "docs/puiseux.md") << text;
    std::cerr << "wrote " << (paths.root / "docs/puiseux.md") << " in " << seconds << " s\n";
  } catch (const InputError& error) {
    std::cerr << error.what() << "\n";
    return 2;
  }
  return 0;
}
