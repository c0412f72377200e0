#include "src/output/scene_yaml.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "src/output/json.h"
#include "src/run/run.h"
#include "src/scene/material_keys.h"
#include "src/scene/material_models.h"
#include "src/scene/scene_field.h"
#include "src/scene/scene_loader.h"
#include "src/scene/scene_schema.h"
#include "src/scene/solver_methods.h"

namespace drape {

namespace {

// Numbers that read back exactly (FormatNumber), lists in flow style.
void Number(YAML::Emitter& out, double value) { out << YAML::Value << FormatNumber(value); }

void Key(YAML::Emitter& out, const std::string& key) { out << YAML::Key << key; }

void Numbers(YAML::Emitter& out, const double* values, int count) {
  out << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int k = 0; k < count; ++k) out << FormatNumber(values[k]);
  out << YAML::EndSeq;
}

void Vector3(YAML::Emitter& out, const Eigen::Vector3d& v) { Numbers(out, v.data(), 3); }

// A row's value (src/scene/scene_field.h) as YAML.
void Value(YAML::Emitter& out, const FieldValue& value) {
  struct Emit {
    YAML::Emitter& out;
    void operator()(std::monostate) const {}
    void operator()(double number) const { Number(out, number); }
    void operator()(int number) const { out << YAML::Value << number; }
    void operator()(bool truth) const { out << YAML::Value << truth; }
    void operator()(const std::string& word) const { out << YAML::Value << word; }
    void operator()(const Eigen::Vector3d& v) const { Numbers(out, v.data(), 3); }
    void operator()(const Eigen::Vector2d& v) const { Numbers(out, v.data(), 2); }
  };
  std::visit(Emit{out}, value);
}

// The keys of `table` (for `kind`) whose rows bind a member of `owner`, but those `except`: each
// with the value the loader stored, an optional member not given left out.
template <typename Owner>
void WriteFields(YAML::Emitter& out, const std::string& table, const Owner& owner,
                 const std::string& kind = "", const std::vector<std::string>& except = {}) {
  for (const SchemaRow* row : SchemaRows(table)) {
    if (!row->field || row->field.owner != typeid(Owner) || !row->Takes(kind)) continue;
    if (std::find(except.begin(), except.end(), row->key) != except.end()) continue;
    const FieldValue value = row->field.get(&owner);
    if (std::holds_alternative<std::monostate>(value)) continue;
    Key(out, row->key);
    Value(out, value);
  }
}

std::string Absolute(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

void WriteGridMesh(const MeshSpec& mesh, YAML::Emitter& out) {
  if (mesh.u.empty()) {
    Key(out, "size");
    Numbers(out, mesh.size.data(), 2);
  } else {
    Key(out, "u");
    Numbers(out, mesh.u.data(), static_cast<int>(mesh.u.size()));
  }
  if (!mesh.v.empty()) {
    Key(out, "v");
    Numbers(out, mesh.v.data(), static_cast<int>(mesh.v.size()));
  }
  Key(out, "nodes");
  out << YAML::Value << YAML::Flow << YAML::BeginSeq << mesh.nodes[0] << mesh.nodes[1]
      << YAML::EndSeq;
}

// The explicit points replace the length, the node count and the direction.
void WriteChainPoints(const MeshSpec& mesh, YAML::Emitter& out) {
  Key(out, "points");
  out << YAML::Value << YAML::BeginSeq;
  for (const auto& point : mesh.points) Vector3(out, point);
  out << YAML::EndSeq;
}

void WriteMesh(const MeshSpec& mesh, YAML::Emitter& out) {
  static const char* const kinds[] = {"grid", "circle", "arc", "chain", "file"};
  Key(out, "mesh");
  out << YAML::Value << YAML::BeginMap;
  const std::string kind = kinds[static_cast<int>(mesh.kind)];
  Key(out, "kind");
  out << YAML::Value << kind;
  const bool points = !mesh.points.empty();
  WriteFields(out, "mesh", mesh, kind,
              points ? std::vector<std::string>{"length", "nodes", "direction"}
                     : std::vector<std::string>{});
  switch (mesh.kind) {
    case MeshSpec::Kind::kGrid:
      WriteGridMesh(mesh, out);
      break;
    case MeshSpec::Kind::kCircle:
    case MeshSpec::Kind::kArc:
      break;
    case MeshSpec::Kind::kChain:
      if (points) WriteChainPoints(mesh, out);
      break;
    case MeshSpec::Kind::kFile:
      Key(out, "path");
      out << YAML::Value << Absolute(mesh.path);
      break;
  }
  out << YAML::EndMap;
}

void WriteSelector(const NodeSelector& selector, YAML::Emitter& out) {
  Key(out, "nodes");
  out << YAML::Value << YAML::Flow << YAML::BeginMap;
  switch (selector.kind) {
    case NodeSelector::Kind::kEdge:
    case NodeSelector::Kind::kCorner:
      Key(out, selector.kind == NodeSelector::Kind::kEdge ? "edge" : "corner");
      out << YAML::Value << selector.name;
      break;
    case NodeSelector::Kind::kIds:
      Key(out, "ids");
      out << YAML::Value << YAML::Flow << selector.ids;
      break;
    case NodeSelector::Kind::kIj:
      Key(out, "ij");
      out << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (const auto& ij : selector.ij) {
        out << YAML::Flow << YAML::BeginSeq << ij[0] << ij[1] << YAML::EndSeq;
      }
      out << YAML::EndSeq;
      break;
    case NodeSelector::Kind::kBox:
      Key(out, "box");
      out << YAML::Value << YAML::Flow << YAML::BeginMap;
      Key(out, "min");
      Vector3(out, selector.min);
      Key(out, "max");
      Vector3(out, selector.max);
      out << YAML::EndMap;
      break;
    case NodeSelector::Kind::kRow:
    case NodeSelector::Kind::kColumn:
      Key(out, selector.kind == NodeSelector::Kind::kRow ? "row" : "column");
      out << YAML::Value << selector.index;
      break;
    case NodeSelector::Kind::kWithin:
    case NodeSelector::Kind::kOutside:
      Key(out, selector.kind == NodeSelector::Kind::kWithin ? "within" : "outside");
      out << YAML::Value << YAML::Flow << YAML::BeginMap;
      Key(out, "center");
      Vector3(out, selector.center);
      Key(out, "radius");
      Number(out, selector.radius);
      out << YAML::EndMap;
      break;
    case NodeSelector::Kind::kAll:
      Key(out, "all");
      out << YAML::Value << true;
      break;
  }
  out << YAML::EndMap;
}

void WriteFamily(const std::string& name, const SpringFamilySpec& family, YAML::Emitter& out) {
  if (!family.present) return;
  Key(out, name);
  out << YAML::Value << YAML::Flow << YAML::BeginMap;
  Key(out, "warp");
  Number(out, family.warp);
  Key(out, "weft");
  Number(out, family.weft);
  out << YAML::EndMap;
}

void WriteSprings(const SpringsSpec& springs, YAML::Emitter& out) {
  Key(out, "springs");
  out << YAML::Value << YAML::BeginMap;
  WriteFamily("structural", springs.structural, out);
  WriteFamily("shear", springs.shear, out);
  WriteFamily("flexion", springs.flexion, out);
  Key(out, "rest_length");
  if (springs.rest_length == SpringsSpec::RestLength::kGiven) {
    Number(out, springs.rest_length_value);
  } else {
    out << YAML::Value
        << (springs.rest_length == SpringsSpec::RestLength::kZero ? "zero" : "initial");
  }
  WriteFields(out, "material.springs", springs);
  out << YAML::EndMap;
}

void WriteFiniteVolume(const FiniteVolumeSpec& fv, YAML::Emitter& out) {
  Key(out, "finite_volume");
  out << YAML::Value << YAML::BeginMap;
  for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
    if (!key.reported_when_zero && fv.*key.member == 0.0) continue;
    // A default twist is left to the rule, which a region re-applies to its own rigidities.
    if (key.member == &FiniteVolumeSpec::D_66 &&
        fv.twist_source == FiniteVolumeSpec::TwistSource::kDefault) {
      continue;
    }
    Key(out, key.key);
    Number(out, fv.*key.member);
  }
  for (const FrictionSetting& setting : FrictionSettings(fv)) {
    Key(out, setting.key);
    Number(out, setting.value);
  }
  Key(out, "cell_shear");
  out << YAML::Value << fv.cell_shear;
  out << YAML::EndMap;
}

void WriteMaterial(const MaterialSpec& material, YAML::Emitter& out) {
  static const char* const mass_keys[] = {"density", "node_mass", "total_mass"};
  Key(out, "material");
  out << YAML::Value << YAML::BeginMap;
  Key(out, "model");
  out << YAML::Value << MaterialModelName(material.model);
  Key(out, mass_keys[static_cast<int>(material.mass_kind)]);
  Number(out, material.mass_value);
  switch (material.model) {
    case MaterialModel::kSprings:
      WriteSprings(material.springs, out);
      break;
    case MaterialModel::kFiniteVolume:
      WriteFiniteVolume(material.finite_volume, out);
      if (material.springs.present) WriteSprings(material.springs, out);  // given beside it
      break;
  }
  if (!material.lines.empty()) {
    Key(out, "lines");
    out << YAML::Value << YAML::BeginSeq;
    for (const SpringLineSpec& line : material.lines) {
      out << YAML::BeginMap;
      WriteSelector(line.nodes, out);
      WriteFields(out, "material.lines", line);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

// Each region with the keys it gives (their values in SI).
void WriteRegions(const std::vector<RegionSpec>& regions, YAML::Emitter& out) {
  if (regions.empty()) return;
  Key(out, "regions");
  out << YAML::Value << YAML::BeginSeq;
  for (const RegionSpec& region : regions) {
    out << YAML::BeginMap;
    if (!region.name.empty()) {
      Key(out, "name");
      out << YAML::Value << region.name;
    }
    WriteSelector(region.nodes, out);
    if (region.density) {
      Key(out, "density");
      Number(out, *region.density);
    }
    for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
      const auto given = region.finite_volume.find(key.key);
      if (given == region.finite_volume.end()) continue;
      Key(out, key.key);
      Number(out, given->second);
    }
    WriteFamily("structural", region.structural, out);
    WriteFamily("shear", region.shear, out);
    WriteFamily("flexion", region.flexion, out);
    if (region.tension_only) {
      Key(out, "tension_only");
      out << YAML::Value << *region.tension_only;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

void WriteFixed(const std::vector<FixedSpec>& fixed, YAML::Emitter& out) {
  Key(out, "fixed");
  out << YAML::Value << YAML::BeginSeq;
  for (const FixedSpec& spec : fixed) {
    out << YAML::BeginMap;
    WriteSelector(spec.nodes, out);
    Key(out, "dofs");
    out << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (int c = 0; c < 3; ++c) {
      if (spec.dofs[c]) out << std::string(1, "xyz"[c]);
    }
    out << YAML::EndSeq;
    WriteFields(out, "fixed", spec);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

void WriteForce(const ForceSpec& force, YAML::Emitter& out) {
  out << YAML::BeginMap;
  WriteSelector(force.nodes, out);
  switch (force.kind) {
    case ForceSpec::Kind::kTotal:
    case ForceSpec::Kind::kEach:
      Key(out, force.kind == ForceSpec::Kind::kTotal ? "total" : "each");
      Vector3(out, force.value);
      break;
    case ForceSpec::Kind::kValues:
      Key(out, "values");
      out << YAML::Value << YAML::BeginSeq;
      for (const auto& value : force.values) {
        out << YAML::Flow << YAML::BeginSeq << FormatNumber(value.x()) << FormatNumber(value.y())
            << FormatNumber(value.z()) << YAML::EndSeq;
      }
      out << YAML::EndSeq;
      break;
    case ForceSpec::Kind::kTraction:
      Key(out, "traction");
      Vector3(out, force.value);
      break;
    case ForceSpec::Kind::kPressure:
      Key(out, "pressure");
      Number(out, force.pressure);
      break;
    case ForceSpec::Kind::kRamp:
      Key(out, "ramp");
      out << YAML::Value << YAML::BeginMap;
      Key(out, "from");
      Vector3(out, force.value);
      Key(out, "to");
      Vector3(out, force.ramp_to);
      out << YAML::EndMap;
      break;
  }
  out << YAML::EndMap;
}

void WriteLoads(const LoadsSpec& loads, YAML::Emitter& out) {
  Key(out, "loads");
  out << YAML::Value << YAML::BeginMap;
  WriteFields(out, "loads", loads);
  Key(out, "forces");
  out << YAML::Value << YAML::BeginSeq;
  for (const ForceSpec& force : loads.forces) WriteForce(force, out);
  out << YAML::EndSeq;
  if (loads.pressure) {
    Key(out, "pressure");
    Number(out, loads.pressure->pressure);
  }
  out << YAML::EndMap;
}

// The kind's keys and friction, with the values the loader read.
void WriteObstacle(const ObstacleSpec& obstacle, YAML::Emitter& out) {
  out << YAML::BeginMap;
  Key(out, obstacle.kind);
  out << YAML::Value << YAML::BeginMap;
  if (!obstacle.file.empty()) {
    Key(out, "file");
    out << YAML::Value << Absolute(obstacle.file);
  }
  WriteFields(out, "obstacles", obstacle, obstacle.kind);
  out << YAML::EndMap << YAML::EndMap;
}

// The method, the tolerance, the limits in effect and the method's options as its solve takes them
// (given, or set for this scene: SolveMethodOptions; else their defaults where the catalogue has a
// finite one); other methods' option sections as given.
void WriteSolver(const Scene& scene, YAML::Emitter& out) {
  const SolverSpec& solver = scene.solver;
  Key(out, "solver");
  out << YAML::Value << YAML::BeginMap;
  WriteFields(out, "solver", solver, "", {"max_iterations", "time_limit", "levels"});
  Key(out, "max_iterations");
  out << YAML::Value << EffectiveMaxIterations(solver, solver.method);
  Key(out, "time_limit");
  Number(out, EffectiveTimeLimit(solver, solver.method));
  if (solver.levels > 0) {  // else not given: the same rule decides again when it is read
    Key(out, "levels");
    out << YAML::Value << solver.levels;
  }
  std::map<std::string, std::map<std::string, double>> options = solver.method_options;
  options[solver.method] = SolveMethodOptions(scene, solver.method);
  if (const SolverMethod* method = FindSolverMethod(solver.method)) {
    for (const MethodOption& option : method->options) {
      if (option.default_value && std::isfinite(*option.default_value)) {
        options[solver.method].emplace(option.key, *option.default_value);
      }
    }
  }
  for (const auto& [name, values] : options) {
    if (values.empty()) continue;
    Key(out, name);
    out << YAML::Value << YAML::BeginMap;
    for (const auto& [key, value] : values) {
      Key(out, key);
      Number(out, value);
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

}  // namespace

void WriteSceneYaml(const Scene& scene, std::ostream& stream) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  Key(out, "name");
  out << YAML::Value << scene.name;
  WriteFields(out, "", scene);
  WriteMesh(scene.mesh, out);
  WriteMaterial(scene.material, out);
  WriteRegions(scene.regions, out);
  WriteFixed(scene.fixed, out);
  WriteLoads(scene.loads, out);
  Key(out, "obstacles");
  out << YAML::Value << YAML::BeginSeq;
  for (const ObstacleSpec& obstacle : scene.obstacles) WriteObstacle(obstacle, out);
  out << YAML::EndSeq;
  Key(out, "contact");
  out << YAML::Value << YAML::BeginMap;
  WriteFields(out, "contact", scene.contact);
  out << YAML::EndMap;
  WriteSolver(scene, out);
  Key(out, "output");
  out << YAML::Value << YAML::BeginMap;
  Key(out, "directory");
  out << YAML::Value << Absolute(scene.output.directory);
  Key(out, "write");
  out << YAML::Value << YAML::Flow << scene.output.write;
  WriteFields(out, "output", scene.output);
  out << YAML::EndMap;
  out << YAML::EndMap;
  stream << "# drape: the scene as solved (--set overrides applied, defaults filled in, SI units)\n"
         << out.c_str() << "\n";
}

}  // namespace drape
