#include "src/fit/fit_writer.h"

#include <cairo.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "src/fit/fit_measurements.h"
#include "src/output/atomic_file.h"
#include "src/output/axis_ticks.h"
#include "src/output/csv_field.h"
#include "src/output/json.h"
#include "src/output/png_text.h"
#include "src/output/report_page.h"
#include "src/output/writers.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// fit.json's numbers read back exactly (null where not finite); report.md shows 6 digits.
std::string Number(double value) { return JsonNumber(value); }
std::string Shown(double value) { return RoundedNumber(value, 6); }

const FitMeasurement& MeasurementOf(const FitProblem& problem, const ResidualBlock& block) {
  return problem.spec().specimens[block.specimen].measurements[block.measurement];
}

std::string UnitOf(const FitMeasurement& measurement) {
  switch (measurement.kind) {
    case FitMeasurement::Kind::kDrapeCoefficient:
      return "1";
    case FitMeasurement::Kind::kReactions:
      return "N";
    default:
      return "m";
  }
}

bool IsScalar(const FitMeasurement& measurement) {
  return measurement.kind == FitMeasurement::Kind::kDrapeCoefficient ||
         measurement.kind == FitMeasurement::Kind::kBendingLength;
}

// The unit of a fitted scene key, from the material registry of summary.json's material_si
// (src/output/writers.h): the value the key names (material.finite_volume.D_warp → D_warp), or
// the family it sets as a whole (material.springs.structural → structural.warp and .weft, one
// unit); "" for a key that is not a material value.
std::string ParameterUnit(const std::string& key, const Scene& scene) {
  const std::string prefix = "material.";
  if (key.rfind(prefix, 0) != 0) return "";
  const std::string rest = key.substr(prefix.size());
  const std::string last = rest.substr(rest.find_last_of('.') + 1);
  auto ends_with = [&rest](const std::string& name) {
    return rest == name ||
           (rest.size() > name.size() && rest[rest.size() - name.size() - 1] == '.' &&
            rest.compare(rest.size() - name.size(), name.size(), name) == 0);
  };
  for (const MaterialValue& value : MaterialSiValues(scene.material)) {
    if (ends_with(value.key) || value.key.rfind(last + ".", 0) == 0) return value.unit;
  }
  return "";
}

// The unit of each fitted parameter (ParameterUnit on the scene of a solved specimen; "" where
// there is none).
std::vector<std::string> ParameterUnits(const FitProblem& problem) {
  const auto& parameters = problem.spec().parameters;
  const auto& equilibria = problem.equilibria();
  const auto solved = std::find_if(equilibria.begin(), equilibria.end(),
                                   [](const FitEquilibrium& e) { return e.model != nullptr; });
  std::vector<std::string> units;
  units.reserve(parameters.size());
  for (const auto& parameter : parameters) {
    units.push_back(solved == equilibria.end() ? "" : ParameterUnit(parameter.key, solved->scene));
  }
  return units;
}

