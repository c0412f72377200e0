#include "src/sweep/fabrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "src/analysis/mesh_rule.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "src/output/csv_record.h"
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
#include "src/scene/file_paths.h"
#include "src/scene/scene_loader.h"
#include "src/solvers/solver.h"
#include "src/sweep/drops.h"
#include "src/sweep/fabrics_report.h"
#include "src/sweep/sweep.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFabricRecordFile = "record.csv";
constexpr const char* kFabricVariantFile = "variant.txt";
constexpr const char* kStandardTesterLabel = "the standard tester";

// ---- loading ------------------------------------------------------------------------------------

// "M3 (75/15/10)" → "M3__75_15_10_": a folder name from a fabric's name.
std::string FolderSlug(const std::string& name) {
  std::string slug;
  for (const unsigned char c : name)
    slug += std::isalnum(c) || c == '-' ? static_cast<char>(c) : '_';
  return slug.substr(0, 40);
}

std::string FabricFolder(int index, int count, const std::string& name) {
  const int width = std::max(3, static_cast<int>(std::to_string(count).size()));
  std::string number = std::to_string(index + 1);
  number.insert(0, static_cast<size_t>(std::max(0, width - static_cast<int>(number.size()))), '0');
  return "fabrics/" + number + "-" + FolderSlug(name);
}

// An error the loader located in the row's overrides, moved to the row's cell; one in --set,
// renumbered to the user's own count.
InputError Relocated(const InputError& error, const FabricRow& row,
                     const std::vector<const FabricCell*>& cells, const std::string& file) {
  const Location& where = error.where();
  if (where.file != "--set" || where.line < 1) {
    return InputError(where.line > 0 ? where : Location{file, row.line, 1, row.name},
                      (where.line > 0 ? "" : "fabric '" + row.name + "': ") + error.problem());
  }
  const int index = where.line - 1;
  if (index >= static_cast<int>(cells.size())) {
    return InputError(
        Location{"--set", index - static_cast<int>(cells.size()) + 1, where.column, where.key},
        error.problem() + " (fabric '" + row.name + "', line " + std::to_string(row.line) + " of " +
            file + ")");
  }
  const FabricCell* cell = cells[index];
  if (!cell) {  // the material as a whole: a parameter the row does not give
    return InputError(Location{file, row.line, 1, where.key},
                      "fabric '" + row.name + "': " + error.problem());
  }
  return InputError(Location{file, cell->line, cell->position, cell->column->name},
                    error.problem());
}

// The outputs every fabric writes whatever the base scene asks: summary.json, shadow.png and
// drape.glb (the report's pictures and 3D view).
void AddNeededOutputs(Scene* scene) {
  for (const char* kind : {"summary", "shadow", "gltf"}) {
    auto& write = scene->output.write;
    if (std::find(write.begin(), write.end(), kind) == write.end()) write.push_back(kind);
  }
}

// ---- a task -------------------------------------------------------------------------------------

struct FabricsContext {
  const FabricsSpec& spec;
  const FabricsOptions& options;
  std::vector<std::string> identities;
};

int FabricOf(const FabricsSpec& spec, int task) { return task / spec.drops; }
int DropOf(const FabricsSpec& spec, int task) { return spec.drops > 1 ? task % spec.drops + 1 : 0; }

std::string FabricTaskFolder(const FabricsSpec& spec, int task) {
  const fs::path folder = fs::path(spec.directory) / spec.fabrics[FabricOf(spec, task)].folder;
  const int drop = DropOf(spec, task);
  return (drop > 0 ? folder / DropFolderName(drop, spec.drops) : folder).string();
}

std::vector<std::string> FabricTaskIdentities(const FabricsSpec& spec) {
  std::vector<std::string> identities(spec.tasks());
  for (int task = 0; task < spec.tasks(); ++task) {
    const FabricCase& fabric = spec.fabrics[FabricOf(spec, task)];
    std::string text = "drape fabrics task\nfabric: " + fabric.row.name +
                       "\nscene: " + fs::path(spec.scene_label).filename().string() + " " +
                       Fingerprint(spec.scene_text) + "\n";
    for (const std::string& set : fabric.overrides) text += "set: " + set + "\n";
    if (!spec.calibration.empty()) text += "calibration: " + spec.calibration.ExactText() + "\n";
    text +=
        "drop: " + std::to_string(DropOf(spec, task)) + " of " + std::to_string(spec.drops) + "\n";
    identities[task] = text;
  }
  return identities;
}

