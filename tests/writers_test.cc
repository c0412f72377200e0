// The result files: each one reads back, consistent with the RunResult it was written from.
// summary.json is read back with yaml-cpp (JSON is YAML), the tables line by line.
#include "src/output/writers.h"

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "costs/constant_force_potential.h"
#include "costs/spring_stretch.h"
#include "src/model/equilibrium.h"
#include "src/output/atomic_file.h"
#include "src/output/png_text.h"
#include "src/output/version.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"
#include "tests/folded_skirt.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

constexpr double kHalfPi = 1.57079632679489661923;

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
    scratch_.emplace("writers_test");
    directory_ = scratch_->path() / "result";  // not made: the writers make it
  }
  void TearDown() override { scratch_.reset(); }

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

  std::optional<testing::ScratchFolder> scratch_;
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
  // Not converged: however its Hessian looks, the state is not called a minimum.
  EXPECT_EQ(summary["state"].as<std::string>(),
            "not an equilibrium (most negative eigenvalue -0.25 N/m)");
  EXPECT_EQ(summary["min_eigenvalue"].as<double>(), -0.25);
  EXPECT_EQ(summary["tolerance"].as<double>(), 1e-9);
  EXPECT_EQ(summary["statistics"]["factorizations"].as<double>(), 7.0);
  EXPECT_EQ(Files(), (std::set<std::string>{"summary.json", "scene.yaml"}));
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
  EXPECT_EQ(lines[0],
            "id,i,j,x_m,y_m,z_m,fixed_x,fixed_y,fixed_z,in_contact,reaction_x_N,reaction_y_N,"
            "reaction_z_N,residual_x_N,residual_y_N,residual_z_N,contact_x_N,contact_y_N,"
            "contact_z_N");
  for (int node = 0; node < model.num_nodes; ++node) {
    const auto fields = Fields(lines[node + 1]);
    ASSERT_EQ(fields.size(), 19u) << lines[node + 1];
    EXPECT_EQ(std::stoi(fields[0]), node);
    EXPECT_EQ(std::stoi(fields[1]), model.grid_index[node][0]);
    EXPECT_EQ(std::stoi(fields[2]), model.grid_index[node][1]);
    EXPECT_EQ(fields[9], "false");  // no obstacle
    for (int c = 0; c < 3; ++c) {
      const int k = 3 * node + c;
      EXPECT_EQ(std::stod(fields[3 + c]), model.positions[k]);
      EXPECT_EQ(fields[6 + c], model.fixed[k] ? "true" : "false");  // as pandas reads booleans
      // The certificate's force: a reaction where the coordinate is fixed, else a residual.
      EXPECT_EQ(std::stod(fields[10 + c]), model.fixed[k] ? result.certificate.node_forces[k] : 0);
      EXPECT_EQ(std::stod(fields[13 + c]), model.fixed[k] ? 0 : result.certificate.node_forces[k]);
      EXPECT_EQ(std::stod(fields[16 + c]), 0.0);
    }
  }
}

// A drape tester whose clamp reaches nearly to the support disk's rim, on a 2 cm lattice with no
// node between the clamp (4.6 cm from the centre) and 1 mm beyond the rim (5.2 cm): the fabric
// rests on the disk only where its edges cross the rim (the edge contact, costs/edge_contact.h),
// with no node in the disk's clearance layer. summary.json's contact.nodes_in_contact counts the
// nodes nodes.csv marks in_contact (NodeInContact), not the nodes in a layer (none).
TEST_F(WritersTest, NodesInContactAgreeWhereTheEdgeContactAloneHoldsTheFabric) {
  const Scene scene = LoadSceneText(R"(name: rim
drape_test: {specimen_diameter: 0.2, disc_diameter: 0.104, clamp_diameter: 0.092, offset: [0, 0]}
mesh: {spacing: 0.02}
material:
  model: finite_volume
  density: 0.08
  finite_volume: {E_warp: 9000, E_weft: 8000, G: 20, D_warp: 2.6e-6, D_weft: 1.7e-6}
output: {write: [summary, nodes]}
)",
                                    "rim.yaml", scratch_->path().string());
  Model model = BuildModel(scene);
  const RunResult result = RunSolve(scene, model, "newton");
  WriteReported(scene, model, result, directory_.string());
  const YAML::Node contact = YAML::LoadFile(Path("summary.json"))["contact"];
  EXPECT_EQ(contact["max_penetration"].as<double>(), 0.0);  // no node in the layer
  const auto lines = Lines(Path("nodes.csv"));
  ASSERT_EQ(Fields(lines[0])[9], "in_contact");
  int marked = 0;
  for (size_t k = 1; k < lines.size(); ++k) marked += Fields(lines[k])[9] == "true" ? 1 : 0;
  EXPECT_GT(marked, 0);
  EXPECT_EQ(contact["nodes_in_contact"].as<int>(), marked);
}

