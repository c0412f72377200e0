#include "src/sweep/calibrate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/version.h"
#include "src/output/writers.h"
#include "src/parallel/process_group.h"
#include "src/scene/yaml_reader.h"
#include "src/sweep/calibrate_report.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

InputError CalibrateError(int position, const std::string& name, const std::string& what) {
  return InputError(Location{"--calibrate", position, 1, name}, what);
}

std::string ShortValue(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// "grid/bending_scale_1.5-bending_friction_share_25".
std::string GridFolder(const std::vector<const CalibrationConstant*>& constants,
                       const std::vector<double>& values) {
  std::string name;
  for (size_t c = 0; c < constants.size(); ++c) {
    name += (c ? "-" : "") + constants[c]->name + "_" + ShortValue(values[c]);
  }
  return "grid/" + name;
}

Calibration CalibrationOf(const std::vector<const CalibrationConstant*>& constants,
                          const std::vector<double>& values) {
  Calibration calibration;
  for (const CalibrationConstant& known : CalibrationConstants()) {  // the registry's order
    for (size_t c = 0; c < constants.size(); ++c) {
      if (constants[c] == &known) calibration.values.emplace_back(known.name, values[c]);
    }
  }
  return calibration;
}

int MeasuredFabrics(const FabricsSpec& spec) {
  int count = 0;
  for (const FabricCase& fabric : spec.fabrics) count += fabric.row.measured_dc ? 1 : 0;
  return count;
}

// The table solved with `calibration` into OUT/`folder`.
FabricsSummary SolveTable(const FabricsOptions& options, const Calibration& calibration,
                          const std::string& folder, bool mesh_warning, std::ostream& log) {
  FabricsOptions run = options;
  run.calibrate.clear();
  run.calibration = calibration;
  run.out = (fs::path(options.out) / folder).string();
  run.mesh_warning = mesh_warning;
  const FabricsSpec spec = LoadFabrics(run);
  return RunFabrics(spec, run, log);
}

std::optional<double> Predicted(const FabricsSummary& summary, size_t fabric) {
  if (fabric >= summary.predictions.size()) return std::nullopt;
  return summary.predictions[fabric].drape_coefficient;
}

FabricStatistics StatisticsOver(const CalibrateSummary& s, const std::vector<int>& fabrics,
                                const std::vector<std::optional<double>>& predicted) {
  std::vector<FabricComparison> comparisons;
  for (const int f : fabrics) {
    if (predicted[f]) comparisons.push_back({*predicted[f], 0.0, *s.measured[f], 0.0});
  }
  return ComputeFabricStatistics(comparisons);
}

// The index of each constant's uncalibrated value in its grid.
std::vector<int> UncalibratedPoint(const std::vector<const CalibrationConstant*>& constants) {
  std::vector<int> indices;
  for (const CalibrationConstant* c : constants) {
    const auto found = std::find(c->grid.begin(), c->grid.end(), c->uncalibrated);
    indices.push_back(static_cast<int>(found - c->grid.begin()));
  }
  return indices;
}

void Fit(const std::vector<const CalibrationConstant*>& constants, CalibrateSummary* s) {
  const std::vector<int> fabrics = FittableFabrics(s->grid);
  s->fitted_fabrics = static_cast<int>(fabrics.size());
  const int fewest = FewestCalibrationFabrics(static_cast<int>(constants.size()));
  if (s->fitted_fabrics < fewest) {
    s->problem = "only " + std::to_string(s->fitted_fabrics) +
                 " measured fabrics have a counted solve at every grid point; a calibration of " +
                 std::to_string(constants.size()) + " constant" +
                 (constants.size() == 1 ? "" : "s") + " needs " + std::to_string(fewest) +
                 " (see each grid point's fabrics.csv for the states)";
    return;
  }
  s->fit = FitCalibrationGrid(s->grid, fabrics);
  std::vector<double> values;
  for (size_t c = 0; c < constants.size(); ++c) values.push_back(s->fit.values[c]);
  s->fitted = CalibrationOf(constants, values);
  s->left_out.assign(s->fabric_names.size(), std::nullopt);
  for (const LeftOut& out : LeaveOneOut(s->grid, fabrics)) s->left_out[out.fabric] = out;
}

void SetStatistics(CalibrateSummary* s) {
  const std::vector<int> fabrics = FittableFabrics(s->grid);
  s->before = StatisticsOver(*s, fabrics, s->uncalibrated);
  s->after = StatisticsOver(*s, fabrics, s->calibrated);
  std::vector<std::optional<double>> left(s->fabric_names.size());
  for (size_t f = 0; f < left.size(); ++f) {
    if (s->left_out[f]) left[f] = s->left_out[f]->predicted;
  }
  s->leave_one_out = StatisticsOver(*s, fabrics, left);
}

std::string OptionalCsv(const std::optional<double>& value) {
  return value ? CsvNumber(*value) : "";
}

void WriteCalibrationCsv(const CalibrateSummary& s, std::ostream& out) {
  std::vector<std::string> header = {"name",
                                     "measured_dc",
                                     "uncalibrated_dc",
                                     "calibrated_dc",
                                     "calibrated_dc_error",
                                     "left_out_dc",
                                     "left_out_difference"};
  for (const std::string& name : s.constants) header.push_back("left_out." + name);
  out << CsvLine(header) << '\n';
  for (size_t f = 0; f < s.fabric_names.size(); ++f) {
    const std::optional<LeftOut>& left = s.left_out[f];
    std::vector<std::string> cells = {s.fabric_names[f],
                                      OptionalCsv(s.measured[f]),
                                      OptionalCsv(s.uncalibrated[f]),
                                      OptionalCsv(s.calibrated[f]),
                                      s.calibrated[f] ? CsvNumber(s.calibrated_error[f]) : "",
                                      left ? CsvNumber(left->predicted) : "",
                                      left ? CsvNumber(left->difference) : ""};
    for (size_t c = 0; c < s.constants.size(); ++c) {
      cells.push_back(left ? CsvNumber(left->fit.values[c]) : "");
    }
    out << CsvLine(cells) << '\n';
  }
}

std::string StatisticsMembers(const FabricStatistics& s) {
  return JsonObject({{"fabrics", std::to_string(s.compared)},
                     {"mean_abs_difference", JsonNumber(s.mean_abs_difference)},
                     {"mean_difference", JsonNumber(s.mean_difference)},
                     {"rms_difference", JsonNumber(s.rms_difference)}},
                    2);
}

double LargestLeftOut(const CalibrateSummary& s) {
  double largest = 0.0;
  for (const auto& left : s.left_out) {
    if (left) largest = std::max(largest, std::abs(left->difference));
  }
  return largest;
}

// calibration.yaml's `fitted:` body: what it was fitted to and how well.
std::string FittedBody(const FabricsOptions& options, const CalibrateSummary& s) {
  char text[600];
  std::snprintf(text, sizeof text,
                "  table: %s\n  fabrics: %d\n  rms_difference: %.4f\n"
                "  mean_abs_difference: {uncalibrated: %.4f, calibrated: %.4f, leave_one_out: "
                "%.4f}\n  largest_leave_one_out_difference: %.4f\n  at_grid_edge: %s\n",
                JsonString(options.table).c_str(), s.fitted_fabrics, s.fit.rms,
                s.before.mean_abs_difference, s.after.mean_abs_difference,
                s.leave_one_out.mean_abs_difference, LargestLeftOut(s),
                s.fit.at_edge ? "true" : "false");
  return text + std::string("  drape_version: ") + JsonString(DrapeVersion()) + "\n";
}

void WriteCalibrationJson(const FabricsOptions& options, const CalibrateSummary& s,
                          const Provenance& provenance, std::ostream& out) {
  std::vector<std::pair<std::string, std::string>> constants;
  for (const auto& [name, value] : s.fitted.values) constants.emplace_back(name, JsonNumber(value));
  std::vector<std::pair<std::string, std::string>> members = {
      {"table", JsonString(options.table)},
      {"constants", JsonObject(constants, 1)},
      {"fabrics_fitted", std::to_string(s.fitted_fabrics)},
      {"grid_points", std::to_string(s.grid.Points())},
      {"at_grid_edge", JsonBool(s.fit.at_edge)},
      {"uncalibrated", StatisticsMembers(s.before)},
      {"calibrated", StatisticsMembers(s.after)},
      {"leave_one_out", StatisticsMembers(s.leave_one_out)},
      {"largest_leave_one_out_difference", JsonNumber(LargestLeftOut(s))},
      {"definitions",
       JsonObject({{"difference", JsonString("predicted_dc - measured_dc")},
                   {"calibrated", JsonString("the table solved at the fitted constants")},
                   {"leave_one_out",
                    JsonString("each fabric's DC at the constants fitted to the other fabrics, "
                               "read from the grid's interpolant")}},
                  1)}};
  for (auto& member : ProvenanceMembers(provenance)) members.push_back(std::move(member));
  out << JsonObject(members, 0) << '\n';
}

void WriteCalibrateOutputs(const FabricsOptions& options, const CalibrateSummary& s) {
  const fs::path directory(s.directory);
  const Provenance provenance{options.command_line, options.overrides};
  WriteAtomically(directory / "calibration.yaml", [&](std::ostream& out) {
    out << CalibrationYaml(
        s.fitted,
        {"A calibration of drape's fabric inputs (docs/reference.md, \"Calibration\"), written by",
         ProvenanceLine(provenance) + ".",
         "Give it to later runs: drape solve SCENE --calibration FILE, drape fabrics TABLE "
         "--calibration FILE."},
        FittedBody(options, s));
  });
  WriteAtomically(directory / "calibration.csv",
                  [&](std::ostream& out) { WriteCalibrationCsv(s, out); });
  WriteAtomically(directory / "calibration.json",
                  [&](std::ostream& out) { WriteCalibrationJson(options, s, provenance, out); });
  WriteAtomically(directory / "report.html",
                  [&](std::ostream& out) { WriteCalibrateReport(s, provenance, out); });
}

// Each grid point's table solved; false when interrupted.
bool SolveGrid(const FabricsOptions& options,
               const std::vector<const CalibrationConstant*>& constants, std::ostream& log,
               CalibrateSummary* s) {
  for (const CalibrationConstant* c : constants) s->grid.axes.push_back(c->grid);
  const int points = s->grid.Points();
  s->grid.dc.assign(s->fabric_names.size(), std::vector<std::optional<double>>(points));
  const int before = s->grid.Point(UncalibratedPoint(constants));
  for (int point = 0; point < points; ++point) {
    const std::vector<int> indices = s->grid.Indices(point);
    std::vector<double> values;
    for (size_t c = 0; c < constants.size(); ++c) values.push_back(constants[c]->grid[indices[c]]);
    const Calibration calibration = CalibrationOf(constants, values);
    log << "calibrate: grid point " << point + 1 << " of " << points << ": " << calibration.Text()
        << std::endl;
    const FabricsSummary table =
        SolveTable(options, calibration, GridFolder(constants, values), point == 0, log);
    s->solves += table.solved;
    if (table.interrupted) return false;
    for (size_t f = 0; f < s->fabric_names.size(); ++f) {
      s->grid.dc[f][point] = Predicted(table, f);
      if (point == before) s->uncalibrated[f] = Predicted(table, f);
    }
  }
  return true;
}

}  // namespace

