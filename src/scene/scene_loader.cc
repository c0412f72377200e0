// Reads a scene: every key of the scene format (docs/architecture.md, "The scene format is a
// contract") is read here, with its range and default. Which keys each map accepts is the scene
// schema's (src/scene/scene_schema.h), which docs/reference.md's scene tables are generated from.
#include "src/scene/scene_loader.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "src/scene/drape_tester.h"
#include "src/scene/fabric_parameters.h"
#include "src/scene/file_paths.h"
#include "src/scene/material_keys.h"
#include "src/scene/material_models.h"
#include "src/scene/obstacle_mesh.h"
#include "src/scene/output_kinds.h"
#include "src/scene/scene_schema.h"
#include "src/scene/scene_size.h"
#include "src/scene/schema_reader.h"
#include "src/scene/solver_methods.h"
#include "src/scene/yaml_overrides.h"
#include "src/scene/yaml_reader.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// ------------------------------------------------------------------------------------ mesh

MeshSpec::Kind MeshKindOf(const std::string& name) {
  if (name == "circle") return MeshSpec::Kind::kCircle;
  if (name == "arc") return MeshSpec::Kind::kArc;
  if (name == "chain") return MeshSpec::Kind::kChain;
  if (name == "file") return MeshSpec::Kind::kFile;
  return MeshSpec::Kind::kGrid;
}

// Explicit grid coordinates: at least one, strictly increasing.
std::vector<double> ReadCoordinates(const YamlValue& value) {
  const auto items = ReadList(value);
  if (!value.get().IsSequence() || items.empty()) {
    Fail(value, "expected a list of increasing coordinates in m, got " + Describe(value.get()));
  }
  std::vector<double> coordinates;
  for (const auto& item : items) {
    const double x = ReadNumber(item);
    if (!coordinates.empty() && !(x > coordinates.back())) {
      std::ostringstream text;
      text << "coordinates must increase strictly, got " << x << " after " << coordinates.back();
      Fail(item, text.str());
    }
    coordinates.push_back(x);
  }
  return coordinates;
}

// Explicit coordinates along one grid axis replace that axis' size and node count; if those are
// given too, they must agree.
void ApplyCoordinates(const YamlMap& map, const std::string& key, int axis, MeshSpec* spec) {
  const auto given = map.Find(key);
  if (!given) return;
  auto& coordinates = axis == 0 ? spec->u : spec->v;
  coordinates = ReadCoordinates(*given);
  const int count = static_cast<int>(coordinates.size());
  const double span = coordinates.back() - coordinates.front();
  const std::string index = "[" + std::to_string(axis) + "]";
  if (map.Has("nodes") && spec->nodes[axis] != count) {
    Fail(*given, "has " + std::to_string(count) + " coordinates but mesh.nodes" + index + " is " +
                     std::to_string(spec->nodes[axis]) + "; give one or the other");
  }
  if (map.Has("size") && std::abs(spec->size[axis] - span) > 1e-12 * std::max(1.0, span)) {
    std::ostringstream text;
    text << "spans " << span << " m but mesh.size" << index << " is " << spec->size[axis]
         << "; give one or the other";
    Fail(*given, text.str());
  }
  spec->nodes[axis] = count;
  spec->size[axis] = span;
}

void ReadGrid(const YamlMap& map, MeshSpec* spec) {
  if (const auto nodes = map.Find("nodes")) {
    if (!nodes->get().IsSequence() || nodes->get().size() != 2) {
      Fail(*nodes, "expected the node counts [nu, nv], got " + Describe(nodes->get()));
    }
    const auto items = ReadList(*nodes);
    for (int k = 0; k < 2; ++k) spec->nodes[k] = ReadIntAtLeast(items[k], 1);
  }
  const auto size = map.Find("size");
  if (size) {
    const auto numbers = ReadNumbers(*size, 2);
    spec->size = Eigen::Vector2d(numbers[0], numbers[1]);
  }
  ApplyCoordinates(map, "u", 0, spec);
  ApplyCoordinates(map, "v", 1, spec);
  if (size) {  // an extent must be positive, unless its axis has a single node
    const auto items = ReadList(*size);
    for (int k = 0; k < 2; ++k) {
      if (spec->nodes[k] > 1) ReadPositive(items[k]);
      ReadNonNegative(items[k]);
    }
  }
  if (spec->nodes[0] * static_cast<long>(spec->nodes[1]) < 2) {
    Fail(map.Has("nodes") ? *map.Find("nodes") : map.value(),
         "a grid needs at least 2 nodes, got " +
             std::to_string(spec->nodes[0] * static_cast<long>(spec->nodes[1])));
  }
}

// Explicit chain nodes: a list of [x, y, z], which replaces length, nodes and direction.
void ReadChainPoints(const YamlMap& map, const YamlValue& points, MeshSpec* spec) {
  for (const char* key : {"length", "nodes", "direction"}) {
    if (map.Has(key)) {
      throw InputError(map.KeyLocation(key), std::string("'") + key +
                                                 "' does not apply when the chain's points "
                                                 "are given");
    }
  }
  if (!points.get().IsSequence()) {
    Fail(points, "expected a list of node positions [x, y, z] in m, got " + Describe(points.get()));
  }
  for (const auto& item : ReadList(points)) spec->points.push_back(ReadVector3(item));
  const size_t minimum = spec->closed ? 3 : 2;
  if (spec->points.size() < minimum) {
    Fail(points, std::string(spec->closed ? "a closed chain" : "a chain") + " needs at least " +
                     std::to_string(minimum) + " points, got " +
                     std::to_string(spec->points.size()));
  }
  spec->chain_nodes = static_cast<int>(spec->points.size());
}

// A direction given (read by its row): not zero, and normalised.
void Normalise(const YamlMap& map, const std::string& key, Eigen::Vector3d* direction) {
  const auto given = map.Find(key);
  if (!given) return;
  if (!(direction->norm() > 0.0)) Fail(*given, "must not be the zero vector");
  direction->normalize();
}

void ReadChain(const YamlMap& map, MeshSpec* spec) {
  if (const auto points = map.Find("points")) {
    ReadChainPoints(map, *points, spec);
    return;
  }
  const auto nodes = map.Find("nodes");
  if (nodes && spec->closed && spec->chain_nodes < 3) {
    Fail(*nodes, "a closed chain needs at least 3 nodes, got 2");
  }
  Normalise(map, "direction", &spec->direction);
}