void WriteJson(const FitProblem& problem, const FitResult& result, const Provenance& provenance,
               std::ostream& out) {
  const auto& parameters = problem.spec().parameters;
  const int p = static_cast<int>(parameters.size());
  auto by_key = [&](const std::function<std::string(int)>& value) {
    std::vector<std::pair<std::string, std::string>> members;
    members.reserve(p);
    for (int j = 0; j < p; ++j) members.emplace_back(parameters[j].key, value(j));
    return JsonInlineObject(members);
  };
  auto numbers = [](int n, const std::function<double(int)>& value) {
    std::vector<std::string> items;
    items.reserve(n);
    for (int k = 0; k < n; ++k) items.push_back(Number(value(k)));
    return JsonList(items);
  };
  const std::vector<std::string> units = ParameterUnits(problem);
  std::vector<std::string> correlation;
  correlation.reserve(p);
  for (int i = 0; i < p; ++i) {
    correlation.push_back(numbers(p, [&](int j) { return result.correlation(i, j); }));
  }
  std::vector<std::string> measurements;
  const auto& blocks = problem.blocks();
  for (size_t b = 0; b < blocks.size(); ++b) {
    const FitMeasurement& measurement = MeasurementOf(problem, blocks[b]);
    std::vector<std::pair<std::string, std::string>> members = {
        {"label", JsonString(blocks[b].label)}};
    if (IsScalar(measurement)) {
      members.emplace_back("measured", Number(measurement.value));
      members.emplace_back("model", Number(result.final_evaluation.model_values[b]));
    } else {
      members.emplace_back("rms_difference", Number(result.final_evaluation.model_values[b]));
    }
    members.emplace_back("unit", JsonString(UnitOf(measurement)));
    measurements.push_back(JsonInlineObject(members));
  }
  std::vector<std::pair<std::string, std::string>> members = {
      {"fit_file", JsonString(problem.spec().file)},
      {"method", JsonString(problem.spec().method)},
      {"converged", JsonBool(result.converged)},
      {"termination", JsonString(result.termination)},
      {"objective", Number(result.objective)},
      {"residual_variance", Number(result.residual_variance)},
      {"evaluations", std::to_string(result.evaluations)},
      {"jacobian_evaluations", std::to_string(result.jacobian_evaluations)},
      {"jacobian", JsonString(result.jacobian_implicit ? "implicit" : "finite differences")},
      {"wall_time_s", Number(result.wall_time_s)},
      {"parameters", by_key([&](int j) { return Number(result.parameters[j]); })},
      {"initial", by_key([&](int j) { return Number(parameters[j].initial); })},
      {"standard_errors", by_key([&](int j) { return Number(result.standard_errors[j]); })},
      {"units", by_key([&](int j) { return JsonString(units[j]); })},
      {"identifiable",
       by_key([&](int j) { return JsonBool(result.identifiability.identifiable[j]); })},
      {"correlation", JsonList(correlation)},
      {"singular_values",
       numbers(p, [&](int k) { return result.identifiability.singular_values[k]; })},
      {"identifiability", JsonList(JsonStrings(result.identifiability.statements))},
      {"measurements", JsonListLines(measurements, 1)},
      {"warnings", JsonList(JsonStrings(problem.spec().warnings))}};
  for (auto& member : ProvenanceMembers(provenance)) members.push_back(std::move(member));
  out << JsonObject(members, 0) << "\n";
}

void WriteHistory(const FitProblem& problem, const FitResult& result, std::ostream& out) {
  out << "evaluation,time_s,objective,best_objective,inner_iterations,inner_converged,jacobian";
  for (const auto& parameter : problem.spec().parameters) out << "," << parameter.key;
  out << "\n";
  for (const auto& record : result.history) {
    out << record.evaluation << "," << CsvNumber(record.time_s) << ","
        << CsvNumber(record.objective) << "," << CsvNumber(record.best_objective) << ","
        << record.inner_iterations << "," << (record.inner_converged ? 1 : 0) << ","
        << (record.with_jacobian ? 1 : 0);
    for (double value : record.parameters) out << "," << CsvNumber(value);
    out << "\n";
  }
}

void WriteSensitivity(const std::vector<Sensitivity>& table, std::ostream& out) {
  out << "measurement,parameter,unit,d_measurement_d_parameter,d_measurement_d_ln_parameter\n";
  for (const auto& row : table) {
    out << JsonString(row.measurement) << "," << row.parameter << "," << row.unit << ","
        << CsvNumber(row.per_parameter) << "," << CsvNumber(row.per_log_parameter) << "\n";
  }
}