std::vector<const CalibrationConstant*> CalibratedConstants(const FabricsOptions& options) {
  std::vector<std::string> known;
  for (const CalibrationConstant& c : CalibrationConstants()) known.push_back(c.name);
  std::vector<const CalibrationConstant*> constants;
  for (size_t k = 0; k < options.calibrate.size(); ++k) {
    const std::string& name = options.calibrate[k];
    const int position = static_cast<int>(k) + 1;
    const CalibrationConstant* constant = FindCalibrationConstant(name);
    if (!constant) {
      throw CalibrateError(position, name,
                           "not a calibration constant" + SuggestionText(name, known));
    }
    if (std::find(constants.begin(), constants.end(), constant) != constants.end()) {
      throw CalibrateError(position, name, "named twice");
    }
    constants.push_back(constant);
  }
  if (constants.size() > static_cast<size_t>(kMostCalibratedConstants)) {
    throw CalibrateError(kMostCalibratedConstants + 1, options.calibrate.back(),
                         "at most " + std::to_string(kMostCalibratedConstants) +
                             " constants per calibration (its grid has 6^k points, each a solve "
                             "of the whole table)");
  }
  if (!options.calibration_file.empty() || !options.calibration.empty()) {
    throw CalibrateError(1, options.calibrate.front(),
                         "fits the uncalibrated model; --calibration applies a calibration to "
                         "later runs and cannot be given with it");
  }
  if (options.only) {
    throw CalibrateError(1, options.calibrate.front(),
                         "runs the whole table at every grid point; --only cannot be given with "
                         "it");
  }
  if (Processes().IsDistributed()) {
    throw CalibrateError(1, options.calibrate.front(),
                         "runs on one process's threads (--threads); run it without mpirun");
  }
  return constants;
}

