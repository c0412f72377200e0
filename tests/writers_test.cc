// The result files: each one reads back, consistent with the RunResult it was written from.
// summary.json is read back with yaml-cpp (JSON is YAML), the tables line by line.
#include "src/output/writers.h"

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "costs/constant_force_potential.h"
#include "costs/spring_stretch.h"
#include "src/model/equilibrium.h"
#include "tests/folded_skirt.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// A 2×2 sheet (ids j*2 + i), top row fixed, node 0 held in z only, slightly off its start.
Model SmallSheet() {
  Model model;
  model.num_nodes = 4;
  model.initial = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  model.positions = model.initial;
  model.positions[4] = 0.01;   // node 1 moves in y
  model.positions[5] = -0.03;  // and down
  model.mass = {0.1, 0.1, 0.1, 0.1};
  model.fixed = {0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  model.grid_index = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  model.triangles = {{0, 1, 3}, {0, 3, 2}};
  model.applied.assign(12, 0.0);
  const int springs[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
  for (const auto& spring : springs) {
    model.terms.push_back(
        MakeTerm("structural", {spring[0], spring[1]}, SpringStretch::Create(100.0, 1.0)));
  }
  for (int node = 0; node < 4; ++node) {
    const double weight[3] = {0, 0, -0.981};
    model.applied[3 * node + 2] = weight[2];
    model.terms.push_back(MakeTerm(
        "gravity", {node}, ConstantForcePotential::Create(weight, &model.initial[3 * node])));
  }
  return model;
}

// WriteOutputs of a state already solved.
void WriteReported(const Scene& scene, const Model& model, const RunResult& result,
                   const std::string& directory) {
  WriteOutputs(scene, model, ReportOf(scene, model, result), directory);
}

RunResult ResultOf(const Model& model) {
  RunResult result;
  result.certificate = ComputeCertificate(model, model.positions.data());
  result.summary.solver = "test-solver";
  result.summary.termination = "stopped: a \"quoted\" word,\na tab\t and a backslash \\";
  result.summary.iterations = 3;
  result.summary.wall_time_s = 0.125;
  for (int k = 0; k <= 3; ++k) {
    result.summary.history.push_back({k, 0.03 * k, -0.5 - 0.1 * k, std::pow(10.0, -2 * k)});
  }
  result.summary.statistics["factorizations"] = 7;
  result.stability.computed = true;
  result.stability.stable = false;
  result.stability.min_eigenvalue = -0.25;
  result.converged = false;
  return result;
}

Scene SceneWriting(const std::vector<std::string>& write) {
  Scene scene;
  scene.name = "small \"sheet\"";
  scene.file = "configs/small.yaml";
  scene.solver.tolerance = 1e-9;
  scene.output.write = write;
  return scene;
}

class WritersTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 ("drape_writers_test_" + std::to_string(::getpid()) + "_" + test->name());
    fs::remove_all(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  std::string Path(const std::string& name) const { return (directory_ / name).string(); }

  // The result files (hidden names left out: the folder's .drape.lock stays there).
  std::set<std::string> Files() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_)) {
      const std::string name = entry.path().filename().string();
      if (name[0] != '.') names.insert(name);
    }
    return names;
  }

  fs::path directory_;
};

