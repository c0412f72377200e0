#include "src/compare/compare_report.h"

#include <ceres/version.h>
#include <cholmod.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlopt.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "src/numerics/library_threads.h"
#include "src/output/atomic_file.h"
#include "src/output/command_output.h"
#include "src/output/csv_field.h"
#include "src/output/gnuplot_plots.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/report_page.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}
std::string Number(double value) { return std::isfinite(value) ? Format("%.3g", value) : "—"; }

// Letters, digits, '-' and '_' only: safe in file names and gnuplot word lists.
std::string Slug(const std::string& name) {
  std::string slug;
  for (char c : name) slug += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return slug.empty() ? "scene" : slug;
}

std::string CpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown";
}

std::string Versions() {
  int major = 0, minor = 0, bugfix = 0;
  nlopt::version(major, minor, bugfix);
  std::ostringstream text;
  text << "Ceres " << CERES_VERSION_STRING << ", NLopt " << major << '.' << minor << '.' << bugfix
       << ", Eigen " << EIGEN_WORLD_VERSION << '.' << EIGEN_MAJOR_VERSION << '.'
       << EIGEN_MINOR_VERSION << ", CHOLMOD " << CHOLMOD_MAIN_VERSION << '.' << CHOLMOD_SUB_VERSION
       << '.' << CHOLMOD_SUBSUB_VERSION << ", " << CommandOutput("gnuplot --version 2>/dev/null");
  return text.str();
}

double RelativeError(const RunRecord& run) { return run.error.rms_m / run.size; }
bool HasPositions(const RunRecord& run) { return !run.positions.empty(); }

// ---- CSV files ----------------------------------------------------------------------------------

void WriteRunsCsv(const std::vector<SceneComparison>& comparisons, std::ostream& out) {
  out << "scene,solver,status,reason,iterations,time_median_s,times_s,callback_time_s,"
         "relative_residual,max_node_force_N,energy_J,energy_gap_J,max_distance_m,rms_distance_m,"
         "max_distance_rel,rms_distance_rel,drape_coefficient_gap,stable,peak_memory_MB";
  for (double level : AccuracyLevels()) out << ",time_to_" << Format("%.0e", level) << "_s";
  out << '\n';
  for (const SceneComparison& comparison : comparisons) {
    for (const RunRecord& run : comparison.runs) {
      std::string times;
      for (double t : run.times_s) times += (times.empty() ? "" : ";") + FormatNumber(t);
      out << CsvField(run.scene) << ',' << run.solver << ',' << RunStatusName(run.status) << ','
          << CsvField(run.reason) << ',' << run.iterations << ',' << CsvNumber(run.time_s) << ','
          << times << ',' << CsvNumber(run.callback_time_s) << ','
          << CsvNumber(run.relative_residual) << ',' << CsvNumber(run.max_node_force) << ','
          << CsvNumber(run.energy) << ',' << CsvNumber(run.energy_gap) << ','
          << CsvNumber(run.error.max_m) << ',' << CsvNumber(run.error.rms_m) << ','
          << CsvNumber(run.error.max_m / run.size) << ',' << CsvNumber(RelativeError(run)) << ','
          << CsvNumber(run.drape_coefficient_gap) << ','
          << (run.stability_computed ? JsonBool(run.stable) : "") << ','
          << CsvNumber(run.peak_memory_mb);
      for (double level : AccuracyLevels()) {  // empty: not reached, or no position errors
        const double t = HasPositions(run) ? TimeToReach(run, level) : -1.0;
        out << ',' << (t < 0 ? "" : CsvNumber(t));
      }
      out << '\n';
    }
  }
}

void WriteCurvesCsv(const std::vector<SceneComparison>& comparisons, std::ostream& out) {
  out << "scene,solver,iteration,time_s,relative_residual,energy_gap_J,max_distance_m,"
         "rms_distance_m,rms_distance_rel\n";
  for (const SceneComparison& comparison : comparisons) {
    for (const RunRecord& run : comparison.runs) {
      for (const CurvePoint& point : run.curve) {
        out << CsvField(run.scene) << ',' << run.solver << ',' << point.iteration << ','
            << FormatNumber(point.time_s) << ',' << FormatNumber(point.relative_residual) << ','
            << FormatNumber(point.energy_gap) << ',' << FormatNumber(point.error.max_m) << ','
            << FormatNumber(point.error.rms_m) << ',' << FormatNumber(point.error.rms_m / run.size)
            << '\n';
      }
    }
  }
}