// The mesh's node count against mesh.max_nodes, before anything is built.
void CheckMeshSize(const YamlMap& map, MeshSpec* spec) {
  const double nodes = EstimatedNodes(*spec);
  if (nodes <= spec->max_nodes) return;
  std::ostringstream text;
  text.precision(3);
  text << "the mesh would have " << nodes << " nodes (about " << nodes * kBytesPerNode / 1e9
       << " GB to solve), above the limit of " << spec->max_nodes
       << " nodes; raise mesh.max_nodes to build it anyway";
  Fail(map.value(), text.str());
}

const std::vector<std::string>& MeshKeys() {
  static const std::vector<std::string> keys = SchemaKeys("mesh");
  return keys;
}

// `default_kind` is the mesh's kind when it gives none: a grid, or a circle (of `default_radius`)
// under a drape_test.
MeshSpec ReadMesh(const YamlValue& value, const std::string& scene_directory,
                  const std::string& default_kind = "grid",
                  double default_radius = MeshSpec().radius) {
  const YamlMap map(value, MeshKeys());
  MeshSpec spec;
  spec.where = value.where;
  spec.radius = default_radius;
  std::string kind = default_kind;
  if (const auto given = map.Find("kind")) {
    kind = std::get<std::string>(ReadRowValue(SchemaRowOf("mesh", "kind"), *given));
  }
  spec.kind = MeshKindOf(kind);
  const auto allowed = SchemaKeys("mesh", kind);
  for (const auto& key : map.Keys()) {
    if (!Contains(allowed, key)) {
      throw InputError(map.KeyLocation(key), "'" + key + "' does not apply to a " + kind +
                                                 " mesh (its keys: " + JoinNames(allowed) + ")");
    }
  }
  ReadFields(map, "mesh", &spec, kind);
  switch (spec.kind) {
    case MeshSpec::Kind::kGrid:
      ReadGrid(map, &spec);
      break;
    case MeshSpec::Kind::kCircle:
    case MeshSpec::Kind::kArc:
      break;
    case MeshSpec::Kind::kChain:
      ReadChain(map, &spec);
      break;
    case MeshSpec::Kind::kFile: {
      const YamlValue path = map.Get("path");
      const std::string given = ReadString(path);
      if (given.empty()) Fail(path, "expected the path of an OBJ or PLY file, got nothing");
      spec.path = ResolvePath(scene_directory, given);
      break;
    }
  }
  CheckMeshSize(map, &spec);
  return spec;
}

// -------------------------------------------------------------------------------- material

// `structural: 1000` or `structural: {warp: 1000, weft: 800}`, N/m.
SpringFamilySpec ReadFamily(const YamlValue& value) {
  SpringFamilySpec family;
  family.present = true;
  family.where = value.where;
  if (value.get().IsMap()) {
    const YamlMap map(value, {"warp", "weft"});
    family.warp = ReadRowNumber(map.Get("warp"));
    family.weft = ReadRowNumber(map.Get("weft"));
  } else if (value.get().IsScalar()) {
    family.warp = family.weft = ReadRowNumber(value);
  } else {
    Fail(value,
         "expected a stiffness in N/m or {warp: ..., weft: ...}, got " + Describe(value.get()));
  }
  return family;
}

void ReadRestLength(const YamlValue& value, SpringsSpec* springs) {
  const YAML::Node& node = value.get();
  const std::vector<std::string> words = {"initial", "zero"};
  if (node.IsScalar() && node.Tag() != "!" && Contains(words, node.Scalar())) {
    springs->rest_length = node.Scalar() == "zero" ? SpringsSpec::RestLength::kZero
                                                   : SpringsSpec::RestLength::kInitial;
    return;
  }
  std::string error;
  if (node.IsScalar() && node.Tag() != "!") {
    if (const auto length = ParseNumber(node.Scalar(), &error)) {
      if (!(*length > 0.0)) Fail(value, "a given rest length must be positive (or write zero)");
      springs->rest_length = SpringsSpec::RestLength::kGiven;
      springs->rest_length_value = *length;
      return;
    }
    if (const auto nearest = NearestName(node.Scalar(), words)) {
      Fail(value, "unknown value '" + node.Scalar() + "'; did you mean '" + *nearest + "'?");
    }
    if (error.rfind("expected a number", 0) != 0) Fail(value, error);
  }
  Fail(value, "expected initial, zero or a length in m, got " + Describe(node));
}

SpringsSpec ReadSprings(const YamlValue& value) {
  const YamlMap map(value, SchemaKeys("material.springs"));
  SpringsSpec springs;
  springs.present = true;
  springs.where = value.where;
  if (const auto v = map.Find("structural")) springs.structural = ReadFamily(*v);
  if (const auto v = map.Find("shear")) springs.shear = ReadFamily(*v);
  if (const auto v = map.Find("flexion")) springs.flexion = ReadFamily(*v);
  if (!springs.structural.present && !springs.shear.present && !springs.flexion.present) {
    Fail(value, "no spring family is given: add structural, shear or flexion (N/m)");
  }
  if (const auto v = map.Find("rest_length")) ReadRestLength(*v, &springs);
  ReadFields(map, "material.springs", &springs);
  return springs;
}

// One model parameter that may be given in SI under its own key or converted from a measurement
// (finite_volume.kes.*, finite_volume.bending_length.*): exactly one way must be used.
// NOLINTNEXTLINE(bugprone-exception-escape): YamlValue's assignment may throw (yaml_reader.h).
struct ParameterWay {
  std::string key;                 // as the user writes it below material.finite_volume
  std::optional<YamlValue> value;  // the given value, if any
  std::function<double(const YamlValue&)> convert;
};

// The one way of `ways` (named for `key`) that is given, or null; two given is an error, located
// at the second.
const ParameterWay* GivenWay(const std::string& key, const std::vector<ParameterWay>& ways) {
  const ParameterWay* given = nullptr;
  for (const auto& way : ways) {
    if (!way.value) continue;
    if (given) {
      Fail(*way.value, "give " + key + " in one way only: '" + given->key + "' is given too");
    }
    given = &way;
  }
  return given;
}

double ReadParameter(const YamlMap& map, const std::string& key, const std::string& unit,
                     const std::vector<ParameterWay>& measured) {
  std::vector<ParameterWay> ways = {{key, map.Find(key), ReadRowNumber}};
  ways.insert(ways.end(), measured.begin(), measured.end());
  const ParameterWay* given = GivenWay(key, ways);
  if (!given) {
    std::string names;
    for (size_t k = 1; k < ways.size(); ++k) names += " or " + ways[k].key;
    Location where = map.value().where;
    where.key = ChildKey(where.key, key);
    throw InputError(
        where, "required key '" + key + "' is missing: give " + key + " (" + unit + ")" + names);
  }
  return given->convert(*given->value);
}