TEST_F(WritersTest, HistoryCsvHasOneRowPerRecordedIteration) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  WriteReported(SceneWriting({"history"}), model, result, directory_.string());

  const auto lines = Lines(Path("history.csv"));
  ASSERT_EQ(lines.size(), 1 + result.summary.history.size());
  EXPECT_EQ(lines[0], "iteration,time_s,energy_J,relative_residual");
  for (size_t k = 0; k < result.summary.history.size(); ++k) {
    const auto fields = Fields(lines[k + 1]);
    ASSERT_EQ(fields.size(), 4u);
    const IterationRecord& record = result.summary.history[k];
    EXPECT_EQ(std::stoi(fields[0]), record.iteration);
    EXPECT_EQ(std::stod(fields[1]), record.time_s);
    EXPECT_EQ(std::stod(fields[2]), record.energy);
    EXPECT_EQ(std::stod(fields[3]), record.relative_residual);
  }
  EXPECT_FALSE(fs::exists(Path(TraceFileName("test-solver"))));  // only methods with a trace
}

// Each method's trace has its own columns, so its own file name (kinetic_<method>.csv).
TEST_F(WritersTest, TraceOfADynamicMethodGoesToItsOwnFile) {
  const Model model = SmallSheet();
  RunResult result = ResultOf(model);
  result.summary.trace_columns = {"step", "t", "w_c"};
  result.summary.trace = {{0, 0.0, 1.5}, {1, 0.01, 0.75}};
  WriteReported(SceneWriting({"history"}), model, result, directory_.string());

  EXPECT_EQ(TraceFileName("puiseux-dynamic"), "kinetic_puiseux-dynamic.csv");
  const auto lines = Lines(Path("kinetic_test-solver.csv"));
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
  EXPECT_EQ(vtk[3], "DATASET UNSTRUCTURED_GRID");
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
  const int cells = find("CELLS 3 11");  // two triangles and a line
  ASSERT_GE(cells, 0);
  EXPECT_EQ(vtk[cells + 1], "3 0 1 3");
  EXPECT_EQ(vtk[cells + 3], "2 0 1");
  const int types = find("CELL_TYPES 3");
  ASSERT_GE(types, 0);
  EXPECT_EQ(vtk[types + 1], "5");  // VTK_TRIANGLE
  EXPECT_EQ(vtk[types + 3], "3");  // VTK_LINE
  const int point_data = find("POINT_DATA 4");
  ASSERT_GE(point_data, 0);
  EXPECT_EQ(vtk[point_data + 1], "SCALARS height double 1");  // a viewer's default field
  EXPECT_EQ(std::strtod(vtk[point_data + 4].c_str(), nullptr), model.positions[5]);
  const int ids = find("SCALARS id int 1");
  ASSERT_GE(ids, 0);
  EXPECT_EQ(vtk[ids + 3], "1");
  const int displacement = find("VECTORS displacement double");
  ASSERT_GE(displacement, 0);
  std::istringstream moved(vtk[displacement + 2]);
  moved >> x >> y >> z;
  EXPECT_EQ(z, model.positions[5] - model.initial[5]);
  // Node 0 is held in z only: its z force is a reaction, its x and y forces residuals.
  const int reaction = find("VECTORS reaction double");
  const int residual = find("VECTORS residual double");
  ASSERT_GE(reaction, 0);
  ASSERT_GE(residual, 0);
  std::istringstream reaction0(vtk[reaction + 1]), residual0(vtk[residual + 1]);
  reaction0 >> x >> y >> z;
  EXPECT_EQ(x, 0.0);
  EXPECT_EQ(z, result.certificate.node_forces[2]);
  residual0 >> x >> y >> z;
  EXPECT_EQ(x, result.certificate.node_forces[0]);
  EXPECT_EQ(z, 0.0);
  EXPECT_GE(find("VECTORS contact_force double"), 0);
  const int fixed = find("SCALARS fixed int 3");
  ASSERT_GE(fixed, 0);
  EXPECT_EQ(vtk[fixed + 2], "0 0 1");  // node 0: held in z
  EXPECT_EQ(vtk[fixed + 3], "0 0 0");  // node 1: free
  EXPECT_GE(find("SCALARS in_contact int 1"), 0);
  const int strain = find("SCALARS strain double 1");
  ASSERT_GE(strain, 0);
  EXPECT_GE(find("CELL_DATA 3"), 0);
  // The line 0–1 was 1 m long and node 1 moved by (0, 0.01, -0.03).
  EXPECT_NEAR(std::stod(vtk[strain + 4]), std::sqrt(1 + 0.01 * 0.01 + 0.03 * 0.03) - 1, 1e-15);
  // The yarn measures of triangle 0 (0, 1, 3) at node 1, where warp 1–0 meets weft 1–3.
  const Eigen::Vector3d warp(-1.0, -0.01, 0.03), weft(0.0, 0.99, 0.03);
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"strain_warp", warp.norm() - 1.0},
           {"strain_weft", weft.norm() - 1.0},
           {"shear_angle", kHalfPi - std::acos(warp.dot(weft) / (warp.norm() * weft.norm()))}}) {
    const int array = find("SCALARS " + name + " double 1");
    ASSERT_GE(array, 0) << name;
    EXPECT_NEAR(std::stod(vtk[array + 2]), value, 1e-15) << name;
    EXPECT_EQ(vtk[array + 3], "0") << name;  // triangle 1 (0, 3, 2) did not move
    EXPECT_EQ(vtk[array + 4], "0") << name;  // the line element has no yarn measures
  }

  int vertices = 0, textures = 0, normals = 0, faces = 0, lines = 0;
  for (const auto& line : Lines(Path("mesh.obj"))) {
    vertices += line.rfind("v ", 0) == 0;
    textures += line.rfind("vt ", 0) == 0;
    normals += line.rfind("vn ", 0) == 0;
    faces += line.rfind("f ", 0) == 0;
    lines += line.rfind("l ", 0) == 0;
    if (line.rfind("f ", 0) == 0 && faces == 1) {
      EXPECT_EQ(line, "f 1/1/1 2/2/2 4/4/4");  // 1-based vertex/texture/normal
    }
    if (line.rfind("vt ", 0) == 0 && textures == 4) {
      EXPECT_EQ(line, "vt 1 1");  // the flat pattern
    }
    if (line.rfind("vn ", 0) == 0 && normals == 3) {
      EXPECT_EQ(line, "vn 0 0 1");  // node 2's normal: the sheet is flat there
    }
  }
  EXPECT_EQ(vertices, 4);
  EXPECT_EQ(textures, 4);
  EXPECT_EQ(normals, 4);
  EXPECT_EQ(faces, 2);
  EXPECT_EQ(lines, 1);
}