// report.md and report.html: the outcome, fit.png, the parameters (with their units), the
// measurements at the optimum, the sensitivities and the identifiability.
std::vector<ReportBlock> ReportBlocks(const FitProblem& problem, const FitResult& result,
                                      const std::vector<Sensitivity>& table,
                                      const Provenance& provenance) {
  const auto& parameters = problem.spec().parameters;
  std::ostringstream outcome;
  outcome << "Fit file `" << problem.spec().file << "`, method `" << problem.spec().method
          << "`: " << (result.converged ? "converged" : "NOT converged") << " ("
          << result.termination << ") after " << result.evaluations << " evaluations ("
          << result.jacobian_evaluations << " with Jacobian), " << Shown(result.wall_time_s)
          << " s. Objective ½Σr² = " << Shown(result.objective) << ", residual variance "
          << Shown(result.residual_variance) << ".";
  std::vector<ReportBlock> blocks = {
      HeadingBlock("Fit report: " + problem.spec().name), TextBlock(ProvenanceLine(provenance)),
      TextBlock(outcome.str()),
      ImageBlock("fit.png", "The fitted shape (blue) and the measured points (red)"),
      HeadingBlock("Parameters")};
  const std::vector<std::string> units = ParameterUnits(problem);
  std::vector<std::vector<std::string>> rows = {
      {"key", "initial", "fitted", "unit", "standard error", "identifiable"}};
  for (size_t j = 0; j < parameters.size(); ++j) {
    rows.push_back(
        {parameters[j].key, Shown(parameters[j].initial), Shown(result.parameters[j]), units[j],
         std::isfinite(result.standard_errors[j]) ? Shown(result.standard_errors[j]) : "—",
         result.identifiability.identifiable[j] ? "yes" : "NO"});
  }
  blocks.push_back(TableBlock(std::move(rows)));
  blocks.push_back(HeadingBlock("Measurements at the optimum"));
  rows = {{"measurement", "measured", "model", "unit"}};
  const auto& residual_blocks = problem.blocks();
  for (size_t b = 0; b < residual_blocks.size(); ++b) {
    const FitMeasurement& measurement = MeasurementOf(problem, residual_blocks[b]);
    rows.push_back({residual_blocks[b].label,
                    IsScalar(measurement) ? Shown(measurement.value) : "rms difference",
                    Shown(result.final_evaluation.model_values[b]), UnitOf(measurement)});
  }
  blocks.push_back(TableBlock(std::move(rows)));
  blocks.push_back(HeadingBlock("Sensitivity (∂measurement/∂parameter at the optimum)"));
  blocks.push_back(TextBlock("Vector measurements: root-mean-square over their components."));
  rows = {{"measurement", "parameter", "∂m/∂θ", "∂m/∂ln θ", "unit of m"}};
  for (const auto& row : table) {
    rows.push_back({row.measurement, row.parameter, Shown(row.per_parameter),
                    Shown(row.per_log_parameter), row.unit});
  }
  blocks.push_back(TableBlock(std::move(rows)));
  blocks.push_back(HeadingBlock("Identifiability"));
  std::string singular;
  for (double s : result.identifiability.singular_values) singular += " " + Shown(s);
  blocks.push_back(TextBlock(
      "Singular values of the Jacobian of the normalised residuals (residual / measurement "
      "uncertainty) with respect to the (log-)parameters:" +
      singular +
      ". A direction whose singular value is below 1 changes the fit by less than one "
      "measurement uncertainty per unit step (a factor e of a log parameter)."));
  for (const auto& statement : result.identifiability.statements) {
    blocks.push_back(TextBlock(statement));
  }
  return blocks;
}

const FitEquilibrium& PlottedEquilibrium(const FitProblem& problem) {
  for (const auto& candidate : problem.equilibria()) {
    if (candidate.model) return candidate;
  }
  assert(false && "a fit has solved at least one equilibrium before writing");
  return problem.equilibria().front();
}

// The plotted points' box: the fitted nodes and the measured points of the first specimen.
void PlotBox(const std::vector<double>& x, const std::vector<Eigen::Vector3d>& measured,
             Eigen::Vector3d* low, Eigen::Vector3d* high) {
  *low = Eigen::Vector3d::Constant(1e300);
  *high = -*low;
  for (size_t k = 0; k + 2 < x.size(); k += 3) {
    const Eigen::Vector3d p(x[k], x[k + 1], x[k + 2]);
    *low = low->cwiseMin(p);
    *high = high->cwiseMax(p);
  }
  for (const auto& p : measured) {
    *low = low->cwiseMin(p);
    *high = high->cwiseMax(p);
  }
}

std::vector<Eigen::Vector3d> MeasuredPoints(const FitProblem& problem) {
  std::vector<Eigen::Vector3d> measured;
  for (const auto& measurement : problem.spec().specimens[0].measurements) {
    if (measurement.kind != FitMeasurement::Kind::kPositions) continue;
    measured.insert(measured.end(), measurement.positions.points.begin(),
                    measurement.positions.points.end());
  }
  return measured;
}

// Draws one view: the frame, its ticks and their values, the axis names, the fitted mesh's edges
// (blue) and the measured points (red). `axes` are the plotted coordinates (0 = x, 1 = y, 2 = z).
struct ViewFrame {
  double left = 0, top = 0, size = 0;  // pixels
  Eigen::Vector3d low;                 // m, at the frame's lower left
  double span = 1;                     // m across the frame
  std::array<int, 2> axes{0, 2};
};

void DrawText(cairo_t* cr, double x, double y, const std::string& text, double align) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, x - align * extents.x_advance, y);
  cairo_show_text(cr, text.c_str());
}