// finite_volume.kes: KES-FB measurements in their own units (src/scene/fabric_parameters.h).
const std::vector<std::string>& KesKeys() {
  static const std::vector<std::string> keys = SchemaKeys("material.finite_volume.kes");
  return keys;
}

// The tensile rigidity of one direction from kes.EMT_<direction> (and LT_<direction>, Fm).
std::optional<YamlValue> CheckedEmt(const YamlMap& kes, const std::string& direction) {
  const auto emt = kes.Find("EMT_" + direction);
  const auto lt = kes.Find("LT_" + direction);
  if (lt && !emt) Fail(*lt, "LT_" + direction + " needs EMT_" + direction + " (%) as well");
  return emt;
}

double KesTensile(const YamlMap& kes, const std::string& direction, const YamlValue& emt) {
  const auto lt = kes.Find("LT_" + direction);
  const auto fm = kes.Find("Fm");
  return KesTensileRigidity(ReadRowNumber(emt), lt ? ReadRowNumber(*lt) : 1.0,
                            fm ? ReadRowNumber(*fm) : kKesStandardMaximumLoad);
}

// The areal density that Peirce's bending length needs: material.density or kes.W.
struct ArealDensity {
  std::optional<double> value;  // kg/m²
  std::string missing;          // why there is none
};

// One friction, given in SI (`si_key`) or as KES measures it (`kes_key`, converted by `convert`),
// at most one of the two; 0, the elastic fabric, when neither is given.
double ReadFriction(const YamlMap& map, const std::optional<YamlMap>& kes,
                    const std::string& si_key, const std::string& kes_key,
                    double (*convert)(double)) {
  const auto si = map.Find(si_key);
  const auto measured = kes ? kes->Find(kes_key) : std::nullopt;
  if (si && measured) {
    Fail(*measured, "give " + si_key + " in one way only: '" + si_key + "' is given too");
  }
  if (si) return ReadRowNumber(*si);
  return measured ? convert(ReadRowNumber(*measured)) : 0.0;
}

// The frictions: bending_friction_<direction> (N) or kes.2HB_<direction> (gf·cm/cm), and
// shear_friction (N/m) or kes.2HG (gf/cm).
void ReadFrictions(const YamlMap& map, const std::optional<YamlMap>& kes, FiniteVolumeSpec* fv) {
  fv->bending_friction_warp =
      ReadFriction(map, kes, "bending_friction_warp", "2HB_warp", KesBendingFriction);
  fv->bending_friction_weft =
      ReadFriction(map, kes, "bending_friction_weft", "2HB_weft", KesBendingFriction);
  fv->shear_friction = ReadFriction(map, kes, "shear_friction", "2HG", KesShearFriction);
}

// A rigidity in a message: four significant digits.
std::string ShortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// The torsional rigidity: D_66 (N·m, ≥ 0) or one of the bias measurements `bias` converts, at most
// one of them; else the default rule (src/scene/fabric_parameters.h).
void ReadTwist(const YamlMap& map, const std::vector<ParameterWay>& bias, FiniteVolumeSpec* fv) {
  std::vector<ParameterWay> ways = {{"D_66", map.Find("D_66"), ReadRowNumber}};
  ways.insert(ways.end(), bias.begin(), bias.end());
  const ParameterWay* given = GivenWay("D_66", ways);
  if (!given) {
    fv->D_66 = DefaultTorsionalRigidity(fv->D_warp, fv->D_weft);
    fv->twist_source = FiniteVolumeSpec::TwistSource::kDefault;
    return;
  }
  fv->D_66 = given->convert(*given->value);
  fv->twist_source = given == &ways.front() ? FiniteVolumeSpec::TwistSource::kGiven
                                            : FiniteVolumeSpec::TwistSource::kBias;
}

// The measurements as given (kes, fast, bending_length: each key with its number and unit), in
// the order the schema lists them, for drape check and summary.json.
std::vector<GivenMeasurement> GivenMeasurements(const YamlMap& map) {
  std::vector<GivenMeasurement> values;
  for (const char* block : {"kes", "fast", "bending_length"}) {
    const auto given = map.Find(block);
    if (!given || !given->get().IsMap()) continue;
    const std::string table = std::string("material.finite_volume.") + block;
    const YamlMap measured(*given, SchemaKeys(table));
    for (const SchemaRow& row : SceneSchema()) {
      if (row.table != table) continue;
      if (const auto v = measured.Find(row.key)) {
        values.push_back({std::string(block) + "." + row.key, ReadNumber(*v), row.unit});
      }
    }
  }
  return values;
}