// A finished task's record file: one row of these columns (no header; a record of another
// layout does not read, and its task is solved again).
const CsvColumns<FabricTaskRecord>& FabricTaskColumns() {
  using R = FabricTaskRecord;
  static const CsvColumns<R> columns = {
      MemberColumn("fabric", &R::fabric),
      MemberColumn("drop", &R::drop),
      MemberColumn("solved", &R::solved),
      MemberColumn("counted", &R::counted),
      MemberColumn("drape_coefficient", &R::drape_coefficient),
      MemberColumn("drape_coefficient_error", &R::drape_coefficient_error),
      MemberColumn("folds", &R::folds),
      MemberColumn("iterations", &R::iterations),
      MemberColumn("time_s", &R::time_s),
      MemberColumn("state", &R::state),
      MemberColumn("drape_version", &R::drape_version),
  };
  return columns;
}

std::string RecordText(const FabricTaskRecord& record) {
  return CsvRow(FabricTaskColumns(), record);
}

std::optional<FabricTaskRecord> ParseRecord(const std::string& line) {
  return ParseCsvRow(FabricTaskColumns(), line);
}

std::optional<FabricTaskRecord> FinishedFabricRecord(const FabricsContext& context, int task) {
  const fs::path folder = FabricTaskFolder(context.spec, task);
  if (ReadWholeFile(folder / kFabricVariantFile) != context.identities[task]) return std::nullopt;
  std::string text = ReadWholeFile(folder / kFabricRecordFile);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return ParseRecord(text);
}

void SaveFabricRecord(const FabricsContext& context, int task, const FabricTaskRecord& record) {
  const fs::path folder = FabricTaskFolder(context.spec, task);
  WriteAtomically(folder / kFabricVariantFile,
                  [&](std::ostream& out) { out << context.identities[task]; });
  WriteAtomically(folder / kFabricRecordFile,
                  [&](std::ostream& out) { out << RecordText(record) << '\n'; });
}

FabricTaskRecord SolveFabricTask(const FabricsContext& context, int task) {
  const FabricsSpec& spec = context.spec;
  const FabricCase& fabric = spec.fabrics[FabricOf(spec, task)];
  const int drop = DropOf(spec, task);
  const std::string folder = FabricTaskFolder(spec, task);
  const Scene scene = drop > 0 ? DropScene(fabric.scene, drop) : fabric.scene;
  Model model = BuildModel(scene);
  if (drop > 0) AddDropWaviness(scene, drop, &model);
  ResultFolderLock lock(folder);
  std::error_code ignored;
  fs::remove(fs::path(folder) / kFabricRecordFile, ignored);  // unfinished from here on
  const SolveReport report = SolveAndReport(scene, model, scene.solver.method, {},
                                            /*automatic_levels=*/drop == 0);
  FabricTaskRecord record;
  record.fabric = FabricOf(spec, task);
  record.drop = drop;
  record.drape_version = DrapeVersion();
  const RunResult& result = report.result;
  if (InterruptRequested()) {
    record.state = "interrupted";
    return record;
  }
  const std::string what = fabric.row.name + (drop > 0 ? ", drop " + std::to_string(drop) : "");
  WriteOutputs(
      scene, model, report, folder,
      Provenance{context.options.command_line + " (fabric " + what + ")", fabric.overrides,
                 context.spec.calibration.empty() ? "" : context.spec.calibration.Provenance()});
  record.solved = true;
  record.counted =
      result.converged && !result.Saddle() && !result.PassesThrough() && report.drape.has_value();
  if (report.drape) {
    record.drape_coefficient = ReportedDrapeCoefficient(report);
    record.folds = report.drape->folds.count;
  }
  const std::optional<double> error = ReportedDrapeCoefficientError(report);
  const std::optional<MeshAdvice> advice = AdviseMeshOfScene(scene);
  record.drape_coefficient_error = error ? *error : (advice ? advice->expected_error : 0.0);
  record.iterations = result.summary.iterations;
  record.time_s = result.summary.wall_time_s;
  record.state = result.converged ? StateText(result) : "not converged: " + StateText(result);
  SaveFabricRecord(context, task, record);
  return record;
}

