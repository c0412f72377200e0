#include "src/scene/scene_schema.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>

#include "src/scene/drape_mesh_rule.h"
#include "src/scene/drape_tester.h"
#include "src/scene/material_keys.h"
#include "src/scene/material_models.h"
#include "src/scene/number_text.h"
#include "src/scene/output_kinds.h"
#include "src/scene/scene.h"

namespace drape {
namespace {

using Base = SchemaRow::Base;

// Builds a row: Row("mesh", "spacing").Number("m", Above(0)).Field(&MeshSpec::spacing)...
class Row {
 public:
  Row(std::string table, std::string key) {
    row_.table = std::move(table);
    row_.key = std::move(key);
  }
  // A composite value (or one given in words), read by hand: its type and range in words.
  Row& Is(std::string type, std::string unit = "", std::string range = "") {
    row_.type = std::move(type);
    row_.unit = std::move(unit);
    row_.range = std::move(range);
    return *this;
  }
  Row& Is(std::string type, std::string unit, SchemaRange bounds) {
    Is(std::move(type), std::move(unit));
    row_.bounds = bounds;
    return *this;
  }
  // A rule in words beside the type ("not zero", "> min"), checked by the loader's code.
  Row& Rule(std::string words) {
    row_.range = std::move(words);
    return *this;
  }
  Row& Number(std::string unit, std::optional<SchemaRange> bounds = std::nullopt) {
    const bool plain = unit.empty() || unit == "1";  // "number, > 1" rather than "> 1"
    return Typed(ValueType::kNumber, plain ? "number" : "", std::move(unit), bounds);
  }
  Row& Integer(SchemaRange bounds) {
    bounds.integer = true;
    return Typed(ValueType::kInteger, "integer", "", bounds);
  }
  Row& Bool() { return Typed(ValueType::kBool, "`true` \\| `false`", "", std::nullopt); }
  Row& Words(std::vector<std::string> words) {
    row_.words = std::move(words);
    return Typed(ValueType::kWord, ChoiceText(row_.words), "", std::nullopt);
  }
  Row& Text() { return Typed(ValueType::kText, "text", "", std::nullopt); }
  Row& Point(std::string unit = "") {
    return Typed(ValueType::kPoint, "[3]", std::move(unit), std::nullopt);
  }
  Row& Pair(std::string type, std::string unit) {
    return Typed(ValueType::kPair, std::move(type), std::move(unit), std::nullopt);
  }
  // The member the value goes to; its value in a default-constructed owner is the default.
  template <typename Owner, typename T>
  Row& Field(T Owner::*member) {
    row_.field = FieldOf(member);
    const Owner blank{};
    row_.default_value = row_.field.get(&blank);
    return *this;
  }
  // A composite value's default, as YAML.
  Row& DefaultYaml(std::string yaml) {
    row_.default_yaml = std::move(yaml);
    return *this;
  }
  Row& DefaultValue(FieldValue value) {
    row_.default_value = std::move(value);
    return *this;
  }
  // The default in words ("**required**", "the method's"): it replaces the typed default.
  Row& Default(std::string text) {
    row_.default_text = std::move(text);
    prose_default_ = true;
    return *this;
  }
  // A remark after the typed default's text: "`0` (elastic)".
  Row& Remark(std::string text) {
    remark_ = " (" + std::move(text) + ")";
    return *this;
  }
  Row& Doc(std::string text) {
    row_.doc = std::move(text);
    return *this;
  }
  Row& For(std::vector<std::string> kinds) {
    row_.kinds = std::move(kinds);
    return *this;
  }
  Row& On(Base base) {
    row_.base = base;
    return *this;
  }
  // The round trip: these overrides give the key; scene.yaml writes it at `at` (with `value`).
  Row& Example(std::vector<std::string> overrides, std::string at = "", std::string value = "") {
    row_.example = std::move(overrides);
    row_.written_at = std::move(at);
    row_.written_value = std::move(value);
    return *this;
  }
  operator SchemaRow() const {  // NOLINT(google-explicit-constructor): a builder
    SchemaRow row = row_;
    if (prose_default_) row.default_value = {};
    if (row.bounds) row.range = row.bounds->Text();
    const std::string text = FieldValueText(row.default_value);
    if (!text.empty()) row.default_yaml = text;
    if (row.default_text.empty() && !row.default_yaml.empty()) {
      row.default_text = "`" + row.default_yaml + "`" + remark_;
    }
    return row;
  }