void WriteReferencesCsv(const std::vector<SceneComparison>& comparisons, std::ostream& out) {
  out << "scene,file,method,tolerance,converged,termination,iterations,time_s,energy_J,"
         "relative_residual,max_node_force_N,stable,energy_tolerance_J,size_m\n";
  for (const SceneComparison& c : comparisons) {
    const SceneReference& r = c.reference;
    out << CsvField(c.name) << ',' << CsvField(c.file) << ',' << r.method << ','
        << FormatNumber(r.tolerance) << ',' << JsonBool(r.converged) << ','
        << CsvField(r.termination) << ',' << r.iterations << ',' << FormatNumber(r.time_s) << ','
        << FormatNumber(r.energy) << ',' << FormatNumber(r.relative_residual) << ','
        << FormatNumber(r.max_node_force) << ',' << (r.stability_computed ? JsonBool(r.stable) : "")
        << ',' << FormatNumber(r.energy_tolerance) << ',' << FormatNumber(c.size) << '\n';
  }
}

// ---- plots --------------------------------------------------------------------------------------

// Log axes drop zeros: times and errors are floored for the plot only (the CSVs keep them).
double Floor(double value, double floor) { return std::max(value, floor); }

// The PNG, "" where gnuplot could not draw it, nothing where there is nothing to plot.
std::optional<std::string> CurvesPlot(const SceneComparison& comparison, GnuplotPlots& plotter) {
  std::string files, titles;
  for (const RunRecord& run : comparison.runs) {
    if (run.curve.empty() || !run.curve_positions_valid) continue;
    const std::string file =
        plotter.Data(Slug(comparison.name) + "__" + run.solver + ".dat", [&](std::ostream& out) {
          out << "# time_s rms_distance_rel relative_residual\n";
          for (const CurvePoint& p : run.curve) {
            out << FormatNumber(Floor(p.time_s, 1e-6)) << ' '
                << FormatNumber(Floor(p.error.rms_m / run.size, 1e-17)) << ' '
                << FormatNumber(Floor(p.relative_residual, 1e-17)) << '\n';
          }
        });
    files += (files.empty() ? "" : " ") + file;
    titles += (titles.empty() ? "" : " ") + run.solver;
  }
  if (files.empty()) return std::nullopt;
  return plotter.Draw("compare_curves.gp", Slug(comparison.name) + "_curves.png",
                      {{"files", files}, {"titles", titles}, {"title", comparison.name}});
}

// The Pareto plot's marker of the k-th scene (gnuplot's point types 1–13; the colour is the
// solver's). compare_pareto.gp draws the same types in its legend of scenes.
int ScenePointType(size_t k) { return static_cast<int>(k % 13) + 1; }

// The PNG, "" where gnuplot could not draw it, nothing where there is nothing to plot.
std::optional<std::string> ParetoPlot(const std::vector<SceneComparison>& comparisons,
                                      GnuplotPlots& plotter) {
  std::vector<std::string> solvers;
  for (const SceneComparison& c : comparisons) {
    for (const RunRecord& run : c.runs) {
      if (HasPositions(run) &&
          std::find(solvers.begin(), solvers.end(), run.solver) == solvers.end()) {
        solvers.push_back(run.solver);
      }
    }
  }
  std::string files, titles;
  for (const std::string& solver : solvers) {
    const std::string file = plotter.Data("pareto__" + solver + ".dat", [&](std::ostream& out) {
      out << "# time_s rms_distance_rel scene point_type\n";
      for (size_t k = 0; k < comparisons.size(); ++k) {
        for (const RunRecord& run : comparisons[k].runs) {
          if (run.solver != solver || !HasPositions(run)) continue;
          out << FormatNumber(Floor(run.time_s, 1e-6)) << ' '
              << FormatNumber(Floor(RelativeError(run), 1e-17)) << ' ' << Slug(comparisons[k].name)
              << ' ' << ScenePointType(k) << '\n';
        }
      }
    });
    files += (files.empty() ? "" : " ") + file;
    titles += (titles.empty() ? "" : " ") + solver;
  }
  if (files.empty()) return std::nullopt;
  std::string scenes;
  for (const SceneComparison& c : comparisons) scenes += (scenes.empty() ? "" : " ") + Slug(c.name);
  return plotter.Draw("compare_pareto.gp", "pareto.png",
                      {{"files", files}, {"titles", titles}, {"scenes", scenes}});
}

