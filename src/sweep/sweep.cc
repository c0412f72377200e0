#include "src/sweep/sweep.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "src/analysis/mesh_rule.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/result_folder.h"
#include "src/output/version.h"
#include "src/output/writers.h"
#include "src/parallel/farm_record.h"
#include "src/parallel/process_group.h"
#include "src/parallel/task_farm.h"
#include "src/run/solve_report.h"
#include "src/run/state_text.h"
#include "src/scene/scene_loader.h"
#include "src/solvers/solver.h"
#include "src/sweep/sweep_report.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRowFile = "row.csv";
constexpr const char* kVariantFile = "variant.txt";
constexpr const char* kPositionsFile = "final_positions.txt";  // warm-start sweeps only

// The columns after the varied keys (and `repeat`).
const std::vector<std::string> kResultColumns = {"converged",
                                                 "stop_reason",
                                                 "iterations",
                                                 "time_s",
                                                 "energy_J",
                                                 "relative_residual",
                                                 "max_node_force_N",
                                                 "stable",
                                                 "drape_coefficient",
                                                 "drape_coefficient_error",
                                                 "folds",
                                                 "certificate",
                                                 "warm_start_from",
                                                 "drape_version"};

// The cells of task `task` before its results: number, values, repeat.
std::vector<std::string> TaskCells(const SweepSpec& spec, int task) {
  std::vector<std::string> cells = {std::to_string(task)};
  for (const SweepValue& value : spec.tasks[task].values) cells.push_back(value.text);
  if (spec.repeat > 1) cells.push_back(std::to_string(spec.tasks[task].repeat));
  return cells;
}

std::vector<std::string> SolvedRow(const SweepSpec& spec, int task, const Scene& scene,
                                   const Model& model, const SolveReport& report, int warm_from) {
  const RunResult& result = report.result;
  const std::optional<double> dc_error = ReportedDrapeCoefficientError(report);
  std::vector<std::string> cells = TaskCells(spec, task);
  const Stability& stability = result.stability;
  const bool stable_known = stability.computed && result.certificate.unsound.empty();
  cells.insert(
      cells.end(),
      {JsonBool(result.converged), result.summary.termination,
       std::to_string(result.summary.iterations), CsvNumber(result.summary.wall_time_s),
       CsvNumber(result.certificate.energy), CsvNumber(result.certificate.relative_residual),
       CsvNumber(result.certificate.max_node_force), stable_known ? JsonBool(stability.stable) : "",
       report.drape ? CsvNumber(ReportedDrapeCoefficient(report)) : "",
       dc_error ? CsvNumber(*dc_error) : "",
       report.drape ? std::to_string(report.drape->folds.count) : "", StateText(result),
       warm_from >= 0 ? std::to_string(warm_from) : "", DrapeVersion()});
  return cells;
}

std::vector<std::string> FailedRow(const SweepSpec& spec, int task, const std::string& why) {
  std::vector<std::string> cells = TaskCells(spec, task);
  cells.insert(cells.end(), {JsonBool(false), "failed: " + why, "", "", "", "", "", "", "", "", "",
                             "", "", DrapeVersion()});
  return cells;
}

// ---- a task's folder ----------------------------------------------------------------------------

struct Context {
  const SweepSpec& spec;
  std::string directory;
  std::string command_line;
  std::string header;  // CSV header line
  std::vector<std::string> identities;
};

// Whether a row's `converged` cell is true or false (a row of an older drape says yes or no: its
// task is solved again, so that sweep.csv has one spelling of booleans).
bool HasBooleanCells(const std::string& line) {
  const std::vector<std::string> cells = SplitCsvLine(line);
  if (cells.size() < kResultColumns.size()) return false;
  const std::string& converged = cells[cells.size() - kResultColumns.size()];
  return converged == JsonBool(true) || converged == JsonBool(false);
}

// The row of a finished task (its folder holds a row for the same variant), else nothing.
std::optional<std::string> FinishedRow(const Context& context, int task) {
  const fs::path folder = TaskFolder(context.directory, context.spec, task);
  if (ReadWholeFile(folder / kVariantFile) != context.identities[task]) return std::nullopt;
  std::istringstream row(ReadWholeFile(folder / kRowFile));
  std::string header, line;
  if (!std::getline(row, header) || header != context.header || !std::getline(row, line) ||
      !HasBooleanCells(line)) {
    return std::nullopt;
  }
  return line;
}