 private:
  static std::string ChoiceText(const std::vector<std::string>& names);
  Row& Typed(ValueType value, std::string type, std::string unit,
             std::optional<SchemaRange> bounds) {
    row_.value = value;
    row_.type = std::move(type);
    row_.unit = std::move(unit);
    row_.bounds = bounds;
    return *this;
  }
  SchemaRow row_;
  std::string remark_;
  bool prose_default_ = false;
};

// "`a` \\| `b`": a choice among names, as the reference's type column writes it.
std::string Row::ChoiceText(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "`" : " \\| `") + name + "`";
  return text;
}

// "`[summary, nodes]`; a drape test adds `profile` and `shadow`": the registry's defaults.
std::string DefaultWriteText() {
  const auto plain = DefaultOutputWrite(false);
  const auto drape_test = DefaultOutputWrite(true);
  std::string list;
  for (const auto& kind : plain) list += (list.empty() ? "" : ", ") + kind;
  std::vector<std::string> added;
  for (const auto& kind : drape_test) {
    if (std::find(plain.begin(), plain.end(), kind) == plain.end())
      added.push_back("`" + kind + "`");
  }
  std::string text = "`[" + list + "]`";
  for (size_t i = 0; i < added.size(); ++i) {
    text += (i == 0 ? "; a drape test adds " : i + 1 == added.size() ? " and " : ", ") + added[i];
  }
  return text;
}

constexpr const char* kRequired = "**required**";
constexpr const char* kNotWritten = "-";

std::vector<SchemaRow> TopLevel() {
  const std::string t;
  return {
      Row(t, "name")
          .Text()
          .Default("the file's stem")
          .Doc("used in reports and in the default output folder; no `/`")
          .Example({"name=other"}),
      Row(t, "dimension")
          .Integer(Between(2, 3))
          .Field(&Scene::dimension)
          .Doc("`2`: nodes move in the x–z plane only (the mesh must lie in one plane y = const)")
          .Example({"mesh.plane=xz", "dimension=2"}),
      Row(t, "mesh")
          .Is("map")
          .Default(kRequired)
          .Doc("the fabric's nodes and links, below")
          .Example({"mesh={kind: grid, nodes: [4, 4]}"}),
      Row(t, "material")
          .Is("map")
          .Default(kRequired)
          .Doc("mass and stiffness, below")
          .Example({"material={density: 0.5, springs: {shear: {warp: 10, weft: 20}}}"}),
      Row(t, "regions")
          .Is("list")
          .Default("none")
          .Doc("material overrides by node selection, below")
          .Example({"regions=[{nodes: {row: 0}, density: 0.4}]"}),
      Row(t, "fixed")
          .Is("list")
          .Default("none")
          .Doc("supports (Dirichlet nodes)")
          .Example({"fixed=[{nodes: {edge: left}}]"}),
      Row(t, "loads")
          .Is("map")
          .Default("none")
          .Doc("gravity and applied forces")
          .Example({"loads={gravity: [0, 0, -1]}"}),
      Row(t, "obstacles")
          .Is("list")
          .Default("none")
          .Doc("rigid bodies the fabric rests on")
          .Example({"obstacles=[{plane: {point: [0, 0, -1], normal: [0, 0, 1]}}]"}),
      Row(t, "contact").Is("map").Doc("contact settings").Example({"contact={thickness: 0.003}"}),
      Row(t, "solver")
          .Is("map")
          .Doc("method and stopping rule")
          .Example({"solver={tolerance: 1e-07}"}),
      Row(t, "output")
          .Is("map")
          .Doc("where results go and which files")
          .Example({"output={obj_up: y}"}),
      Row(t, "drape_test")
          .Is("map")
          .Default("none")
          .Doc("a drape test given by its geometry: it makes `mesh` (all but its `spacing`), "
               "`fixed`, `obstacles` and gravity, below")
          .On(Base::kDrapeTest)
          .Example({"drape_test={specimen_diameter: 0.24}"}, "mesh",
                   "{kind: circle, radius: 0.12}"),
  };
}

std::vector<SchemaRow> DrapeTest() {
  const std::string t = "drape_test";
  auto row = [&](const char* key) { return Row(t, key).On(Base::kDrapeTest); };
  return {
      row("specimen_diameter")
          .Number("m", Above(0))
          .Field(&DrapeTestSpec::specimen_diameter)
          .Doc("the circular specimen: a `circle` mesh of this diameter, lying on the disc's "
               "clearance layer (z = `contact.thickness`)")
          .Example({"drape_test.specimen_diameter=0.24"}, "mesh.radius", "0.12"),
      row("disc_diameter")
          .Number("m", Above(0))
          .Field(&DrapeTestSpec::disc_diameter)
          .Doc("the support disc (a `disk` obstacle at z = 0); smaller than the specimen")
          .Example({"drape_test.disc_diameter=0.2"}, "obstacles[0].disk.radius", "0.1"),
      row("clamp_diameter")
          .Number("m", Above(0))
          .Field(&DrapeTestSpec::clamp_diameter)
          .Default("disc − 1 cm")
          .Doc("the nodes within it (around the disc's centre) are held in x, y and z: the "
               "specimen clamped between the support and cover discs; the ring out to the rim "
               "rests on the disc by contact")
          .Example({"drape_test.clamp_diameter=0.1"}, "fixed[0].nodes.within.radius", "0.05"),
      row("offset")
          .Pair("[x, y]", "m")
          .Field(&DrapeTestSpec::offset)
          .Doc("the disc's centre seen from the specimen's: a real specimen is never centred "
               "exactly, and the offset keeps the lattice from imposing the fold pattern")
          .Example({"drape_test.offset=[0.002, 0.001]"}, "obstacles[0].disk.center",
                   "[0.002, 0.001, 0]"),
      row("drops")
          .Integer(Between(1, kMostDrops))
          .Field(&DrapeTestSpec::drops)
          .Doc("repeated drops (`drape solve --drops N` overrides it), below; scene.yaml, the "
               "expanded scene of one drop, does not write it")
          .Example({"drape_test.drops=3"}, kNotWritten),
      row("placement")
          .Number("m", AtLeast(0))
          .Field(&DrapeTestSpec::placement)
          .Doc("each drop moves the disc's centre from `offset` by a point drawn uniformly from a "
               "disc of this radius (not in scene.yaml, as `drops`)")
          .Example({"drape_test.placement=0.001"}, kNotWritten),
      row("waviness")
          .Number("m", AtLeast(0))
          .Field(&DrapeTestSpec::waviness)
          .Doc("each drop starts the overhang this far out of plane at most: w g(θ) s², s from 0 "
               "at the rim to 1 at the edge, g a random sum of the angular modes 1–12 scaled to "
               "max \\|g\\| = 1 (not in scene.yaml, as `drops`)")
          .Example({"drape_test.waviness=0.001"}, kNotWritten),
      row("seed")
          .Integer(AtLeast(0))
          .Field(&DrapeTestSpec::seed)
          .Doc("the drops' random draws come from (seed, drop number) alone (not in scene.yaml, "
               "as `drops`)")
          .Example({"drape_test.seed=7"}, kNotWritten),
      row("accuracy")
          .Number("", Between(kFinestDrapeAccuracy, kMostDrapeError))
          .Field(&DrapeTestSpec::accuracy)
          .Default("`0.05`")
          .Doc("the drape coefficient's error bar the test needs: without `mesh.spacing`, drape "
               "chooses the lattice that reaches it; a run whose bar is wider says so and exits "
               "1: [Accuracy](#accuracy)")
          .Example({"drape_test.accuracy=0.1"}, "mesh.spacing", "0.0086"),
  };
}

std::vector<SchemaRow> Mesh() {
  const std::string t = "mesh";
  return {
      Row(t, "kind")
          .Words({"grid", "circle", "arc", "chain", "file"})
          .DefaultValue(std::string("grid"))
          .Example({"mesh={kind: arc}"}),
      Row(t, "size")
          .For({"grid"})
          .Is("[2]", "m", "each > 0 (≥ 0 along an axis of 1 node)")
          .DefaultYaml("[1, 1]")
          .Doc("extent along u (x, warp) and v (weft)")
          .Example({"mesh.size=[2, 3]"}),
      Row(t, "nodes")
          .For({"grid"})
          .Is("[2] integers", "", Whole(AtLeast(1)))
          .DefaultYaml("[15, 15]")
          .Doc("node counts along u and v; at least 2 nodes in all")
          .Example({"mesh.nodes=[4, 5]"}),
      Row(t, "u")
          .For({"grid"})
          .Is("list", "m", "strictly increasing")
          .Doc("explicit (non-uniform) coordinates along u; they set that axis' node count and "
               "size (a `nodes`/`size` given too must agree)")
          .Example({"mesh={u: [0, 0.5, 2], nodes: [3, 3]}"}, "mesh.u", "[0, 0.5, 2]"),
      Row(t, "v")
          .For({"grid"})
          .Is("list", "m", "strictly increasing")
          .Doc("explicit coordinates along v, as `u`")
          .Example({"mesh={v: [0, 1, 3]}"}, "mesh.v", "[0, 1, 3]"),
      Row(t, "plane")
          .For({"grid"})
          .Words({"xy", "xz"})
          .Field(&MeshSpec::plane)
          .Doc("`xy` lies flat; `xz` stands vertical with v along +z")
          .Example({"mesh.plane=xz"}),
      Row(t, "origin")
          .For({"grid", "circle", "arc", "chain"})
          .Point("m")
          .Field(&MeshSpec::origin)
          .Doc("position of node (0, 0), the centre, or the first node")
          .Example({"mesh.origin=[1, 2, 3]"}),
      Row(t, "radius")
          .For({"circle", "arc"})
          .Number("m", Above(0))
          .Field(&MeshSpec::radius)
          .Doc("disc radius")
          .Example({"mesh={kind: circle, radius: 0.2, spacing: 0.05}"}, "mesh.radius", "0.2"),
      Row(t, "spacing")
          .For({"circle"})
          .Number("m", Above(0))
          .Field(&MeshSpec::spacing)
          .Doc("lattice spacing of the square grid clipped to the disc: [The circle's "
               "lattice](#the-circles-lattice)")
          .Example({"mesh={kind: circle, spacing: 0.05}"}, "mesh.spacing", "0.05"),
      Row(t, "rings")
          .For({"arc"})
          .Integer(AtLeast(1))
          .Field(&MeshSpec::rings)
          .Doc("concentric rings")
          .Example({"mesh={kind: arc, rings: 3}"}, "mesh.rings", "3"),
      Row(t, "spokes")
          .For({"arc"})
          .Integer(AtLeast(3))
          .Field(&MeshSpec::spokes)
          .Doc("radial spokes")
          .Example({"mesh={kind: arc, spokes: 5}"}, "mesh.spokes", "5"),
      Row(t, "length")
          .For({"chain"})
          .Number("m", Above(0))
          .Field(&MeshSpec::length)
          .Doc("length of the line")
          .Example({"mesh={kind: chain, length: 2}"}, "mesh.length", "2"),
      Row(t, "nodes")
          .For({"chain"})
          .Integer(AtLeast(2))
          .Field(&MeshSpec::chain_nodes)
          .Doc("nodes along the line")
          .Example({"mesh={kind: chain, nodes: 4}"}, "mesh.nodes", "4"),
      Row(t, "direction")
          .For({"chain"})
          .Point()
          .Rule("not zero")
          .Field(&MeshSpec::direction)
          .Doc("direction of the line (normalised)")
          .Example({"mesh={kind: chain, direction: [0, 1, 0]}"}, "mesh.direction", "[0, 1, 0]"),
      Row(t, "path")
          .For({"file"})
          .Text()
          .Default(kRequired)
          .Doc("an OBJ, PLY or STL surface: [Mesh files](#mesh-files)")
          .Example({"mesh={kind: file, path: tests/data/meshes/square.obj}"}, "mesh.path"),
      Row(t, "points")
          .For({"chain"})
          .Is("list of [3]", "m")
          .Doc("explicit node positions, in order (each offset by `origin`); replaces `length`, "
               "`nodes` and `direction` (giving those too is an error); at least 2 (3 if closed)")
          .Example({"mesh={kind: chain, points: [[0, 0, 0], [1, 0, 0]]}"}, "mesh.points",
                   "[[0, 0, 0], [1, 0, 0]]"),
      Row(t, "closed")
          .For({"chain"})
          .Bool()
          .Field(&MeshSpec::closed)
          .Doc("`true`: a link from the last node back to the first (a closed profile, e.g. an "
               "airfoil); flexion links wrap around too (from 5 nodes on)")
          .Example({"mesh={kind: chain, closed: true}"}, "mesh.closed", "true"),
      Row(t, "max_nodes")
          .Integer(Between(2, kLargestMaxNodes))
          .Field(&MeshSpec::max_nodes)
          .Doc("the largest mesh the scene may build: a mesh with more nodes (counted before "
               "anything is built: nu × nv, 1 + rings × spokes, the circle's lattice; a file's "
               "vertices once read) is a located error that gives the node count and the memory "
               "it would take (about 4 kB per node); raise it to build a larger one")
          .Example({"mesh.max_nodes=500"}),
  };
}

std::vector<SchemaRow> Material() {
  const std::string t = "material";
  return {
      Row(t, "model")
          .Words(MaterialModelNames())
          .DefaultValue(MaterialModelName(MaterialSpec().model))
          .Doc("one of the material models below")
          .On(Base::kFiniteVolume)
          .Example({"material.model=finite_volume"}),
      Row(t, "density")
          .Number("kg/m²", Above(0))
          .Doc("areal density (per metre for a chain), lumped to the nodes")
          .Example({"material.density=0.3"}),
      Row(t, "node_mass")
          .Number("kg", Above(0))
          .Doc("mass of every node")
          .Example({"material={node_mass: 0.01, springs: {structural: 100}}"}, "material.node_mass",
                   "0.01"),
      Row(t, "total_mass")
          .Number("kg", Above(0))
          .Doc("mass of the whole fabric")
          .Example({"material={total_mass: 2, springs: {structural: 100}}"}, "material.total_mass",
                   "2"),
      Row(t, "springs")
          .Is("map")
          .Default("**required** for `springs`; optional beside `finite_volume`")
          .Doc("below")
          .Example({"material.springs={flexion: {warp: 5, weft: 6}}"}),
      Row(t, "finite_volume")
          .Is("map")
          .Default("**required** for `finite_volume`")
          .Doc("below")
          .On(Base::kFiniteVolume)
          .Example({"material.finite_volume.G=20"}, "material.finite_volume", "{G: 20}"),
      Row(t, "lines")
          .Is("list")
          .Default("none")
          .Doc("spring lines (seams, tapes, threads) on top of the material, below")
          .Example({"material.lines=[{nodes: {row: 0}, structural: 30}]"}),
  };
}

std::vector<SchemaRow> Lines() {
  const std::string t = "material.lines";
  const std::string line = "material.lines=[{nodes: {row: 1}, structural: 30, tension_only: true}]";
  return {
      Row(t, "nodes")
          .Is("a node selection")
          .Default(kRequired)
          .Doc("the nodes the line runs through")
          .Example({line}, "material.lines[0].nodes", "{row: 1}"),
      Row(t, "structural")
          .Number("N/m", Above(0))
          .Field(&SpringLineSpec::stiffness)
          .Default(kRequired)
          .Doc("stiffness of each of the line's springs")
          .Example({line}, "material.lines[0].structural", "30"),
      Row(t, "tension_only")
          .Bool()
          .Field(&SpringLineSpec::tension_only)
          .Doc("a stitched thread: no force under compression")
          .Example({line}, "material.lines[0].tension_only", "true"),
  };
}

std::vector<SchemaRow> Springs() {
  const std::string t = "material.springs";
  const std::string family = "number or `{warp: …, weft: …}`";
  return {
      Row(t, "structural")
          .Is(family, "N/m", Above(0))
          .Default("not built")
          .Doc("springs between neighbours along u (warp) and v (weft)")
          .Example({"material.springs.structural={warp: 10, weft: 20}"}),
      Row(t, "shear")
          .Is(family, "N/m", Above(0))
          .Default("not built")
          .Doc("diagonal springs of each quad")
          .Example({"material.springs.shear={warp: 3, weft: 4}"}),
      Row(t, "flexion")
          .Is(family, "N/m", Above(0))
          .Default("not built")
          .Doc("skip-one springs (bending resistance)")
          .Example({"material.springs.flexion={warp: 1, weft: 2}"}),
      Row(t, "rest_length")
          .Is("`initial` \\| `zero` \\| a length", "m", Above(0))
          .DefaultYaml("initial")
          .Doc("rest length of every spring: as meshed, zero, or the given length")
          .Example({"material.springs.rest_length=zero"}),
      Row(t, "tension_only")
          .Bool()
          .Field(&SpringsSpec::tension_only)
          .Doc("no resistance under compression")
          .Example({"material.springs.tension_only=true"}),
      Row(t, "stretch_limit")
          .Number("", Above(1))
          .Field(&SpringsSpec::stretch_limit)
          .Default("none")
          .Doc("maximum stretch ratio allowed: a penalty ½κ max(\\|d\\| − λL₀, 0)² with κ = 1000 k "
               "on every spring for the energy solvers (a spring ends at most (λ_free − λ)/1001 "
               "above the limit); Provot's constraint for `explicit-euler`; `springs` model only")
          .Example({"material.springs.stretch_limit=1.1"}),
  };
}

// material.finite_volume: the SI keys of src/scene/material_keys.h, the measurements and the
// frictions' settings.
std::vector<SchemaRow> FiniteVolume() {
  const std::string t = "material.finite_volume";
  const std::string at = "material.finite_volume.";
  auto row = [&](const char* key) { return Row(t, key).On(Base::kFiniteVolume); };
  auto set = [&](const std::string& key, const std::string& value) {
    return std::vector<std::string>{at + key + "=" + value};
  };
  return {
      row("E_warp")
          .Number("N/m", Above(0))
          .Default("**required** unless given by `kes` or `fast`")
          .Doc("membrane (tensile) rigidity per unit width along the warp")
          .Example(set("E_warp", "2000")),
      row("E_weft")
          .Number("N/m", Above(0))
          .Default("**required** unless given by `kes` or `fast`")
          .Doc("membrane (tensile) rigidity per unit width along the weft")
          .Example(set("E_weft", "3000")),
      row("nu_warp")
          .Number("1")
          .Field(&FiniteVolumeSpec::nu_warp)
          .Doc("Poisson's ratio; `nu_warp * nu_weft < 1`")
          .Example(set("nu_warp", "0.2")),
      row("nu_weft")
          .Number("1")
          .Field(&FiniteVolumeSpec::nu_weft)
          .Doc("Poisson's ratio; `nu_warp * nu_weft < 1`")
          .Example(set("nu_weft", "0.3")),
      row("G")
          .Number("N/m", Above(0))
          .Default("**required** unless given by `kes` or `fast`")
          .Doc("in-plane shear rigidity")
          .Example(set("G", "20")),
      row("D_warp")
          .Number("N*m", Above(0))
          .Default("**required** unless given by `kes`, `fast` or `bending_length`")
          .Doc("bending rigidity along the warp")
          .Example(set("D_warp", "2e-05")),
      row("D_weft")
          .Number("N*m", Above(0))
          .Default("**required** unless given by `kes`, `fast` or `bending_length`")
          .Doc("bending rigidity along the weft")
          .Example(set("D_weft", "3e-05")),
      row("D_12")
          .Number("N*m")
          .Field(&FiniteVolumeSpec::D_12)
          .Doc("coupling rigidity; `D_12² < D_warp * D_weft`")
          .Example(set("D_12", "1e-06")),
      row("D_66")
          .Number("N*m", AtLeast(0))
          .Default("`√(D_warp · D_weft) / 3` unless given by `kes.B_bias` or `bending_length.bias`")
          .Doc("torsional (twisting) rigidity, M₁₂ = D_66 · 2κ₁₂; an isotropic plate's is "
               "D (1 − ν)/2; the default and its source: [Twist](#twist)")
          .Example(set("D_66", "5e-06")),
      row("kes")
          .Is("map")
          .Doc("KES-FB measurements (below)")
          .Example({at.substr(0, at.size() - 1) +
                    "={E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, kes: {B_weft: 0.1}}"},
                   "material.finite_volume.D_weft", "9.80665e-06"),
      row("fast")
          .Is("map")
          .Doc("SiroFAST measurements (below)")
          .Example({at.substr(0, at.size() - 1) +
                    "={E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, fast: {B_weft: 7.5}}"},
                   "material.finite_volume.D_weft", "7.5e-06"),
      row("bending_length")
          .Is("`{warp: cm, weft: cm, bias: cm}`")
          .Doc("Peirce bending lengths (below)")
          .Example({at.substr(0, at.size() - 1) +
                    "={E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, bending_length: {weft: "
                    "1.5}}"},
                   "material.finite_volume.D_weft", "6.61948875e-06"),
      row("bending_friction_warp")
          .Number("N", AtLeast(0))
          .Field(&FiniteVolumeSpec::bending_friction_warp)
          .Remark("elastic")
          .Doc("the friction moment per unit width (N·m/m) between fibres and yarns in bending "
               "along the warp, H = 2HB/2 (or `kes.2HB_warp`); below")
          .Example(set("bending_friction_warp", "0.001")),
      row("bending_friction_weft")
          .Number("N", AtLeast(0))
          .Field(&FiniteVolumeSpec::bending_friction_weft)
          .Remark("elastic")
          .Doc("the same along the weft (or `kes.2HB_weft`)")
          .Example(set("bending_friction_weft", "0.002")),
      row("bending_friction_smoothing")
          .Number("1/m", Above(0))
          .Field(&FiniteVolumeSpec::bending_friction_smoothing)
          .Doc("δ: the curvature below which the friction's kink at the flat state is smoothed "
               "(written where the fabric has a bending friction)")
          .Example({at + "bending_friction_warp=0.001", at + "bending_friction_smoothing=0.05"}),
      row("shear_friction")
          .Number("N/m", AtLeast(0))
          .Field(&FiniteVolumeSpec::shear_friction)
          .Remark("elastic")
          .Doc("the friction force per unit width between yarns in shear, HG = 2HG/2 (or "
               "`kes.2HG`); below")
          .Example(set("shear_friction", "0.01")),
      row("shear_friction_smoothing")
          .Number("rad", Above(0))
          .Field(&FiniteVolumeSpec::shear_friction_smoothing)
          .Doc("δ: the shear angle below which the shear friction's kink at the rest state is "
               "smoothed (written where the fabric has a shear friction)")
          .Example({at + "shear_friction=0.01", at + "shear_friction_smoothing=0.002"}),
      row("friction_load_steps")
          .Integer(AtLeast(0))
          .Field(&FiniteVolumeSpec::friction_load_steps)
          .Remark("monotone")
          .Doc("N ≥ 1: the frictions' incremental form, the loads ramped in N steps (below); 0: "
               "the loads at once")
          .Example(set("friction_load_steps", "3")),
      row("cell_shear")
          .Bool()
          .Field(&FiniteVolumeSpec::cell_shear)
          .Doc("`true`: the in-plane shear taken once per whole lattice cell, at its centre; "
               "`false`: at the corners of each control volume (Hu/Teng's), which charge a fold "
               "oblique to the lattice a shear the fabric does not have (below)")
          .Example(set("cell_shear", "false")),
  };
}

// material.finite_volume.kes: each measurement is written as the SI value it converts to.
std::vector<SchemaRow> Kes() {
  const std::string t = "material.finite_volume.kes";
  const std::string fv = "material.finite_volume=";
  const std::string si = "material.finite_volume.";
  auto row = [&](const char* key) { return Row(t, key).On(Base::kFiniteVolume); };
  return {
      row("B_warp")
          .Number("gf·cm²/cm", Above(0))
          .Doc("→ `D_warp` (N·m): D = B × 9.80665e-5")
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_weft: 1e-5, kes: {B_warp: 0.1}}"},
                   si + "D_warp", "9.80665e-06"),
      row("B_weft")
          .Number("gf·cm²/cm", Above(0))
          .Doc("→ `D_weft` (N·m), as `B_warp`")
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, kes: {B_weft: 0.1}}"},
                   si + "D_weft", "9.80665e-06"),
      row("B_bias")
          .Number("gf·cm²/cm", Above(0))
          .Doc("the bending rigidity of a strip cut at 45° to the warp → `D_66` (N·m) by the "
               "orthotropic plate's compliance: D_66 = 1 / (4/B₄₅ − 1/D_warp − 1/D_weft) "
               "(with `D_12` = 0; [Twist](#twist))")
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: "
                         "{B_bias: 0.08}}"},
                   si + "D_66", "3.227283647121932e-06"),
      row("G")
          .Number("gf/(cm·deg)", Above(0))
          .Doc("→ `G` (N/m, per radian): G = G_kes × 0.980665 × 180/π = G_kes × 56.188")
          .Example({fv + "{E_warp: 1000, E_weft: 1000, D_warp: 1e-5, D_weft: 1e-5, kes: {G: 1}}"},
                   si + "G", "56.18796561619688"),
      row("W")
          .Number("mg/cm²", Above(0))
          .Doc("→ the areal density (kg/m²), replacing `material.density`: ρ = W / 100")
          .Example({"material={model: finite_volume, finite_volume: {E_warp: 1000, E_weft: 1000, "
                    "G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: {W: 12}}}"},
                   "material.density", "0.12"),
      row("EMT_warp")
          .Number("%", Above(0))
          .Doc("→ `E_warp` (N/m): E = LT · Fm / (EMT/100)")
          .Example({fv + "{E_weft: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: {EMT_warp: 5}}"},
                   si + "E_warp", "9806.65"),
      row("EMT_weft")
          .Number("%", Above(0))
          .Doc("→ `E_weft` (N/m), as `EMT_warp`")
          .Example({fv + "{E_warp: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: {EMT_weft: 5}}"},
                   si + "E_weft", "9806.65"),
      row("LT_warp")
          .Number("1", Above(0))
          .DefaultValue(1.0)
          .Doc("the linearity of the tensile curve, with `EMT_warp`")
          .Example({fv + "{E_weft: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: {EMT_warp: 5, "
                         "LT_warp: 0.5}}"},
                   si + "E_warp", "4903.325"),
      row("LT_weft")
          .Number("1", Above(0))
          .DefaultValue(1.0)
          .Doc("the linearity of the tensile curve, with `EMT_weft`")
          .Example({fv + "{E_warp: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: {EMT_weft: 5, "
                         "LT_weft: 0.5}}"},
                   si + "E_weft", "4903.325"),
      row("Fm")
          .Number("gf/cm", Above(0))
          .DefaultValue(500.0)
          .Doc("the load at which EMT was measured (500 gf/cm, the standard condition, is "
               "490.33 N/m); only with `EMT_warp` or `EMT_weft`")
          .Example({fv + "{E_weft: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, kes: {EMT_warp: 5, "
                         "Fm: 250}}"},
                   si + "E_warp", "4903.325"),
      row("2HB_warp")
          .Number("gf·cm/cm", AtLeast(0))
          .DefaultValue(0.0)
          .Doc("→ `bending_friction_warp` (N): H = 2HB/2 × 9.80665e-3")
          .Example({si + "kes={2HB_warp: 0.2}"}, si + "bending_friction_warp", "9.80665e-04"),
      row("2HB_weft")
          .Number("gf·cm/cm", AtLeast(0))
          .DefaultValue(0.0)
          .Doc("→ `bending_friction_weft` (N), as `2HB_warp`")
          .Example({si + "kes={2HB_weft: 0.2}"}, si + "bending_friction_weft", "9.80665e-04"),
      row("2HG")
          .Number("gf/cm", AtLeast(0))
          .DefaultValue(0.0)
          .Doc("→ `shear_friction` (N/m): HG = 2HG/2 × 0.980665")
          .Example({si + "kes={2HG: 2}"}, si + "shear_friction", "0.980665"),
  };
}

