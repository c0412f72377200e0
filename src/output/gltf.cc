#include "src/output/gltf.h"

#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "src/output/render.h"
#include "src/output/surface_fields.h"
#include "src/output/version.h"

namespace drape {

namespace {

// drape's (x, y, z), z up, in glTF's axes, +Y up.
Eigen::Vector3f GltfAxes(const Eigen::Vector3d& v) {
  return Eigen::Vector3f(static_cast<float>(v.x()), static_cast<float>(v.z()),
                         static_cast<float>(-v.y()));
}

// The buffer, its views and accessors of one glTF model, built up array by array.
class GltfArrays {
 public:
  explicit GltfArrays(tinygltf::Model* model) : model_(model) { model_->buffers.emplace_back(); }

  // An accessor of `count` elements of `components` floats each (type: TINYGLTF_TYPE_*), with
  // its per-component min and max where `bounds` (glTF requires them for POSITION).
  int Floats(const std::vector<float>& values, int components, int type, bool bounds) {
    assert(components > 0 && values.size() % components == 0);
    tinygltf::Accessor accessor;
    accessor.bufferView =
        View(values.data(), values.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.count = values.size() / components;
    accessor.type = type;
    if (bounds) {
      accessor.minValues.assign(components, INFINITY);
      accessor.maxValues.assign(components, -INFINITY);
      for (size_t k = 0; k < values.size(); ++k) {
        double& low = accessor.minValues[k % components];
        double& high = accessor.maxValues[k % components];
        low = std::min(low, static_cast<double>(values[k]));
        high = std::max(high, static_cast<double>(values[k]));
      }
    }
    model_->accessors.push_back(accessor);
    return static_cast<int>(model_->accessors.size()) - 1;
  }

  int Indices(const std::vector<std::uint32_t>& indices) {
    tinygltf::Accessor accessor;
    accessor.bufferView = View(indices.data(), indices.size() * sizeof(std::uint32_t),
                               TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.count = indices.size();
    accessor.type = TINYGLTF_TYPE_SCALAR;
    model_->accessors.push_back(accessor);
    return static_cast<int>(model_->accessors.size()) - 1;
  }

 private:
  // A view of `bytes` appended to the buffer at a multiple of 4 bytes (glTF's alignment).
  int View(const void* bytes, size_t size, int target) {
    std::vector<unsigned char>& data = model_->buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    data.resize(data.size() + size);
    if (size > 0) std::memcpy(data.data() + view.byteOffset, bytes, size);
    model_->bufferViews.push_back(view);
    return static_cast<int>(model_->bufferViews.size()) - 1;
  }

  tinygltf::Model* model_;
};

// A material of one colour, matte, both faces lit.
int AddMaterial(const std::string& name, const std::vector<double>& colour,
                tinygltf::Model* model) {
  tinygltf::Material material;
  material.name = name;
  material.pbrMetallicRoughness.baseColorFactor = {colour[0], colour[1], colour[2], 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.9;
  material.doubleSided = true;
  model->materials.push_back(material);
  return static_cast<int>(model->materials.size()) - 1;
}

// A node holding one mesh of one primitive, added to the scene.
void AddMeshNode(const std::string& name, const tinygltf::Primitive& primitive,
                 tinygltf::Model* model) {
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(primitive);
  model->meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = name;
  node.mesh = static_cast<int>(model->meshes.size()) - 1;
  model->nodes.push_back(node);
  model->scenes[0].nodes.push_back(static_cast<int>(model->nodes.size()) - 1);
}

void AppendPoint(const Eigen::Vector3d& point, std::vector<float>* positions) {
  const Eigen::Vector3f p = GltfAxes(point);
  positions->insert(positions->end(), p.data(), p.data() + 3);
}

// A node of one primitive in one colour: `positions` (glTF's axes, 3 per vertex), `normals`
// (the same, or empty) and `indices` drawn as `mode` (TINYGLTF_MODE_*).
void AddShapeNode(const std::string& name, const std::vector<float>& positions,
                  const std::vector<float>& normals, const std::vector<std::uint32_t>& indices,
                  int mode, const std::vector<double>& colour, GltfArrays* arrays,
                  tinygltf::Model* gltf) {
  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = arrays->Floats(positions, 3, TINYGLTF_TYPE_VEC3, true);
  if (!normals.empty()) {
    primitive.attributes["NORMAL"] = arrays->Floats(normals, 3, TINYGLTF_TYPE_VEC3, false);
  }
  primitive.indices = arrays->Indices(indices);
  primitive.mode = mode;
  primitive.material = AddMaterial(name, colour, gltf);
  AddMeshNode(name, primitive, gltf);
}

// The fields of GltfFields(), one value per node each, in its order.
std::vector<std::vector<float>> FieldValues(const Model& model, const RunResult& result) {
  const std::vector<double> stretch = VertexAreaStretch(model);
  const std::vector<double>& contact = result.certificate.contact_forces;
  const bool known_start = model.initial.size() == model.positions.size();
  std::vector<std::vector<float>> fields(GltfFields().size(),
                                         std::vector<float>(model.num_nodes, 0.0f));
  for (int k = 0; k < model.num_nodes; ++k) {
    const Eigen::Vector3d x = model.position(k);
    fields[0][k] = static_cast<float>(x.z());
    if (known_start) fields[1][k] = static_cast<float>((x - model.initial_position(k)).norm());
    fields[2][k] = static_cast<float>(stretch[k]);
    if (contact.size() == model.positions.size()) {
      const double force = NodeAt(contact, k).norm();
      if (std::isfinite(force)) fields[3][k] = static_cast<float>(force);
    }
    fields[4][k] =
        static_cast<float>(model.fixed[3 * k] + model.fixed[3 * k + 1] + model.fixed[3 * k + 2]) /
        3.0f;
  }
  return fields;
}

// The lowest and the highest node's height z, m.
std::pair<double, double> HeightRange(const Model& model) {
  double low = INFINITY, high = -INFINITY;
  for (int k = 0; k < model.num_nodes; ++k) {
    low = std::min(low, model.position(k).z());
    high = std::max(high, model.position(k).z());
  }
  return {low, high};
}

// COLOR_0 of the fabric: its height from blue (lowest) to sand (highest), as drape.png's two
// faces are coloured.
std::vector<float> HeightColours(const Model& model) {
  const auto [low, high] = HeightRange(model);
  const Eigen::Vector3f blue(0.29f, 0.53f, 0.86f), sand(0.87f, 0.75f, 0.55f);
  std::vector<float> colours;
  colours.reserve(3 * model.num_nodes);
  for (int k = 0; k < model.num_nodes; ++k) {
    const float t =
        high > low ? static_cast<float>((model.position(k).z() - low) / (high - low)) : 0.5f;
    const Eigen::Vector3f colour = (1.0f - t) * blue + t * sand;
    colours.insert(colours.end(), colour.data(), colour.data() + 3);
  }
  return colours;
}

void AddFabric(const Model& model, const RunResult& result, GltfArrays* arrays,
               tinygltf::Model* gltf) {
  std::vector<float> positions, normals, pattern;
  for (int k = 0; k < model.num_nodes; ++k) AppendPoint(model.position(k), &positions);
  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = arrays->Floats(positions, 3, TINYGLTF_TYPE_VEC3, true);
  std::vector<std::uint32_t> indices;
  if (!model.triangles.empty()) {
    for (const Eigen::Vector3d& n : VertexNormals(model)) {
      // A node in no triangle has no normal: glTF's NORMAL must be of unit length.
      const Eigen::Vector3f m = n.norm() > 0.0 ? GltfAxes(n) : Eigen::Vector3f(0.0f, 1.0f, 0.0f);
      normals.insert(normals.end(), m.data(), m.data() + 3);
    }
    for (const auto& [u, v] : PatternCoordinates(model)) {
      pattern.push_back(static_cast<float>(u));
      pattern.push_back(static_cast<float>(1.0 - v));  // glTF's texture origin is top left
    }
    primitive.attributes["NORMAL"] = arrays->Floats(normals, 3, TINYGLTF_TYPE_VEC3, false);
    primitive.attributes["TEXCOORD_0"] = arrays->Floats(pattern, 2, TINYGLTF_TYPE_VEC2, false);
    for (const auto& t : model.triangles) indices.insert(indices.end(), t.begin(), t.end());
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
  } else if (!model.edges.empty()) {
    for (const auto& e : model.edges) indices.insert(indices.end(), e.begin(), e.end());
    primitive.mode = TINYGLTF_MODE_LINE;
  } else {
    for (int k = 0; k < model.num_nodes; ++k) indices.push_back(k);
    primitive.mode = TINYGLTF_MODE_POINTS;
  }
  primitive.attributes["COLOR_0"] =
      arrays->Floats(HeightColours(model), 3, TINYGLTF_TYPE_VEC3, false);
  const std::vector<std::vector<float>> fields = FieldValues(model, result);
  for (size_t f = 0; f < fields.size(); ++f) {
    primitive.attributes[GltfFields()[f].attribute] =
        arrays->Floats(fields[f], 1, TINYGLTF_TYPE_SCALAR, true);
  }
  primitive.indices = arrays->Indices(indices);
  primitive.material = AddMaterial("fabric", {1.0, 1.0, 1.0}, gltf);  // COLOR_0 gives its colour
  AddMeshNode("fabric", primitive, gltf);
}

// Each obstacle polygon as a fan of triangles, all in one mesh.
void AddObstacles(const Scene& scene, const Model& model, GltfArrays* arrays,
                  tinygltf::Model* gltf) {
  const std::vector<std::vector<Eigen::Vector3d>> polygons = ObstaclePolygons(scene, model);
  if (polygons.empty()) return;
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
  for (const auto& polygon : polygons) {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (size_t k = 1; k + 1 < polygon.size(); ++k) {
      normal += (polygon[k] - polygon[0]).cross(polygon[k + 1] - polygon[0]);
    }
    if (!(normal.norm() > 0.0)) continue;  // a degenerate polygon has no face to draw
    const Eigen::Vector3f n = GltfAxes(normal.normalized());
    const auto first = static_cast<std::uint32_t>(positions.size() / 3);
    for (const Eigen::Vector3d& corner : polygon) {
      const Eigen::Vector3f p = GltfAxes(corner);
      positions.insert(positions.end(), p.data(), p.data() + 3);
      normals.insert(normals.end(), n.data(), n.data() + 3);
    }
    for (std::uint32_t k = 1; k + 1 < polygon.size(); ++k) {
      indices.insert(indices.end(), {first, first + k, first + k + 1});
    }
  }
  if (indices.empty()) return;
  AddShapeNode("obstacles", positions, normals, indices, TINYGLTF_MODE_TRIANGLES,
               {0.62, 0.62, 0.60}, arrays, gltf);
}

// The shadow's outline r(θ) at height `z`, drape's axes.
Eigen::Vector3d OutlinePoint(const RadialProfile& profile, int k, double radius, double z) {
  return {profile.centre[0] + radius * std::cos(profile.theta[k]),
          profile.centre[1] + radius * std::sin(profile.theta[k]), z};
}

// The height of the shadow and the crests: a hundredth of the drape's extent below its lowest
// node; and that extent.
std::pair<double, double> ShadowHeightAndExtent(const Model& model, const DrapeAnalysis& drape) {
  const auto [low, high] = HeightRange(model);
  const double extent = std::max(high - low, 2.0 * drape.radius_max);
  return {low - 0.01 * extent, extent};
}

// The shadow: a fan about the profile's centre, counter-clockwise seen from above (its face
// looks up).
void AddShadow(const DrapeAnalysis& drape, double z, GltfArrays* arrays, tinygltf::Model* gltf) {
  const RadialProfile& profile = drape.profile;
  const int rays = static_cast<int>(profile.radius.size());
  std::vector<float> positions;
  AppendPoint({profile.centre[0], profile.centre[1], z}, &positions);
  for (int k = 0; k < rays; ++k) {
    AppendPoint(OutlinePoint(profile, k, profile.radius[k], z), &positions);
  }
  std::vector<std::uint32_t> fan;
  for (int k = 0; k < rays; ++k) {
    fan.insert(fan.end(), {0u, static_cast<std::uint32_t>(1 + k),
                           static_cast<std::uint32_t>(1 + (k + 1) % rays)});
  }
  AddShapeNode("shadow", positions, {}, fan, TINYGLTF_MODE_TRIANGLES, {0.80, 0.80, 0.80}, arrays,
               gltf);
}

// A line at each fold crest's angle from the disc's rim (or the centre) to the outline, just
// above the shadow so that it is not hidden in it.
void AddCrests(const DrapeAnalysis& drape, double z, GltfArrays* arrays, tinygltf::Model* gltf) {
  const RadialProfile& profile = drape.profile;
  const int rays = static_cast<int>(profile.radius.size());
  std::vector<float> positions;
  for (double angle : drape.folds.angles_deg) {
    const int k = static_cast<int>(std::lround(angle / 360.0 * rays)) % rays;
    AppendPoint(OutlinePoint(profile, k, drape.disc_radius, z), &positions);
    AppendPoint(OutlinePoint(profile, k, profile.radius[k], z), &positions);
  }
  std::vector<std::uint32_t> lines(positions.size() / 3);
  for (std::uint32_t k = 0; k < lines.size(); ++k) lines[k] = k;
  AddShapeNode("fold crests", positions, {}, lines, TINYGLTF_MODE_LINE, {0.85, 0.10, 0.10}, arrays,
               gltf);
}

void AddShadowAndCrests(const Model& model, const DrapeAnalysis& drape, GltfArrays* arrays,
                        tinygltf::Model* gltf) {
  const RadialProfile& profile = drape.profile;
  if (profile.radius.size() < 3 || profile.theta.size() != profile.radius.size()) return;
  const auto [z, extent] = ShadowHeightAndExtent(model, drape);
  AddShadow(drape, z, arrays, gltf);
  if (!drape.folds.angles_deg.empty()) AddCrests(drape, z + 0.002 * extent, arrays, gltf);
}

tinygltf::Value SceneExtras(const Scene& scene, const Provenance& provenance) {
  tinygltf::Value::Object units;
  for (const GltfField& field : GltfFields()) units[field.attribute] = tinygltf::Value(field.unit);
  tinygltf::Value::Object extras;
  extras["drape_scene"] = tinygltf::Value(scene.name);
  extras["provenance"] = tinygltf::Value(ProvenanceLine(provenance));
  extras["field_units"] = tinygltf::Value(units);
  return tinygltf::Value(extras);
}

}  // namespace

const std::vector<GltfField>& GltfFields() {
  static const std::vector<GltfField> fields = {
      {"_HEIGHT", "m", "the node's height z as solved (drape's axes, z up)"},
      {"_DISPLACEMENT", "m", "the node's distance from where it started"},
      {"_AREA_STRETCH", "1",
       "the area of the node's triangles over their area at the start, minus 1"},
      {"_CONTACT_FORCE", "N", "the magnitude of the obstacles' force on the node"},
      {"_FIXED", "1", "the share of the node's coordinates that are prescribed (0, 1/3, 2/3, 1)"},
  };
  return fields;
}

void WriteGlb(const Scene& scene, const Model& model, const SolveReport& report,
              const Provenance& provenance, std::ostream& out) {
  assert(model.num_nodes > 0);
  tinygltf::Model gltf;
  gltf.asset.version = "2.0";
  gltf.asset.generator = "drape " + DrapeVersion();
  gltf.scenes.emplace_back();
  gltf.scenes[0].name = scene.name;
  gltf.scenes[0].extras = SceneExtras(scene, provenance);
  gltf.defaultScene = 0;
  GltfArrays arrays(&gltf);
  AddFabric(model, report.result, &arrays, &gltf);
  AddObstacles(scene, model, &arrays, &gltf);
  if (report.drape) AddShadowAndCrests(model, *report.drape, &arrays, &gltf);
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&gltf, out, /*prettyPrint=*/false, /*writeBinary=*/true)) {
    throw std::runtime_error("tinygltf could not write the glTF file");
  }
}

}  // namespace drape