std::vector<std::string> Lines(const std::string& path) {
  std::ifstream file(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

TEST_F(WritersTest, SummaryJsonReadsBackWithTheValuesOfTheResult) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  const Scene scene = SceneWriting({"summary"});
  WriteReported(scene, model, result, directory_.string());

  const YAML::Node summary = YAML::LoadFile(Path("summary.json"));
  EXPECT_EQ(summary["scene"].as<std::string>(), scene.name);
  EXPECT_EQ(summary["solver"].as<std::string>(), "test-solver");
  EXPECT_FALSE(summary["converged"].as<bool>());
  EXPECT_EQ(summary["termination"].as<std::string>(), result.summary.termination);
  EXPECT_EQ(summary["iterations"].as<int>(), 3);
  EXPECT_EQ(summary["wall_time_s"].as<double>(), 0.125);
  EXPECT_EQ(summary["nodes"].as<int>(), 4);
  EXPECT_EQ(summary["free_dofs"].as<int>(), model.num_free_dofs());
  const auto terms = summary["terms"].as<std::map<std::string, int>>();
  EXPECT_EQ(terms, model.TermCounts());
  EXPECT_EQ(summary["energy"]["total"].as<double>(), result.certificate.energy);
  for (const auto& [type, energy] : result.certificate.energy_by_type) {
    EXPECT_EQ(summary["energy"][type].as<double>(), energy) << type;
  }
  EXPECT_EQ(summary["residual"]["max_node_force"].as<double>(), result.certificate.max_node_force);
  EXPECT_EQ(summary["residual"]["relative"].as<double>(), result.certificate.relative_residual);
  const auto reactions = summary["reactions"]["sum"].as<std::vector<double>>();
  ASSERT_EQ(reactions.size(), 3u);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(reactions[c], result.certificate.reaction_sum[c]);
  EXPECT_FALSE(summary["stable"].as<bool>());
  EXPECT_EQ(summary["min_eigenvalue"].as<double>(), -0.25);
  EXPECT_EQ(summary["tolerance"].as<double>(), 1e-9);
  EXPECT_EQ(summary["statistics"]["factorizations"].as<double>(), 7.0);
  EXPECT_EQ(Files(), std::set<std::string>{"summary.json"});
}

TEST_F(WritersTest, NonFiniteNumbersAndUnknownStabilityAreNull) {
  const Model model = SmallSheet();
  RunResult result = ResultOf(model);
  result.summary.wall_time_s = NAN;
  result.certificate.energy = INFINITY;
  result.stability = Stability{};  // not computed
  WriteReported(SceneWriting({"summary"}), model, result, directory_.string());

  const YAML::Node summary = YAML::LoadFile(Path("summary.json"));
  EXPECT_TRUE(summary["wall_time_s"].IsNull());
  EXPECT_TRUE(summary["energy"]["total"].IsNull());
  EXPECT_TRUE(summary["stable"].IsNull());
  EXPECT_FALSE(summary["min_eigenvalue"].IsDefined());
  EXPECT_TRUE(summary["residual"]["relative"].IsScalar());
}

TEST_F(WritersTest, NodesCsvHasOneFullPrecisionRowPerNode) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  WriteReported(SceneWriting({"nodes"}), model, result, directory_.string());

  const auto lines = Lines(Path("nodes.csv"));
  ASSERT_EQ(lines.size(), 1u + model.num_nodes);
  EXPECT_EQ(lines[0], "id,i,j,x,y,z,fixed,fx,fy,fz,contact_fx,contact_fy,contact_fz");
  const std::vector<std::string> letters = {"z", "", "xyz", "xyz"};
  for (int node = 0; node < model.num_nodes; ++node) {
    const auto fields = Fields(lines[node + 1]);
    ASSERT_EQ(fields.size(), 13u) << lines[node + 1];
    EXPECT_EQ(std::stoi(fields[0]), node);
    EXPECT_EQ(std::stoi(fields[1]), model.grid_index[node][0]);
    EXPECT_EQ(std::stoi(fields[2]), model.grid_index[node][1]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(std::stod(fields[3 + c]), model.positions[3 * node + c]);
      EXPECT_EQ(std::stod(fields[7 + c]), result.certificate.node_forces[3 * node + c]);
    }
    EXPECT_EQ(fields[6], letters[node]);
  }
}

TEST_F(WritersTest, HistoryCsvHasOneRowPerRecordedIteration) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  WriteReported(SceneWriting({"history"}), model, result, directory_.string());

  const auto lines = Lines(Path("history.csv"));
  ASSERT_EQ(lines.size(), 1 + result.summary.history.size());
  EXPECT_EQ(lines[0], "iteration,time_s,energy,residual");
  for (size_t k = 0; k < result.summary.history.size(); ++k) {
    const auto fields = Fields(lines[k + 1]);
    ASSERT_EQ(fields.size(), 4u);
    const IterationRecord& record = result.summary.history[k];
    EXPECT_EQ(std::stoi(fields[0]), record.iteration);
    EXPECT_EQ(std::stod(fields[1]), record.time_s);
    EXPECT_EQ(std::stod(fields[2]), record.energy);
    EXPECT_EQ(std::stod(fields[3]), record.relative_residual);
  }
  EXPECT_FALSE(fs::exists(Path("kinetic.csv")));  // only for methods that record a trace
}

