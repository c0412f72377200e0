// Result files. Each is written to a hidden temporary name in the output folder, flushed, and then
// renamed over its final name (rename is atomic within one file system), so a reader never sees a
// half-written file, even if the run is killed while writing.
#include "src/output/writers.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "src/analysis/drape_analysis.h"
#include "src/model/contact.h"
#include "src/output/render.h"
#include "src/output/result_folder.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

// A number with every digit needed to read it back exactly (%.17g).
std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// JSON has no NaN or infinity: those are written as null.
std::string JsonNumber(double value) { return std::isfinite(value) ? Number(value) : "null"; }

std::string JsonString(const std::string& text) {
  std::string quoted = "\"";
  for (unsigned char c : text) {
    switch (c) {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\r':
        quoted += "\\r";
        break;
      case '\t':
        quoted += "\\t";
        break;
      default:
        if (c < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
          quoted += escaped;
        } else {
          quoted += static_cast<char>(c);
        }
    }
  }
  return quoted + "\"";
}

std::string JsonBool(bool value) { return value ? "true" : "false"; }

// `"key": value` members of one JSON object, joined with the indentation of `depth`.
std::string JsonObject(const std::vector<std::pair<std::string, std::string>>& members, int depth) {
  if (members.empty()) return "{}";
  const std::string inner(2 * (depth + 1), ' ');
  std::string text = "{\n";
  for (size_t k = 0; k < members.size(); ++k) {
    text += inner + JsonString(members[k].first) + ": " + members[k].second;
    text += k + 1 < members.size() ? ",\n" : "\n";
  }
  return text + std::string(2 * depth, ' ') + "}";
}

template <typename Map, typename Format>
std::string JsonMap(const Map& map, int depth, Format format) {
  std::vector<std::pair<std::string, std::string>> members;
  for (const auto& [key, value] : map) members.emplace_back(key, format(value));
  return JsonObject(members, depth);
}

// Writes directory/name through a temporary file in the same directory, then renames it.
void WriteAtomically(const fs::path& directory, const std::string& name,
                     const std::function<void(std::ostream&)>& write) {
  const fs::path final_path = directory / name;
  const fs::path temporary = directory / ("." + name + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) {
      throw std::runtime_error("cannot write " + temporary.string() + ": " + std::strerror(errno));
    }
    write(file);
    file.flush();
    if (!file) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error("cannot write " + temporary.string() + ": " + std::strerror(errno));
    }
  }
  std::error_code error;
  fs::rename(temporary, final_path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + final_path.string() + ": " + error.message());
  }
}

std::string FixedLetters(const Model& model, int node) {
  std::string letters;
  for (int c = 0; c < 3; ++c) {
    if (model.fixed[3 * node + c]) letters += "xyz"[c];
  }
  return letters;
}

bool AnyFixed(const Model& model, int node) {
  return model.fixed[3 * node] || model.fixed[3 * node + 1] || model.fixed[3 * node + 2];
}

// The certificate's force on a node (reaction where fixed, residual where free); NaN if the
// certificate could not be evaluated.
double NodeForce(const RunResult& result, int k) {
  const auto& forces = result.certificate.node_forces;
  return k < static_cast<int>(forces.size()) ? forces[k] : NAN;
}

std::string JsonArray(const std::vector<double>& values) {
  std::string text = "[";
  for (size_t k = 0; k < values.size(); ++k) text += (k ? ", " : "") + JsonNumber(values[k]);
  return text + "]";
}