FiniteVolumeSpec ReadFiniteVolume(const YamlValue& value, const ArealDensity& density) {
  const YamlMap map(value, SchemaKeys("material.finite_volume"));
  FiniteVolumeSpec fv;
  fv.present = true;
  fv.where = value.where;
  std::optional<YamlMap> kes, fast, peirce;
  if (const auto v = map.Find("kes")) kes.emplace(*v, KesKeys());
  if (const auto v = map.Find("fast")) fast.emplace(*v, SchemaKeys("material.finite_volume.fast"));
  if (const auto v = map.Find("bending_length")) {
    if (v->get().IsScalar()) {
      Fail(*v, "give the bending length per direction: {warp: cm, weft: cm}");
    }
    peirce.emplace(*v, SchemaKeys("material.finite_volume.bending_length"));
  }
  auto find = [](const std::optional<YamlMap>& block, const std::string& key) {
    return block ? block->Find(key) : std::nullopt;
  };
  const auto kes_rigidity = [](const YamlValue& v) { return KesBendingRigidity(ReadRowNumber(v)); };
  const auto peirce_rigidity = [&density](const YamlValue& v) {
    const double length = ReadRowNumber(v);
    if (!density.value) Fail(v, "a bending length needs the areal density: " + density.missing);
    return PeirceBendingRigidity(length, *density.value);
  };
  const auto kes_way = [&](const std::string& direction) {
    return ParameterWay{
        "kes.EMT_" + direction, kes ? CheckedEmt(*kes, direction) : std::nullopt,
        [&kes, direction](const YamlValue& v) { return KesTensile(*kes, direction, v); }};
  };
  const auto fast_rigidity = [](const YamlValue& v) {
    return FastBendingRigidity(ReadRowNumber(v));
  };
  const auto fast_tensile = [](const YamlValue& v) {
    return FastTensileRigidity(ReadRowNumber(v));
  };
  fv.E_warp =
      ReadParameter(map, "E_warp", "N/m",
                    {kes_way("warp"), {"fast.E100_warp", find(fast, "E100_warp"), fast_tensile}});
  fv.E_weft =
      ReadParameter(map, "E_weft", "N/m",
                    {kes_way("weft"), {"fast.E100_weft", find(fast, "E100_weft"), fast_tensile}});
  fv.G = ReadParameter(map, "G", "N/m",
                       {{"kes.G", find(kes, "G"),
                         [](const YamlValue& v) { return KesShearRigidity(ReadRowNumber(v)); }},
                        {"fast.EB5", find(fast, "EB5"),
                         [](const YamlValue& v) { return FastShearRigidity(ReadRowNumber(v)); }}});
  fv.D_warp = ReadParameter(map, "D_warp", "N·m",
                            {{"kes.B_warp", find(kes, "B_warp"), kes_rigidity},
                             {"fast.B_warp", find(fast, "B_warp"), fast_rigidity},
                             {"bending_length.warp", find(peirce, "warp"), peirce_rigidity}});
  fv.D_weft = ReadParameter(map, "D_weft", "N·m",
                            {{"kes.B_weft", find(kes, "B_weft"), kes_rigidity},
                             {"fast.B_weft", find(fast, "B_weft"), fast_rigidity},
                             {"bending_length.weft", find(peirce, "weft"), peirce_rigidity}});
  if (const auto fm = find(kes, "Fm"); fm && !kes->Has("EMT_warp") && !kes->Has("EMT_weft")) {
    Fail(*fm, "Fm (gf/cm) applies only with EMT_warp or EMT_weft");
  }
  ReadFields(map, "material.finite_volume", &fv);
  if (!(fv.nu_warp * fv.nu_weft < 1.0)) {
    Fail(map.Has("nu_weft") ? *map.Find("nu_weft") : *map.Find("nu_warp"),
         "nu_warp * nu_weft must be less than 1 (else the membrane energy is not positive)");
  }
  ReadFrictions(map, kes, &fv);
  if (const auto v = map.Find("D_12"); v && !(fv.D_12 * fv.D_12 < fv.D_warp * fv.D_weft)) {
    Fail(*v, "D_12² must be less than D_warp * D_weft (else the bending energy is not positive)");
  }
  const auto bias_rigidity = [&fv](double b45, const YamlValue& v) {
    const double d66 = BiasTorsionalRigidity(b45, fv.D_warp, fv.D_weft, fv.D_12);
    if (!(d66 > 0.0) || !std::isfinite(d66)) {
      Fail(v, "a bias bending rigidity of " + ShortNumber(b45) +
                  " N·m is too stiff for the warp's and weft's (" + ShortNumber(fv.D_warp) +
                  " and " + ShortNumber(fv.D_weft) + " N·m): no torsional rigidity gives it; " +
                  "an orthotropic plate's bias is below " +
                  ShortNumber(StiffestBiasRigidity(fv.D_warp, fv.D_weft, fv.D_12)) + " N·m");
    }
    return d66;
  };
  ReadTwist(map,
            {{"kes.B_bias", find(kes, "B_bias"),
              [&](const YamlValue& v) { return bias_rigidity(kes_rigidity(v), v); }},
             {"bending_length.bias", find(peirce, "bias"),
              [&](const YamlValue& v) { return bias_rigidity(peirce_rigidity(v), v); }}},
            &fv);
  fv.measured = GivenMeasurements(map);
  return fv;
}

void ReadMass(const YamlMap& map, MaterialSpec* material) {
  static const std::vector<std::pair<std::string, MaterialSpec::MassKind>> kinds = {
      {"density", MaterialSpec::MassKind::kDensity},
      {"node_mass", MaterialSpec::MassKind::kNodeMass},
      {"total_mass", MaterialSpec::MassKind::kTotalMass}};
  std::string first;
  for (const auto& [key, kind] : kinds) {
    const auto given = map.Find(key);
    if (!given) continue;
    if (!first.empty()) {
      throw InputError(map.KeyLocation(key),
                       "give only one of density, node_mass and "
                       "total_mass ('" +
                           first + "' is given too)");
    }
    first = key;
    material->mass_kind = kind;
    material->mass_value = ReadRowNumber(*given);
  }
  if (first.empty()) {
    Fail(map.value(),
         "the mass is missing: give density (kg/m², per metre for a chain), "
         "node_mass (kg per node) or total_mass (kg)");
  }
}

// The mass of a finite-volume material: material.density / node_mass / total_mass, or the KES
// weight finite_volume.kes.W (mg/cm²) instead, never both. Returns the areal density that a
// bending length is converted with.
ArealDensity ReadFiniteVolumeMass(const YamlMap& map, MaterialSpec* material) {
  std::optional<YamlValue> weight;
  std::string weight_key;
  if (const auto fv = map.Find("finite_volume"); fv && fv->get().IsMap()) {
    for (const char* block : {"kes", "fast"}) {
      const auto measured = YamlMap(*fv).Find(block);
      if (!measured || !measured->get().IsMap()) continue;
      const auto w = YamlMap(*measured).Find("W");
      if (!w) continue;
      if (weight) {
        Fail(*w,
             "give the mass in one way only: finite_volume.kes.W and finite_volume.fast.W are "
             "both given");
      }
      weight = w;
      weight_key = std::string("finite_volume.") + block + ".W";
    }
  }
  if (!weight) {
    ReadMass(map, material);
    if (material->mass_kind == MaterialSpec::MassKind::kDensity) return {material->mass_value, ""};
    return {std::nullopt,
            "give material.density (kg/m²), finite_volume.kes.W (mg/cm²) or finite_volume.fast.W "
            "(g/m²)"};
  }
  for (const char* key : {"density", "node_mass", "total_mass"}) {
    if (map.Has(key)) {
      throw InputError(map.KeyLocation(key), std::string("give the mass in one way only: '") + key +
                                                 "' and " + weight_key + " are both given");
    }
  }
  material->mass_kind = MaterialSpec::MassKind::kDensity;
  const double w = ReadRowNumber(*weight);
  material->mass_value =
      weight_key == "finite_volume.kes.W" ? KesArealDensity(w) : FastArealDensity(w);
  return {material->mass_value, ""};
}

NodeSelector ReadSelector(const YamlValue& value);

// material.lines: [{nodes: <selection>, structural: N/m, tension_only: bool}, ...].
std::vector<SpringLineSpec> ReadLines(const YamlValue& value) {
  if (!value.get().IsSequence() && !value.get().IsNull()) {
    Fail(value, "expected a list of spring lines (- nodes: ..., structural: N/m), got " +
                    Describe(value.get()));
  }
  std::vector<SpringLineSpec> lines;
  for (const auto& item : ReadList(value)) {
    const YamlMap map(item, SchemaKeys("material.lines"));
    SpringLineSpec line;
    line.where = item.where;
    line.nodes = ReadSelector(map.Get("nodes"));
    map.Get("structural");  // required
    ReadFields(map, "material.lines", &line);
    lines.push_back(line);
  }
  return lines;
}