// A task whose fabric the model refuses is a record saying so, saved (it would fail again); any
// other failure (memory, a folder that cannot be written) is not saved: a re-run tries again.
FabricTaskRecord RunFabricTask(const FabricsContext& context, int task) {
  FabricTaskRecord failed;
  failed.fabric = FabricOf(context.spec, task);
  failed.drop = DropOf(context.spec, task);
  failed.drape_version = DrapeVersion();
  try {
    return SolveFabricTask(context, task);
  } catch (const InputError& error) {
    failed.state = std::string("failed: ") + error.what();
    try {
      SaveFabricRecord(context, task, failed);
    } catch (const std::exception&) {
    }
  } catch (const std::bad_alloc&) {
    failed.state = "failed: out of memory";
  } catch (const std::exception& error) {
    failed.state = std::string("failed: ") + error.what();
  }
  return failed;
}

// A farm task's result: a FarmRecord, solved, skipped or interrupted, with the task's record.
std::string RunFarmTask(const FabricsContext& context, int task) {
  auto result = [task](const std::string& kind, const FabricTaskRecord& record) {
    return EncodeFarmRecords({{kind, task, RecordText(record), {}}});
  };
  if (const auto record = FinishedFabricRecord(context, task)) return result("skipped", *record);
  if (InterruptRequested()) {
    FabricTaskRecord record;
    record.fabric = FabricOf(context.spec, task);
    record.drop = DropOf(context.spec, task);
    record.state = "not run (interrupted)";
    return result("interrupted", record);
  }
  const FabricTaskRecord record = RunFabricTask(context, task);
  return result(record.state == "interrupted" ? "interrupted" : "solved", record);
}

// ---- the outputs --------------------------------------------------------------------------------

std::string HeaderWithUnit(const std::string& name, const std::string& unit) {
  return unit.empty() || unit == "1" ? name : name + " [" + unit + "]";
}

// The SI keys over all fabrics, in the order the first fabric that has each reports it.
std::vector<std::pair<std::string, std::string>> SiColumns(const FabricsSpec& spec) {
  std::vector<std::pair<std::string, std::string>> columns;
  for (const FabricCase& fabric : spec.fabrics) {
    for (const MaterialValue& value : MaterialSiValues(fabric.scene.material)) {
      const auto same = [&](const auto& c) { return c.first == value.key; };
      if (std::none_of(columns.begin(), columns.end(), same)) {
        columns.emplace_back(value.key, value.unit);
      }
    }
  }
  return columns;
}

const std::vector<std::pair<std::string, std::string>>& ResultColumns() {
  static const std::vector<std::pair<std::string, std::string>> columns = {
      {"predicted_dc", ""},
      {"predicted_dc_error", ""},
      {"folds", ""},
      {"drops", ""},
      {"drops_counted", ""},
      {"predicted_dc_sd", ""},
      {"measured_dc", ""},
      {"measured_dc_sd", ""},
      {"measured_folds", ""},
      {"difference", ""},
      {"within_error_bar", ""},
      {"time_s", "s"},
      {"state", ""},
      {"folder", ""},
      {"drape_version", ""}};
  return columns;
}

bool IsResultColumn(const FabricColumn& column) {
  return column.kind == FabricColumn::Kind::kMeasuredDc ||
         column.kind == FabricColumn::Kind::kMeasuredDcSd ||
         column.kind == FabricColumn::Kind::kMeasuredFolds ||
         column.kind == FabricColumn::Kind::kName;
}

std::vector<std::string> InputColumns(const FabricsSpec& spec) {
  std::vector<std::string> names;
  for (const std::string& name : spec.table.header) {
    for (const FabricColumn& column : FabricColumns()) {
      if (column.name == name && !IsResultColumn(column)) names.push_back(name);
    }
  }
  return names;
}

const FabricColumn& ColumnNamed(const std::string& name) {
  for (const FabricColumn& column : FabricColumns()) {
    if (column.name == name) return column;
  }
  assert(false && "a header name that ReadFabricTable accepted");
  return FabricColumns().front();
}

std::optional<double> Difference(const FabricCase& fabric, const FabricPrediction& prediction) {
  if (!fabric.row.measured_dc || !prediction.drape_coefficient) return std::nullopt;
  return *prediction.drape_coefficient - *fabric.row.measured_dc;
}