// The numbers after `prefix` on each line of `path` that starts with it.
std::vector<Eigen::Vector3d> ObjVectors(const std::string& path, const std::string& prefix) {
  std::vector<Eigen::Vector3d> vectors;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::istringstream fields(line.substr(prefix.size()));
    Eigen::Vector3d v;
    fields >> v.x() >> v.y() >> v.z();
    vectors.push_back(v);
  }
  return vectors;
}

TEST_F(WritersTest, ObjUpYIsTheZUpMeshTurnedAQuarterAboutX) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  Scene scene = SceneWriting({"obj"});
  WriteReported(scene, model, result, directory_.string());
  const auto z_up = ObjVectors(Path("mesh.obj"), "v ");
  const auto z_normals = ObjVectors(Path("mesh.obj"), "vn ");
  scene.output.obj_up = "y";
  WriteReported(scene, model, result, directory_.string());
  const auto y_up = ObjVectors(Path("mesh.obj"), "v ");
  const auto y_normals = ObjVectors(Path("mesh.obj"), "vn ");
  ASSERT_EQ(z_up.size(), 4u);
  ASSERT_EQ(y_up.size(), z_up.size());
  ASSERT_EQ(z_normals.size(), 4u);
  ASSERT_EQ(y_normals.size(), z_normals.size());
  // (x, y, z) → (x, z, −y): a proper rotation (det +1) taking +z to +y.
  Eigen::Matrix3d turn;
  turn << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  ASSERT_EQ(turn.determinant(), 1.0);
  ASSERT_EQ(turn * Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  for (size_t k = 0; k < z_up.size(); ++k) {
    EXPECT_EQ(y_up[k], turn * z_up[k]) << "vertex " << k;
    EXPECT_EQ(y_normals[k], turn * z_normals[k]) << "normal " << k;
  }
  // The flat sheet's normal was +z: it is +y now, so the drape stands upright in a y-up viewer.
  EXPECT_EQ(y_normals[2], Eigen::Vector3d::UnitY());
  // Node 1 hangs 3 cm down (z = −0.03): −0.03 along the file's y.
  EXPECT_EQ(y_up[1].y(), model.positions[5]);
}