MaterialSpec ReadMaterial(const YamlValue& value) {
  const YamlMap map(value, SchemaKeys("material"));
  MaterialSpec material;
  material.where = value.where;
  if (const auto model = map.Find("model")) {
    material.model = MaterialModelNamed(ReadChoice(*model, MaterialModelNames()));
  }
  switch (material.model) {
    case MaterialModel::kSprings:
      ReadMass(map, &material);
      if (map.Has("finite_volume")) {
        throw InputError(map.KeyLocation("finite_volume"),
                         "'finite_volume' applies only when material.model is finite_volume (here "
                         "it is springs; springs may be added beside a finite_volume material)");
      }
      material.springs = ReadSprings(map.Get("springs"));
      break;
    case MaterialModel::kFiniteVolume: {
      const ArealDensity density = ReadFiniteVolumeMass(map, &material);
      material.finite_volume = ReadFiniteVolume(map.Get("finite_volume"), density);
      if (const auto springs = map.Find("springs")) {
        material.springs = ReadSprings(*springs);
        if (material.springs.stretch_limit) {
          throw InputError(YamlMap(*springs).KeyLocation("stretch_limit"),
                           "'stretch_limit' applies only when material.model is springs");
        }
      }
      break;
    }
  }
  if (const auto lines = map.Find("lines")) material.lines = ReadLines(*lines);
  return material;
}

// ------------------------------------------------------------------------- node selections

std::array<int, 2> ReadIj(const YamlValue& value) {
  if (!value.get().IsSequence() || value.get().size() != 2) {
    Fail(value, "expected a grid index [i, j], got " + Describe(value.get()));
  }
  const auto items = ReadList(value);
  return {ReadIntAtLeast(items[0], 0), ReadIntAtLeast(items[1], 0)};
}

void ReadSelectorKind(const std::string& kind, const YamlValue& value, NodeSelector* selector) {
  if (kind == "edge") {
    selector->kind = NodeSelector::Kind::kEdge;
    selector->name = ReadChoice(value, {"top", "bottom", "left", "right"});
  } else if (kind == "corner") {
    selector->kind = NodeSelector::Kind::kCorner;
    selector->name = ReadChoice(value, {"top-left", "top-right", "bottom-left", "bottom-right"});
  } else if (kind == "ids") {
    selector->kind = NodeSelector::Kind::kIds;
    if (!value.get().IsSequence())
      Fail(value, "expected a list of node ids, got " + Describe(value.get()));
    for (const auto& item : ReadList(value)) selector->ids.push_back(ReadIntAtLeast(item, 0));
  } else if (kind == "ij") {
    selector->kind = NodeSelector::Kind::kIj;
    if (!value.get().IsSequence())
      Fail(value, "expected a list of [i, j] pairs, got " + Describe(value.get()));
    for (const auto& item : ReadList(value)) selector->ij.push_back(ReadIj(item));
  } else if (kind == "row" || kind == "column") {
    selector->kind = kind == "row" ? NodeSelector::Kind::kRow : NodeSelector::Kind::kColumn;
    selector->index = ReadIntAtLeast(value, 0);
  } else if (kind == "box") {
    selector->kind = NodeSelector::Kind::kBox;
    const YamlMap box(value, {"min", "max"});
    selector->min = ReadVector3(box.Get("min"));
    selector->max = ReadVector3(box.Get("max"));
    if ((selector->min.array() > selector->max.array()).any()) {
      Fail(box.Get("max"), "max must be at least min in every coordinate");
    }
  } else if (kind == "within" || kind == "outside") {
    selector->kind = kind == "within" ? NodeSelector::Kind::kWithin : NodeSelector::Kind::kOutside;
    const YamlMap within(value, {"center", "radius"});
    selector->center = ReadVector3(within.Get("center"));
    selector->radius = ReadPositive(within.Get("radius"));
  } else if (kind == "region") {
    selector->region = ReadString(value);
    if (selector->region.empty()) Fail(value, "expected the name of a region, got an empty name");
  } else {
    selector->kind = NodeSelector::Kind::kAll;
    if (!ReadBool(value)) Fail(value, "'all: false' selects nothing; write all: true");
  }
}

NodeSelector ReadSelector(const YamlValue& value) {
  static const std::vector<std::string> kinds = SchemaKeys("nodes");
  if (!value.get().IsMap()) {
    Fail(value, "expected a node selection such as {edge: top} or {ids: [0, 3]}, got " +
                    Describe(value.get()));
  }
  const YamlMap map(value, kinds);
  const auto keys = map.Keys();
  if (keys.empty()) Fail(value, "no selection given: use one of " + JoinNames(kinds));
  if (keys.size() > 1) {
    throw InputError(map.KeyLocation(keys[1]),
                     "select nodes in one way only ('" + keys[0] + "' is given too)");
  }
  NodeSelector selector;
  const YamlValue kind_value = map.Get(keys[0]);
  selector.where = kind_value.where;
  ReadSelectorKind(keys[0], kind_value, &selector);
  return selector;
}

// ------------------------------------------------------------------------------- regions

// The spring keys a region may give need material.springs; the finite-volume ones a
// finite_volume material; density a material given by density.
void CheckRegionKeyApplies(const YamlMap& map, const std::string& key,
                           const MaterialSpec& material) {
  const bool fv_key = key != "density" && key != "structural" && key != "shear" &&
                      key != "flexion" && key != "tension_only" && key != "nodes";
  if (key == "density" && material.mass_kind != MaterialSpec::MassKind::kDensity) {
    throw InputError(map.KeyLocation(key),
                     "a region's density needs the material's mass as density (kg/m²)");
  }
  switch (material.model) {
    case MaterialModel::kSprings:
      if (fv_key) {
        throw InputError(map.KeyLocation(key),
                         "'" + key + "' applies only when material.model is finite_volume");
      }
      break;
    case MaterialModel::kFiniteVolume:
      break;
  }
  const bool spring_key =
      key == "structural" || key == "shear" || key == "flexion" || key == "tension_only";
  if (spring_key && !material.springs.present) {
    throw InputError(map.KeyLocation(key), "'" + key + "' needs material.springs");
  }
}

void ReadRegionKey(const std::string& key, const YamlValue& value, RegionSpec* region) {
  region->given[key] = value.where;
  if (key == "density") region->density = ReadRowNumber(value);
  if (key == "structural") region->structural = ReadFamily(value);
  if (key == "shear") region->shear = ReadFamily(value);
  if (key == "flexion") region->flexion = ReadFamily(value);
  if (key == "tension_only") region->tension_only = ReadBool(value);
  for (const FiniteVolumeKey& fv : FiniteVolumeKeys()) {
    if (fv.key == key) region->finite_volume[key] = ReadRowNumber(value);
  }
}

