// Result files, each written atomically (src/output/atomic_file.h).
#include "src/output/writers.h"

#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/mesh_rule.h"
#include "src/model/contact.h"
#include "src/output/atomic_file.h"
#include "src/output/gltf.h"
#include "src/output/json.h"
#include "src/output/render.h"
#include "src/output/result_folder.h"
#include "src/output/scene_yaml.h"
#include "src/output/surface_fields.h"
#include "src/run/state_text.h"
#include "src/scene/material_keys.h"
#include "src/scene/material_models.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

template <typename Map, typename Format>
std::string JsonMap(const Map& map, int depth, Format format) {
  std::vector<std::pair<std::string, std::string>> members;
  members.reserve(map.size());
  for (const auto& [key, value] : map) members.emplace_back(key, format(value));
  return JsonObject(members, depth);
}

// The certificate's force on a node (reaction where fixed, residual where free); NaN if the
// certificate could not be evaluated.
double NodeForce(const RunResult& result, int k) {
  const auto& forces = result.certificate.node_forces;
  return k < static_cast<int>(forces.size()) ? forces[k] : NAN;
}

std::string JsonArray(const std::vector<double>& values) {
  std::vector<std::string> items;
  items.reserve(values.size());
  for (double value : values) items.push_back(JsonNumber(value));
  return JsonList(items);
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

std::string JsonVector(const Eigen::Vector3d& v) { return JsonArray({v.x(), v.y(), v.z()}); }

// How deep the fabric sits in the obstacles' clearance layer (the contact penalty's accuracy), and
// the force the obstacles exert on it, in total and per obstacle (in the scene's order), N.
void AddContactMembers(const Scene& scene, const RunResult& result,
                       std::vector<std::pair<std::string, std::string>>* members) {
  if (scene.obstacles.empty()) return;
  const ContactReport& contact = result.contact;
  const Certificate& certificate = result.certificate;
  std::vector<std::string> by_obstacle;
  for (const auto& sum : certificate.contact_sum_by_obstacle)
    by_obstacle.push_back(JsonVector(sum));
  std::vector<std::pair<std::string, std::string>> fields = {
      {"thickness", JsonNumber(contact.thickness)},
      {"stiffness", JsonNumber(contact.stiffness)},
      {"nodes_in_contact", std::to_string(contact.nodes_in_contact)},
      {"max_penetration", JsonNumber(contact.max_penetration)},
      {"max_penetration_fraction", JsonNumber(contact.max_penetration_fraction)},
      {"allowed_fraction", JsonNumber(contact.allowed_fraction)},
      {"nodes_under_disk", std::to_string(contact.nodes_under_disk)},
      {"edges_through_disk", std::to_string(contact.edges_through_disk)},
      {"under_disk_inside_m", JsonNumber(contact.under_disk_inside)},
      {"edges_through_body", std::to_string(contact.edges_through_body)},
      {"force_sum", JsonVector(certificate.contact_sum)},
      {"force_by_obstacle", JsonList(by_obstacle)}};
  if (contact.friction) {
    fields.emplace_back("friction",
                        JsonObject({{"passes", std::to_string(contact.friction_passes)},
                                    {"push_change", JsonNumber(contact.friction_push_change)},
                                    {"push_tolerance", JsonNumber(kFrictionPushTolerance)},
                                    {"settled", JsonBool(contact.friction_settled)}},
                                   2));
  }
  members->emplace_back("contact", JsonObject(fields, 1));
}

// summary.json's `self_intersections`: whether the fabric's surface was tested (its positions
// finite), how many triangles, how many crossings of a triangle's side and a triangle, and the
// first of them (src/model/self_intersection.h).
std::string SelfIntersectionsJson(const SelfIntersections& found) {
  std::vector<std::pair<std::string, std::string>> fields = {
      {"checked", JsonBool(found.checked)},
      {"triangles", std::to_string(found.triangles)},
      {"crossings", std::to_string(found.crossings)}};
  if (found.Any()) {
    fields.emplace_back("first_side",
                        JsonList({std::to_string(found.side[0]), std::to_string(found.side[1])}));
    fields.emplace_back("first_triangle", JsonList({std::to_string(found.triangle[0]),
                                                    std::to_string(found.triangle[1]),
                                                    std::to_string(found.triangle[2])}));
  }
  return JsonObject(fields, 1);
}

// summary.json's `levels` (one object per level, coarsest first) and `extrapolation` (per
// quantity: value, error_estimate, observed_order, or available: false with the reason).
void AddLevelsMembers(const LevelsReport& report,
                      std::vector<std::pair<std::string, std::string>>* members) {
  std::vector<std::string> levels;
  for (const LevelRecord& level : report.levels) {
    std::vector<std::pair<std::string, std::string>> fields = {
        {"spacing_m", JsonNumber(level.spacing)},
        {"nodes", std::to_string(level.nodes)},
        {"iterations", std::to_string(level.iterations)},
        {"wall_time_s", JsonNumber(level.wall_time_s)},
        {"energy", JsonNumber(level.energy)},
        {"converged", JsonBool(level.converged)},
        {"stable", JsonBool(level.stable)},
        {"drape_coefficient",
         level.drape_coefficient ? JsonNumber(*level.drape_coefficient) : "null"},
        {"folds", level.folds ? std::to_string(*level.folds) : "null"},
        {"edges_through_disk", std::to_string(level.edges_through_disk)},
        {"edges_through_body", std::to_string(level.edges_through_body)},
        {"self_crossings", std::to_string(level.self_crossings)},
        {"started_flat", JsonBool(level.started_flat)},
        {"restarted_flat", JsonBool(level.restarted_flat)}};
    levels.push_back(JsonObject(fields, 2));
  }
  members->emplace_back("levels", JsonList(levels));
  std::vector<std::pair<std::string, std::string>> extrapolation;
  for (const Extrapolation& e : report.extrapolations) {
    std::vector<std::pair<std::string, std::string>> fields = {
        {"available", JsonBool(e.available)}};
    if (e.available) {
      fields.emplace_back("value", JsonNumber(e.value));
      fields.emplace_back("error_estimate", JsonNumber(e.error_estimate));
      fields.emplace_back("observed_order", JsonNumber(e.observed_order));
    } else {
      fields.emplace_back("reason", JsonString(e.reason));
    }
    extrapolation.emplace_back(e.quantity, JsonObject(fields, 2));
  }
  members->emplace_back("extrapolation", JsonObject(extrapolation, 1));
  if (const auto& bar = report.drape_error) {
    std::vector<std::string> folds;
    for (int count : bar->folds) folds.push_back(std::to_string(count));
    std::vector<std::pair<std::string, std::string>> fields = {
        {"estimate", JsonNumber(bar->error())},
        {"basis", JsonString(bar->basis())},
        {"levels_estimate", JsonNumber(bar->levels_error)},
        {"levels_basis", JsonString(bar->levels_basis)}};
    if (bar->mesh_rule_error) {
      fields.emplace_back("mesh_rule_estimate", JsonNumber(*bar->mesh_rule_error));
    }
    fields.emplace_back("folds_by_level", JsonList(folds));
    fields.emplace_back("folds_differ", JsonBool(bar->folds_differ));
    members->emplace_back("drape_coefficient_error", JsonObject(fields, 1));
  }
}

}  // namespace