std::string DrapePlot(const SceneComparison& comparison, const std::vector<double>& positions,
                      bool colour_by_distance, const std::string& name, const std::string& title,
                      GnuplotPlots& plotter) {
  const std::vector<double>& reference = comparison.reference.positions;
  const std::string file =
      plotter.Data(Slug(comparison.name) + "__" + name + ".dat", [&](std::ostream& out) {
        out << "# x y z colour\n";
        for (size_t node = 0; 3 * node + 2 < positions.size(); ++node) {
          double distance = 0.0;
          for (int c = 0; c < 3; ++c) {
            distance += std::pow(positions[3 * node + c] - reference[3 * node + c], 2);
          }
          out << FormatNumber(positions[3 * node]) << ' ' << FormatNumber(positions[3 * node + 1])
              << ' ' << FormatNumber(positions[3 * node + 2]) << ' '
              << FormatNumber(colour_by_distance ? std::sqrt(distance) : positions[3 * node + 2])
              << '\n';
        }
      });
  return plotter.Draw("compare_drape.gp", Slug(comparison.name) + "_" + name + ".png",
                      {{"input", file},
                       {"title", title},
                       {"colour", colour_by_distance ? "distance to the reference (m)" : "z (m)"}});
}

// ---- report blocks ------------------------------------------------------------------------------

std::string Seconds(double t) {
  if (t == kTimeUnknown) return "n/a";
  return t < 0 ? "—" : Format("%.3g s", t);
}

std::string ReferenceText(const SceneComparison& c) {
  const SceneReference& r = c.reference;
  std::ostringstream text;
  text << "Scene `" << c.file << "`: " << c.num_nodes << " nodes, " << c.free_dofs
       << " free dofs, size " << Number(c.size) << " m. Reference: " << r.method
       << " asked for a relative residual of " << Number(r.tolerance) << ": "
       << (r.converged ? "converged" : "stopped") << " (" << r.termination << ") in "
       << r.iterations << " iterations, " << Seconds(r.time_s) << "; "
       << (r.relative_residual <= r.scene_tolerance ? "accepted: within"
                                                    : "NOT within (errors below are approximate)")
       << " the scene's tolerance " << Number(r.scene_tolerance) << ". Certificate: energy "
       << Format("%.10g", r.energy) << " J, relative residual " << Number(r.relative_residual)
       << ", largest nodal force " << Number(r.max_node_force) << " N, "
       << (r.stability_computed ? (r.stable ? "stable" : "unstable") : "stability unknown")
       << ". A converged run whose energy differs by more than " << Number(r.energy_tolerance)
       << " J is reported as a different equilibrium.";
  return text.str();
}

ReportBlock FinalTable(const SceneComparison& c) {
  std::vector<std::vector<std::string>> rows = {
      {"solver", "status", "iterations", "time", "residual", "energy gap (J)", "max dist (m)",
       "RMS dist / size", "DC gap", "peak memory (MB)", "reason"}};
  for (const RunRecord& run : c.runs) {
    const bool measured = HasPositions(run);
    const bool has_dc = measured && std::isfinite(run.drape_coefficient_gap);
    rows.push_back(
        {run.solver, RunStatusName(run.status), measured ? std::to_string(run.iterations) : "—",
         measured ? Seconds(run.time_s) : "—", measured ? Number(run.relative_residual) : "—",
         measured ? Number(run.energy_gap) : "—", measured ? Number(run.error.max_m) : "—",
         measured ? Number(RelativeError(run)) : "—",
         has_dc ? Number(run.drape_coefficient_gap) : "—",
         measured ? Number(run.peak_memory_mb) : "—", run.reason});
  }
  return TableBlock(std::move(rows));
}