void DrawAxes(cairo_t* cr, const ViewFrame& view, const std::array<std::string, 2>& names) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, view.left, view.top, view.size, view.size);
  cairo_stroke(cr);
  for (int a = 0; a < 2; ++a) {
    const int axis = view.axes[a];
    for (double tick : AxisTicks(view.low[axis], view.low[axis] + view.span)) {
      const double at = (tick - view.low[axis]) / view.span * view.size;
      const std::string label = RoundedNumber(tick, 4);
      if (a == 0) {
        const double px = view.left + at, py = view.top + view.size;
        cairo_move_to(cr, px, py);
        cairo_line_to(cr, px, py + 5);
        cairo_stroke(cr);
        DrawText(cr, px, py + 17, label, 0.5);
      } else {
        const double px = view.left, py = view.top + view.size - at;
        cairo_move_to(cr, px, py);
        cairo_line_to(cr, px - 5, py);
        cairo_stroke(cr);
        DrawText(cr, px - 8, py + 4, label, 1.0);
      }
    }
  }
  DrawText(cr, view.left + view.size / 2, view.top + view.size + 34, names[0], 0.5);
  cairo_save(cr);
  cairo_translate(cr, view.left - 52, view.top + view.size / 2);
  cairo_rotate(cr, -M_PI / 2);
  DrawText(cr, 0, 0, names[1], 0.5);
  cairo_restore(cr);
}