void WritePositions(const fs::path& path, const std::vector<double>& positions) {
  WriteAtomically(path, [&](std::ostream& out) {
    for (const double x : positions) out << FormatNumber(x) << '\n';
  });
}

// The final positions a finished task saved (FormatNumber: they read back exactly); empty if none.
std::vector<double> ReadPositions(const fs::path& path) {
  std::ifstream in(path);
  std::vector<double> positions;
  std::string line;
  while (std::getline(in, line)) positions.push_back(std::strtod(line.c_str(), nullptr));
  return positions;
}

// What one task gives back to the chain: its row, whether it is finished (saved), and its final
// positions (the next task's warm start).
struct TaskOutcome {
  std::string kind;  // solved, failed (saved as a finished row), unsaved, interrupted
  std::string row;
  std::vector<double> positions;
};

void SaveRow(const Context& context, int task, const std::string& row) {
  const fs::path folder = TaskFolder(context.directory, context.spec, task);
  WriteAtomically(folder / kVariantFile,
                  [&](std::ostream& out) { out << context.identities[task]; });
  WriteAtomically(folder / kRowFile, [&](std::ostream& out) {
    out << context.header << '\n' << row << '\n';
  });
}

// Starts the model from `warm` (the previous task's final positions: free coordinates only, the
// fixed ones as the scene says) when it fits; true if it did.
bool WarmStart(const Scene& scene, const std::vector<double>* warm, Model* model) {
  if (!warm || warm->size() != model->positions.size() || scene.solver.levels > 1) return false;
  for (size_t k = 0; k < warm->size(); ++k) {
    if (!model->fixed[k]) model->positions[k] = (*warm)[k];
  }
  return true;
}

TaskOutcome SolveTask(const Context& context, int task, const std::vector<double>* warm,
                      int warm_from) {
  const SweepSpec& spec = context.spec;
  const std::string folder = TaskFolder(context.directory, spec, task);
  const Scene scene = TaskScene(spec, task);
  Model model = BuildModel(scene);
  ResultFolderLock lock(folder);  // throws if another run is writing this task
  std::error_code ignored;
  fs::remove(fs::path(folder) / kRowFile, ignored);  // unfinished from here on
  const bool warmed = WarmStart(scene, warm, &model);
  const SolveReport report =
      SolveAndReport(scene, model, scene.solver.method, {}, /*automatic_levels=*/!warmed);
  TaskOutcome outcome;
  if (InterruptRequested()) {
    outcome.kind = "interrupted";
    outcome.row = CsvLine(FailedRow(spec, task, report.result.summary.termination));
    return outcome;
  }
  WriteOutputs(scene, model, report, folder,
               Provenance{context.command_line + " (task " + std::to_string(task) + ")",
                          TaskOverrides(spec, task)});
  if (spec.warm_axis >= 0) WritePositions(fs::path(folder) / kPositionsFile, model.positions);
  outcome.kind = "solved";
  outcome.row = CsvLine(SolvedRow(spec, task, scene, model, report, warmed ? warm_from : -1));
  outcome.positions = model.positions;
  SaveRow(context, task, outcome.row);
  return outcome;
}

// A task whose scene fails (an InputError at build or solve time, e.g. a method that refuses the
// model) is a failed row, saved: it would fail again, so a restart keeps it. Any other failure
// (out of memory, a file that cannot be written, another run holding the folder) depends on the
// moment: its row goes into sweep.csv but not into the folder, and a restart solves it again.
TaskOutcome RunTask(const Context& context, int task, const std::vector<double>* warm,
                    int warm_from) {
  std::string why;
  try {
    return SolveTask(context, task, warm, warm_from);
  } catch (const InputError& error) {
    why = error.what();
  } catch (const std::bad_alloc&) {
    return {"unsaved", CsvLine(FailedRow(context.spec, task, "out of memory")), {}};
  } catch (const std::exception& error) {
    return {"unsaved", CsvLine(FailedRow(context.spec, task, error.what())), {}};
  }
  TaskOutcome outcome{"failed", CsvLine(FailedRow(context.spec, task, why)), {}};
  try {
    fs::create_directories(TaskFolder(context.directory, context.spec, task));
    SaveRow(context, task, outcome.row);
  } catch (const std::exception&) {
    outcome.kind = "unsaved";
  }
  return outcome;
}