TEST_F(WritersTest, TraceOfADynamicMethodGoesToKineticCsv) {
  const Model model = SmallSheet();
  RunResult result = ResultOf(model);
  result.summary.trace_columns = {"step", "t", "w_c"};
  result.summary.trace = {{0, 0.0, 1.5}, {1, 0.01, 0.75}};
  WriteReported(SceneWriting({"history"}), model, result, directory_.string());

  const auto lines = Lines(Path("kinetic.csv"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "step,t,w_c");
  EXPECT_EQ(std::stod(Fields(lines[2])[2]), 0.75);
}

TEST_F(WritersTest, VtkAndObjDescribeTheSameMesh) {
  Model model = SmallSheet();
  model.edges = {{0, 1}};
  const RunResult result = ResultOf(model);
  WriteReported(SceneWriting({"vtk", "obj"}), model, result, directory_.string());

  const auto vtk = Lines(Path("mesh.vtk"));
  ASSERT_GT(vtk.size(), 4u);
  EXPECT_EQ(vtk[0], "# vtk DataFile Version 3.0");
  EXPECT_EQ(vtk[2], "ASCII");
  EXPECT_EQ(vtk[3], "DATASET POLYDATA");
  auto find = [&vtk](const std::string& start) {
    for (size_t k = 0; k < vtk.size(); ++k) {
      if (vtk[k].rfind(start, 0) == 0) return static_cast<int>(k);
    }
    return -1;
  };
  const int points = find("POINTS 4 double");
  ASSERT_GE(points, 0);
  std::istringstream node1(vtk[points + 2]);
  double x, y, z;
  node1 >> x >> y >> z;
  EXPECT_EQ(y, model.positions[4]);
  EXPECT_EQ(z, model.positions[5]);
  const int polygons = find("POLYGONS 2 8");
  ASSERT_GE(polygons, 0);
  EXPECT_EQ(vtk[polygons + 1], "3 0 1 3");
  EXPECT_GE(find("LINES 1 3"), 0);
  EXPECT_GE(find("POINT_DATA 4"), 0);
  const int displacement = find("VECTORS displacement double");
  ASSERT_GE(displacement, 0);
  std::istringstream moved(vtk[displacement + 2]);
  moved >> x >> y >> z;
  EXPECT_EQ(z, model.positions[5] - model.initial[5]);
  EXPECT_GE(find("VECTORS force double"), 0);
  const int fixed = find("SCALARS fixed int 1");
  ASSERT_GE(fixed, 0);
  EXPECT_EQ(vtk[fixed + 2], "1");  // node 0: held in z
  EXPECT_EQ(vtk[fixed + 3], "0");  // node 1: free

  int vertices = 0, faces = 0, lines = 0;
  for (const auto& line : Lines(Path("mesh.obj"))) {
    vertices += line.rfind("v ", 0) == 0;
    faces += line.rfind("f ", 0) == 0;
    lines += line.rfind("l ", 0) == 0;
    if (line.rfind("f ", 0) == 0 && faces == 1) {
      EXPECT_EQ(line, "f 1 2 4");  // 1-based
    }
  }
  EXPECT_EQ(vertices, 4);
  EXPECT_EQ(faces, 2);
  EXPECT_EQ(lines, 1);
}

TEST_F(WritersTest, CreatesTheFolderAndLeavesNoTemporaryFile) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  directory_ /= "nested/deeper";
  WriteReported(SceneWriting({"summary", "nodes", "history", "vtk", "obj"}), model, result,
                directory_.string());
  EXPECT_EQ(Files(), (std::set<std::string>{"summary.json", "nodes.csv", "history.csv", "mesh.vtk",
                                            "mesh.obj"}));
  // Writing again replaces the files in place.
  WriteReported(SceneWriting({"summary", "nodes", "history", "vtk", "obj"}), model, result,
                directory_.string());
  EXPECT_EQ(Files().size(), 5u);
  directory_ = directory_.parent_path().parent_path();  // TearDown removes the whole tree
}

// A PNG's size and how many of its pixels are not the white background.
struct Picture {
  int width = 0, height = 0;
  double inked = 0.0;  // fraction of the pixels that are not white
};

Picture ReadPng(const std::string& path) {
  cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
  Picture picture;
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    picture.width = cairo_image_surface_get_width(surface);
    picture.height = cairo_image_surface_get_height(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    int inked = 0;
    for (int row = 0; row < picture.height; ++row) {
      const auto* pixels = reinterpret_cast<const uint32_t*>(data + row * stride);
      for (int column = 0; column < picture.width; ++column) {
        inked += (pixels[column] & 0xffffffu) != 0xffffffu;
      }
    }
    picture.inked = double(inked) / (picture.width * picture.height);
  }
  cairo_surface_destroy(surface);
  return picture;
}

// The hand-built 7-lobe skirt of tests/folded_skirt.h on an 18 cm disk.
Scene DrapeScene(const std::vector<std::string>& write) {
  Scene scene = SceneWriting(write);
  ObstacleSpec disk;
  disk.kind = "disk";
  disk.radius = 0.09;
  scene.obstacles.push_back(disk);
  return scene;
}