std::string MeshRuleJson(const MeshAdvice& advice) {
  return JsonObject({{"spacing_m", JsonNumber(advice.spacing)},
                     {"bending_length_m", JsonNumber(advice.bending_length)},
                     {"error_per_spacing", JsonNumber(advice.error_per_spacing)},
                     {"expected_drape_coefficient_error", JsonNumber(advice.expected_error)},
                     {"accuracy", JsonNumber(advice.accuracy)},
                     {"spacing_needed_m", JsonNumber(advice.spacing_needed)},
                     {"spacing_chosen", JsonBool(advice.spacing_chosen)},
                     {"coarse", JsonBool(advice.coarse)}},
                    1);
}

namespace {

// The balance of the whole fabric: reactions + contact + constraint = −(weight + loads).
std::string BalanceObject(const Certificate& certificate) {
  return JsonObject({{"reactions", JsonVector(certificate.reaction_sum)},
                     {"contact", JsonVector(certificate.contact_sum)},
                     {"constraint", JsonVector(certificate.constraint_sum)},
                     {"weight_and_loads", JsonVector(certificate.applied_sum)},
                     {"relative_error", JsonNumber(certificate.balance_error)},
                     {"balanced", JsonBool(certificate.balanced)}},
                    1);
}

// summary.json's provenance: the format, ProvenanceMembers (drape's version, the OpenBLAS kernels,
// the command line, its --set overrides) and the material parameters in SI units (with their
// units).
void AddProvenanceMembers(const Scene& scene, const Provenance& provenance,
                          std::vector<std::pair<std::string, std::string>>* members) {
  members->emplace_back("format_version", std::to_string(kResultFormatVersion));
  for (auto& member : ProvenanceMembers(provenance)) members->push_back(std::move(member));
  std::vector<std::pair<std::string, std::string>> values = {
      {"model", JsonString(MaterialModelName(scene.material.model))}};
  std::vector<std::pair<std::string, std::string>> units;
  for (const MaterialValue& value : MaterialSiValues(scene.material)) {
    values.emplace_back(value.key, JsonNumber(value.value));
    units.emplace_back(value.key, JsonString(value.unit));
  }
  values.emplace_back("units", JsonObject(units, 2));
  members->emplace_back("material_si", JsonObject(values, 1));
  const std::vector<GivenMeasurement>& measured = scene.material.finite_volume.measured;
  if (measured.empty()) return;
  std::vector<std::pair<std::string, std::string>> given, given_units;
  for (const GivenMeasurement& value : measured) {
    given.emplace_back(value.key, JsonNumber(value.value));
    given_units.emplace_back(value.key, JsonString(value.unit.empty() ? "1" : value.unit));
  }
  given.emplace_back("units", JsonObject(given_units, 2));
  members->emplace_back("material_as_given", JsonObject(given, 1));
}

// summary.json's `units`: the unit of each member whose name carries none (a path through the
// objects, `levels[]` for every level; "1" for a ratio). A member the run does not write is not
// in the file, its unit is listed all the same. `statistics` are the method's own, in its units.
std::string UnitsObject() {
  static const std::vector<std::pair<std::string, std::string>> units = {
      {"energy", "J"},
      {"residual.max_node_force", "N"},
      {"residual.relative", "1"},
      {"residual.round_off_floor", "1"},
      {"reactions.sum", "N"},
      {"balance.reactions", "N"},
      {"balance.contact", "N"},
      {"balance.constraint", "N"},
      {"balance.weight_and_loads", "N"},
      {"balance.relative_error", "1"},
      {"min_eigenvalue", "N/m"},
      {"drape_coefficient", "1"},
      {"drape.cusick", "1"},
      {"drape.ratio", "1"},
      {"mesh_rule.expected_drape_coefficient_error", "1"},
      {"mesh_rule.accuracy", "1"},
      {"contact.thickness", "m"},
      {"contact.stiffness", "N/m^2"},
      {"contact.max_penetration", "m"},
      {"contact.max_penetration_fraction", "1"},
      {"contact.allowed_fraction", "1"},
      {"contact.force_sum", "N"},
      {"contact.force_by_obstacle", "N"},
      {"contact.friction.push_change", "1"},
      {"contact.friction.push_tolerance", "1"},
      {"tolerance", "1"},
      {"levels[].energy", "J"},
      {"levels[].drape_coefficient", "1"},
      {"extrapolation.energy", "J"},
      {"extrapolation.drape_coefficient", "1"},
      {"drape_coefficient_error.estimate", "1"},
      {"drape_coefficient_error.levels_estimate", "1"},
      {"drape_coefficient_error.mesh_rule_estimate", "1"}};
  std::vector<std::pair<std::string, std::string>> members;
  members.reserve(units.size());
  for (const auto& [path, unit] : units) members.emplace_back(path, JsonString(unit));
  return JsonObject(members, 1);
}

void WriteSummary(const Scene& scene, const Model& model, const SolveReport& report,
                  const Provenance& provenance, std::ostream& out) {
  const RunResult& result = report.result;
  const Certificate& certificate = result.certificate;
  const SolverSummary& summary = result.summary;
  std::vector<std::pair<std::string, double>> energy{{"total", certificate.energy}};
  for (const auto& [type, value] : certificate.energy_by_type) energy.emplace_back(type, value);
  const std::string reaction_sum = JsonVector(certificate.reaction_sum);

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
      {"mass_kg", JsonNumber(std::accumulate(model.mass.begin(), model.mass.end(), 0.0))},
      {"terms", JsonMap(model.TermCounts(), 1, [](int count) { return std::to_string(count); })},
      {"energy", JsonMap(energy, 1, [](double v) { return JsonNumber(v); })},
      {"residual", JsonObject({{"max_node_force", JsonNumber(certificate.max_node_force)},
                               {"relative", JsonNumber(certificate.relative_residual)},
                               {"round_off_floor", JsonNumber(result.residual_floor)},
                               {"at_round_off_floor", JsonBool(result.at_floor)}},
                              1)},
      {"reactions", JsonObject({{"sum", reaction_sum}}, 1)},
      {"balance", BalanceObject(certificate)},
      {"stable", result.stability.computed ? JsonBool(result.stability.stable) : "null"},
      {"saddle", JsonBool(result.Saddle())},
      {"state", JsonString(StateText(result))},
      {"interrupted", JsonBool(result.summary.termination.rfind("interrupted", 0) == 0)},
  };
  if (result.stability.computed && !result.stability.stable && certificate.unsound.empty()) {
    members.emplace_back("min_eigenvalue", JsonNumber(result.stability.min_eigenvalue));
  }
  if (!certificate.unsound.empty()) {
    members.emplace_back("state_problem", JsonString(certificate.unsound));
  }
  if (report.drape) AddDrapeMembers(*report.drape, &members);
  if (report.mesh_advice) members.emplace_back("mesh_rule", MeshRuleJson(*report.mesh_advice));
  AddContactMembers(scene, result, &members);
  members.emplace_back("self_intersections", SelfIntersectionsJson(result.self_intersections));
  members.emplace_back("tolerance", JsonNumber(scene.solver.tolerance));
  members.emplace_back("statistics",
                       JsonMap(summary.statistics, 1, [](double v) { return JsonNumber(v); }));
  if (report.levels) AddLevelsMembers(*report.levels, &members);
  members.emplace_back("units", UnitsObject());
  AddProvenanceMembers(scene, provenance, &members);
  out << JsonObject(members, 0) << "\n";
}