// A region's `name`: a non-empty text, given to one region only.
std::string ReadRegionName(const YamlValue& value, const std::vector<RegionSpec>& earlier) {
  const std::string name = ReadString(value);
  if (name.empty()) Fail(value, "expected a name for the region, got an empty name");
  for (const RegionSpec& region : earlier) {
    if (region.name == name) {
      Fail(value, "another region is already named '" + name + "' (at line " +
                      std::to_string(region.where.line) + ")");
    }
  }
  return name;
}

std::vector<RegionSpec> ReadRegions(const YamlValue& value, const MaterialSpec& material) {
  if (!value.get().IsSequence() && !value.get().IsNull()) {
    Fail(value,
         "expected a list of regions (- nodes: ..., D_warp: ...), got " + Describe(value.get()));
  }
  const std::vector<std::string> keys = SchemaKeys("regions");
  std::vector<std::string> overrides;  // every key but the selection and the name
  for (const std::string& key : keys) {
    if (key != "nodes" && key != "name") overrides.push_back(key);
  }
  std::vector<RegionSpec> regions;
  for (const auto& item : ReadList(value)) {
    const YamlMap map(item, keys);
    RegionSpec region;
    region.where = item.where;
    region.nodes = ReadSelector(map.Get("nodes"));
    if (const auto name = map.Find("name")) region.name = ReadRegionName(*name, regions);
    for (const std::string& key : map.Keys()) {
      if (key == "nodes" || key == "name") continue;
      CheckRegionKeyApplies(map, key, material);
      ReadRegionKey(key, map.Get(key), &region);
    }
    if (region.given.empty()) {
      Fail(item, "the region overrides nothing: give one or more of " + JoinNames(overrides));
    }
    regions.push_back(region);
  }
  return regions;
}

// --------------------------------------------------------------------------- fixed, loads

std::array<bool, 3> ReadDofs(const YamlValue& value) {
  if (!value.get().IsSequence()) {
    Fail(value, "expected a list of directions such as [x, z], got " + Describe(value.get()));
  }
  const auto items = ReadList(value);
  if (items.empty()) Fail(value, "fixes nothing: list at least one of x, y, z");
  std::array<bool, 3> dofs{false, false, false};
  const std::vector<std::string> names = {"x", "y", "z"};
  for (const auto& item : items) {
    const std::string name = ReadChoice(item, names);
    const size_t axis = std::find(names.begin(), names.end(), name) - names.begin();
    if (dofs[axis]) Fail(item, "'" + name + "' is listed twice");
    dofs[axis] = true;
  }
  return dofs;
}

std::vector<FixedSpec> ReadFixed(const YamlValue& value) {
  if (!value.get().IsSequence() && !value.get().IsNull()) {
    Fail(value, "expected a list of fixed selections (- nodes: ...), got " + Describe(value.get()));
  }
  std::vector<FixedSpec> fixed;
  for (const auto& item : ReadList(value)) {
    const YamlMap map(item, SchemaKeys("fixed"));
    FixedSpec spec;
    spec.where = item.where;
    spec.nodes = ReadSelector(map.Get("nodes"));
    if (const auto dofs = map.Find("dofs")) spec.dofs = ReadDofs(*dofs);
    ReadFields(map, "fixed", &spec);
    fixed.push_back(spec);
  }
  return fixed;
}

// `values: [[fx, fy, fz], ...]`: one force per selected node (their count is checked against the
// selection when the model is built).
void ReadForceValues(const YamlValue& value, ForceSpec* force) {
  if (!value.get().IsSequence() || value.get().size() == 0) {
    Fail(value, "expected a list of forces [fx, fy, fz] in N, one per selected node, got " +
                    Describe(value.get()));
  }
  force->kind = ForceSpec::Kind::kValues;
  force->values_where = value.where;
  for (const auto& item : ReadList(value)) force->values.push_back(ReadVector3(item));
}

// `ramp: {from: [fx, fy, fz], to: [fx, fy, fz]}`: N per node, linear along the selection.
void ReadForceRamp(const YamlValue& value, ForceSpec* force) {
  const YamlMap ramp(value, {"from", "to"});
  force->kind = ForceSpec::Kind::kRamp;
  force->value = ReadVector3(ramp.Get("from"));
  force->ramp_to = ReadVector3(ramp.Get("to"));
}

ForceSpec ReadForce(const YamlValue& item) {
  const YamlMap map(item, SchemaKeys("loads.forces"));
  ForceSpec force;
  force.where = item.where;
  force.nodes = ReadSelector(map.Get("nodes"));
  std::vector<std::string> given;
  for (const auto& key : map.Keys()) {
    if (key != "nodes") given.push_back(key);
  }
  if (given.size() > 1) {
    throw InputError(map.KeyLocation(given[1]),
                     "give the force in one way only (total, each, values, ramp, traction or "
                     "pressure), not both: '" +
                         given[0] + "' is given too");
  }
  if (const auto values = map.Find("values")) {
    ReadForceValues(*values, &force);
  } else if (const auto ramp = map.Find("ramp")) {
    ReadForceRamp(*ramp, &force);
  } else if (const auto total = map.Find("total")) {
    force.kind = ForceSpec::Kind::kTotal;
    force.value = ReadVector3(*total);
  } else if (const auto each = map.Find("each")) {
    force.kind = ForceSpec::Kind::kEach;
    force.value = ReadVector3(*each);
  } else if (const auto traction = map.Find("traction")) {
    force.kind = ForceSpec::Kind::kTraction;
    force.value = ReadVector3(*traction);
  } else if (const auto pressure = map.Find("pressure")) {
    force.kind = ForceSpec::Kind::kPressure;
    force.pressure = ReadNumber(*pressure);
  } else {
    Location where = item.where;
    where.key = ChildKey(item.where.key, "total");
    throw InputError(where,
                     "the force is missing: give total: [fx, fy, fz] (N, shared), "
                     "each: [fx, fy, fz] (N per node), values: [[fx, fy, fz], ...] (one per "
                     "node), ramp: {from: [...], to: [...]} (N per node), traction: [tx, ty, "
                     "tz] (Pa) or pressure: p (Pa, along the surface normal)");
  }
  return force;
}