Model SevenFolds() {
  SkirtShape shape;
  shape.lobes = 7;
  return FoldedSkirt(shape);
}

RunResult Finished() {
  RunResult result;
  result.summary.solver = "hand-built";
  return result;
}

TEST_F(WritersTest, DrawsTheSheetInThreeDimensions) {
  const Model model = SmallSheet();
  WriteReported(SceneWriting({"png", "profile", "shadow"}), model, ResultOf(model),
                directory_.string());
  // No drape coefficient for a sheet: no profile, no shadow view.
  ASSERT_EQ(Files(), std::set<std::string>{"drape.png"});
  const Picture picture = ReadPng(Path("drape.png"));
  EXPECT_EQ(picture.width, 900);
  EXPECT_EQ(picture.height, 700);
  EXPECT_GT(picture.inked, 0.05);
}

TEST_F(WritersTest, DrawsAChainFromTheFront) {
  Model model;
  model.dimension = 2;
  model.num_nodes = 5;
  for (int k = 0; k < 5; ++k) {
    model.positions.insert(model.positions.end(), {0.25 * k, 0.0, -0.1 * (k * (4 - k))});
    if (k) model.edges.push_back({k - 1, k});
  }
  model.initial = model.positions;
  model.fixed = {1, 1, 1, 0, 1, 0, 0, 1, 0, 0, 1, 0, 1, 1, 1};
  model.mass.assign(5, 0.1);
  model.applied.assign(15, 0.0);
  model.grid_index.assign(5, {-1, -1});
  WriteReported(SceneWriting({"png"}), model, Finished(), directory_.string());
  const Picture picture = ReadPng(Path("drape.png"));
  EXPECT_EQ(picture.width, 900);
  EXPECT_GT(picture.inked, 0.005);
}

TEST_F(WritersTest, DrapeSceneGetsItsProfileFoldsAndPictures) {
  const Model model = SevenFolds();
  WriteReported(DrapeScene({"summary", "profile", "png"}), model, Finished(), directory_.string());
  EXPECT_EQ(Files(),
            (std::set<std::string>{"summary.json", "profile.csv", "drape.png", "shadow.png"}));

  const YAML::Node drape = YAML::LoadFile(Path("summary.json"))["drape"];
  EXPECT_EQ(drape["folds"].as<int>(), 7);
  EXPECT_EQ(drape["fold_angles_deg"].size(), 7u);
  EXPECT_NEAR(drape["radius_max_m"].as<double>(), 0.138, 1e-12);  // SkirtCrestRadius
  EXPECT_GT(drape["radius_min_m"].as<double>(), 0.09);
  EXPECT_LT(drape["radius_min_m"].as<double>(), drape["radius_mean_m"].as<double>());
  EXPECT_EQ(drape["profile_centre_m"].as<std::vector<double>>(), (std::vector<double>{0, 0}));

  const auto lines = Lines(Path("profile.csv"));
  ASSERT_EQ(lines.size(), 361u);
  EXPECT_EQ(lines[0],
            "theta_deg,radius_m,flat_radius_m,overhang_fraction,smoothed_overhang_fraction");
  const auto crest = Fields(lines[1]);
  ASSERT_EQ(crest.size(), 5u);
  EXPECT_EQ(std::stod(crest[0]), 0.0);
  EXPECT_NEAR(std::stod(crest[1]), 0.138, 1e-12);
  EXPECT_NEAR(std::stod(crest[2]), 0.15, 1e-12);
  EXPECT_NEAR(std::stod(crest[3]), (0.138 - 0.09) / (0.15 - 0.09), 1e-9);
  EXPECT_EQ(std::stod(Fields(lines[360])[0]), 359.0);

  const Picture shadow = ReadPng(Path("shadow.png"));
  EXPECT_EQ(shadow.width, 800);
  EXPECT_EQ(shadow.height, 800);
  EXPECT_GT(shadow.inked, 0.1);
  const Picture view = ReadPng(Path("drape.png"));
  EXPECT_EQ(view.width, 900);
  EXPECT_GT(view.inked, 0.1);
}

TEST_F(WritersTest, ShadowAloneWritesOnlyTheTopView) {
  WriteReported(DrapeScene({"shadow"}), SevenFolds(), Finished(), directory_.string());
  EXPECT_EQ(Files(), std::set<std::string>{"shadow.png"});
}

}  // namespace
}  // namespace drape