// material.finite_volume.fast: each measurement is written as the SI value it converts to.
std::vector<SchemaRow> Fast() {
  const std::string t = "material.finite_volume.fast";
  const std::string fv = "material.finite_volume=";
  const std::string si = "material.finite_volume.";
  auto row = [&](const char* key) { return Row(t, key).On(Base::kFiniteVolume); };
  return {
      row("W")
          .Number("g/m²", Above(0))
          .Doc("→ the areal density (kg/m²), replacing `material.density`: ρ = W / 1000")
          .Example({"material={model: finite_volume, finite_volume: {E_warp: 1000, E_weft: 1000, "
                    "G: 10, D_warp: 1e-5, D_weft: 1e-5, fast: {W: 150}}}"},
                   "material.density", "0.15"),
      row("B_warp")
          .Number("µN·m", Above(0))
          .Doc("→ `D_warp` (N·m): D = B × 1e-6")
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_weft: 1e-5, fast: {B_warp: 7.5}}"},
                   si + "D_warp", "7.5e-06"),
      row("B_weft")
          .Number("µN·m", Above(0))
          .Doc("→ `D_weft` (N·m), as `B_warp`")
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, fast: {B_weft: 7.5}}"},
                   si + "D_weft", "7.5e-06"),
      row("EB5")
          .Number("%", Above(0))
          .Doc("the bias extensibility at 5 gf/cm → `G` (N/m): FAST's G = 123 / EB5")
          .Example(
              {fv + "{E_warp: 1000, E_weft: 1000, D_warp: 1e-5, D_weft: 1e-5, fast: {EB5: 2}}"},
              si + "G", "61.5"),
      row("E100_warp")
          .Number("%", Above(0))
          .Doc("the extensibility at 100 gf/cm → `E_warp` (N/m): E = 98.0665 / (E100/100)")
          .Example({fv + "{E_weft: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, fast: {E100_warp: 2}}"},
                   si + "E_warp", "4903.325"),
      row("E100_weft")
          .Number("%", Above(0))
          .Doc("→ `E_weft` (N/m), as `E100_warp`")
          .Example({fv + "{E_warp: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, fast: {E100_weft: 2}}"},
                   si + "E_weft", "4903.325"),
  };
}