bool Within(const FabricCase& fabric, const FabricPrediction& prediction) {
  const auto delta = Difference(fabric, prediction);
  return delta && std::abs(*delta) <= prediction.error + fabric.row.measured_dc_sd.value_or(0.0);
}

double TotalTime(const std::vector<FabricTaskRecord>& records) {
  double total = 0.0;
  for (const FabricTaskRecord& record : records) total += record.time_s;
  return total;
}

// The drape that solved a fabric's records ("0.1 (git …)"; two or more joined with " + " where a
// re-run kept records of another drape).
std::string RecordVersions(const std::vector<FabricTaskRecord>& records) {
  std::vector<std::string> versions;
  for (const FabricTaskRecord& record : records) {
    if (std::find(versions.begin(), versions.end(), record.drape_version) == versions.end()) {
      versions.push_back(record.drape_version);
    }
  }
  std::string text;
  for (const std::string& version : versions) text += (text.empty() ? "" : " + ") + version;
  return text.empty() ? DrapeVersion() : text;
}

std::string OptionalNumber(const std::optional<double>& value) {
  return value ? CsvNumber(*value) : "";
}

void WriteFabricsCsv(const FabricsSpec& spec, const std::vector<FabricPrediction>& predictions,
                     const std::vector<std::vector<FabricTaskRecord>>& records, std::ostream& out) {
  const std::vector<std::string> inputs = InputColumns(spec);
  const auto si = SiColumns(spec);
  std::vector<std::string> header = {"name"};
  for (const std::string& name : inputs)
    header.push_back(HeaderWithUnit(name, ColumnNamed(name).unit));
  for (const auto& [key, unit] : si) header.push_back(HeaderWithUnit("si." + key, unit));
  for (const auto& [name, unit] : ResultColumns()) header.push_back(HeaderWithUnit(name, unit));
  out << CsvLine(header) << '\n';
  for (size_t f = 0; f < spec.fabrics.size(); ++f) {
    const FabricCase& fabric = spec.fabrics[f];
    const FabricPrediction& p = predictions[f];
    std::vector<std::string> cells = {fabric.row.name};
    for (const std::string& name : inputs) {
      const FabricCell* cell = fabric.row.Cell(name);
      cells.push_back(cell ? cell->text : "");
    }
    const std::vector<MaterialValue> values = MaterialSiValues(fabric.scene.material);
    for (const auto& column : si) {
      const std::string& key = column.first;
      const auto found = std::find_if(values.begin(), values.end(),
                                      [&key](const MaterialValue& v) { return v.key == key; });
      cells.push_back(found == values.end() ? "" : CsvNumber(found->value));
    }
    const auto delta = Difference(fabric, p);
    cells.insert(
        cells.end(),
        {OptionalNumber(p.drape_coefficient), p.drape_coefficient ? CsvNumber(p.error) : "",
         p.drape_coefficient ? std::to_string(p.folds) : "", std::to_string(spec.drops),
         std::to_string(p.counted), OptionalNumber(p.standard_deviation),
         OptionalNumber(fabric.row.measured_dc), OptionalNumber(fabric.row.measured_dc_sd),
         fabric.row.measured_folds ? std::to_string(*fabric.row.measured_folds) : "",
         OptionalNumber(delta), delta ? JsonBool(Within(fabric, p)) : "",
         CsvNumber(TotalTime(records[f])), p.state, fabric.folder, RecordVersions(records[f])});
    out << CsvLine(cells) << '\n';
  }
}

std::string StatisticsJson(const FabricStatistics& s) {
  if (s.compared == 0) return "null";
  return JsonObject(
      {{"fabrics_compared", std::to_string(s.compared)},
       {"mean_abs_difference", JsonNumber(s.mean_abs_difference)},
       {"mean_difference", JsonNumber(s.mean_difference)},
       {"rms_difference", JsonNumber(s.rms_difference)},
       {"within_error_bars", std::to_string(s.within)},
       {"within_error_bars_fraction", JsonNumber(static_cast<double>(s.within) / s.compared)}},
      1);
}