// For a scene with a drape coefficient (HasDrapeCoefficient): `drape_coefficient` (Cusick's, with
// a disk) and `drape` (both conventions, the areas, the rasterisation's error bound, the radial
// profile's centre and radii, and the folds).
void AddDrapeMembers(const DrapeAnalysis& analysis,
                     std::vector<std::pair<std::string, std::string>>* members) {
  const DrapeCoefficient& dc = analysis.coefficient;
  const Folds& folds = analysis.folds;
  const bool disc = analysis.disc_radius > 0.0;
  if (disc) members->emplace_back("drape_coefficient", JsonNumber(dc.cusick));
  const auto& centre = analysis.profile.centre;
  members->emplace_back("drape",
                        JsonObject({{"cusick", disc ? JsonNumber(dc.cusick) : "null"},
                                    {"ratio", JsonNumber(dc.ratio)},
                                    {"shadow_area_m2", JsonNumber(dc.shadow.area)},
                                    {"flat_area_m2", JsonNumber(dc.flat_area)},
                                    {"area_error_bound_m2", JsonNumber(dc.shadow.error_bound)},
                                    {"profile_centre_m", JsonArray({centre[0], centre[1]})},
                                    {"radius_min_m", JsonNumber(analysis.radius_min)},
                                    {"radius_mean_m", JsonNumber(analysis.radius_mean)},
                                    {"radius_max_m", JsonNumber(analysis.radius_max)},
                                    {"folds", std::to_string(folds.count)},
                                    {"fold_angles_deg", JsonArray(folds.angles_deg)}},
                                   1));
}

// How deep the fabric sits in the obstacles' clearance layer (the contact penalty's accuracy).
void AddContactMembers(const Scene& scene, const Model& model,
                       std::vector<std::pair<std::string, std::string>>* members) {
  if (scene.obstacles.empty()) return;
  const ContactReport contact =
      MeasureContact(scene.obstacles, scene.contact, model, model.positions.data());
  members->emplace_back(
      "contact",
      JsonObject({{"thickness", JsonNumber(contact.thickness)},
                  {"stiffness", JsonNumber(contact.stiffness)},
                  {"nodes_in_contact", std::to_string(contact.nodes_in_contact)},
                  {"max_penetration", JsonNumber(contact.max_penetration)},
                  {"max_penetration_fraction", JsonNumber(contact.max_penetration_fraction)},
                  {"allowed_fraction", JsonNumber(contact.allowed_fraction)}},
                 1));
}

void WriteSummary(const Scene& scene, const Model& model, const RunResult& result,
                  const std::optional<DrapeAnalysis>& drape, std::ostream& out) {
  const Certificate& certificate = result.certificate;
  const SolverSummary& summary = result.summary;
  std::vector<std::pair<std::string, double>> energy{{"total", certificate.energy}};
  for (const auto& [type, value] : certificate.energy_by_type) energy.emplace_back(type, value);
  const Eigen::Vector3d& reactions = certificate.reaction_sum;
  const std::string reaction_sum = "[" + JsonNumber(reactions.x()) + ", " +
                                   JsonNumber(reactions.y()) + ", " + JsonNumber(reactions.z()) +
                                   "]";

  std::vector<std::pair<std::string, std::string>> members = {
      {"scene", JsonString(scene.name)},
      {"scene_file", JsonString(scene.file)},
      {"solver", JsonString(summary.solver)},
      {"converged", JsonBool(result.converged)},
      {"termination", JsonString(summary.termination)},
      {"iterations", std::to_string(summary.iterations)},
      {"wall_time_s", JsonNumber(summary.wall_time_s)},
      {"nodes", std::to_string(model.num_nodes)},
      {"free_dofs", std::to_string(model.num_free_dofs())},
      {"terms", JsonMap(model.TermCounts(), 1, [](int count) { return std::to_string(count); })},
      {"energy", JsonMap(energy, 1, JsonNumber)},
      {"residual", JsonObject({{"max_node_force", JsonNumber(certificate.max_node_force)},
                               {"relative", JsonNumber(certificate.relative_residual)}},
                              1)},
      {"reactions", JsonObject({{"sum", reaction_sum}}, 1)},
      {"stable", result.stability.computed ? JsonBool(result.stability.stable) : "null"},
  };
  if (result.stability.computed && !result.stability.stable) {
    members.emplace_back("min_eigenvalue", JsonNumber(result.stability.min_eigenvalue));
  }
  if (drape) AddDrapeMembers(*drape, &members);
  AddContactMembers(scene, model, &members);
  members.emplace_back("tolerance", JsonNumber(scene.solver.tolerance));
  members.emplace_back("statistics", JsonMap(summary.statistics, 1, JsonNumber));
  out << JsonObject(members, 0) << "\n";
}

