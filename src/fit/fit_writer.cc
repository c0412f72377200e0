#include "src/fit/fit_writer.h"

#include <cairo.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "src/fit/fit_measurements.h"
#include "src/output/atomic_file.h"
#include "src/output/json.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// fit.json's numbers carry 10 significant digits.
std::string Number(double value) { return JsonNumber(value, 10); }

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

void WriteJson(const FitProblem& problem, const FitResult& result, std::ostream& out) {
  const auto& parameters = problem.spec().parameters;
  const int p = static_cast<int>(parameters.size());
  out << "{\n  \"fit_file\": " << JsonString(problem.spec().file) << ",\n";
  out << "  \"method\": " << JsonString(problem.spec().method) << ",\n";
  out << "  \"converged\": " << (result.converged ? "true" : "false") << ",\n";
  out << "  \"termination\": " << JsonString(result.termination) << ",\n";
  out << "  \"objective\": " << Number(result.objective) << ",\n";
  out << "  \"residual_variance\": " << Number(result.residual_variance) << ",\n";
  out << "  \"evaluations\": " << result.evaluations << ",\n";
  out << "  \"jacobian_evaluations\": " << result.jacobian_evaluations << ",\n";
  out << "  \"jacobian\": "
      << JsonString(result.jacobian_implicit ? "implicit" : "finite differences") << ",\n";
  out << "  \"wall_time_s\": " << Number(result.wall_time_s) << ",\n";
  auto by_key = [&](const std::string& name, const std::function<std::string(int)>& value) {
    out << "  " << JsonString(name) << ": {";
    for (int j = 0; j < p; ++j) {
      out << (j ? ", " : "") << JsonString(parameters[j].key) << ": " << value(j);
    }
    out << "},\n";
  };
  by_key("parameters", [&](int j) { return Number(result.parameters[j]); });
  by_key("initial", [&](int j) { return Number(parameters[j].initial); });
  by_key("standard_errors", [&](int j) { return Number(result.standard_errors[j]); });
  by_key("identifiable", [&](int j) {
    return std::string(result.identifiability.identifiable[j] ? "true" : "false");
  });
  out << "  \"correlation\": [";
  for (int i = 0; i < p; ++i) {
    out << (i ? ", " : "") << "[";
    for (int j = 0; j < p; ++j) out << (j ? ", " : "") << Number(result.correlation(i, j));
    out << "]";
  }
  out << "],\n  \"singular_values\": [";
  for (int k = 0; k < p; ++k) {
    out << (k ? ", " : "") << Number(result.identifiability.singular_values[k]);
  }
  out << "],\n  \"identifiability\": [";
  const auto& statements = result.identifiability.statements;
  for (size_t k = 0; k < statements.size(); ++k)
    out << (k ? ", " : "") << JsonString(statements[k]);
  out << "],\n  \"measurements\": [";
  const auto& blocks = problem.blocks();
  for (size_t b = 0; b < blocks.size(); ++b) {
    const FitMeasurement& measurement = MeasurementOf(problem, blocks[b]);
    out << (b ? ",\n    " : "\n    ") << "{\"label\": " << JsonString(blocks[b].label);
    if (IsScalar(measurement)) {
      out << ", \"measured\": " << Number(measurement.value)
          << ", \"model\": " << Number(result.final_evaluation.model_values[b]);
    } else {
      out << ", \"rms_difference\": " << Number(result.final_evaluation.model_values[b]);
    }
    out << ", \"unit\": " << JsonString(UnitOf(measurement)) << "}";
  }
  out << "\n  ]\n}\n";
}

void WriteHistory(const FitProblem& problem, const FitResult& result, std::ostream& out) {
  out << "evaluation,time_s,objective,best_objective,inner_iterations,inner_converged,jacobian";
  for (const auto& parameter : problem.spec().parameters) out << "," << parameter.key;
  out << "\n";
  for (const auto& record : result.history) {
    out << record.evaluation << "," << Number(record.time_s) << "," << Number(record.objective)
        << "," << Number(record.best_objective) << "," << record.inner_iterations << ","
        << (record.inner_converged ? 1 : 0) << "," << (record.with_jacobian ? 1 : 0);
    for (double value : record.parameters) out << "," << Number(value);
    out << "\n";
  }
}

void WriteSensitivity(const std::vector<Sensitivity>& table, std::ostream& out) {
  out << "measurement,parameter,unit,d_measurement_d_parameter,d_measurement_d_ln_parameter\n";
  for (const auto& row : table) {
    out << JsonString(row.measurement) << "," << row.parameter << "," << row.unit << ","
        << Number(row.per_parameter) << "," << Number(row.per_log_parameter) << "\n";
  }
}