// The obstacles' force on a node (0 without obstacles; NaN if the certificate failed).
double ContactForce(const RunResult& result, int k) {
  const auto& forces = result.certificate.contact_forces;
  if (forces.empty()) return result.certificate.evaluable ? 0.0 : NAN;
  return k < static_cast<int>(forces.size()) ? forces[k] : NAN;
}

// The certificate's force split by the node's constraint: the reaction on the fixed coordinates
// (0 on free ones) and the residual on the free ones (0 on fixed ones), N.
double Reaction(const Model& model, const RunResult& result, int k) {
  return model.fixed[k] ? NodeForce(result, k) : 0.0;
}
double Residual(const Model& model, const RunResult& result, int k) {
  return model.fixed[k] ? 0.0 : NodeForce(result, k);
}

// mesh.vtk's in_contact: 1 where an obstacle pushes on the node (NodeInContact, as nodes.csv's
// in_contact and summary.json's nodes_in_contact), else 0.
int InContact(const RunResult& result, int node) {
  return NodeInContact(result.certificate.contact_forces, node) ? 1 : 0;
}

}  // namespace

std::string SummaryJsonText(const Scene& scene, const Model& model, const SolveReport& report,
                            const Provenance& provenance) {
  std::ostringstream out;
  WriteSummary(scene, model, report, provenance, out);
  return out.str();
}