void WriteFabricsJson(const FabricsSpec& spec, const FabricsSummary& summary,
                      const Provenance& provenance, std::ostream& out) {
  std::vector<std::pair<std::string, std::string>> members = {
      {"table", JsonString(spec.table.file)},
      {"scene", JsonString(spec.scene_label)},
      {"fabrics", std::to_string(summary.fabrics)},
      {"drops_per_fabric", std::to_string(spec.drops)},
      {"fabrics_predicted", std::to_string(summary.predicted)},
      {"statistics", StatisticsJson(summary.statistics)},
      {"definitions",
       JsonObject({{"difference", JsonString("predicted_dc - measured_dc")},
                   {"within_error_bars",
                    JsonString("|difference| <= predicted_dc_error + measured_dc_sd (0 where not "
                               "given)")},
                   {"predicted_dc", JsonString(spec.drops > 1 ? "the mean over the counted drops"
                                                              : "the single solve's drape "
                                                                "coefficient")}},
                  1)},
      {"units", JsonObject({{"drape coefficients and differences", JsonString("1")},
                            {"time_s", JsonString("s")},
                            {"fabrics.csv", JsonString("each numeric column's unit in its "
                                                       "header, [unit]")}},
                           1)}};
  for (auto& member : ProvenanceMembers(provenance)) members.push_back(std::move(member));
  out << JsonObject(members, 0) << '\n';
}

// Progress: one line per finished task, and the fabric's prediction when its last task is in.
class FabricsCollector {
 public:
  FabricsCollector(const FabricsSpec& spec, std::ostream& log)
      : spec_(spec),
        log_(log),
        records_(spec.fabrics.size()),
        waiting_(spec.fabrics.size(), spec.drops) {}

  void Collect(const std::string& result, FabricsSummary* summary) {
    const FarmRecord farmed = DecodeFarmRecords(result).at(0);
    const std::string& kind = farmed.kind;
    const auto record = ParseRecord(farmed.row);
    if (!record) return;
    if (kind == "interrupted") {
      summary->interrupted = true;
      return;
    }
    (kind == "skipped" ? summary->skipped : summary->solved) += 1;
    records_[record->fabric].push_back(*record);
    if (--waiting_[record->fabric] > 0 || kind == "skipped") {
      if (kind == "solved" && record->drop > 0) Progress(*record);
      return;
    }
    const FabricPrediction p = PredictFabric(records_[record->fabric]);
    const FabricRow& row = spec_.fabrics[record->fabric].row;
    char text[200];
    std::snprintf(text, sizeof text, "fabrics: %s (%d of %zu done): ", row.name.c_str(), ++done_,
                  spec_.fabrics.size());
    log_ << text;
    if (p.drape_coefficient) {
      std::snprintf(text, sizeof text, "DC %.3f ± %.3f, %d folds", *p.drape_coefficient, p.error,
                    p.folds);
      log_ << text;
      if (row.measured_dc) {
        std::snprintf(text, sizeof text, ", measured %.3f (Δ %+.3f)", *row.measured_dc,
                      *p.drape_coefficient - *row.measured_dc);
        log_ << text;
      }
      log_ << ", ";
    }
    log_ << p.state << std::endl;
  }

  std::vector<std::vector<FabricTaskRecord>>& records() { return records_; }

 private:
  void Progress(const FabricTaskRecord& r) {
    char text[160];
    std::snprintf(text, sizeof text, "fabrics: %s drop %d: DC %.3f, %d folds, ",
                  spec_.fabrics[r.fabric].row.name.c_str(), r.drop, r.drape_coefficient, r.folds);
    log_ << text << r.state << std::endl;
  }

  const FabricsSpec& spec_;
  std::ostream& log_;
  std::vector<std::vector<FabricTaskRecord>> records_;
  std::vector<int> waiting_;
  int done_ = 0;
};

std::vector<int> FabricFarmTasks(const FabricsSpec& spec, const FabricsOptions& options) {
  if (options.only) return {*options.only};
  std::vector<int> tasks(spec.tasks());
  for (int t = 0; t < spec.tasks(); ++t) tasks[t] = t;
  return tasks;
}

}  // namespace

const std::string& StandardTesterScene() {
  static const std::string text =
      "# The standard drape tester (Cusick 1968; BS 5058, ISO 9073-9): a 30 cm specimen on the\n"
      "# 18 cm disc, on a 5 mm lattice (the cost a table of fabrics can pay; each prediction\n"
      "# carries its error bar), solved by Newton from the flat start.\n"
      "name: fabrics\n"
      "drape_test: {specimen_diameter: 0.30}\n"
      "mesh: {spacing: 0.005}\n"
      "solver: {method: newton, tolerance: 1.0e-8, max_iterations: 2000, time_limit: 1200}\n"
      "output: {write: [summary, shadow]}\n";
  return text;
}