std::vector<SchemaRow> BendingLength() {
  const std::string t = "material.finite_volume.bending_length";
  const std::string fv = "material.finite_volume=";
  return {
      Row(t, "warp")
          .Number("cm", Above(0))
          .Doc("→ `D_warp` (N·m): D = ρ g_n c³")
          .On(Base::kFiniteVolume)
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_weft: 1e-5, bending_length: "
                         "{warp: 1.5}}"},
                   "material.finite_volume.D_warp", "6.61948875e-06"),
      Row(t, "weft")
          .Number("cm", Above(0))
          .Doc("→ `D_weft` (N·m), as `warp`")
          .On(Base::kFiniteVolume)
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, bending_length: "
                         "{weft: 1.5}}"},
                   "material.finite_volume.D_weft", "6.61948875e-06"),
      Row(t, "bias")
          .Number("cm", Above(0))
          .Doc("the bending length of a strip cut at 45° to the warp → B₄₅ = ρ g_n c³ → `D_66` "
               "(N·m), as `kes.B_bias`")
          .On(Base::kFiniteVolume)
          .Example({fv + "{E_warp: 1000, E_weft: 1000, G: 10, D_warp: 1e-5, D_weft: 1e-5, "
                         "bending_length: {bias: 1.5}}"},
                   "material.finite_volume.D_66", "2.473555989872958e-06"),
  };
}