std::vector<double> NodeReactions(const Model& model, const RunResult& result) {
  std::vector<double> forces(model.num_dofs());
  for (int k = 0; k < model.num_dofs(); ++k) forces[k] = Reaction(model, result, k);
  return forces;
}

std::vector<double> NodeContactForces(const Model& model, const RunResult& result) {
  std::vector<double> forces(model.num_dofs());
  for (int k = 0; k < model.num_dofs(); ++k) forces[k] = ContactForce(result, k);
  return forces;
}

const std::vector<std::string>& NodesCsvColumns() {
  static const std::vector<std::string> columns = {"id",
                                                   "i",
                                                   "j",
                                                   "x_m",
                                                   "y_m",
                                                   "z_m",
                                                   "fixed_x",
                                                   "fixed_y",
                                                   "fixed_z",
                                                   "in_contact",
                                                   "reaction_x_N",
                                                   "reaction_y_N",
                                                   "reaction_z_N",
                                                   "residual_x_N",
                                                   "residual_y_N",
                                                   "residual_z_N",
                                                   "contact_x_N",
                                                   "contact_y_N",
                                                   "contact_z_N"};
  return columns;
}

namespace {

// nodes.csv (format kResultFormatVersion): the columns of NodesCsvColumns().
void WriteNodes(const Model& model, const RunResult& result, std::ostream& out) {
  const std::vector<std::string>& columns = NodesCsvColumns();
  for (size_t k = 0; k < columns.size(); ++k) out << (k ? "," : "") << columns[k];
  out << '\n';
  for (int node = 0; node < model.num_nodes; ++node) {
    const auto ij = node < static_cast<int>(model.grid_index.size()) ? model.grid_index[node]
                                                                     : std::array<int, 2>{-1, -1};
    out << node << ',' << ij[0] << ',' << ij[1];
    for (int c = 0; c < 3; ++c) out << ',' << FormatNumber(model.positions[3 * node + c]);
    for (int c = 0; c < 3; ++c) out << ',' << JsonBool(model.fixed[3 * node + c] != 0);
    out << ',' << JsonBool(NodeInContact(result.certificate.contact_forces, node));
    for (int c = 0; c < 3; ++c) out << ',' << FormatNumber(Reaction(model, result, 3 * node + c));
    for (int c = 0; c < 3; ++c) out << ',' << FormatNumber(Residual(model, result, 3 * node + c));
    for (int c = 0; c < 3; ++c) out << ',' << FormatNumber(ContactForce(result, 3 * node + c));
    out << '\n';
  }
}

void WriteHistory(const SolverSummary& summary, std::ostream& out) {
  out << "iteration,time_s,energy_J,relative_residual\n";
  for (const IterationRecord& record : summary.history) {
    out << record.iteration << ',' << FormatNumber(record.time_s) << ','
        << FormatNumber(record.energy) << ',' << FormatNumber(record.relative_residual) << '\n';
  }
}

// The per-step series some methods record beyond the history (puiseux-dynamic's kinetic energy).
void WriteTrace(const SolverSummary& summary, std::ostream& out) {
  for (size_t k = 0; k < summary.trace_columns.size(); ++k) {
    out << (k ? "," : "") << summary.trace_columns[k];
  }
  out << '\n';
  for (const auto& row : summary.trace) {
    for (size_t k = 0; k < row.size(); ++k) out << (k ? "," : "") << FormatNumber(row[k]);
    out << '\n';
  }
}

void WriteVectors(const std::string& name, const std::function<double(int)>& value, int count,
                  std::ostream& out) {
  out << "VECTORS " << name << " double\n";
  for (int node = 0; node < count; ++node) {
    out << FormatNumber(value(3 * node)) << ' ' << FormatNumber(value(3 * node + 1)) << ' '
        << FormatNumber(value(3 * node + 2)) << '\n';
  }
}

double Distance(const std::vector<double>& x, int a, int b) {
  return (NodeAt(x, a) - NodeAt(x, b)).norm();
}

// The cells' strain from the start (model.initial): A/A₀ − 1 for a triangle, L/L₀ − 1 for a line
// element; 0 where the start is degenerate.
std::vector<double> CellStrains(const Model& model) {
  std::vector<double> strains;
  strains.reserve(model.triangles.size() + model.edges.size());
  const bool known = model.initial.size() == model.positions.size();
  for (const auto& t : model.triangles) {
    const double rest = known ? TriangleArea(model.initial, t) : 0.0;
    strains.push_back(rest > 0.0 ? TriangleArea(model.positions, t) / rest - 1.0 : 0.0);
  }
  for (const auto& e : model.edges) {
    const double rest = known ? Distance(model.initial, e[0], e[1]) : 0.0;
    strains.push_back(rest > 0.0 ? Distance(model.positions, e[0], e[1]) / rest - 1.0 : 0.0);
  }
  return strains;
}

// The yarn measures of the cells of a woven lattice (grid and circle meshes: every triangle has a
// corner where a warp link, along i, meets a weft link, along j), from that corner's two arms:
// the warp and weft strains L/L₀ − 1 and the shear angle γ = θ₀ − θ, rad (the closing of the angle
// between the yarns, positive when it closes, as fv_membrane's γ = π/2 − θ from a square start).
// Line elements: 0 for all three. Empty when some triangle has no such corner or the start is
// unknown.
struct YarnCellMeasures {
  std::vector<double> warp_strain, weft_strain, shear_angle;
};

// The corner of triangle t whose arms are a warp and a weft link (its index in t), or -1.
int YarnCorner(const Model& model, const std::array<int, 3>& t) {
  if (model.grid_index.size() != static_cast<size_t>(model.num_nodes)) return -1;
  for (int c = 0; c < 3; ++c) {
    const auto& here = model.grid_index[t[c]];
    const auto& a = model.grid_index[t[(c + 1) % 3]];
    const auto& b = model.grid_index[t[(c + 2) % 3]];
    if (here[0] < 0 || a[0] < 0 || b[0] < 0) return -1;
    auto along_i = [&](const std::array<int, 2>& n) {
      return n[1] == here[1] && std::abs(n[0] - here[0]) == 1;
    };
    auto along_j = [&](const std::array<int, 2>& n) {
      return n[0] == here[0] && std::abs(n[1] - here[1]) == 1;
    };
    if ((along_i(a) && along_j(b)) || (along_j(a) && along_i(b))) return c;
  }
  return -1;
}

YarnCellMeasures CellYarnMeasures(const Model& model) {
  YarnCellMeasures measures;
  if (model.initial.size() != model.positions.size() || model.triangles.empty()) return measures;
  for (const auto& t : model.triangles) {
    const int c = YarnCorner(model, t);
    if (c < 0) return {};
    int warp = t[(c + 1) % 3], weft = t[(c + 2) % 3];
    if (model.grid_index[warp][1] != model.grid_index[t[c]][1]) std::swap(warp, weft);
    const Eigen::Vector3d u = model.position(warp) - model.position(t[c]);
    const Eigen::Vector3d v = model.position(weft) - model.position(t[c]);
    const Eigen::Vector3d u0 = model.initial_position(warp) - model.initial_position(t[c]);
    const Eigen::Vector3d v0 = model.initial_position(weft) - model.initial_position(t[c]);
    if (!(u0.norm() > 0.0 && v0.norm() > 0.0)) return {};
    auto angle = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return std::atan2(a.cross(b).norm(), a.dot(b));
    };
    measures.warp_strain.push_back(u.norm() / u0.norm() - 1.0);
    measures.weft_strain.push_back(v.norm() / v0.norm() - 1.0);
    measures.shear_angle.push_back(angle(u0, v0) - angle(u, v));
  }
  for (size_t e = 0; e < model.edges.size(); ++e) {
    measures.warp_strain.push_back(0.0);
    measures.weft_strain.push_back(0.0);
    measures.shear_angle.push_back(0.0);
  }
  return measures;
}