// Runs a Python check with Debian's python3 (the packages' modules are there); "" when it passed,
// else its output. Skips when a module is not installed.
bool PythonHas(const std::string& module) {
  return std::system(("/usr/bin/python3 -c 'import " + module + "' 2>/dev/null").c_str()) == 0;
}

std::string RunPython(const fs::path& folder, const std::string& script) {
  const fs::path file = folder / "check.py", log = folder / "check.log";
  std::ofstream(file) << script;
  const std::string command = "cd '" + folder.string() + "' && /usr/bin/python3 " + file.string() +
                              " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  fs::remove(file);
  fs::remove(log);
  return status == 0 ? "" : text.str() + "(exit status " + std::to_string(status) + ")";
}

// mesh.vtk as Python's meshio reads it: the unstructured grid, its cells and every point array.
TEST_F(WritersTest, MeshioReadsTheVtkFile) {
  if (!PythonHas("meshio")) GTEST_SKIP() << "python3-meshio is not installed (CI installs it)";
  Model model = SmallSheet();
  model.edges = {{0, 1}};
  WriteReported(SceneWriting({"vtk"}), model, ResultOf(model), directory_.string());
  EXPECT_EQ(RunPython(directory_, R"(
import meshio
mesh = meshio.read("mesh.vtk")
assert mesh.points.shape == (4, 3), mesh.points.shape
kinds = sorted(block.type for block in mesh.cells)
assert kinds == ["line", "triangle"], kinds
shapes = {name: data.reshape(len(data), -1).shape for name, data in mesh.point_data.items()}
expected = {"height": (4, 1), "id": (4, 1), "displacement": (4, 3), "reaction": (4, 3), "residual": (4, 3),
            "contact_force": (4, 3), "fixed": (4, 3), "in_contact": (4, 1)}
for name, shape in expected.items():
    assert shapes.get(name) == shape, (name, shapes)
assert list(mesh.point_data["fixed"][0]) == [0, 0, 1]
assert list(mesh.point_data["id"].ravel()) == [0, 1, 2, 3]
for name in ["strain", "strain_warp", "strain_weft", "shear_angle"]:
    assert name in mesh.cell_data, (name, mesh.cell_data.keys())
    assert sum(len(block) for block in mesh.cell_data[name]) == 3, name
)"),
            "");
}

// mesh.vtk as VTK's own legacy reader reads it.
TEST_F(WritersTest, VtkReadsTheVtkFile) {
  if (!PythonHas("vtk")) GTEST_SKIP() << "python3-vtk9 is not installed (CI installs it)";
  Model model = SmallSheet();
  model.edges = {{0, 1}};
  WriteReported(SceneWriting({"vtk"}), model, ResultOf(model), directory_.string());
  EXPECT_EQ(RunPython(directory_, R"(
import vtk
reader = vtk.vtkUnstructuredGridReader()
reader.SetFileName("mesh.vtk")
reader.ReadAllScalarsOn()
reader.ReadAllVectorsOn()
reader.Update()
grid = reader.GetOutput()
assert grid.GetNumberOfPoints() == 4, grid.GetNumberOfPoints()
assert grid.GetNumberOfCells() == 3, grid.GetNumberOfCells()
data = grid.GetPointData()
assert data.GetScalars().GetName() == "height", data.GetScalars().GetName()
assert data.GetVectors().GetName() == "displacement", data.GetVectors().GetName()
for name, components in [("height", 1), ("id", 1), ("displacement", 3), ("reaction", 3), ("residual", 3),
                         ("contact_force", 3), ("fixed", 3), ("in_contact", 1)]:
    array = data.GetArray(name)
    assert array is not None, name
    assert array.GetNumberOfComponents() == components, (name, array.GetNumberOfComponents())
for name in ["strain", "strain_warp", "strain_weft", "shear_angle"]:
    array = grid.GetCellData().GetArray(name)
    assert array is not None, name
    assert array.GetNumberOfTuples() == 3, name
)"),
            "");
}