void WriteNodes(const Model& model, const RunResult& result, std::ostream& out) {
  out << "id,i,j,x,y,z,fixed,fx,fy,fz\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    const auto ij = node < static_cast<int>(model.grid_index.size()) ? model.grid_index[node]
                                                                     : std::array<int, 2>{-1, -1};
    out << node << ',' << ij[0] << ',' << ij[1];
    for (int c = 0; c < 3; ++c) out << ',' << Number(model.positions[3 * node + c]);
    out << ',' << FixedLetters(model, node);
    for (int c = 0; c < 3; ++c) out << ',' << Number(NodeForce(result, 3 * node + c));
    out << '\n';
  }
}

void WriteHistory(const SolverSummary& summary, std::ostream& out) {
  out << "iteration,time_s,energy,residual\n";
  for (const IterationRecord& record : summary.history) {
    out << record.iteration << ',' << Number(record.time_s) << ',' << Number(record.energy) << ','
        << Number(record.relative_residual) << '\n';
  }
}

// The per-step series some methods record beyond the history (puiseux-dynamic's kinetic energy).
void WriteTrace(const SolverSummary& summary, std::ostream& out) {
  for (size_t k = 0; k < summary.trace_columns.size(); ++k) {
    out << (k ? "," : "") << summary.trace_columns[k];
  }
  out << '\n';
  for (const auto& row : summary.trace) {
    for (size_t k = 0; k < row.size(); ++k) out << (k ? "," : "") << Number(row[k]);
    out << '\n';
  }
}

void WriteVectors(const std::string& name, const std::function<double(int)>& value, int count,
                  std::ostream& out) {
  out << "VECTORS " << name << " double\n";
  for (int node = 0; node < count; ++node) {
    out << Number(value(3 * node)) << ' ' << Number(value(3 * node + 1)) << ' '
        << Number(value(3 * node + 2)) << '\n';
  }
}

// Legacy ASCII VTK polydata: the surface triangles, the line elements, and per node the
// displacement from the start, the certificate's force and whether the node is (partly) fixed.
void WriteVtk(const Scene& scene, const Model& model, const RunResult& result, std::ostream& out) {
  std::string title = "drape " + scene.name;
  std::replace(title.begin(), title.end(), '\n', ' ');
  out << "# vtk DataFile Version 3.0\n" << title.substr(0, 250) << "\nASCII\nDATASET POLYDATA\n";
  out << "POINTS " << model.num_nodes << " double\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    out << Number(model.positions[3 * node]) << ' ' << Number(model.positions[3 * node + 1]) << ' '
        << Number(model.positions[3 * node + 2]) << '\n';
  }
  if (!model.triangles.empty()) {
    out << "POLYGONS " << model.triangles.size() << ' ' << 4 * model.triangles.size() << '\n';
    for (const auto& t : model.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  if (!model.edges.empty()) {
    out << "LINES " << model.edges.size() << ' ' << 3 * model.edges.size() << '\n';
    for (const auto& e : model.edges) out << "2 " << e[0] << ' ' << e[1] << '\n';
  }
  out << "POINT_DATA " << model.num_nodes << '\n';
  WriteVectors(
      "displacement",
      [&model](int k) {
        return k < static_cast<int>(model.initial.size()) ? model.positions[k] - model.initial[k]
                                                          : 0.0;
      },
      model.num_nodes, out);
  WriteVectors(
      "force", [&result](int k) { return NodeForce(result, k); }, model.num_nodes, out);
  out << "SCALARS fixed int 1\nLOOKUP_TABLE default\n";
  for (int node = 0; node < model.num_nodes; ++node) out << (AnyFixed(model, node) ? 1 : 0) << '\n';
}

// Wavefront OBJ: vertices, triangular faces and line elements (1-based indices).
void WriteObj(const Scene& scene, const Model& model, std::ostream& out) {
  out << "# drape: " << scene.name << "\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    out << "v " << Number(model.positions[3 * node]) << ' ' << Number(model.positions[3 * node + 1])
        << ' ' << Number(model.positions[3 * node + 2]) << '\n';
  }
  for (const auto& t : model.triangles) {
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  for (const auto& e : model.edges) out << "l " << e[0] + 1 << ' ' << e[1] + 1 << '\n';
}

// profile.csv: the shadow's radial profile, one row per ray (see ComputeRadialProfile), with the
// flat specimen's radius on the same ray, and the overhang fraction the folds are counted on, raw
// and smoothed (see DrapeAnalysis, CountFolds).
void WriteProfile(const DrapeAnalysis& analysis, std::ostream& out) {
  out << "theta_deg,radius_m,flat_radius_m,overhang_fraction,smoothed_overhang_fraction\n";
  const auto& profile = analysis.profile;
  for (size_t k = 0; k < profile.radius.size(); ++k) {
    out << Number(360.0 * k / profile.radius.size()) << ',' << Number(profile.radius[k]) << ','
        << Number(analysis.flat_profile.radius[k]) << ',' << Number(analysis.overhang[k]) << ','
        << Number(analysis.folds.smoothed[k]) << '\n';
  }
}

// The captions of drape.png for a drape: both drape coefficients and the fold count.
std::vector<std::string> DrapeCaption(const DrapeAnalysis& analysis) {
  std::string line = "drape coefficient ";
  if (analysis.disc_radius > 0.0)
    line += CoefficientText(analysis.coefficient.cusick) + " (Cusick), ";
  line += CoefficientText(analysis.coefficient.ratio) + " (A_shadow/A_flat); " +
          std::to_string(analysis.folds.count) + " folds";
  return {line};
}

bool Requested(const Scene& scene, const std::string& what) {
  const auto& write = scene.output.write;
  return std::find(write.begin(), write.end(), what) != write.end();
}

}  // namespace