LoadsSpec ReadLoads(const YamlValue& value) {
  const YamlMap map(value, SchemaKeys("loads"));
  LoadsSpec loads;
  loads.where = value.where;
  ReadFields(map, "loads", &loads);
  if (const auto forces = map.Find("forces")) {
    if (!forces->get().IsSequence() && !forces->get().IsNull()) {
      Fail(*forces, "expected a list of forces (- nodes: ...), got " + Describe(forces->get()));
    }
    for (const auto& item : ReadList(*forces)) loads.forces.push_back(ReadForce(item));
  }
  if (const auto pressure = map.Find("pressure")) {
    PressureSpec spec;
    spec.where = pressure->where;
    spec.pressure = ReadNumber(*pressure);
    loads.pressure = spec;
  }
  return loads;
}

// ------------------------------------------------------------------------------ obstacles

// Every key an obstacle may have (the schema's); which kinds take which is the registry's
// (src/model/obstacle_kinds.h), checked when the model is built.
const std::vector<std::string>& ObstacleKeys() {
  static const std::vector<std::string> keys = SchemaKeys("obstacles");
  return keys;
}

ObstacleSpec ReadObstacle(const YamlValue& item, const std::string& scene_directory) {
  const YamlMap outer(item);
  const auto kinds = outer.Keys();
  if (kinds.empty()) Fail(item, "expected one obstacle (- sphere: {...})");
  if (kinds.size() > 1) {
    throw InputError(outer.KeyLocation(kinds[1]),
                     "one obstacle per list item ('" + kinds[0] + "' is given too)");
  }
  const YamlValue value = outer.Get(kinds[0]);
  ObstacleSpec obstacle;
  obstacle.kind = kinds[0];
  obstacle.where = value.where;
  const YamlMap map(value, ObstacleKeys());
  for (const std::string& key : map.Keys()) obstacle.given[key] = map.Get(key).where;
  ReadFields(map, "obstacles", &obstacle);
  Normalise(map, "normal", &obstacle.normal);
  if (map.Has("file")) obstacle.file = ReadString(map.Get("file"));
  if (obstacle.kind == "mesh") LoadObstacleMesh(scene_directory, &obstacle);
  return obstacle;
}

std::vector<ObstacleSpec> ReadObstacles(const YamlValue& value,
                                        const std::string& scene_directory) {
  if (!value.get().IsSequence() && !value.get().IsNull()) {
    Fail(value, "expected a list of obstacles (- sphere: {...}), got " + Describe(value.get()));
  }
  std::vector<ObstacleSpec> obstacles;
  for (const auto& item : ReadList(value)) {
    obstacles.push_back(ReadObstacle(item, scene_directory));
  }
  return obstacles;
}

ContactSpec ReadContact(const YamlValue& value) {
  const YamlMap map(value, SchemaKeys("contact"));
  ContactSpec contact;
  contact.where = value.where;
  ReadFields(map, "contact", &contact);
  return contact;
}

// ---------------------------------------------------------------------- solver and output

std::vector<std::string> MethodNames() {
  std::vector<std::string> names;
  for (const auto& method : SolverMethods()) names.push_back(method.name);
  return names;
}

// solver.<method>: only that method's keys, each a number in its registered range.
std::map<std::string, double> ReadMethodOptions(const SolverMethod& method,
                                                const YamlValue& value) {
  std::vector<std::string> keys;
  for (const auto& option : method.options) keys.push_back(option.key);
  const YamlMap map(value, keys);
  std::map<std::string, double> options;
  for (const auto& key : map.Keys()) {
    const YamlValue given = map.Get(key);
    const double number = ReadNumber(given);
    const std::string problem = CheckMethodOption(*FindMethodOption(method, key), number);
    if (!problem.empty()) Fail(given, problem);
    options[key] = number;
  }
  return options;
}

SolverSpec ReadSolver(const YamlValue& value) {
  const auto methods = MethodNames();
  std::vector<std::string> keys = SchemaKeys("solver");
  keys.insert(keys.end(), methods.begin(), methods.end());
  const YamlMap map(value, keys);
  SolverSpec solver;
  solver.where = value.where;
  ReadFields(map, "solver", &solver);
  if (const auto method = map.Find("method")) {
    if (!FindSolverMethod(solver.method)) {
      const auto nearest = NearestName(solver.method, methods);
      Fail(*method, "unknown method '" + solver.method + "'" +
                        (nearest ? "; did you mean '" + *nearest + "'?" : "") +
                        " (methods: " + JoinNames(methods) + ")");
    }
  }
  if (const auto v = map.Find("levels")) solver.levels_where = v->where;
  for (const auto& method : SolverMethods()) {
    if (const auto v = map.Find(method.name)) {
      solver.method_options[method.name] = ReadMethodOptions(method, *v);
    }
  }
  return solver;
}

OutputSpec ReadOutput(const YamlValue& value, const Scene& scene) {
  const YamlMap map(value, SchemaKeys("output"));
  OutputSpec output;
  output.where = value.where;
  output.directory = DefaultResultFolder(scene.directory, scene.name);
  if (const auto directory = map.Find("directory")) {
    const std::string given = ReadString(*directory);
    if (given.empty()) Fail(*directory, "expected a folder, got nothing");
    output.directory = ResolvePath(scene.directory, given);
    output.directory_where = directory->where;
  }
  output.write = DefaultOutputWrite(scene.drape_test.has_value());
  if (const auto write = map.Find("write")) {
    if (!write->get().IsSequence()) {
      Fail(*write, "expected a list such as [summary, nodes], got " + Describe(write->get()));
    }
    output.write.clear();
    for (const auto& item : ReadList(*write)) {
      const std::string kind = ReadChoice(item, OutputKindNames());
      if (Contains(output.write, kind)) Fail(item, "'" + kind + "' is listed twice");
      output.write.push_back(kind);
    }
  }
  ReadFields(map, "output", &output);
  return output;
}

// -------------------------------------------------------------------------------- the scene

std::string ReadName(const YamlValue& value) {
  const std::string name = ReadString(value);
  if (name.empty() || name == "." || name == ".." ||
      name.find_first_of("/\\") != std::string::npos) {
    Fail(value, "expected a plain name (no '/'), got " + Describe(value.get()));
  }
  return name;
}

// A top-level section, or an empty one located at the top of the file when it is left out.
YamlValue OptionalSection(const YamlMap& top, const std::string& key) {
  if (auto given = top.Find(key)) return *given;
  YamlValue absent = top.value();
  absent.node.reset(YAML::Node());
  absent.where.key = key;
  return absent;
}

// ------------------------------------------------------------------- region references