ReportBlock SpeedTable(const SceneComparison& c) {
  std::vector<std::vector<std::string>> rows(1, {"solver"});
  for (double level : AccuracyLevels()) rows[0].push_back("to " + Format("%.0e", level));
  for (const RunRecord& run : c.runs) {
    std::vector<std::string> row = {run.solver};
    for (double level : AccuracyLevels()) {
      row.push_back(HasPositions(run) ? Seconds(TimeToReach(run, level)) : "—");
    }
    rows.push_back(std::move(row));
  }
  return TableBlock(std::move(rows));
}

const RunRecord* LargestDeviation(const SceneComparison& c) {
  const RunRecord* largest = nullptr;
  for (const RunRecord& run : c.runs) {
    if (!HasPositions(run) || !std::isfinite(run.error.max_m)) continue;
    if (!largest || run.error.max_m > largest->error.max_m) largest = &run;
  }
  return largest;
}

// The plot, or where gnuplot could not draw it (missing, too old: GnuplotPlots::Draw), a line that
// says so in its place: a chart is never silently missing. Nothing where there is nothing to plot.
void AddPlot(const std::optional<std::string>& png, const std::string& caption,
             std::vector<ReportBlock>* blocks) {
  if (!png) return;
  if (!png->empty()) {
    blocks->push_back(ImageBlock(*png, caption));
    return;
  }
  blocks->push_back(
      TextBlock("Not drawn: " + caption +
                " (gnuplot failed or is not installed; its messages are in plots/gnuplot.log)"));
}

std::vector<ReportBlock> SceneBlocks(const SceneComparison& c, GnuplotPlots* plots) {
  std::vector<ReportBlock> blocks = {HeadingBlock(c.name)};
  if (!c.error.empty()) {
    blocks.push_back(TextBlock("Scene `" + c.file + "` not compared: " + c.error));
    return blocks;
  }
  blocks.push_back(TextBlock(ReferenceText(c)));
  blocks.push_back(
      TextBlock("Final state of every run (time: median of the repeats, without the "
                "time spent measuring in the iteration callback):"));
  blocks.push_back(FinalTable(c));
  blocks.push_back(
      TextBlock("Time to reach a relative position error (RMS node distance to the "
                "reference / size):"));
  blocks.push_back(SpeedTable(c));
  std::string blind;
  for (const RunRecord& run : c.runs) {
    if (!run.curve_positions_valid) blind += (blind.empty() ? "" : ", ") + run.solver;
  }
  if (!blind.empty()) {
    blocks.push_back(TextBlock("n/a: " + blind +
                               " did not expose the current iterate in model.positions during the "
                               "iteration callback, so their intermediate position errors are "
                               "unknown (their final state above is measured)."));
  }
  if (!plots) return blocks;
  GnuplotPlots& plotter = *plots;
  AddPlot(CurvesPlot(c, plotter), "Position error against time, " + c.name, &blocks);
  AddPlot(DrapePlot(c, c.reference.positions, false, "reference",
                    c.name + ": reference (" + c.reference.method + ")", plotter),
          "Reference drape, " + c.name, &blocks);
  if (const RunRecord* run = LargestDeviation(c)) {
    const std::string title =
        c.name + ": " + run->solver + ", largest distance " + Number(run->error.max_m) + " m";
    AddPlot(DrapePlot(c, run->positions, true, "deviation", title, plotter),
            "Largest deviation: " + run->solver + " on " + c.name, &blocks);
  }
  return blocks;
}

// compare.json: how the report was made (ProvenanceMembers) and what was asked, beside the CSV
// files (which carry no comment line, so that pandas reads them as they are).
void WriteCompareJson(const CompareOptions& options, double total_time_s, std::ostream& out) {
  std::vector<std::pair<std::string, std::string>> members = {
      {"scenes", JsonList(JsonStrings(options.scenes))},
      {"solvers", JsonList(JsonStrings(options.solvers))},
      {"repeat", std::to_string(options.repeat)},
      {"time_limit_s", JsonNumber(options.time_limit)},
      {"reference_tolerance", JsonNumber(options.reference_tolerance)},
      {"total_time_s", JsonNumber(total_time_s)},
      {"files", JsonList(JsonStrings(
                    {"runs.csv", "curves.csv", "references.csv", "report.md", "report.html"}))}};
  for (auto& member : ProvenanceMembers(Provenance{options.command_line, options.overrides})) {
    members.push_back(std::move(member));
  }
  out << JsonObject(members, 0) << "\n";
}