void WriteCellScalars(const std::string& name, const std::vector<double>& values,
                      std::ostream& out) {
  out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
  for (double value : values) out << FormatNumber(value) << '\n';
}

// Legacy ASCII VTK unstructured grid, titled with drape's provenance and the scene: triangles
// (VTK_TRIANGLE) and line elements (VTK_LINE); per node its height (z, m: the first field, which a
// viewer shows by default), displacement from the start (m), reaction, residual and contact force
// (N), the per-coordinate fixed mask (0/1 × 3), in_contact (0/1) and its id; per cell the strain
// (CellStrains) and, on a woven lattice, the yarn strains and shear angle (CellYarnMeasures).
void WriteVtk(const Scene& scene, const Model& model, const RunResult& result,
              const Provenance& provenance, std::ostream& out) {
  std::string title = ProvenanceLine(provenance) + "; scene: " + scene.name;
  std::replace(title.begin(), title.end(), '\n', ' ');
  out << "# vtk DataFile Version 3.0\n"
      << title.substr(0, 250) << "\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << model.num_nodes << " double\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    const auto p = model.position(node);
    out << FormatNumber(p.x()) << ' ' << FormatNumber(p.y()) << ' ' << FormatNumber(p.z()) << '\n';
  }
  const size_t cells = model.triangles.size() + model.edges.size();
  out << "CELLS " << cells << ' ' << 4 * model.triangles.size() + 3 * model.edges.size() << '\n';
  for (const auto& t : model.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for (const auto& e : model.edges) out << "2 " << e[0] << ' ' << e[1] << '\n';
  out << "CELL_TYPES " << cells << '\n';
  for (size_t k = 0; k < cells; ++k) out << (k < model.triangles.size() ? 5 : 3) << '\n';
  out << "POINT_DATA " << model.num_nodes << '\n';
  out << "SCALARS height double 1\nLOOKUP_TABLE default\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    out << FormatNumber(model.positions[3 * node + 2]) << '\n';
  }
  WriteVectors(
      "displacement",
      [&model](int k) {
        return k < static_cast<int>(model.initial.size()) ? model.positions[k] - model.initial[k]
                                                          : 0.0;
      },
      model.num_nodes, out);
  WriteVectors(
      "reaction", [&](int k) { return Reaction(model, result, k); }, model.num_nodes, out);
  WriteVectors(
      "residual", [&](int k) { return Residual(model, result, k); }, model.num_nodes, out);
  WriteVectors(
      "contact_force", [&result](int k) { return ContactForce(result, k); }, model.num_nodes, out);
  out << "SCALARS fixed int 3\nLOOKUP_TABLE default\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    out << (model.fixed[3 * node] ? 1 : 0) << ' ' << (model.fixed[3 * node + 1] ? 1 : 0) << ' '
        << (model.fixed[3 * node + 2] ? 1 : 0) << '\n';
  }
  out << "SCALARS in_contact int 1\nLOOKUP_TABLE default\n";
  for (int node = 0; node < model.num_nodes; ++node) out << InContact(result, node) << '\n';
  out << "SCALARS id int 1\nLOOKUP_TABLE default\n";
  for (int node = 0; node < model.num_nodes; ++node) out << node << '\n';
  if (cells == 0) return;
  out << "CELL_DATA " << cells << '\n';
  WriteCellScalars("strain", CellStrains(model), out);
  const YarnCellMeasures yarns = CellYarnMeasures(model);
  if (yarns.shear_angle.empty()) return;
  WriteCellScalars("strain_warp", yarns.warp_strain, out);
  WriteCellScalars("strain_weft", yarns.weft_strain, out);
  WriteCellScalars("shear_angle", yarns.shear_angle, out);
}