// Replaces `{region: NAME}` by a copy of the named region's selection. A region may refer only to
// a region named before it (so references cannot loop).
void ResolveRegionReference(const std::vector<RegionSpec>& regions, size_t visible,
                            NodeSelector* selector) {
  if (selector->region.empty()) return;
  std::vector<std::string> names;
  for (size_t r = 0; r < visible; ++r) {
    if (regions[r].name == selector->region) {
      *selector = regions[r].nodes;
      return;
    }
    if (!regions[r].name.empty()) names.push_back(regions[r].name);
  }
  const bool named_later =
      std::any_of(regions.begin() + static_cast<std::ptrdiff_t>(visible), regions.end(),
                  [&](const RegionSpec& region) { return region.name == selector->region; });
  std::string problem = "no region named '" + selector->region + "'";
  if (named_later) {
    problem += " before this one (a region may select only an earlier region)";
  } else {
    problem += names.empty() ? " (no region is named: give a region `name`)"
                             : " (named regions: " + JoinNames(names) + ")";
  }
  throw InputError(selector->where, problem);
}

void ResolveRegionReferences(Scene* scene) {
  auto& regions = scene->regions;
  for (size_t r = 0; r < regions.size(); ++r) {
    ResolveRegionReference(regions, r, &regions[r].nodes);
  }
  for (auto& line : scene->material.lines) {
    ResolveRegionReference(regions, regions.size(), &line.nodes);
  }
  for (auto& fixed : scene->fixed) ResolveRegionReference(regions, regions.size(), &fixed.nodes);
  for (auto& force : scene->loads.forces) {
    ResolveRegionReference(regions, regions.size(), &force.nodes);
  }
}

// A scene with a drape_test block leaves the mesh's shape, the supports and the obstacles to it.
void RefuseWhatTheDrapeTestSets(const YamlMap& top) {
  for (const std::string key : {"fixed", "obstacles"}) {
    if (top.Has(key)) {
      throw InputError(top.KeyLocation(key),
                       "'" + key +
                           "' is set by drape_test (the clamp and the disc): leave it out, "
                           "or write the test out by hand without drape_test");
    }
  }
  if (const auto mesh = top.Find("mesh")) {
    const YamlMap map(*mesh);
    for (const std::string& key : map.Keys()) {
      if (Contains(MeshKeys(), key) && !Contains(DrapeTestMeshKeys(), key)) {
        throw InputError(map.KeyLocation(key),
                         "'" + key +
                             "' is set by drape_test (specimen_diameter): a drape test's "
                             "mesh takes only " +
                             JoinNames(DrapeTestMeshKeys()));
      }
    }
    YamlMap(*mesh, DrapeTestMeshKeys());  // any other key: unknown, the nearest one suggested
  }
}

// A fit or sweep file given where a scene is expected: both name their base scene under `scene`,
// which a scene never has. Says which command reads it, instead of "unknown key 'scene'".
void RefuseFitAndSweepFiles(const YamlValue& root) {
  const YAML::Node& node = root.get();
  if (!node.IsMap() || !node["scene"]) return;
  const bool fit = node["parameters"] || node["measurements"];
  const bool sweep = node["grid"] || node["zip"] || node["sample"];
  Location where = root.where;
  where.key = "scene";
  if (!fit && !sweep) {
    throw InputError(where,
                     "a scene has no 'scene' key (a fit or a sweep file names its base scene "
                     "there: run it with `drape fit` or `drape sweep`)");
  }
  const std::string kind = fit ? "fit" : "sweep";
  throw InputError(where, "this is a " + kind + " file, not a scene: run `drape " + kind + " " +
                              where.file + "`");
}

void ReadScene(const YamlValue& root, Scene* scene) {
  RefuseFitAndSweepFiles(root);
  const YamlMap top(root, SchemaKeys(""));
  if (const auto name = top.Find("name")) scene->name = ReadName(*name);
  ReadFields(top, "", scene);
  if (const auto test = top.Find("drape_test")) {
    scene->drape_test = ReadDrapeTest(*test);
    RefuseWhatTheDrapeTestSets(top);
    scene->mesh = ReadMesh(OptionalSection(top, "mesh"), scene->directory, "circle",
                           scene->drape_test->specimen_diameter / 2);
  } else {
    scene->mesh = ReadMesh(top.Get("mesh"), scene->directory);
  }
  scene->material = ReadMaterial(top.Get("material"));
  if (const auto v = top.Find("regions")) scene->regions = ReadRegions(*v, scene->material);
  if (const auto v = top.Find("fixed")) scene->fixed = ReadFixed(*v);
  if (const auto v = top.Find("loads")) scene->loads = ReadLoads(*v);
  ResolveRegionReferences(scene);
  if (const auto v = top.Find("obstacles")) scene->obstacles = ReadObstacles(*v, scene->directory);
  scene->contact = ReadContact(OptionalSection(top, "contact"));
  if (scene->drape_test) {
    ExpandDrapeTest(scene);
    RequireTheMeshRuleForAnAccuracy(*scene);
    const auto mesh = top.Find("mesh");
    if (!mesh || !YamlMap(*mesh).Has("spacing")) ChooseDrapeTestSpacing(scene);
  }
  scene->solver = ReadSolver(OptionalSection(top, "solver"));
  scene->output = ReadOutput(OptionalSection(top, "output"), *scene);
  if (!top.Has("loads")) scene->loads.where = OptionalSection(top, "loads").where;
}

}  // namespace

SceneDocument SceneDocument::Read(const std::string& path) {
  SceneDocument document;
  document.blank_.file = path;
  document.blank_.directory = DirectoryOf(path);
  document.blank_.name = fs::path(path).stem().string();
  document.what_ = "scene file";
  document.text_ = ReadYamlFileText(path, document.what_);
  return document;
}

SceneDocument SceneDocument::Parse(const std::string& text, const std::string& label,
                                   const std::string& directory) {
  SceneDocument document;
  document.blank_.file = label;
  document.blank_.directory = directory;
  document.blank_.name = "scene";
  document.what_ = "scene";
  document.text_ = text;
  return document;
}

Scene SceneDocument::Load(const std::vector<std::string>& overrides,
                          const std::vector<SceneValue>& values) const {
  Scene scene = blank_;
  scene.root = Location{blank_.file, 1, 1, ""};
  YamlOrigins origins(blank_.file);
  YAML::Node document = ParseYamlText(text_, blank_.file, what_);
  ApplyOverrides(document, overrides, &origins);
  {
    const std::lock_guard<std::mutex> lock(*loading_);
    ApplyValues(document, values, static_cast<int>(overrides.size()), &origins);
  }
  ReadScene(YamlRoot(document, origins), &scene);
  return scene;
}

Scene LoadScene(const std::string& path, const std::vector<std::string>& overrides) {
  return SceneDocument::Read(path).Load(overrides);
}

Scene LoadSceneText(const std::string& text, const std::string& label, const std::string& directory,
                    const std::vector<std::string>& overrides) {
  return SceneDocument::Parse(text, label, directory).Load(overrides);
}

}  // namespace drape