// One farm task: a chain's tasks in order, up to `last` (-1: all), each skipped if finished. The
// result: a FarmRecord per task (its kind, number and sweep.csv row).
std::string RunChain(const Context& context, const std::vector<int>& chain, int last) {
  std::vector<FarmRecord> result;
  std::vector<double> warm;  // the previous task's final positions
  int previous = -1;
  for (const int task : chain) {
    TaskOutcome outcome;
    if (const auto row = FinishedRow(context, task)) {
      outcome = {"skipped", *row, {}};
      if (context.spec.warm_axis >= 0) {
        outcome.positions = ReadPositions(
            fs::path(TaskFolder(context.directory, context.spec, task)) / kPositionsFile);
      }
    } else if (InterruptRequested()) {
      outcome = {
          "interrupted", CsvLine(FailedRow(context.spec, task, "not run (interrupted)")), {}};
    } else {
      outcome = RunTask(context, task, previous >= 0 && !warm.empty() ? &warm : nullptr, previous);
    }
    result.push_back({outcome.kind, task, outcome.row, {}});
    warm = std::move(outcome.positions);
    previous = task;
    if (task == last) break;
  }
  return EncodeFarmRecords(result);
}

// ---- the coordinator's table --------------------------------------------------------------------

class SweepTable {
 public:
  SweepTable(const Context& context, std::ostream& log) : context_(context), log_(log) {
    std::map<std::string, int> other_versions;  // rows kept from another drape, by its version
    for (int task = 0; task < static_cast<int>(context.spec.tasks.size()); ++task) {
      const auto row = FinishedRow(context, task);
      if (!row) continue;
      rows_[task] = *row;
      const std::string version = SplitCsvLine(*row).back();
      if (version != DrapeVersion()) ++other_versions[version];
    }
    for (const auto& [version, count] : other_versions) {
      log_ << "sweep: " << count << " finished task" << (count == 1 ? "" : "s")
           << " kept from drape " << version << " (this is " << DrapeVersion()
           << "; sweep.csv's drape_version column says which drape solved each row)\n";
    }
  }

  void Collect(const std::string& result, SweepSummary* summary) {
    for (const FarmRecord& record : DecodeFarmRecords(result)) {
      if (record.kind == "skipped") ++summary->skipped;
      if (record.kind == "interrupted") summary->interrupted = true;
      if (record.kind == "interrupted" || record.kind == "skipped") continue;
      rows_[record.task] = record.row;
      if (record.kind == "solved") ++summary->solved;
      ++done_;
      Progress(record.task, record.row);
    }
    Write();
  }

  void Write() const {
    WriteAtomically(fs::path(context_.directory) / "sweep.csv", [&](std::ostream& out) {
      out << context_.header << '\n';
      for (const auto& [task, row] : rows_) out << row << '\n';
    });
  }

  const std::map<int, std::string>& rows() const { return rows_; }

 private:
  // "sweep: task 7 (3 done): converged, 42 iterations, 1.2 s, energy ..., DC 0.65, warm from 6".
  void Progress(int task, const std::string& line) const {
    const std::vector<std::string> cells = SplitCsvLine(line);
    const size_t at = cells.size() - kResultColumns.size();
    auto cell = [&](const char* name) {
      for (size_t k = 0; k < kResultColumns.size(); ++k) {
        if (kResultColumns[k] == name) return cells[at + k];
      }
      return std::string();
    };
    const auto rounded = [&](const char* name, int digits) {
      return RoundedNumber(std::strtod(cell(name).c_str(), nullptr), digits);
    };
    log_ << "sweep: task " << task << " (" << done_ << " done this run): "
         << (cell("converged") == JsonBool(true) ? "converged" : "not converged") << ", "
         << (cell("iterations").empty() ? "" : cell("iterations") + " iterations, ")
         << (cell("time_s").empty() ? "" : rounded("time_s", 3) + " s, ")
         << (cell("drape_coefficient").empty() ? "" : "DC " + rounded("drape_coefficient", 4))
         << (cell("drape_coefficient_error").empty()
                 ? ""
                 : " ± " + rounded("drape_coefficient_error", 2))
         << (cell("drape_coefficient").empty() ? "" : ", ") << cell("stop_reason")
         << (cell("warm_start_from").empty() ? "" : ", warm from task " + cell("warm_start_from"))
         << std::endl;
  }