// nodes.csv as pandas reads it with no option: whole numbers, booleans and numbers, no NaN.
TEST_F(WritersTest, PandasReadsNodesCsvWithTypedColumns) {
  if (!PythonHas("pandas")) GTEST_SKIP() << "python3-pandas is not installed (CI installs it)";
  const Model model = SmallSheet();
  WriteReported(SceneWriting({"nodes"}), model, ResultOf(model), directory_.string());
  EXPECT_EQ(RunPython(directory_, R"(
import pandas
nodes = pandas.read_csv("nodes.csv")
assert len(nodes) == 4, len(nodes)
for column in ["id", "i", "j"]:
    assert str(nodes[column].dtype) == "int64", (column, nodes[column].dtype)
for column in ["fixed_x", "fixed_y", "fixed_z", "in_contact"]:
    assert str(nodes[column].dtype) == "bool", (column, nodes[column].dtype)
for column in nodes.columns:
    assert nodes[column].dtype.kind in "ibf", (column, nodes[column].dtype)
assert list(nodes["fixed_z"]) == [True, False, True, True]
assert nodes.notna().all().all()
)"),
            "");
}

// A picture of an earlier run does not survive a run that draws none.
TEST_F(WritersTest, AStaleDrapePngIsRemoved) {
  const Model model = SmallSheet();
  WriteReported(SceneWriting({"png", "summary"}), model, ResultOf(model), directory_.string());
  ASSERT_TRUE(fs::exists(Path("drape.png")));
  WriteReported(SceneWriting({"summary"}), model, ResultOf(model), directory_.string());
  EXPECT_EQ(Files(), (std::set<std::string>{"summary.json", "scene.yaml"}));
}

// Every text file of the folder that can hold a comment or a field says how it was made, in the
// one form of ProvenanceLine / ProvenanceMembers; the CSV files hold none (summary.json beside them
// does) so that pandas reads them without options.
TEST_F(WritersTest, EveryFileThatCanSayItCarriesTheProvenance) {
  const Model model = SmallSheet();
  const Provenance provenance{"drape solve small.yaml --set solver.tolerance=1e-9",
                              {"solver.tolerance=1e-9"}};
  const Scene scene = SceneWriting({"summary", "nodes", "history", "vtk", "obj", "png"});
  WriteOutputs(scene, model, ReportOf(scene, model, ResultOf(model)), directory_.string(),
               provenance);
  EXPECT_EQ(PngTexts(ReadWholeFile(Path("drape.png"))).at("Software"), "drape " + DrapeVersion());
  const std::string line = ProvenanceLine(provenance);
  EXPECT_EQ(Lines(Path("mesh.vtk"))[1].rfind(line, 0), 0u) << Lines(Path("mesh.vtk"))[1];
  EXPECT_EQ(Lines(Path("mesh.obj"))[0], "# " + line);
  EXPECT_EQ(Lines(Path("scene.yaml"))[0], "# " + line);
  const YAML::Node summary = YAML::LoadFile(Path("summary.json"));
  EXPECT_EQ(summary["drape_version"].as<std::string>(), DrapeVersion());
  EXPECT_EQ(summary["command_line"].as<std::string>(), provenance.command_line);
  EXPECT_EQ(summary["overrides"][0].as<std::string>(), "solver.tolerance=1e-9");
  EXPECT_EQ(summary["units"]["energy"].as<std::string>(), "J");
  EXPECT_EQ(summary["units"]["residual.max_node_force"].as<std::string>(), "N");
  for (const char* csv : {"nodes.csv", "history.csv"}) {
    EXPECT_NE(Lines(Path(csv))[0][0], '#') << csv;
  }
}

TEST_F(WritersTest, CreatesTheFolderAndLeavesNoTemporaryFile) {
  const Model model = SmallSheet();
  const RunResult result = ResultOf(model);
  directory_ /= "nested/deeper";
  WriteReported(SceneWriting({"summary", "nodes", "history", "vtk", "obj"}), model, result,
                directory_.string());
  EXPECT_EQ(Files(), (std::set<std::string>{"summary.json", "nodes.csv", "history.csv", "mesh.vtk",
                                            "mesh.obj", "scene.yaml"}));
  // Writing again replaces the files in place.
  WriteReported(SceneWriting({"summary", "nodes", "history", "vtk", "obj"}), model, result,
                directory_.string());
  EXPECT_EQ(Files().size(), 6u);
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
  ASSERT_EQ(Files(), (std::set<std::string>{"drape.png", "scene.yaml"}));
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
  EXPECT_EQ(Files(), (std::set<std::string>{"summary.json", "profile.csv", "drape.png",
                                            "shadow.png", "scene.yaml"}));

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
  EXPECT_EQ(Files(), (std::set<std::string>{"shadow.png", "scene.yaml"}));
}

}  // namespace
}  // namespace drape
