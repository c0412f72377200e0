#include "src/scene/drape_tester.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "src/scene/drape_mesh_rule.h"
#include "src/scene/number_text.h"
#include "src/scene/scene_schema.h"
#include "src/scene/scene_size.h"
#include "src/scene/schema_reader.h"

namespace drape {
namespace {

// Standard gravity as the shipped tester scenes give it (m/s²).
constexpr double kTesterGravity = 9.81;
// The clamp is this much narrower than the disc unless given: a 5 mm ring of the specimen rests
// on the disc by contact inside its rim (m).
constexpr double kClampNarrowerThanDisc = 0.01;

std::string Centimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g cm", metres * 100.0);
  return text;
}

std::string Millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", metres * 1000.0);
  return text;
}

std::string Metres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", metres);
  return text;
}

// The circle lattice the loader chooses for `accuracy` (src/scene/drape_mesh_rule.h).
MeshSpec LatticeForAccuracy(const Scene& scene, double accuracy, double bending_length) {
  MeshSpec chosen = scene.mesh;
  chosen.spacing =
      std::min(SpacingForDrapeError(accuracy, bending_length, DrapeErrorPerSpacing(scene)),
               kCoarsestChosenSpacing);
  return chosen;
}

}  // namespace

const std::vector<std::string>& DrapeTestKeys() {
  static const std::vector<std::string> keys = SchemaKeys("drape_test");
  return keys;
}

const std::vector<std::string>& DrapeTestMeshKeys() {
  static const std::vector<std::string> keys = {"spacing", "max_nodes"};
  return keys;
}

double ClampDiameter(const DrapeTestSpec& test) {
  return test.clamp_diameter ? *test.clamp_diameter : test.disc_diameter - kClampNarrowerThanDisc;
}

DrapeTestSpec ReadDrapeTest(const YamlValue& value) {
  const YamlMap map(value, DrapeTestKeys());
  DrapeTestSpec test;
  test.where = value.where;
  ReadFields(map, "drape_test", &test);
  const YamlValue& at = map.value();
  test.accuracy_where = map.Has("accuracy") ? map.Get("accuracy").where : test.where;
  if (!(test.disc_diameter < test.specimen_diameter)) {
    Fail(map.Has("disc_diameter") ? map.Get("disc_diameter") : at,
         "the disc (" + Centimetres(test.disc_diameter) + ") must be smaller than the specimen (" +
             Centimetres(test.specimen_diameter) + ")");
  }
  const double clamp = ClampDiameter(test);
  if (!(clamp > 0.0 && clamp <= test.disc_diameter)) {
    Fail(map.Has("clamp_diameter") ? map.Get("clamp_diameter") : at,
         "the clamp (" + Centimetres(clamp) + ") must be positive and no wider than the disc (" +
             Centimetres(test.disc_diameter) + ")" +
             (test.clamp_diameter ? "" : "; give clamp_diameter for a disc this small"));
  }
  const double reach = test.offset.norm() + test.placement + test.disc_diameter / 2;
  if (!(reach < test.specimen_diameter / 2)) {
    Fail(map.Has("offset") ? map.Get("offset") : at,
         "the disc, moved by the offset (and the drops' placement scatter), reaches past the "
         "specimen's edge");
  }
  return test;
}

void ExpandDrapeTest(Scene* scene) {
  const DrapeTestSpec& test = *scene->drape_test;
  const double lift = scene->contact.thickness;
  Location where = test.where;
  MeshSpec& mesh = scene->mesh;
  mesh.kind = MeshSpec::Kind::kCircle;
  mesh.radius = test.specimen_diameter / 2;
  mesh.origin = Eigen::Vector3d(0.0, 0.0, lift);
  mesh.where = where;

  FixedSpec clamp;
  clamp.nodes.kind = NodeSelector::Kind::kWithin;
  clamp.nodes.center = Eigen::Vector3d(test.offset.x(), test.offset.y(), lift);
  clamp.nodes.radius = ClampDiameter(test) / 2;
  clamp.nodes.where = where;
  clamp.where = where;
  scene->fixed = {clamp};

  ObstacleSpec disc;
  disc.kind = "disk";
  disc.center = Eigen::Vector3d(test.offset.x(), test.offset.y(), 0.0);
  disc.radius = test.disc_diameter / 2;
  disc.given = {{"center", where}, {"radius", where}};
  disc.where = where;
  scene->obstacles = {disc};

  if (!scene->loads.gravity) scene->loads.gravity = Eigen::Vector3d(0.0, 0.0, -kTesterGravity);
}