CalibrateSummary RunCalibrate(const FabricsOptions& given, std::ostream& log) {
  const std::vector<const CalibrationConstant*> constants = CalibratedConstants(given);
  FabricsOptions options = given;
  if (options.out.empty()) {
    options.out =
        (fs::path("out") / (fs::path(options.table).stem().string() + "-calibration")).string();
  }
  const FabricsSpec spec = LoadFabrics(options);  // the table and every row checked
  const int fewest = FewestCalibrationFabrics(static_cast<int>(constants.size()));
  if (MeasuredFabrics(spec) < fewest) {
    throw InputError(Location{spec.table.file, 0, 0, "measured_dc"},
                     "a calibration of " + std::to_string(constants.size()) + " constant" +
                         (constants.size() == 1 ? "" : "s") + " needs at least " +
                         std::to_string(fewest) +
                         " fabrics with a measured_dc (each leave-one-out fit keeps one more "
                         "fabric than it has constants); the table has " +
                         std::to_string(MeasuredFabrics(spec)));
  }
  CheckOutputWritable(options.out, {}, "out");
  CalibrateSummary s;
  s.directory = options.out;
  for (const CalibrationConstant* c : constants) s.constants.push_back(c->name);
  for (const FabricCase& fabric : spec.fabrics) {
    s.fabric_names.push_back(fabric.row.name);
    s.measured.push_back(fabric.row.measured_dc);
  }
  s.grid.measured = s.measured;
  s.uncalibrated.assign(spec.fabrics.size(), std::nullopt);
  s.calibrated.assign(spec.fabrics.size(), std::nullopt);
  s.calibrated_error.assign(spec.fabrics.size(), 0.0);
  s.left_out.assign(spec.fabrics.size(), std::nullopt);
  if (!SolveGrid(options, constants, log, &s)) {
    s.interrupted = true;
    return s;
  }
  Fit(constants, &s);
  if (!s.problem.empty()) return s;
  log << "calibrate: fitted " << s.fitted.Text() << "; solving the table there" << std::endl;
  const FabricsSummary after = SolveTable(options, s.fitted, "calibrated", false, log);
  s.solves += after.solved;
  if (after.interrupted) {
    s.interrupted = true;
    return s;
  }
  for (size_t f = 0; f < spec.fabrics.size(); ++f) {
    s.calibrated[f] = Predicted(after, f);
    if (f < after.predictions.size()) s.calibrated_error[f] = after.predictions[f].error;
  }
  SetStatistics(&s);
  WriteCalibrateOutputs(options, s);
  return s;
}

std::string CalibrateLine(const CalibrateSummary& s) {
  if (s.interrupted) return "calibrate: interrupted; a re-run keeps what was solved";
  if (!s.problem.empty()) return "calibrate: nothing fitted: " + s.problem;
  char figures[300];
  std::snprintf(figures, sizeof figures,
                " to %d fabrics: mean |Δ| %.3f uncalibrated, %.3f calibrated, %.3f left out "
                "(largest %.3f); %d solves this run",
                s.fitted_fabrics, s.before.mean_abs_difference, s.after.mean_abs_difference,
                s.leave_one_out.mean_abs_difference, LargestLeftOut(s), s.solves);
  std::string line = "calibrated " + s.fitted.Text() + figures;
  if (s.fit.at_edge) line += "; at the end of the searched grid: the best value may lie beyond it";
  return line + "; results in " + s.directory + "/calibration.yaml";
}

}  // namespace drape