// A vector in the OBJ's axes: as solved for `up` "z"; for "y" a quarter turn about x,
// (x, y, z) → (x, z, −y), so that drape's +z is the file's +y (a rotation: right-handed, and
// the normals turn with the positions).
Eigen::Vector3d ObjAxes(const Eigen::Vector3d& v, const std::string& up) {
  if (up == "z") return v;
  assert(up == "y" && "output.obj_up is checked by the loader");
  return {v.x(), v.z(), -v.y()};
}

// Wavefront OBJ: a comment with drape's provenance, vertices (z up as solved, or y up with
// output.obj_up: y), and for a surface the vertex normals and the flat pattern as texture
// coordinates (f v/vt/vn), then line elements (1-based).
void WriteObj(const Scene& scene, const Model& model, const Provenance& provenance,
              std::ostream& out) {
  const std::string& up = scene.output.obj_up;
  out << "# " << ProvenanceLine(provenance) << "\n";
  out << "# drape: " << scene.name << " (" << up << " up, m)\n";
  for (int node = 0; node < model.num_nodes; ++node) {
    const Eigen::Vector3d p = ObjAxes(model.position(node), up);
    out << "v " << FormatNumber(p.x()) << ' ' << FormatNumber(p.y()) << ' ' << FormatNumber(p.z())
        << '\n';
  }
  if (!model.triangles.empty()) {
    for (const auto& [u, v] : PatternCoordinates(model)) {
      out << "vt " << FormatNumber(u) << ' ' << FormatNumber(v) << '\n';
    }
    for (const Eigen::Vector3d& normal : VertexNormals(model)) {
      const Eigen::Vector3d n = ObjAxes(normal, up);
      out << "vn " << FormatNumber(n.x()) << ' ' << FormatNumber(n.y()) << ' '
          << FormatNumber(n.z()) << '\n';
    }
  }
  for (const auto& t : model.triangles) {
    out << "f";
    for (int v : t) out << ' ' << v + 1 << '/' << v + 1 << '/' << v + 1;
    out << '\n';
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
    out << FormatNumber(360.0 * k / profile.radius.size()) << ',' << FormatNumber(profile.radius[k])
        << ',' << FormatNumber(analysis.flat_profile.radius[k]) << ','
        << FormatNumber(analysis.overhang[k]) << ',' << FormatNumber(analysis.folds.smoothed[k])
        << '\n';
  }
}