std::optional<SchemaRange> KeyBounds(FiniteVolumeKey::Range range) {
  switch (range) {
    case FiniteVolumeKey::Range::kPositive:
      return Above(0);
    case FiniteVolumeKey::Range::kNonNegative:
      return AtLeast(0);
    case FiniteVolumeKey::Range::kAny:
      break;
  }
  return std::nullopt;
}

// regions: the selection, the name, and the overrides (the finite-volume ones are
// src/scene/material_keys.h's).
std::vector<SchemaRow> Regions() {
  const std::string t = "regions";
  auto region = [](const std::string& keys) {
    return std::vector<std::string>{"regions=[{nodes: {row: 0}, " + keys + "}]"};
  };
  std::vector<SchemaRow> rows = {
      Row(t, "nodes")
          .Is("a node selection")
          .Default(kRequired)
          .Doc("which nodes")
          .Example(region("density: 0.4"), "regions[0].nodes", "{row: 0}"),
      Row(t, "name")
          .Text()
          .Default("none")
          .Doc("a name, unique among the regions, by which supports, loads, spring lines and "
               "later regions select the region's nodes: `nodes: {region: hem}`")
          .Example(region("density: 0.4, name: hem"), "regions[0].name", "hem"),
      Row(t, "density")
          .For({"the material gives `density` (or `kes.W`)"})
          .Number("kg/m²", Above(0))
          .Default("the material's")
          .Doc("the areal density")
          .Example(region("density: 0.4"), "regions[0].density", "0.4"),
      Row(t, "structural")
          .For({"`material.springs` is given"})
          .Is("number or `{warp: …, weft: …}`", "N/m", Above(0))
          .Default("the material's")
          .Doc("that spring family")
          .Example(region("structural: {warp: 5, weft: 6}"), "regions[0].structural",
                   "{warp: 5, weft: 6}"),
      Row(t, "shear")
          .For({"`material.springs` is given"})
          .Is("number or `{warp: …, weft: …}`", "N/m", Above(0))
          .Default("the material's")
          .Doc("that spring family")
          .Example(region("shear: {warp: 5, weft: 6}"), "regions[0].shear", "{warp: 5, weft: 6}"),
      Row(t, "flexion")
          .For({"`material.springs` is given"})
          .Is("number or `{warp: …, weft: …}`", "N/m", Above(0))
          .Default("the material's")
          .Doc("that spring family")
          .Example(region("flexion: {warp: 5, weft: 6}"), "regions[0].flexion",
                   "{warp: 5, weft: 6}"),
      Row(t, "tension_only")
          .For({"`material.springs` is given"})
          .Bool()
          .Default("the material's")
          .Doc("the springs' `tension_only`")
          .Example(region("tension_only: true"), "regions[0].tension_only", "true"),
  };
  for (const FiniteVolumeKey& key : FiniteVolumeKeys()) {
    rows.push_back(Row(t, key.key)
                       .For({"`finite_volume`"})
                       .Number(key.unit, KeyBounds(key.range))
                       .Default("the material's")
                       .Doc("`finite_volume." + key.key + "`")
                       .On(Base::kFiniteVolume)
                       .Example(region(key.key + ": 1e-06"), "regions[0]." + key.key, "1e-06"));
  }
  return rows;
}