FabricsSpec LoadFabrics(const FabricsOptions& options) {
  FabricsSpec spec;
  spec.table = ReadFabricTable(options.table);
  spec.scene_label = options.scene.empty() ? kStandardTesterLabel : options.scene;
  // The base scene, read and parsed once for every row.
  const SceneDocument base =
      options.scene.empty() ? SceneDocument::Parse(StandardTesterScene(), kStandardTesterLabel, ".")
                            : SceneDocument::Read(options.scene);
  spec.scene_text = base.text();
  spec.calibration = options.calibration;
  spec.directory = options.out.empty() ? (fs::path("out") / fs::path(options.table).stem()).string()
                                       : options.out;
  const int count = static_cast<int>(spec.table.rows.size());
  for (int f = 0; f < count; ++f) {
    FabricCase fabric;
    fabric.row = spec.table.rows[f];
    std::vector<const FabricCell*> cells;
    fabric.overrides = FabricOverrides(fabric.row, &cells);
    fabric.overrides.insert(fabric.overrides.end(), options.overrides.begin(),
                            options.overrides.end());
    try {
      fabric.scene = base.Load(fabric.overrides);
    } catch (const InputError& error) {
      throw Relocated(error, fabric.row, cells, spec.table.file);
    }
    if (!fabric.scene.drape_test) {
      throw InputError(Location{spec.scene_label, 1, 1, "drape_test"},
                       "drape fabrics predicts drape coefficients: the base scene needs a "
                       "drape_test");
    }
    ApplyCalibration(options.calibration, &fabric.scene);
    AddNeededOutputs(&fabric.scene);
    fabric.folder = FabricFolder(f, count, fabric.row.name);
    spec.fabrics.push_back(std::move(fabric));
  }
  spec.drops = options.drops ? *options.drops : spec.fabrics.front().scene.drape_test->drops;
  if (options.only && (*options.only < 0 || *options.only >= spec.tasks())) {
    throw InputError("--only " + std::to_string(*options.only) +
                     ": not a task of the table (its tasks are 0 to " +
                     std::to_string(spec.tasks() - 1) + ")");
  }
  return spec;
}

FabricPrediction PredictFabric(const std::vector<FabricTaskRecord>& records) {
  FabricPrediction p;
  p.tasks = static_cast<int>(records.size());
  std::vector<DropRecord> drops;
  double error = 0.0;
  for (const FabricTaskRecord& r : records) {
    DropRecord drop;
    drop.drop = r.drop;
    drop.drape_coefficient = r.drape_coefficient;
    drop.folds = r.folds;
    drop.counted = r.counted;
    drops.push_back(drop);
    if (r.counted) error = std::max(error, r.drape_coefficient_error);
  }
  const DropStatistics s = ComputeDropStatistics(drops);
  p.counted = s.counted;
  if (s.counted > 0) {
    p.drape_coefficient = s.mean;
    p.error = error;
    if (s.counted > 1) p.standard_deviation = s.standard_deviation;
    p.folds = s.modal_folds.front();
  }
  if (records.empty()) {
    p.state = "not solved (interrupted)";
  } else if (records.size() == 1 && records.front().drop == 0) {
    p.state = records.front().state;
  } else {
    p.state = std::to_string(s.counted) + " of " + std::to_string(records.size()) +
              " drops at a stable minimum";
  }
  return p;
}

FabricStatistics ComputeFabricStatistics(const std::vector<FabricComparison>& comparisons) {
  FabricStatistics s;
  s.compared = static_cast<int>(comparisons.size());
  if (s.compared == 0) return s;
  double sum = 0.0, abs_sum = 0.0, squares = 0.0;
  for (const FabricComparison& c : comparisons) {
    const double delta = c.predicted - c.measured;
    sum += delta;
    abs_sum += std::abs(delta);
    squares += delta * delta;
    if (std::abs(delta) <= c.error + c.measured_sd) ++s.within;
  }
  s.mean_difference = sum / s.compared;
  s.mean_abs_difference = abs_sum / s.compared;
  s.rms_difference = std::sqrt(squares / s.compared);
  return s;
}