void WriteReport(const FitProblem& problem, const FitResult& result,
                 const std::vector<Sensitivity>& table, std::ostream& out) {
  const auto& parameters = problem.spec().parameters;
  out << "# Fit report: " << problem.spec().name << "\n\n";
  out << "Fit file `" << problem.spec().file << "`, method `" << problem.spec().method
      << "`: " << (result.converged ? "converged" : "NOT converged") << " (" << result.termination
      << ") after " << result.evaluations << " evaluations (" << result.jacobian_evaluations
      << " with Jacobian), " << Number(result.wall_time_s)
      << " s. Objective ½Σr² = " << Number(result.objective) << ", residual variance "
      << Number(result.residual_variance)
      << ".\n\n## Parameters\n\n| key | initial | fitted | standard error | identifiable |\n"
      << "|---|---|---|---|---|\n";
  for (size_t j = 0; j < parameters.size(); ++j) {
    out << "| " << parameters[j].key << " | " << Number(parameters[j].initial) << " | "
        << Number(result.parameters[j]) << " | "
        << (std::isfinite(result.standard_errors[j]) ? Number(result.standard_errors[j]) : "—")
        << " | " << (result.identifiability.identifiable[j] ? "yes" : "**no**") << " |\n";
  }
  out << "\n## Measurements at the optimum\n\n| measurement | measured | model | unit |\n"
      << "|---|---|---|---|\n";
  const auto& blocks = problem.blocks();
  for (size_t b = 0; b < blocks.size(); ++b) {
    const FitMeasurement& measurement = MeasurementOf(problem, blocks[b]);
    out << "| " << blocks[b].label << " | "
        << (IsScalar(measurement) ? Number(measurement.value) : "rms difference") << " | "
        << Number(result.final_evaluation.model_values[b]) << " | " << UnitOf(measurement)
        << " |\n";
  }
  out << "\n## Sensitivity (∂measurement/∂parameter at the optimum)\n\n"
      << "Vector measurements: root-mean-square over their components.\n\n"
      << "| measurement | parameter | ∂m/∂θ | ∂m/∂ln θ | unit of m |\n|---|---|---|---|---|\n";
  for (const auto& row : table) {
    out << "| " << row.measurement << " | " << row.parameter << " | " << Number(row.per_parameter)
        << " | " << Number(row.per_log_parameter) << " | " << row.unit << " |\n";
  }
  out << "\n## Identifiability\n\nSingular values of the Jacobian of the normalised residuals "
         "(residual / measurement uncertainty) with respect to the (log-)parameters:";
  for (double s : result.identifiability.singular_values) out << " " << Number(s);
  out << ". A direction whose singular value is below 1 changes the fit by less than one "
         "measurement uncertainty per unit step (a factor e of a log parameter).\n\n";
  for (const auto& statement : result.identifiability.statements) out << "- " << statement << "\n";
}

// fit.png: the fitted shape (blue mesh edges) over the measured points (red), side view (x–z)
// and top view (x–y), drawn with cairo.
void WritePng(const FitProblem& problem, const fs::path& path) {
  const FitEquilibrium* first = nullptr;
  for (const auto& candidate : problem.equilibria()) {
    if (!first && candidate.model) first = &candidate;
  }
  const FitEquilibrium& equilibrium = *first;
  const Model& model = *equilibrium.model;
  const std::vector<double>& x = equilibrium.positions;
  std::vector<Eigen::Vector3d> measured;
  for (const auto& measurement : problem.spec().specimens[0].measurements) {
    if (measurement.kind != FitMeasurement::Kind::kPositions) continue;
    measured.insert(measured.end(), measurement.positions.points.begin(),
                    measurement.positions.points.end());
  }
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), high = -low;
  for (int k = 0; k < model.num_nodes; ++k) {
    const Eigen::Vector3d p(x[3 * k], x[3 * k + 1], x[3 * k + 2]);
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  for (const auto& p : measured) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double span = std::max(1e-9, (high - low).maxCoeff());
  const int panel = 500, margin = 30;
  cairo_surface_t* surface =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, 2 * panel + 3 * margin, panel + 2 * margin);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  for (int view = 0; view < 2; ++view) {
    const int vertical = view == 0 ? 2 : 1;  // side view: z up; top view: y up
    const double left = margin + view * (panel + margin);
    auto to_screen = [&](const Eigen::Vector3d& p, double* sx, double* sy) {
      *sx = left + (p.x() - low.x()) / span * panel;
      *sy = margin + panel - (p[vertical] - low[vertical]) / span * panel;
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
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, left, margin - 10);
    cairo_show_text(
        cr, view == 0 ? "side view (x-z): fitted (blue), measured (red)" : "top view (x-y)");
  }
  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cannot write " + path.string());
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

void WriteFitOutputs(const FitProblem& problem, const FitResult& result,
                     const std::string& directory) {
  const fs::path folder(directory);
  fs::create_directories(folder);
  const std::vector<Sensitivity> table = SensitivityTable(problem, result);
  WriteAtomically(folder / "fit.json", [&](std::ostream& out) { WriteJson(problem, result, out); });
  WriteAtomically(folder / "history.csv",
                  [&](std::ostream& out) { WriteHistory(problem, result, out); });
  WriteAtomically(folder / "sensitivity.csv",
                  [&](std::ostream& out) { WriteSensitivity(table, out); });
  WriteAtomically(folder / "report.md",
                  [&](std::ostream& out) { WriteReport(problem, result, table, out); });
  WriteFileAtomically(folder / "fit.png", [&](const fs::path& path) { WritePng(problem, path); });
}

}  // namespace drape