void DrawShapes(cairo_t* cr, const ViewFrame& view, const Model& model,
                const std::vector<double>& x, const std::vector<Eigen::Vector3d>& measured) {
  auto to_screen = [&](const Eigen::Vector3d& p, double* sx, double* sy) {
    *sx = view.left + (p[view.axes[0]] - view.low[view.axes[0]]) / view.span * view.size;
    *sy = view.top + view.size - (p[view.axes[1]] - view.low[view.axes[1]]) / view.span * view.size;
  };
  cairo_set_source_rgb(cr, 0.1, 0.3, 0.8);
  cairo_set_line_width(cr, 0.6);
  auto line = [&](int a, int b) {
    double ax, ay, bx, by;
    to_screen(Eigen::Vector3d(x[3 * a], x[3 * a + 1], x[3 * a + 2]), &ax, &ay);
    to_screen(Eigen::Vector3d(x[3 * b], x[3 * b + 1], x[3 * b + 2]), &bx, &by);
    cairo_move_to(cr, ax, ay);
    cairo_line_to(cr, bx, by);
  };
  for (const auto& t : model.triangles) {
    line(t[0], t[1]);
    line(t[1], t[2]);
    line(t[2], t[0]);
  }
  for (const auto& e : model.edges) line(e[0], e[1]);
  if (model.triangles.empty() && model.edges.empty()) {
    for (int k = 0; k + 1 < model.num_nodes; ++k) line(k, k + 1);
  }
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
  for (const auto& p : measured) {
    double sx, sy;
    to_screen(p, &sx, &sy);
    cairo_arc(cr, sx, sy, 1.8, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

// fit.png: the fitted shape (blue mesh edges) over the measured points (red), side view (x–z)
// and top view (x–y) on one scale, with axes in metres, and under them FitPlotTextOf's caption
// (the fitted values and the final residual); drawn with cairo.
void WritePng(const FitProblem& problem, const FitResult& result, const fs::path& path) {
  const FitEquilibrium& equilibrium = PlottedEquilibrium(problem);
  const std::vector<double>& x = equilibrium.positions;
  const std::vector<Eigen::Vector3d> measured = MeasuredPoints(problem);
  const FitPlotText text = FitPlotTextOf(problem, result);
  Eigen::Vector3d low, high;
  PlotBox(x, measured, &low, &high);
  const double span = std::max(1e-9, (high - low).maxCoeff());
  const int panel = 460, left = 80, gap = 90, top = 40, below = 50, line_height = 18;
  const int width = left + 2 * panel + gap + 30;
  const int height = top + panel + below + line_height * static_cast<int>(text.caption.size()) + 10;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_font_size(cr, 12);
  for (int v = 0; v < 2; ++v) {
    ViewFrame view;
    view.left = left + v * (panel + gap);
    view.top = top;
    view.size = panel;
    view.low = low;
    view.span = span;
    view.axes = {0, v == 0 ? 2 : 1};
    DrawShapes(cr, view, *equilibrium.model, x, measured);
    DrawAxes(cr, view, {text.axis_labels[0], text.axis_labels[v == 0 ? 2 : 1]});
    DrawText(cr, view.left, top - 12, text.titles[v], 0.0);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  for (size_t k = 0; k < text.caption.size(); ++k) {
    DrawText(cr, left, top + panel + below + line_height * (k + 0.5), text.caption[k], 0.0);
  }
  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cannot write " + path.string());
  AddDrapeVersionToPngFile(path);
}

}  // namespace

std::vector<Sensitivity> SensitivityTable(const FitProblem& problem, const FitResult& result) {
  std::vector<Sensitivity> table;
  const auto& parameters = problem.spec().parameters;
  const std::vector<double> dtheta =
      problem.ParameterDerivatives(problem.ToUnknowns(result.parameters));
  for (const auto& block : problem.blocks()) {
    const FitMeasurement& measurement = MeasurementOf(problem, block);
    const double unscale = measurement.sigma / std::sqrt(measurement.weight);
    for (size_t j = 0; j < parameters.size(); ++j) {
      const Eigen::VectorXd column = result.jacobian.col(j).segment(block.offset, block.count);
      const double signed_or_rms =
          block.count == 1 ? column[0]
                           : column.norm() / std::sqrt(static_cast<double>(block.count));
      Sensitivity row;
      row.measurement = block.label;
      row.parameter = parameters[j].key;
      row.unit = UnitOf(measurement);
      row.per_parameter = signed_or_rms * unscale / dtheta[j];
      row.per_log_parameter = row.per_parameter * result.parameters[j];
      table.push_back(row);
    }
  }
  return table;
}

FitPlotText FitPlotTextOf(const FitProblem& problem, const FitResult& result) {
  FitPlotText text;
  text.titles = {"side view: fitted shape (blue), measured points (red)", "top view"};
  text.axis_labels = {"x (m)", "y (m)", "z (m)"};
  const auto& parameters = problem.spec().parameters;
  const std::vector<std::string> units = ParameterUnits(problem);
  for (size_t j = 0; j < parameters.size() && j < result.parameters.size(); ++j) {
    const std::string& unit = units[j];
    std::string line = parameters[j].key + " = " + RoundedNumber(result.parameters[j], 6);
    if (!unit.empty() && unit != "1") line += " " + unit;
    if (j < result.standard_errors.size()) {
      const double error = result.standard_errors[j];
      line += std::isfinite(error) ? " (standard error " + RoundedNumber(error, 3) + ")"
                                   : " (not identifiable)";
    }
    text.caption.push_back(line);
  }
  const Eigen::Index residuals = result.jacobian.rows();
  std::string residual =
      "final residual: objective 1/2 sum r^2 = " + RoundedNumber(result.objective, 6) +
      " (r = (model - measured) / sigma)";
  if (residuals > 0) {
    residual +=
        ", RMS r = " +
        RoundedNumber(std::sqrt(2.0 * result.objective / static_cast<double>(residuals)), 4) +
        " over " + std::to_string(residuals) + " residuals";
  }
  text.caption.push_back(residual);
  text.caption.push_back(std::string("converged ") + (result.converged ? "yes" : "no") + ", " +
                         std::to_string(result.evaluations) + " evaluations (" +
                         problem.spec().method + ")");
  return text;
}

void WriteFitOutputs(const FitProblem& problem, const FitResult& result,
                     const std::string& directory, const Provenance& provenance) {
  const fs::path folder(directory);
  fs::create_directories(folder);
  const std::vector<Sensitivity> table = SensitivityTable(problem, result);
  WriteAtomically(folder / "fit.json",
                  [&](std::ostream& out) { WriteJson(problem, result, provenance, out); });
  WriteAtomically(folder / "history.csv",
                  [&](std::ostream& out) { WriteHistory(problem, result, out); });
  WriteAtomically(folder / "sensitivity.csv",
                  [&](std::ostream& out) { WriteSensitivity(table, out); });
  WriteFileAtomically(folder / "fit.png",
                      [&](const fs::path& path) { WritePng(problem, result, path); });
  const std::vector<ReportBlock> report = ReportBlocks(problem, result, table, provenance);
  WriteAtomically(folder / "report.md",
                  [&](std::ostream& out) { WriteMarkdownReport(report, out); });
  WriteAtomically(folder / "report.html",
                  [&](std::ostream& out) { WriteHtmlReport(report, folder, out); });
}

}  // namespace drape