void WriteOutputs(const Scene& scene, const Model& model, const RunResult& result,
                  const std::string& directory) {
  ResultFolder result_folder(directory);  // the files go to its staging folder, then move in
  const fs::path& folder = result_folder.staging();
  std::optional<DrapeAnalysis> drape;
  if (HasDrapeCoefficient(scene, model)) drape = AnalyseDrape(scene, model);
  if (Requested(scene, "summary")) {
    WriteAtomically(folder, "summary.json",
                    [&](std::ostream& out) { WriteSummary(scene, model, result, drape, out); });
  }
  if (Requested(scene, "nodes")) {
    WriteAtomically(folder, "nodes.csv",
                    [&](std::ostream& out) { WriteNodes(model, result, out); });
  }
  if (Requested(scene, "history")) {
    WriteAtomically(folder, "history.csv",
                    [&](std::ostream& out) { WriteHistory(result.summary, out); });
  }
  // The per-step trace of the methods that record one goes with the history.
  if ((Requested(scene, "history") || Requested(scene, "kinetic")) &&
      !result.summary.trace_columns.empty()) {
    WriteAtomically(folder, "kinetic.csv",
                    [&](std::ostream& out) { WriteTrace(result.summary, out); });
  }
  if (Requested(scene, "vtk")) {
    WriteAtomically(folder, "mesh.vtk",
                    [&](std::ostream& out) { WriteVtk(scene, model, result, out); });
  }
  if (Requested(scene, "obj")) {
    WriteAtomically(folder, "mesh.obj", [&](std::ostream& out) { WriteObj(scene, model, out); });
  }
  if (drape && Requested(scene, "profile")) {
    WriteAtomically(folder, "profile.csv", [&](std::ostream& out) { WriteProfile(*drape, out); });
  }
  if (Requested(scene, "png") && model.num_nodes > 0) {
    DrapeViewOptions view;
    if (drape) view.caption = DrapeCaption(*drape);
    WriteAtomically(folder, "drape.png",
                    [&](std::ostream& out) { DrawDrapeView(scene, model, out, view); });
  }
  if (drape && (Requested(scene, "png") || Requested(scene, "shadow"))) {
    WriteAtomically(folder, "shadow.png",
                    [&](std::ostream& out) { DrawShadowView(scene, model, *drape, out); });
  }
  result_folder.Commit();
}

}  // namespace drape