std::vector<SchemaRow> NodeSelections() {
  const std::string t = "nodes";
  auto fixed = [](const std::string& selection) {
    return std::vector<std::string>{"fixed=[{nodes: " + selection + "}]"};
  };
  auto row = [&](const char* key, const std::string& type, const std::string& doc,
                 const std::string& example) {
    const std::string name = key;
    const bool lengths = name == "box" || name == "within" || name == "outside";  // in m
    return Row(t, key)
        .Is(type, lengths ? "m" : "")
        .Doc(doc)
        .Example(fixed(example), "fixed[0].nodes", example);
  };
  return {
      row("edge", "`top` \\| `bottom` \\| `left` \\| `right`", "a grid border: `{edge: top}`",
          "{edge: bottom}"),
      row("corner", "`top-left` \\| `top-right` \\| `bottom-left` \\| `bottom-right`",
          "a grid corner: `{corner: top-left}`", "{corner: top-right}"),
      row("ids", "list of integers ≥ 0", "nodes by id: `{ids: [0, 14]}`", "{ids: [0, 1]}"),
      row("ij", "list of [i, j]", "grid nodes by (i, j): `{ij: [[0, 0], [14, 0]]}`",
          "{ij: [[0, 0], [1, 0]]}"),
      row("row", "integer ≥ 0", "the lattice row j (grid, chain, circle): `{row: 15}`", "{row: 1}"),
      row("column", "integer ≥ 0", "the lattice column i: `{column: 0}`", "{column: 2}"),
      row("box", "`{min: [3], max: [3]}`",
          "nodes inside the box (max ≥ min): `{box: {min: [x, y, z], max: [x, y, z]}}`",
          "{box: {min: [0, 0, 0], max: [1, 1, 0]}}"),
      row("within", "`{center: [3], radius: > 0}`",
          "nodes within distance r: `{within: {center: [x, y, z], radius: r}}`",
          "{within: {center: [0, 0, 0], radius: 0.5}}"),
      row("outside", "`{center: [3], radius: > 0}`",
          "nodes at distance r or more (a rim): `{outside: {center: [x, y, z], radius: r}}`",
          "{outside: {center: [0, 0, 0], radius: 0.5}}"),
      row("all", "`true`", "every node: `{all: true}`", "{all: true}"),
      Row(t, "region")
          .Text()
          .Doc("the nodes of the region of that name (`regions`): `{region: hem}`; scene.yaml "
               "writes the region's own selection")
          .Example({"regions=[{name: hem, nodes: {row: 2}, density: 0.4}]",
                    "fixed=[{nodes: {region: hem}}]"},
                   "fixed[0].nodes", "{row: 2}"),
  };
}

std::vector<SchemaRow> Fixed() {
  const std::string t = "fixed";
  const std::string fixed = "fixed=[{nodes: {edge: left}, dofs: [z], move: [0, 0, 0.1]}]";
  return {
      Row(t, "nodes")
          .Is("a node selection")
          .Default(kRequired)
          .Doc("the supported nodes")
          .Example({fixed}, "fixed[0].nodes", "{edge: left}"),
      Row(t, "dofs")
          .Is("list of `x`, `y`, `z` (no repeats)")
          .DefaultYaml("[x, y, z]")
          .Doc("the directions held; a subset fixes only those")
          .Example({fixed}, "fixed[0].dofs", "[z]"),
      Row(t, "move")
          .Point("m")
          .Field(&FixedSpec::move)
          .Doc("prescribed displacement of the selection")
          .Example({fixed}, "fixed[0].move", "[0, 0, 0.1]"),
  };
}

std::vector<SchemaRow> Loads() {
  const std::string t = "loads";
  return {
      Row(t, "gravity")
          .Point("m/s²")
          .Field(&LoadsSpec::gravity)
          .Default("none (no weight)")
          .Doc("e.g. `[0, 0, -9.81]`")
          .Example({"loads.gravity=[0, 0, -9.81]"}),
      Row(t, "forces")
          .Is("list")
          .Default("none")
          .Doc("each `{nodes: selection, ...}` with exactly one of `total`, `each`, `values`, "
               "`ramp`, `traction`, `pressure` (below)")
          .Example({"loads.forces=[{nodes: {row: 0}, total: [0, 0, 1]}]"}),
      Row(t, "pressure")
          .Number("N/m")
          .Default("none")
          .Doc("pressure inside a closed chain (`mesh.closed: true`) in a 2-D scene: the "
               "potential −p × (area enclosed in the x–z plane), below")
          .Example({"loads.pressure=50"}),
  };
}

std::vector<SchemaRow> Forces() {
  const std::string t = "loads.forces";
  auto force = [](const std::string& entry) {
    return std::vector<std::string>{"loads.forces=[{nodes: {row: 0}, " + entry + "}]"};
  };
  return {
      Row(t, "nodes")
          .Is("a node selection")
          .Default(kRequired)
          .Doc("the loaded nodes")
          .Example(force("each: [0, 0, 1]"), "loads.forces[0].nodes", "{row: 0}"),
      Row(t, "total")
          .Point("N")
          .Doc("shared equally among the selected nodes")
          .Example(force("total: [0, 0, 2]"), "loads.forces[0].total", "[0, 0, 2]"),
      Row(t, "each")
          .Point("N")
          .Doc("on every selected node")
          .Example(force("each: [0, 0, 3]"), "loads.forces[0].each", "[0, 0, 3]"),
      Row(t, "values")
          .Is("list of [3]", "N")
          .Doc("one force per selected node, in increasing id order (for a grid edge: along u, or "
               "along v); the count must equal the selection's, else an error located at "
               "`values`")
          .Example(force("values: [[1, 0, 0], [2, 0, 0], [3, 0, 0]]"), "loads.forces[0].values",
                   "[[1, 0, 0], [2, 0, 0], [3, 0, 0]]"),
      Row(t, "ramp")
          .Is("`{from: [3], to: [3]}`", "N")
          .Doc("a per-node force varying linearly along the selection: node k gets (1 − s_k) "
               "`from` + s_k `to`, where s_k ∈ [0, 1] is its position projected on the segment "
               "from the selection's first node (lowest id) to its last (highest id), clamped; "
               "`from` is the force at the first node, `to` at the last")
          .Example(force("ramp: {from: [0, 0, 1], to: [0, 0, 2]}"), "loads.forces[0].ramp",
                   "{from: [0, 0, 1], to: [0, 0, 2]}"),
      Row(t, "traction")
          .Point("Pa")
          .Doc("a force per unit area: each selected node gets the traction times its lumped "
               "area (the area its mass is lumped from: a quarter of each grid cell, a third of "
               "each triangle; on a chain its lumped length, and the traction is then in N/m)")
          .Example(force("traction: [0, 0, 4]"), "loads.forces[0].traction", "[0, 0, 4]"),
      Row(t, "pressure")
          .Number("Pa")
          .Doc("a force per unit area normal to the surface: each selected node gets p × its "
               "lumped area along its initial unit normal (the area-weighted normal of its "
               "triangles, by the right-hand rule over the mesh's node order: +z for a grid or "
               "circle in the x–y plane, so p > 0 pushes towards +z). Needs a surface mesh "
               "(triangles)")
          .Example(force("pressure: 5"), "loads.forces[0].pressure", "5"),
  };
}