  const Context& context_;
  std::ostream& log_;
  std::map<int, std::string> rows_;
  int done_ = 0;
};

// The farm's tasks: the chains to run (with --only, the one holding that task).
std::vector<int> FarmTasks(const SweepSpec& spec, const SweepOptions& options) {
  if (options.only) return {ChainOf(spec, *options.only)};
  std::vector<int> chains(spec.chains.size());
  for (int c = 0; c < static_cast<int>(chains.size()); ++c) chains[c] = c;
  return chains;
}

// sweep.json: what the sweep is, how many rows sweep.csv has, and how it was made
// (ProvenanceMembers): the sidecar of sweep.csv, which carries no comment line so that pandas
// reads it as it is.
void WriteSweepJson(const SweepSpec& spec, const SweepSummary& summary,
                    const Provenance& provenance, std::ostream& out) {
  std::vector<std::pair<std::string, std::string>> members = {
      {"sweep_file", JsonString(spec.file)},
      {"scene_file", JsonString(spec.scene_file)},
      {"design", JsonString(spec.design)},
      {"tasks", std::to_string(spec.tasks.size())},
      {"rows", std::to_string(summary.rows)},
      {"rows_converged", std::to_string(summary.converged)}};
  for (auto& member : ProvenanceMembers(provenance)) members.push_back(std::move(member));
  out << JsonObject(members, 0) << "\n";
}

void CountRows(const SweepTable& table, SweepSummary* summary) {
  summary->rows = static_cast<int>(table.rows().size());
  for (const auto& [task, row] : table.rows()) {
    const auto cells = SplitCsvLine(row);
    if (cells[cells.size() - kResultColumns.size()] == JsonBool(true)) {
      ++summary->converged;
      summary->converged_tasks.insert(task);
    }
  }
}

// The mesh rule's warning (src/analysis/mesh_rule.h), once, for the sweep's tasks (with --only,
// that task) whose mesh is coarser than their fabric needs: how many, which, and `drape solve`'s
// warning for the one expected to be furthest off. From each task's scene alone (no model built):
// a sweep over the bending or the density moves the spacing its fabrics need. A scene that cannot
// be loaded is its task's failed row, not a warning.
void WarnOfCoarseMeshes(const SweepSpec& spec, const SweepOptions& options, std::ostream& log) {
  std::vector<std::string> labels;
  std::vector<std::optional<MeshAdvice>> advice;
  for (int task = 0; task < static_cast<int>(spec.tasks.size()); ++task) {
    if (options.only && task != *options.only) continue;
    labels.push_back(std::to_string(task));
    try {
      advice.push_back(AdviseMeshOfScene(TaskScene(spec, task)));
    } catch (const InputError&) {
      advice.push_back(std::nullopt);
    }
  }
  if (const auto line = CoarseMeshesLine(labels, advice, "task", "drape_coefficient_error")) {
    log << "drape sweep: warning: " << *line << "\n";
  }
}

}  // namespace

std::optional<std::string> CoarseMeshesLine(const std::vector<std::string>& labels,
                                            const std::vector<std::optional<MeshAdvice>>& advice,
                                            const std::string& what,
                                            const std::string& error_column) {
  constexpr size_t kNamed = 8;  // the first eight named, then "…"
  std::vector<size_t> coarse;
  size_t worst = 0;
  for (size_t k = 0; k < advice.size(); ++k) {
    if (!advice[k] || !advice[k]->coarse) continue;
    if (coarse.empty() || advice[k]->expected_error > advice[worst]->expected_error) worst = k;
    coarse.push_back(k);
  }
  if (coarse.empty()) return std::nullopt;
  std::string names;
  for (size_t k = 0; k < std::min(coarse.size(), kNamed); ++k) {
    names += (k ? ", " : "") + labels[coarse[k]];
  }
  if (coarse.size() > kNamed) names += ", …";
  const auto plural = [&](size_t count) { return what + (count == 1 ? "" : "s"); };
  return std::to_string(coarse.size()) + " of " + std::to_string(advice.size()) + " " +
         plural(advice.size()) + " on a mesh coarser than their fabric's mesh rule (" +
         plural(coarse.size()) + " " + names + "; each row's " + error_column +
         " includes the rule's error); the furthest off, " + what + " " + labels[worst] + ": " +
         CoarseMeshWarning(*advice[worst]);
}