void RequireTheMeshRuleForAnAccuracy(const Scene& scene) {
  const DrapeTestSpec& test = *scene.drape_test;
  if (!test.accuracy || LimperBendingLength(scene)) return;
  throw InputError(test.accuracy_where,
                   "the mesh rule, by which a run is held to an accuracy, covers a finite_volume "
                   "fabric with a bending rigidity and a density, under gravity "
                   "(docs/drape-tester.md): leave the accuracy out for this fabric");
}

void ChooseDrapeTestSpacing(Scene* scene) {
  DrapeTestSpec& test = *scene->drape_test;
  const std::optional<double> bending_length = LimperBendingLength(*scene);
  if (!bending_length) return;  // no rule for this fabric: the mesh's own default spacing
  const double accuracy = AskedDrapeAccuracy(*scene);
  const MeshSpec chosen = LatticeForAccuracy(*scene, accuracy, *bending_length);
  const double nodes = EstimatedNodes(chosen);
  if (nodes > chosen.max_nodes) {
    // The finest accuracy of two decimals whose lattice is within the limit, if one is.
    std::optional<double> reachable;
    for (int hundredths = static_cast<int>(std::ceil(accuracy * 100.0 - 1e-9));
         hundredths <= 100 * kMostDrapeError; ++hundredths) {
      const MeshSpec coarser = LatticeForAccuracy(*scene, hundredths / 100.0, *bending_length);
      if (EstimatedNodes(coarser) <= chosen.max_nodes) {
        reachable = hundredths / 100.0;
        break;
      }
    }
    char text[400];
    std::snprintf(text, sizeof text,
                  "an accuracy of %s needs a %s lattice for this fabric (bending length %s; the "
                  "mesh rule, docs/drape-tester.md), about %.3g nodes, above mesh.max_nodes %d: ",
                  FormatNumber(accuracy).c_str(), Millimetres(chosen.spacing).c_str(),
                  Millimetres(*bending_length).c_str(), nodes, chosen.max_nodes);
    throw InputError(test.accuracy_where,
                     text + (reachable ? "ask for " + FormatNumber(*reachable) +
                                             " or more, or raise mesh.max_nodes"
                                       : std::string("raise mesh.max_nodes")));
  }
  scene->mesh.spacing = chosen.spacing;
  test.spacing_chosen = true;
}

std::string DrapeTestText(const Scene& scene) {
  const DrapeTestSpec& test = *scene.drape_test;
  const ObstacleSpec& disc = scene.obstacles.front();
  const NodeSelector& clamp = scene.fixed.front().nodes;
  const Eigen::Vector3d& g = *scene.loads.gravity;
  std::string text = "drape test: specimen " + Centimetres(test.specimen_diameter) + ", disc " +
                     Centimetres(test.disc_diameter) + ", clamp " +
                     Centimetres(ClampDiameter(test)) + ", the disc's centre at (" +
                     Metres(test.offset.x()) + ", " + Metres(test.offset.y()) + ") m; " +
                     std::to_string(test.drops) + (test.drops == 1 ? " drop" : " drops");
  if (test.drops > 1) {
    text += " (seed " + std::to_string(test.seed) + ", placement within " + Metres(test.placement) +
            " m, waviness " + Metres(test.waviness) + " m)";
  }
  if (test.spacing_chosen) {
    text += "; mesh.spacing " + Millimetres(scene.mesh.spacing) + " chosen for an accuracy of " +
            FormatNumber(AskedDrapeAccuracy(scene)) + " (the mesh rule, bending length " +
            Millimetres(*LimperBendingLength(scene)) + ")";
  }
  text += "\nexpands to: mesh {kind: circle, radius: " + Metres(scene.mesh.radius) +
          ", spacing: " + Metres(scene.mesh.spacing) + ", origin: [0, 0, " +
          Metres(scene.mesh.origin.z()) + "]}; fixed: [{nodes: {within: {center: [" +
          Metres(clamp.center.x()) + ", " + Metres(clamp.center.y()) + ", " +
          Metres(clamp.center.z()) + "], radius: " + Metres(clamp.radius) +
          "}}}]; obstacles: [{disk: {center: [" + Metres(disc.center.x()) + ", " +
          Metres(disc.center.y()) + ", 0], radius: " + Metres(disc.radius) +
          "}}]; loads.gravity: [" + Metres(g.x()) + ", " + Metres(g.y()) + ", " + Metres(g.z()) +
          "]\n";
  return text;
}

}  // namespace drape