FabricsSummary RunFabrics(const FabricsSpec& spec, const FabricsOptions& options,
                          std::ostream& log) {
  RunLibrariesOnOneThread();  // one thread per task for CHOLMOD and OpenBLAS
  FabricsSummary summary;
  summary.directory = spec.directory;
  summary.fabrics = static_cast<int>(spec.fabrics.size());
  summary.tasks = spec.tasks();
  if (Processes().IsCoordinator()) {
    CheckOutputWritable(spec.directory, {}, options.out.empty() ? "" : "out");
    std::vector<std::string> names;
    std::vector<std::optional<MeshAdvice>> advice;
    for (const FabricCase& fabric : spec.fabrics) {
      names.push_back(fabric.row.name);
      advice.push_back(AdviseMeshOfScene(fabric.scene));
    }
    const auto line = CoarseMeshesLine(names, advice, "fabric", "predicted_dc_error");
    if (line && options.mesh_warning) {
      log << "drape fabrics: warning: " << *line << std::endl;
    }
  }
  fs::create_directories(spec.directory);
  const FabricsContext context{spec, options, FabricTaskIdentities(spec)};
  FabricsCollector collector(spec, log);
  TaskFarmOptions farm_options;
  farm_options.local_threads = options.threads;
  const TaskFarmSummary farm = RunTaskFarm(
      FabricFarmTasks(spec, options), [&](int task) { return RunFarmTask(context, task); },
      [&](int /*task*/, const std::string& result) { collector.Collect(result, &summary); },
      farm_options);
  summary.coordinator = farm.coordinator;
  if (!farm.coordinator || options.only) return summary;
  std::vector<FabricPrediction> predictions;
  std::vector<FabricComparison> comparisons;
  for (size_t f = 0; f < spec.fabrics.size(); ++f) {
    predictions.push_back(PredictFabric(collector.records()[f]));
    const FabricPrediction& p = predictions.back();
    const FabricRow& row = spec.fabrics[f].row;
    if (p.drape_coefficient) ++summary.predicted;
    if (p.drape_coefficient && row.measured_dc) {
      comparisons.push_back(
          {*p.drape_coefficient, p.error, *row.measured_dc, row.measured_dc_sd.value_or(0.0)});
    }
  }
  summary.statistics = ComputeFabricStatistics(comparisons);
  summary.predictions = predictions;
  std::map<std::string, int> other_versions;  // records kept from another drape, by its version
  for (const auto& records : collector.records()) {
    for (const FabricTaskRecord& record : records) {
      if (record.drape_version != DrapeVersion()) ++other_versions[record.drape_version];
    }
  }
  for (const auto& [version, count] : other_versions) {
    log << "fabrics: " << count << " finished task" << (count == 1 ? "" : "s")
        << " kept from drape " << version << " (this is " << DrapeVersion()
        << "; fabrics.csv's drape_version column says which drape solved each row)" << std::endl;
  }
  const Provenance provenance{options.command_line, options.overrides,
                              spec.calibration.empty() ? "" : spec.calibration.Provenance()};
  const fs::path directory(spec.directory);
  WriteAtomically(directory / "fabrics.csv", [&](std::ostream& out) {
    WriteFabricsCsv(spec, predictions, collector.records(), out);
  });
  WriteAtomically(directory / "fabrics.json",
                  [&](std::ostream& out) { WriteFabricsJson(spec, summary, provenance, out); });
  WriteAtomically(directory / "report.html", [&](std::ostream& out) {
    WriteFabricsReport(spec, predictions, summary, provenance, out);
  });
  return summary;
}

std::string FabricsLine(const FabricsSummary& s) {
  std::string text = std::to_string(s.fabrics) + (s.fabrics == 1 ? " fabric: " : " fabrics: ") +
                     std::to_string(s.predicted) + " predicted (" + std::to_string(s.solved) +
                     " solves this run, " + std::to_string(s.skipped) + " kept)";
  if (s.statistics.compared > 0) {
    char figures[200];
    std::snprintf(figures, sizeof figures,
                  "; against %d measured: mean |Δ| %.3f, mean Δ %+.3f, RMS %.3f; %d of %d within "
                  "the error bars",
                  s.statistics.compared, s.statistics.mean_abs_difference,
                  s.statistics.mean_difference, s.statistics.rms_difference, s.statistics.within,
                  s.statistics.compared);
    text += figures;
  }
  return text + (s.interrupted ? "; interrupted" : "");
}

}  // namespace drape