std::vector<std::string> SweepColumns(const SweepSpec& spec) {
  std::vector<std::string> columns = {"task"};
  for (const SweepKey& key : spec.keys) columns.push_back(key.key);
  if (spec.repeat > 1) columns.push_back("repeat");
  columns.insert(columns.end(), kResultColumns.begin(), kResultColumns.end());
  return columns;
}

std::string TaskFolder(const std::string& directory, const SweepSpec& spec, int task) {
  const int width = std::max(4, static_cast<int>(std::to_string(spec.tasks.size() - 1).size()));
  std::string number = std::to_string(task);
  number.insert(0, static_cast<size_t>(std::max(0, width - static_cast<int>(number.size()))), '0');
  return (fs::path(directory) / "tasks" / number).string();
}

std::vector<std::string> TaskIdentities(const SweepSpec& spec) {
  // The base scene by its name and its text (not its full path: a sweep folder moved with its
  // scene, e.g. onto a cluster, keeps its finished tasks).
  const std::string scene = "scene: " + fs::path(spec.scene_file).filename().string() +
                            "\nscene_fingerprint: " + Fingerprint(spec.scene->text()) + "\n";
  std::vector<std::string> identities(spec.tasks.size());
  for (const auto& chain : spec.chains) {  // in chain order: a task's source comes before it
    for (const int task : chain) {
      std::string text = "drape sweep task " + std::to_string(task) + "\n" + scene;
      for (const std::string& set : TaskOverrides(spec, task)) text += "set: " + set + "\n";
      text += "repeat: " + std::to_string(spec.tasks[task].repeat) + "\n";
      const int source = WarmStartSource(spec, task);
      text += "warm_start_from: " +
              (source < 0 ? std::string("none")
                          : std::to_string(source) + " " + Fingerprint(identities[source])) +
              "\n";
      identities[task] = text;
    }
  }
  return identities;
}

std::string Fingerprint(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

SweepSummary RunSweep(const SweepSpec& spec, const SweepOptions& options, std::ostream& log) {
  RunLibrariesOnOneThread();  // one thread per task for CHOLMOD and OpenBLAS, unless the user says
  SweepSummary summary;
  summary.directory = options.out.empty() ? spec.output_directory : options.out;
  summary.tasks = static_cast<int>(spec.tasks.size());
  // Before any solve (it leaves no folder behind), by the coordinator alone: on every rank, one
  // rank's removal of the folder it made raced another's probe of it.
  if (Processes().IsCoordinator()) {
    CheckOutputWritable(summary.directory, {}, options.out.empty() ? "" : "out");
    WarnOfCoarseMeshes(spec, options, log);
  }
  fs::create_directories(summary.directory);  // sweep.csv is written even if no task finishes
  const Context context{spec, summary.directory, options.command_line, CsvLine(SweepColumns(spec)),
                        TaskIdentities(spec)};
  SweepTable table(context, log);
  const int last = options.only ? *options.only : -1;
  TaskFarmOptions farm_options;
  farm_options.local_threads = options.threads;
  const TaskFarmSummary farm = RunTaskFarm(
      FarmTasks(spec, options),
      [&](int chain) { return RunChain(context, spec.chains[chain], last); },
      [&](int /*chain*/, const std::string& result) { table.Collect(result, &summary); },
      farm_options);
  summary.coordinator = farm.coordinator;
  summary.workers = farm.workers;
  if (!farm.coordinator) return summary;
  table.Write();
  WriteAtomically(fs::path(summary.directory) / "sweep.yaml",
                  [&](std::ostream& out) { out << ReadWholeFile(spec.file); });
  CountRows(table, &summary);
  const Provenance provenance{options.command_line, {}};
  WriteAtomically(fs::path(summary.directory) / "sweep.json",
                  [&](std::ostream& out) { WriteSweepJson(spec, summary, provenance, out); });
  if (options.plots && !options.only) WriteSweepReport(spec, summary.directory, provenance);
  return summary;
}

}  // namespace drape