std::vector<ReportBlock> HeaderBlocks(const CompareOptions& options, double total_time_s) {
  const LibraryThreads threads = RunLibrariesOnOneThread();
  std::ostringstream machine;
  machine << "Machine: " << CpuModel() << ", " << std::thread::hardware_concurrency()
          << " logical CPUs (nproc). Threads: runs are sequential; Ceres runs with its default of "
             "1 thread; CHOLMOD's OpenMP regions "
          << (threads.openmp_single ? "on 1 thread" : "as the environment sets them")
          << ", OpenBLAS "
          << (threads.openblas_single ? "on 1 thread" : "as the environment sets it")
          << " (src/numerics/library_threads.h); OpenBLAS kernels " << BlasKernelsText()
          << ". Versions: " << Versions() << '.';
  std::ostringstream method;
  method << "Each scene is solved first by the reference (newton to a relative residual of "
         << Number(options.reference_tolerance)
         << "; if it does not reach the scene's tolerance, the converged run with the smallest "
            "residual among the selected solvers). Every solver then runs with the scene's "
            "tolerance and iteration limit and a time limit of "
         << Number(options.time_limit) << " s; " << options.repeat
         << " timed repeat(s), the median is reported. Errors are measured in the iteration "
            "callback; its time is subtracted from the solver's clock. Peak memory: the "
            "process's peak resident size (VmHWM) reset through /proc/self/clear_refs before "
            "each run, minus the resident size (VmRSS) at its start. Total time of this "
            "comparison: "
         << Seconds(total_time_s) << '.';
  return {HeadingBlock("drape solver comparison"),
          TextBlock(ProvenanceLine(Provenance{options.command_line, options.overrides}) + "."),
          TextBlock(machine.str()), TextBlock(method.str())};
}

}  // namespace

void WriteCompareReport(const std::vector<SceneComparison>& comparisons,
                        const CompareOptions& options, double total_time_s, std::ostream& log) {
  const fs::path out_dir = options.out_dir;
  fs::create_directories(out_dir);
  WriteAtomically(out_dir / "runs.csv", [&](std::ostream& o) { WriteRunsCsv(comparisons, o); });
  WriteAtomically(out_dir / "curves.csv", [&](std::ostream& o) { WriteCurvesCsv(comparisons, o); });
  WriteAtomically(out_dir / "references.csv",
                  [&](std::ostream& o) { WriteReferencesCsv(comparisons, o); });
  WriteAtomically(out_dir / "compare.json",
                  [&](std::ostream& o) { WriteCompareJson(options, total_time_s, o); });

  std::optional<GnuplotPlots> plots;
  if (options.plots) plots.emplace(out_dir, options.tools_dir, log);
  std::vector<ReportBlock> blocks = HeaderBlocks(options, total_time_s);
  if (plots) {
    AddPlot(ParetoPlot(comparisons, *plots),
            "Time against final position error, every solver and scene", &blocks);
  }
  for (const SceneComparison& comparison : comparisons) {
    std::vector<ReportBlock> scene_blocks = SceneBlocks(comparison, plots ? &*plots : nullptr);
    blocks.insert(blocks.end(), scene_blocks.begin(), scene_blocks.end());
  }
  blocks.push_back(
      TextBlock("Raw numbers: runs.csv (one row per run), curves.csv (one row per "
                "iteration per run), references.csv (one row per scene); how they were made: "
                "compare.json."));
  WriteAtomically(out_dir / "report.md", [&](std::ostream& o) { WriteMarkdownReport(blocks, o); });
  WriteAtomically(out_dir / "report.html",
                  [&](std::ostream& o) { WriteHtmlReport(blocks, out_dir, o); });
}

}  // namespace drape