// The keys of the obstacle kinds (src/model/obstacle_kinds.h; the test holds them to it).
std::vector<SchemaRow> Obstacles() {
  const std::string t = "obstacles";
  auto row = [&](const char* key, std::vector<std::string> kinds, const std::string& doc,
                 const std::string& body, const std::string& value) {
    const std::string kind = kinds.front();
    return Row(t, key)
        .For(std::move(kinds))
        .Default(kRequired)
        .Doc(doc)
        .Example({"obstacles=[{" + kind + ": " + body + "}]"}, "obstacles[0]." + kind + "." + key,
                 value);
  };
  const std::string sphere = "{center: [0, 0, -1], radius: 0.5}";
  const std::string cylinder = "{center: [0, 0, -1], radius: 0.5, height: 0.25}";
  const std::string box = "{min: [0, 0, -2], max: [1, 1, -1]}";
  const std::string plane = "{point: [0, 0, -1], normal: [0, 0, 2]}";
  const std::vector<std::string> round = {"sphere", "disk", "cylinder"};
  const std::string file = "file: tests/data/meshes/octahedron.obj";
  const std::string mesh = "{" + file + ", translation: [0, 0, -2]}";
  const std::string mesh_scaled = "{" + file + ", scale: 2, translation: [0, 0, -3]}";
  const std::string mesh_turned = "{" + file + ", rotation: [90, 0, 0], translation: [0, 0, -2]}";
  return {
      row("center", round, "the centre (of a cylinder's top face)", sphere, "[0, 0, -1]")
          .Point("m")
          .Field(&ObstacleSpec::center),
      row("radius", round, "the radius", sphere, "0.5")
          .Number("m", Above(0))
          .Field(&ObstacleSpec::radius),
      row("height", {"cylinder"}, "the height (it extends downward, like a pedestal)", cylinder,
          "0.25")
          .Number("m", Above(0))
          .Field(&ObstacleSpec::height),
      row("min", {"box"}, "the lowest corner", box, "[0, 0, -2]")
          .Point("m")
          .Field(&ObstacleSpec::min),
      row("max", {"box"}, "the highest corner", box, "[1, 1, -1]")
          .Point("m")
          .Rule("> min")
          .Field(&ObstacleSpec::max),
      row("point", {"plane"}, "a point of the plane", plane, "[0, 0, -1]")
          .Point("m")
          .Field(&ObstacleSpec::center),
      row("normal", {"plane"}, "the normal, towards the fabric's side (normalised)", plane,
          "[0, 0, 1]")
          .Point()
          .Rule("not zero")
          .Field(&ObstacleSpec::normal),
      row("position", {"pin"}, "the tip", "{position: [0, 0, -1]}", "[0, 0, -1]")
          .Point("m")
          .Field(&ObstacleSpec::center),
      row("file", {"mesh"},
          "a closed triangle surface, outward normals: OBJ, PLY or STL "
          "([Mesh files](#mesh-files)); polygons are split into fans",
          mesh, "")  // written as an absolute path
          .Text(),
      Row(t, "scale")
          .For({"mesh"})
          .Number("1", Above(0))
          .Field(&ObstacleSpec::scale)
          .Doc("multiplies the file's coordinates (0.001 for a file in mm)")
          .Example({"obstacles=[{mesh: " + mesh_scaled + "}]"}, "obstacles[0].mesh.scale", "2"),
      Row(t, "rotation")
          .For({"mesh"})
          .Point("°")
          .Field(&ObstacleSpec::rotation)
          .Doc("turns the scaled file about the axes x, then y, then z (fixed axes), in degrees")
          .Example({"obstacles=[{mesh: " + mesh_turned + "}]"}, "obstacles[0].mesh.rotation",
                   "[90, 0, 0]"),
      Row(t, "translation")
          .For({"mesh"})
          .Point("m")
          .Field(&ObstacleSpec::translation)
          .Doc("then moves it by this vector")
          .Example({"obstacles=[{mesh: " + mesh + "}]"}, "obstacles[0].mesh.translation",
                   "[0, 0, -2]"),
      Row(t, "friction")
          .Number("1", AtLeast(0))
          .Field(&ObstacleSpec::friction)
          .Doc("Coulomb's coefficient μ of the fabric on this obstacle (0: frictionless): a "
               "node it pushes on with force λ slides only under a tangential force above μ λ "
               "(costs/obstacle_friction.h)")
          .Example({"obstacles=[{plane: {point: [0, 0, -1], normal: [0, 0, 1], friction: 0.3}}]"},
                   "obstacles[0].plane.friction", "0.3"),
  };
}

std::vector<SchemaRow> ContactSolverOutput() {
  return {
      Row("contact", "thickness")
          .Number("m", AtLeast(0))
          .Field(&ContactSpec::thickness)
          .Doc("fabric half-thickness kept off every obstacle; twice it is the distance two "
               "layers of the fabric keep apart (`contact.self`)")
          .Example({"contact.thickness=0.002"}),
      Row("contact", "self")
          .Bool()
          .Field(&ContactSpec::self)
          .Doc("`true`: the fabric's contact with itself, for a fabric of triangles in 3-D (a "
               "chain has no surface): a node and a triangle, or two triangle sides, that share "
               "no node keep twice `contact.thickness` apart, and no solver step passes a piece "
               "of the fabric through another; `false`: none (the certificate still refuses a "
               "state through itself)")
          .Example({"contact.self=false"}),
      Row("solver", "method")
          .Text()
          .Field(&SolverSpec::method)
          .Doc("one of the methods `drape solvers` lists; `--solver` overrides it")
          .Example({"solver.method=ceres-lm"}),
      Row("solver", "tolerance")
          .Number("1", Above(0))
          .Field(&SolverSpec::tolerance)
          .Doc("relative equilibrium residual to reach (free residual forces / weight and loads)")
          .Example({"solver.tolerance=1e-06"}),
      Row("solver", "max_iterations")
          .Integer(AtLeast(1))
          .Field(&SolverSpec::max_iterations)
          .Default("the method's (see [Solvers](#solvers))")
          .Example({"solver.max_iterations=50"}),
      Row("solver", "time_limit")
          .Number("s", Above(0))
          .Field(&SolverSpec::time_limit)
          .Default("the method's (see [Solvers](#solvers))")
          .Doc("per solve and per build of the model; what it bounds: [Time limit](#time-limit)")
          .Example({"solver.time_limit=30"}),
      Row("solver", "levels")
          .Integer(Between(1, kMostLevels))
          .Field(&SolverSpec::levels)
          .Default("not given: `2` for a drape test (a `circle` or `grid` mesh with a support "
                   "`disk`) whose level of twice the spacing has 4 spacings across the disc's "
                   "radius (2 cm under the standard 18 cm disc), else `1`")
          .Doc("solve on this many nested lattices, coarse to fine: [Levels](#levels)")
          .Example({"solver.levels=2"}),
      Row("solver", "<method>")
          .Is("map of numbers")
          .Doc("options of that method, e.g. `ceres-lbfgs: {memory: 10}`, `puiseux-dynamic: {dt: "
               "0.01, beta: 0.001}`; only the keys that method accepts, each within its range "
               "(`drape solvers` lists them, with their defaults and ranges; so does the options "
               "table under [Solvers](#solvers)); a value out of range is a located error before "
               "anything is built")
          .Example({"solver.ceres-lbfgs.memory=7"}),
      Row("output", "directory")
          .Is("path")
          .Default("`out/<name>`")
          .Doc("relative to the scene file's folder unless absolute; `--out` overrides it")
          .Example({"output.directory=/tmp/drape-schema-example"}),
      Row("output", "write")
          .Is("list, no repeats")
          .Default(DefaultWriteText())
          .Doc("any of the output kinds below")
          .Example({"output.write=[nodes, png]"}),
      Row("output", "obj_up")
          .Words({"z", "y"})
          .Field(&OutputSpec::obj_up)
          .Doc("the up axis of `mesh.obj`: `z` as solved; `y` turns the mesh a quarter turn "
               "about x, (x, y, z) → (x, z, −y), positions and normals alike (a rotation, so "
               "still right-handed), so that Blender's and three.js's default import stand the "
               "drape upright")
          .Example({"output.obj_up=y"}),
  };
}

