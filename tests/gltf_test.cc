// drape.glb (src/output/gltf.h), read back by tinygltf's loader: the same vertex positions (in
// glTF's +Y-up axes), unit normals, the triangles as written, every field, the obstacles, a chain
// as lines, and a 10,000-node drape within 2 MB.
#include "src/output/gltf.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>

#include "tests/test_scenes.h"

namespace drape {
namespace {

// The glTF file's bytes as written, and the model tinygltf reads from them.
struct WrittenGlb {
  std::string bytes;
  tinygltf::Model gltf;
};

WrittenGlb WriteAndRead(const Scene& scene, const Model& model) {
  std::ostringstream out;
  WriteGlb(scene, model, SolveReport{}, Provenance{"drape solve test.yaml", {}}, out);
  WrittenGlb written;
  written.bytes = out.str();
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  const bool read = loader.LoadBinaryFromMemory(
      &written.gltf, &error, &warning, reinterpret_cast<const unsigned char*>(written.bytes.data()),
      static_cast<unsigned int>(written.bytes.size()));
  EXPECT_TRUE(read) << error;
  EXPECT_EQ(warning, "");
  return written;
}

// The accessor's values as doubles, component by component.
template <typename Stored>
std::vector<double> Values(const tinygltf::Model& gltf, int accessor_index) {
  const tinygltf::Accessor& accessor = gltf.accessors.at(accessor_index);
  const tinygltf::BufferView& view = gltf.bufferViews.at(accessor.bufferView);
  const int components = tinygltf::GetNumComponentsInType(accessor.type);
  const unsigned char* data =
      gltf.buffers.at(view.buffer).data.data() + view.byteOffset + accessor.byteOffset;
  std::vector<double> values(accessor.count * components);
  for (size_t k = 0; k < values.size(); ++k) {
    Stored value;
    std::memcpy(&value, data + k * sizeof(Stored), sizeof(Stored));
    values[k] = static_cast<double>(value);
  }
  return values;
}

const tinygltf::Primitive& PrimitiveOf(const tinygltf::Model& gltf, const std::string& node) {
  for (const tinygltf::Node& n : gltf.nodes) {
    if (n.name == node) return gltf.meshes.at(n.mesh).primitives.at(0);
  }
  ADD_FAILURE() << "no node " << node;
  static const tinygltf::Primitive none;
  return none;
}

// The sphere scene on an 11 × 11 lattice, its sheet bent into a dome so that every axis matters.
testing::Solved DomeOverTheSphere() {
  testing::Solved solved{
      testing::LoadConfig("configs/fv/sphere.yaml", {"mesh.nodes=[11, 11]"}), {}, {}};
  solved.model = BuildModel(solved.scene);
  for (int k = 0; k < solved.model.num_nodes; ++k) {
    Eigen::Map<Eigen::Vector3d> x = solved.model.position(k);
    x.z() += 0.05 - 0.5 * (x.x() * x.x() + 0.7 * x.y() * x.y());
  }
  return solved;
}

TEST(Gltf, ThePositionsNormalsAndTrianglesReadBackAsWritten) {
  const testing::Solved dome = DomeOverTheSphere();
  const Model& model = dome.model;
  const WrittenGlb written = WriteAndRead(dome.scene, model);
  const tinygltf::Model& gltf = written.gltf;
  EXPECT_EQ(gltf.asset.version, "2.0");
  const tinygltf::Primitive& fabric = PrimitiveOf(gltf, "fabric");
  EXPECT_EQ(fabric.mode, TINYGLTF_MODE_TRIANGLES);

  const std::vector<double> positions = Values<float>(gltf, fabric.attributes.at("POSITION"));
  ASSERT_EQ(positions.size(), 3u * model.num_nodes);
  for (int k = 0; k < model.num_nodes; ++k) {  // glTF's (x, y, z) is drape's (x, z, −y)
    const Eigen::Vector3d x = model.position(k);
    EXPECT_NEAR(positions[3 * k], x.x(), 1e-7);
    EXPECT_NEAR(positions[3 * k + 1], x.z(), 1e-7);
    EXPECT_NEAR(positions[3 * k + 2], -x.y(), 1e-7);
  }
  const std::vector<double> normals = Values<float>(gltf, fabric.attributes.at("NORMAL"));
  ASSERT_EQ(normals.size(), positions.size());
  for (int k = 0; k < model.num_nodes; ++k) {
    EXPECT_NEAR(std::hypot(normals[3 * k], normals[3 * k + 1], normals[3 * k + 2]), 1.0, 1e-6);
    EXPECT_GT(normals[3 * k + 1], 0.0) << "the dome's outer face was up on the flat sheet";
  }
  const std::vector<double> indices = Values<std::uint32_t>(gltf, fabric.indices);
  ASSERT_EQ(indices.size(), 3 * model.triangles.size());
  for (size_t t = 0; t < model.triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(indices[3 * t + c], model.triangles[t][c]);
  }
}

TEST(Gltf, EveryFieldIsAnAttributeWithItsUnit) {
  const testing::Solved dome = DomeOverTheSphere();
  const WrittenGlb written = WriteAndRead(dome.scene, dome.model);
  const tinygltf::Primitive& fabric = PrimitiveOf(written.gltf, "fabric");
  const tinygltf::Value& units = written.gltf.scenes.at(0).extras.Get("field_units");
  for (const GltfField& field : GltfFields()) {
    ASSERT_EQ(fabric.attributes.count(field.attribute), 1u) << field.attribute;
    const std::vector<double> values =
        Values<float>(written.gltf, fabric.attributes.at(field.attribute));
    EXPECT_EQ(values.size(), static_cast<size_t>(dome.model.num_nodes)) << field.attribute;
    EXPECT_EQ(units.Get(field.attribute).Get<std::string>(), field.unit);
  }
  const std::vector<double> height = Values<float>(written.gltf, fabric.attributes.at("_HEIGHT"));
  for (int k = 0; k < dome.model.num_nodes; ++k) {
    EXPECT_NEAR(height[k], dome.model.position(k).z(), 1e-7);
  }
  // The nodes held in x and y near the apex (the scene's `fixed`) have two thirds of theirs fixed.
  const std::vector<double> fixed = Values<float>(written.gltf, fabric.attributes.at("_FIXED"));
  for (int k = 0; k < dome.model.num_nodes; ++k) {
    const int count =
        dome.model.fixed[3 * k] + dome.model.fixed[3 * k + 1] + dome.model.fixed[3 * k + 2];
    EXPECT_NEAR(fixed[k], count / 3.0, 1e-7);
  }
  EXPECT_EQ(written.gltf.scenes.at(0).extras.Get("drape_scene").Get<std::string>(), "sphere");
}

// The sphere obstacle as drape.png draws it: facets all at its radius from its centre.
TEST(Gltf, TheObstaclesAreItsSurfaces) {
  const testing::Solved dome = DomeOverTheSphere();
  const WrittenGlb written = WriteAndRead(dome.scene, dome.model);
  const tinygltf::Primitive& obstacles = PrimitiveOf(written.gltf, "obstacles");
  const std::vector<double> corners =
      Values<float>(written.gltf, obstacles.attributes.at("POSITION"));
  ASSERT_GT(corners.size(), 3u * 50);
  const ObstacleSpec& ball = dome.scene.obstacles.at(0);
  const Eigen::Vector3d centre = ball.center;
  for (size_t k = 0; k < corners.size(); k += 3) {
    const Eigen::Vector3d corner(corners[k], -corners[k + 2], corners[k + 1]);  // back to z up
    EXPECT_NEAR((corner - centre).norm(), ball.radius, 1e-6);
  }
}

TEST(Gltf, AChainIsLines) {
  testing::Solved chain{testing::LoadConfig("configs/examples/chain.yaml"), {}, {}};
  chain.model = BuildModel(chain.scene);
  const WrittenGlb written = WriteAndRead(chain.scene, chain.model);
  const tinygltf::Primitive& fabric = PrimitiveOf(written.gltf, "fabric");
  EXPECT_EQ(fabric.mode, TINYGLTF_MODE_LINE);
  EXPECT_EQ(Values<std::uint32_t>(written.gltf, fabric.indices).size(),
            2 * chain.model.edges.size());
}

// A drape's shadow (its outline r(θ) as a fan about the centre) and its fold crests (a line from
// the disc's rim to the outline at each crest's angle), below the fabric.
TEST(Gltf, ADrapesShadowAndFoldCrestsAreBelowIt) {
  testing::Solved dome = DomeOverTheSphere();
  SolveReport report;
  DrapeAnalysis drape;
  drape.disc_radius = 0.05;
  for (int k = 0; k < 36; ++k) {
    drape.profile.theta.push_back(2.0 * M_PI * k / 36);
    drape.profile.radius.push_back(0.15 + 0.02 * std::cos(6.0 * 2.0 * M_PI * k / 36));
  }
  drape.radius_max = 0.17;
  drape.folds.count = 2;
  drape.folds.angles_deg = {0.0, 60.0};
  report.drape = drape;
  std::ostringstream out;
  WriteGlb(dome.scene, dome.model, report, Provenance{}, out);
  const std::string bytes = out.str();
  tinygltf::Model gltf;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(
      &gltf, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
      static_cast<unsigned int>(bytes.size())))
      << error;
  double lowest = INFINITY;
  for (int k = 0; k < dome.model.num_nodes; ++k) {
    lowest = std::min(lowest, dome.model.position(k).z());
  }
  const std::vector<double> shadow =
      Values<float>(gltf, PrimitiveOf(gltf, "shadow").attributes.at("POSITION"));
  ASSERT_EQ(shadow.size(), 3u * 37);  // the centre and one point per ray
  for (int k = 0; k < 36; ++k) {
    const double x = shadow[3 * (k + 1)], y = -shadow[3 * (k + 1) + 2];
    EXPECT_NEAR(std::hypot(x, y), drape.profile.radius[k], 1e-6);
    EXPECT_LT(shadow[3 * (k + 1) + 1], lowest);
  }
  const tinygltf::Primitive& crests = PrimitiveOf(gltf, "fold crests");
  EXPECT_EQ(crests.mode, TINYGLTF_MODE_LINE);
  const std::vector<double> ends = Values<float>(gltf, crests.attributes.at("POSITION"));
  ASSERT_EQ(ends.size(), 3u * 4);
  EXPECT_NEAR(ends[0], 0.05, 1e-6);  // the first crest, at 0°, from the rim
  EXPECT_NEAR(ends[3], 0.17, 1e-6);  // to the outline
  EXPECT_NEAR(std::atan2(-ends[11], ends[9]), M_PI / 3, 1e-6);  // the second at 60°
}

// 101 × 101 nodes: the file stays under the 2 MB that a viewer in a web page loads at once.
TEST(Gltf, ATenThousandNodeDrapeIsUnderTwoMegabytes) {
  testing::Solved sheet{
      testing::LoadConfig("configs/fv/sphere.yaml", {"mesh.nodes=[101, 101]"}), {}, {}};
  sheet.model = BuildModel(sheet.scene);
  ASSERT_GE(sheet.model.num_nodes, 10000);
  EXPECT_LT(WriteAndRead(sheet.scene, sheet.model).bytes.size(), 2'000'000u);
}

}  // namespace
}  // namespace drape