// The captions of drape.png for a drape: both drape coefficients (Cusick's with the error bar of
// the stdout line, where there is one) and the fold count.
std::vector<std::string> DrapeCaption(const OutputContext& context) {
  const DrapeAnalysis& analysis = *context.report.drape;
  std::string line = "drape coefficient ";
  if (analysis.disc_radius > 0.0) {
    line += CoefficientText(analysis.coefficient.cusick);
    if (const std::optional<double> error = ReportedDrapeCoefficientError(context.report)) {
      line += " ± " + RoundedNumber(*error, 2);
    }
    line += " (Cusick), ";
  }
  line += CoefficientText(analysis.coefficient.ratio) + " (A_shadow/A_flat); " +
          std::to_string(analysis.folds.count) + " folds";
  return {line};
}

bool Requested(const Scene& scene, OutputKind kind) {
  const auto& write = scene.output.write;
  return std::find(write.begin(), write.end(), OutputKindOf(kind).name) != write.end();
}

bool HasDrape(const OutputContext& context) { return context.report.drape.has_value(); }

}  // namespace

std::vector<MaterialValue> MaterialSiValues(const MaterialSpec& material) {
  static const char* const mass_keys[] = {"density", "node_mass", "total_mass"};
  static const char* const mass_units[] = {"kg/m^2", "kg", "kg"};
  const int mass = static_cast<int>(material.mass_kind);
  std::vector<MaterialValue> values = {{mass_keys[mass], material.mass_value, mass_units[mass]}};
  switch (material.model) {
    case MaterialModel::kSprings:
      break;  // the springs below
    case MaterialModel::kFiniteVolume: {
      const FiniteVolumeSpec& fv = material.finite_volume;
      for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
        if (key.reported_when_zero || fv.*key.member != 0.0) {
          values.push_back({key.key, fv.*key.member, key.unit});
        }
      }
      for (const FrictionSetting& setting : FrictionSettings(fv)) {
        values.push_back({setting.key, setting.value, setting.unit});
      }
      break;
    }
  }
  const std::pair<const char*, const SpringFamilySpec*> families[] = {
      {"structural", &material.springs.structural},
      {"shear", &material.springs.shear},
      {"flexion", &material.springs.flexion}};
  values.reserve(values.size() + 2 * std::size(families));
  for (const auto& [name, family] : families) {
    if (!family->present) continue;
    values.push_back({std::string(name) + ".warp", family->warp, "N/m"});
    values.push_back({std::string(name) + ".weft", family->weft, "N/m"});
  }
  return values;
}