std::vector<SchemaRow> AllRows() {
  std::vector<SchemaRow> rows;
  for (auto part :
       {TopLevel, DrapeTest, Mesh, Material, Lines, Springs, FiniteVolume, Kes, Fast, BendingLength,
        Regions, NodeSelections, Fixed, Loads, Forces, Obstacles, ContactSolverOutput}) {
    for (SchemaRow& row : part()) rows.push_back(std::move(row));
  }
  return rows;
}

std::string Cell(const std::string& text) { return text.empty() ? "" : " " + text; }

// "[3] m, > 0": the type, the unit and the range in one cell.
std::string TypeCell(const SchemaRow& row) {
  std::string text = row.type;
  if (!row.unit.empty() && row.unit != "1") text += (text.empty() ? "" : " ") + row.unit;
  if (!row.range.empty()) text += (text.empty() ? "" : ", ") + row.range;
  return text.empty() ? "number" : text;
}

std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

bool SchemaRange::Contains(double value) const {
  if (integer && value != std::floor(value)) return false;
  const bool above = lower_inclusive ? value >= lower : value > lower;
  const bool below = upper_inclusive ? value <= upper : value < upper;
  return above && below;
}

std::string SchemaRange::Text() const {
  const bool below = std::isfinite(upper), above = std::isfinite(lower);
  if (above && below) {
    if (integer && upper < 1e6) return FormatNumber(lower) + "–" + FormatNumber(upper);
    return "in [" + FormatNumber(lower) + ", " + FormatNumber(upper) + "]";
  }
  if (above) return (lower_inclusive ? "≥ " : "> ") + FormatNumber(lower);
  if (below) return (upper_inclusive ? "≤ " : "< ") + FormatNumber(upper);
  return "";
}

std::string SchemaRange::Refusal(double value) const {
  const std::string got = ", got " + FormatNumber(value);
  if (integer && value != std::floor(value)) return "expected a whole number" + got;
  if (integer && lower_inclusive && upper_inclusive && upper == lower + 1) {
    return "must be " + FormatNumber(lower) + " or " + FormatNumber(upper) + got;
  }
  const bool low = lower_inclusive ? value < lower : value <= lower;
  if (low && lower == 0)
    return (lower_inclusive ? "must not be negative" : "must be positive") + got;
  if (low && lower_inclusive) return "must be at least " + FormatNumber(lower) + got;
  if (low) return "must be greater than " + FormatNumber(lower) + got;
  return (upper_inclusive ? "must be at most " : "must be less than ") + FormatNumber(upper) + got;
}

SchemaRange Above(double bound) {
  SchemaRange range;
  range.lower = bound;
  return range;
}

SchemaRange AtLeast(double bound) {
  SchemaRange range = Above(bound);
  range.lower_inclusive = true;
  return range;
}

SchemaRange Between(double lower, double upper) {
  SchemaRange range = AtLeast(lower);
  range.upper = upper;
  range.upper_inclusive = true;
  return range;
}

SchemaRange Whole(SchemaRange range) {
  range.integer = true;
  return range;
}

bool SchemaRow::Takes(const std::string& kind) const {
  return kind.empty() || kinds.empty() ||
         std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

const std::vector<SchemaRow>& SceneSchema() {
  static const std::vector<SchemaRow> rows = AllRows();
  return rows;
}

std::vector<std::string> SchemaTables() {
  std::vector<std::string> tables;
  for (const SchemaRow& row : SceneSchema()) {
    if (std::find(tables.begin(), tables.end(), row.table) == tables.end()) {
      tables.push_back(row.table);
    }
  }
  return tables;
}

std::vector<std::string> SchemaKeys(const std::string& table, const std::string& kind) {
  std::vector<std::string> keys;
  for (const SchemaRow& row : SceneSchema()) {
    if (row.table != table || row.key.front() == '<' || !row.Takes(kind)) continue;
    if (std::find(keys.begin(), keys.end(), row.key) == keys.end()) keys.push_back(row.key);
  }
  return keys;
}

std::vector<const SchemaRow*> SchemaRows(const std::string& table) {
  std::vector<const SchemaRow*> rows;
  for (const SchemaRow& row : SceneSchema()) {
    if (row.table == table) rows.push_back(&row);
  }
  return rows;
}

const SchemaRow& SchemaRowOf(const std::string& table, const std::string& key,
                             const std::string& kind) {
  for (const SchemaRow& row : SceneSchema()) {
    if (row.table == table && row.key == key && row.Takes(kind)) return row;
  }
  assert(false && "a key without its schema row");
  return SceneSchema().front();
}

const SchemaRow* SchemaRowAt(const std::string& path) {
  std::vector<std::string> parts;  // without list indices
  size_t start = 0;
  while (start <= path.size()) {
    const size_t dot = std::min(path.find('.', start), path.size());
    const std::string part = path.substr(start, dot - start);
    parts.push_back(part.substr(0, part.find('[')));
    start = dot + 1;
  }
  if (parts.size() > 2 && parts[0] == "obstacles") parts.erase(parts.begin() + 1);  // the kind
  const auto nodes = std::find(parts.begin() + 1, parts.end(), "nodes");
  if (parts.size() > 1 && nodes != parts.end() && nodes + 1 != parts.end()) {
    parts.erase(parts.begin(), nodes);  // a node selection, anywhere
  }
  for (size_t count = parts.size(); count > 0; --count) {
    std::string ancestor;
    for (size_t k = 0; k < count; ++k) ancestor += (k == 0 ? "" : ".") + parts[k];
    for (const SchemaRow& row : SceneSchema()) {
      if (row.Path() == ancestor) return &row;
    }
  }
  return nullptr;
}

std::string SchemaUnit(const std::string& path) {
  const SchemaRow* row = SchemaRowAt(path);
  return row ? row->unit : "";
}

std::string SchemaMarkdown(const std::string& table) {
  const auto rows = SchemaRows(table);
  const bool kinds = std::any_of(rows.begin(), rows.end(),
                                 [](const SchemaRow* row) { return !row->kinds.empty(); });
  std::string text =
      kinds ? "| key | applies to | type, unit | default | meaning |\n|---|---|---|---|---|\n"
            : "| key | type, unit | default | meaning |\n|---|---|---|---|\n";
  for (const SchemaRow* row : rows) {
    text += "| `" + row->key + "` |";
    if (kinds) text += Cell(row->kinds.empty() ? "all" : Joined(row->kinds)) + " |";
    text += Cell(TypeCell(*row)) + " |" + Cell(row->default_text) + " |" + Cell(row->doc) + " |\n";
  }
  return text;
}

}  // namespace drape