void CheckOutputWritable(const std::string& directory, const Location& key,
                         const std::string& option) {
  const fs::path folder = fs::absolute(fs::path(directory));
  // The outermost folder this check creates: removed again, so a run that fails later (a model
  // that cannot be built) leaves nothing behind.
  fs::path created;
  for (fs::path p = folder; !p.empty() && p != p.root_path(); p = p.parent_path()) {
    std::error_code ignored;
    if (!fs::exists(p, ignored)) {
      created = p;
      continue;
    }
    if (fs::is_directory(p, ignored)) break;
    // A file in the way: nothing is made.
    const std::string problem = p == folder ? "'" + p.string() + "' is a file, not a folder"
                                            : "cannot make the folder '" + folder.string() +
                                                  "': '" + p.string() + "' is a file";
    if (key.line > 0) throw InputError(key, problem);
    throw std::runtime_error(option.empty() ? problem : option + ": " + problem);
  }
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw std::runtime_error("cannot create " + folder.string() + ": " + error.message());
  const fs::path probe = folder / (".drape-write-check" + std::to_string(::getpid()));
  bool writable;
  {
    std::ofstream file(probe, std::ios::binary | std::ios::trunc);
    writable = static_cast<bool>(file);
  }
  const int saved_errno = errno;
  fs::remove(probe, error);
  if (!created.empty()) fs::remove_all(created, error);
  if (!writable) {
    throw std::runtime_error("cannot write into " + folder.string() + ": " +
                             std::strerror(saved_errno));
  }
}

const std::vector<OutputFileWriter>& OutputFileWriters() {
  using Kind = OutputKind;
  static const std::vector<OutputFileWriter> writers = {
      {"summary.json",
       {Kind::kSummary},
       nullptr,
       [](const OutputContext& c, std::ostream& out) {
         out << SummaryJsonText(c.scene, c.model, c.report, c.provenance);
       }},
      {"nodes.csv",
       {Kind::kNodes},
       nullptr,
       [](const OutputContext& c, std::ostream& out) {
         WriteNodes(c.model, c.report.result, out);
       }},
      {"history.csv",
       {Kind::kHistory},
       nullptr,
       [](const OutputContext& c, std::ostream& out) {
         WriteHistory(c.report.result.summary, out);
       }},
      // The per-step trace of the methods that record one goes with the history.
      {"kinetic_<method>.csv",
       {Kind::kHistory, Kind::kKinetic},
       [](const OutputContext& c) { return !c.report.result.summary.trace_columns.empty(); },
       [](const OutputContext& c, std::ostream& out) { WriteTrace(c.report.result.summary, out); }},
      {"mesh.vtk",
       {Kind::kVtk},
       nullptr,
       [](const OutputContext& c, std::ostream& out) {
         WriteVtk(c.scene, c.model, c.report.result, c.provenance, out);
       }},
      {"mesh.obj",
       {Kind::kObj},
       nullptr,
       [](const OutputContext& c, std::ostream& out) {
         WriteObj(c.scene, c.model, c.provenance, out);
       }},
      {"drape.glb",
       {Kind::kGltf},
       [](const OutputContext& c) { return c.model.num_nodes > 0; },
       [](const OutputContext& c, std::ostream& out) {
         WriteGlb(c.scene, c.model, c.report, c.provenance, out);
       }},
      {"profile.csv",
       {Kind::kProfile},
       HasDrape,
       [](const OutputContext& c, std::ostream& out) { WriteProfile(*c.report.drape, out); }},
      {"drape.png",
       {Kind::kPng},
       [](const OutputContext& c) { return c.model.num_nodes > 0; },
       [](const OutputContext& c, std::ostream& out) {
         DrapeViewOptions view;
         if (c.report.drape) view.caption = DrapeCaption(c);
         DrawDrapeView(c.scene, c.model, out, view);
       }},
      {"shadow.png",
       {Kind::kPng, Kind::kShadow},
       HasDrape,
       [](const OutputContext& c, std::ostream& out) {
         ShadowViewOptions view;
         view.drape_coefficient_error = ReportedDrapeCoefficientError(c.report);
         DrawShadowView(c.scene, c.model, *c.report.drape, out, view);
       }},
  };
  return writers;
}

void WriteOutputs(const Scene& scene, const Model& model, const SolveReport& report,
                  const std::string& directory, const Provenance& provenance) {
  ResultFolder result_folder(directory);  // the files go to its staging folder, then move in
  const fs::path& folder = result_folder.staging();
  const OutputContext context{scene, model, report, provenance};
  for (const OutputFileWriter& writer : OutputFileWriters()) {
    const bool requested = std::any_of(writer.kinds.begin(), writer.kinds.end(),
                                       [&](OutputKind kind) { return Requested(scene, kind); });
    if (!requested || (writer.applies && !writer.applies(context))) continue;
    WriteAtomically(folder / OutputFileName(writer.file, report.result.summary.solver),
                    [&](std::ostream& out) { writer.write(context, out); });
  }
  WriteAtomically(folder / kSolvedSceneFile, [&](std::ostream& out) {
    out << "# " << ProvenanceLine(provenance) << "\n";
    WriteSceneYaml(scene, out);
  });
  result_folder.Commit();
}

}  // namespace drape
