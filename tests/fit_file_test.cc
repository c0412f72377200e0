// The fit file: every key of its format (docs/reference.md, "The fit file") read, and bad input
// reported as file:line:column.
#include "src/fit/fit_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "src/cli/cli.h"
#include "tests/fit_test_support.h"

namespace drape::testing {
namespace {

std::string BaseScene() { return SourcePath("configs/fit/drape_fv.yaml"); }

// A fit file in a fresh folder, with the base scene copied next to it (the scene path is relative
// to the fit file) and small data files.
std::string WriteFitFolder(const std::string& name, const std::string& fit_text) {
  const std::string folder = FitTempDir(name);
  std::filesystem::copy_file(BaseScene(), folder + "/base.yaml");
  std::filesystem::copy_file(BaseScene(), folder + "/other.yaml");
  WriteTextFile(folder + "/scan.csv", "id,x,y,z\n0,0.1,0.2,0.3\n5,0.1,0.2,-0.1\n");
  WriteTextFile(folder + "/cloud.xyz", "0.1 0.2 0.3\n0.0 0.1 -0.05\n");
  WriteTextFile(folder + "/cloud.ply",
                "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n0.1 0.2 0.3\n0 0 -0.1\n");
  WriteTextFile(folder + "/forces.csv", "id,fx,fy,fz\n60,0,0,0.01\n");
  WriteTextFile(folder + "/fit.yaml", fit_text);
  return folder + "/fit.yaml";
}

constexpr char kFullFit[] = R"(scene: base.yaml
parameters:
  - {key: material.finite_volume.D_warp, initial: 1.0e-5, bounds: [1.0e-7, 1.0e-3], log: true}
  - {key: material.finite_volume.G, initial: 1.0, bounds: [0.0, 10]}
measurements:
  - drape_coefficient: {value: 0.62, weight: 2, disc_radius: 0.06}
  - positions: {file: scan.csv, sigma: 0.0005}
  - positions: {file: cloud.xyz}
  - positions: {file: cloud.ply}
  - bending_length: {value: 0.021, direction: weft}
  - reactions: {file: forces.csv}
  - scene: other.yaml
    measurements:
      - drape_coefficient: {value: 0.5}
method: sbplx
max_evaluations: 50
tolerance: 1.0e-6
output: {directory: out/fit}
)";

TEST(FitFileTest, ReadsEveryKeyOfTheFormat) {
  const std::string path = WriteFitFolder("full", kFullFit);
  const FitSpec spec = LoadFitFile(path);
  ASSERT_EQ(spec.parameters.size(), 2u);
  EXPECT_EQ(spec.parameters[0].key, "material.finite_volume.D_warp");
  EXPECT_TRUE(spec.parameters[0].log);
  EXPECT_DOUBLE_EQ(spec.parameters[0].lower, 1e-7);
  EXPECT_FALSE(spec.parameters[1].log);
  ASSERT_EQ(spec.specimens.size(), 2u);
  const auto& m = spec.specimens[0].measurements;
  ASSERT_EQ(m.size(), 6u);
  EXPECT_EQ(m[0].kind, FitMeasurement::Kind::kDrapeCoefficient);
  EXPECT_DOUBLE_EQ(m[0].weight, 2.0);
  EXPECT_DOUBLE_EQ(m[0].disc_radius, 0.06);
  EXPECT_FALSE(m[1].positions.cloud);
  EXPECT_EQ(m[1].positions.ids, (std::vector<int>{0, 5}));
  EXPECT_DOUBLE_EQ(m[1].sigma, 0.0005);
  EXPECT_TRUE(m[2].positions.cloud);
  EXPECT_EQ(m[2].positions.points.size(), 2u);
  EXPECT_TRUE(m[3].positions.cloud);
  EXPECT_DOUBLE_EQ(m[3].positions.points[1].z(), -0.1);
  EXPECT_EQ(m[4].direction, "weft");
  EXPECT_DOUBLE_EQ(m[4].sigma, 0.001);  // default
  EXPECT_EQ(m[5].reactions.ids, (std::vector<int>{60}));
  EXPECT_DOUBLE_EQ(m[5].sigma, 0.01 * 0.01);  // 1% of the largest measured force
  EXPECT_EQ(spec.specimens[1].measurements.size(), 1u);
  EXPECT_NE(spec.specimens[1].scene_file.find("other.yaml"), std::string::npos);
  EXPECT_EQ(spec.method, "sbplx");
  EXPECT_EQ(spec.max_evaluations, 50);
  EXPECT_EQ(spec.output_directory, std::filesystem::path(path).parent_path().string() + "/out/fit");
}

TEST(FitFileTest, DefaultsToBobyqaAndOutFitName) {
  const std::string path = WriteFitFolder("defaults", R"(scene: base.yaml
parameters:
  - {key: material.finite_volume.D_warp, initial: 1.0e-5, bounds: [1.0e-7, 1.0e-3]}
measurements:
  - drape_coefficient: {value: 0.62}
)");
  const FitSpec spec = LoadFitFile(path);
  EXPECT_EQ(spec.method, "bobyqa");
  EXPECT_EQ(spec.output_directory,
            std::filesystem::path(path).parent_path().string() + "/out/fit");  // out/<stem>
  EXPECT_FALSE(spec.parameters[0].log);
}

// A drape coefficient measured on a drape tester whose mesh rule expects a discretisation error
// above the measurement's sigma: a warning located at the measurement, with both figures; none
// where sigma covers it, nor on a scene without a support disc (the rule's domain).
TEST(FitFileTest, WarnsOfAMeshWhoseErrorExceedsTheMeasurementsSigma) {
  const std::string scene = SourcePath("configs/fv/drape_tester_cotton_30.yaml");
  const auto fit_text = [&](const std::string& sigma) {
    return "scene: " + scene +
           "\nparameters:\n  - {key: material.finite_volume.kes.B_warp, initial: 0.1, "
           "bounds: [0.02, 0.5]}\nmeasurements:\n  - drape_coefficient: {value: 0.7, sigma: " +
           sigma + "}\n";
  };
  const std::vector<std::string> at_1cm = {"mesh.spacing=0.01"};  // coarse for the cotton
  const FitSpec coarse = LoadFitFile(WriteFitFolder("mesh_warning", fit_text("0.02")), at_1cm);
  ASSERT_EQ(coarse.warnings.size(), 1u);
  const std::string& warning = coarse.warnings[0];
  EXPECT_NE(warning.find("fit.yaml:5:"), std::string::npos) << warning;
  EXPECT_NE(warning.find("measurements[0].drape_coefficient: the drape coefficient on the 1 cm "
                         "mesh of "),
            std::string::npos)
      << warning;
  EXPECT_NE(warning.find("about 0.11 (mesh rule for a 1.9 cm bending length"), std::string::npos)
      << warning;
  EXPECT_NE(warning.find("times the measurement's sigma 0.02"), std::string::npos) << warning;
  EXPECT_TRUE(
      LoadFitFile(WriteFitFolder("mesh_covered", fit_text("0.2")), at_1cm).warnings.empty());
  // The shipped cotton's own 4.7 mm expects 0.050: a sigma of 0.05 covers it, not 1 cm (0.11).
  EXPECT_TRUE(LoadFitFile(WriteFitFolder("mesh_fine", fit_text("0.05"))).warnings.empty());
  EXPECT_EQ(LoadFitFile(WriteFitFolder("mesh_fine_1cm", fit_text("0.05")), at_1cm).warnings.size(),
            1u);
  EXPECT_TRUE(LoadFitFile(WriteFitFolder("mesh_no_disc", kFullFit)).warnings.empty());
}

// A drape test that leaves its lattice to its accuracy gets it chosen once, at the initial
// parameters: a parameter that changes the bending length (here the density, an eighth of it
// doubles c) would otherwise move the lattice between evaluations, and the objective with it.
TEST(FitFileTest, KeepsTheLatticeTheAccuracyChoseAtTheInitialParameters) {
  const std::string folder = FitTempDir("chosen_lattice");
  WriteTextFile(folder + "/tester.yaml",
                "drape_test: {accuracy: 0.05}\nmaterial: {model: finite_volume, density: 0.12, "
                "finite_volume: {E_warp: 8000, E_weft: 5000, G: 50, D_warp: 1.2e-5, D_weft: "
                "8e-6}}\n");
  WriteTextFile(folder + "/fit.yaml",
                "scene: tester.yaml\nparameters:\n  - {key: material.density, initial: 0.12, "
                "bounds: [0.01, 1]}\nmeasurements:\n  - drape_coefficient: {value: 0.7}\n");
  const FitSpec spec = LoadFitFile(folder + "/fit.yaml");
  const FitSpecimen& specimen = spec.specimens[0];
  ASSERT_TRUE(specimen.chosen_spacing);
  const Scene initial = SpecimenSceneAt(spec, specimen, {0.12});
  EXPECT_DOUBLE_EQ(initial.mesh.spacing, *specimen.chosen_spacing);
  const Scene lighter = SpecimenSceneAt(spec, specimen, {0.015});
  EXPECT_DOUBLE_EQ(lighter.mesh.spacing, *specimen.chosen_spacing);
  // Loaded afresh at that density, the accuracy would choose a coarser lattice.
  const Scene afresh = specimen.scene->Load({}, {{"material.density", YAML::Node(0.015)}});
  EXPECT_GT(afresh.mesh.spacing, 1.5 * *specimen.chosen_spacing);
}

// Runs LoadFitFile and returns the error message ("" if none).
std::string ErrorOf(const std::string& name, const std::string& text) {
  const std::string path = WriteFitFolder(name, text);
  try {
    LoadFitFile(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(FitFileTest, LocatesBadInput) {
  const std::string head = "scene: base.yaml\nparameters:\n";
  const std::string good_parameter =
      "  - {key: material.finite_volume.D_warp, initial: 1.0e-5, bounds: [1.0e-7, 1.0e-3]}\n";
  const std::string good_measurements = "measurements:\n  - drape_coefficient: {value: 0.6}\n";
  // An unknown top-level key.
  EXPECT_NE(ErrorOf("unknown", head + good_parameter + good_measurements + "methd: bobyqa\n")
                .find("fit.yaml:6:1: methd: unknown key"),
            std::string::npos);
  // Initial value outside the bounds, located at the value.
  EXPECT_NE(ErrorOf("outside", head +
                                   "  - {key: material.finite_volume.D_warp, initial: 1.0, "
                                   "bounds: [1.0e-7, 1.0e-3]}\n" +
                                   good_measurements)
                .find("fit.yaml:3:51: parameters[0].initial: the initial value lies outside"),
            std::string::npos);
  // A key the scene does not have, located at the parameter's key.
  EXPECT_NE(ErrorOf("badkey", head +
                                  "  - {key: material.finite_volume.D_wrap, initial: 1.0e-5, "
                                  "bounds: [1.0e-7, 1.0e-3]}\n" +
                                  good_measurements)
                .find("fit.yaml:3:11: parameters[0].key: not a numeric key of"),
            std::string::npos);
  // An unknown method, with a suggestion.
  EXPECT_NE(ErrorOf("method", head + good_parameter + good_measurements + "method: bobyqua\n")
                .find("fit.yaml:6:9: method: unknown value 'bobyqua'; did you mean 'bobyqa'?"),
            std::string::npos);
  // A bad row of a data file is located in the data file.
  const std::string path = WriteFitFolder("badrow", head + good_parameter +
                                                        "measurements:\n  - positions: {file: "
                                                        "bad.csv}\n");
  WriteTextFile(std::filesystem::path(path).parent_path().string() + "/bad.csv",
                "id,x,y,z\n3,0.1,0.2,0.3\n4,0.1,abc,0.3\n");
  std::string message;
  try {
    LoadFitFile(path);
  } catch (const InputError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("bad.csv:3:7: expected a number"), std::string::npos) << message;
  // A node id beyond the scene's nodes.
  const std::string far = WriteFitFolder("farid", head + good_parameter +
                                                      "measurements:\n  - positions: {file: "
                                                      "far.csv}\n");
  WriteTextFile(std::filesystem::path(far).parent_path().string() + "/far.csv",
                "id,x,y,z\n3,0.1,0.2,0.3\n400,0.1,0.2,0.3\n");
  try {
    LoadFitFile(far);
    message.clear();
  } catch (const InputError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("far.csv:3:1: node id 400 is out of range"), std::string::npos) << message;
  // Another specimen without measurements.
  EXPECT_NE(
      ErrorOf("specimen", head + good_parameter + good_measurements + "  - scene: other.yaml\n")
          .find("fit.yaml:6:12: measurements[1].scene: another specimen needs its own"),
      std::string::npos);
}

// Every example fit file of the repository loads (tests/configs_test.cc skips fit files).
// A scan as a binary PLY (what scanners and meshio write) or an STL reads as the same cloud as
// the ASCII PLY; a truncated one is refused at the measurement, naming the byte.
TEST(FitFileTest, BinaryPlyAndStlScansAreClouds) {
  const std::string folder = FitTempDir("binary_scan");
  const std::vector<Eigen::Vector3f> points = {
      {0.1f, 0.2f, 0.3f}, {0.0f, 0.0f, -0.1f}, {0.25f, 0.0f, 0.0f}};
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
      "y\nproperty float z\nend_header\n";
  std::string stl(80, ' ');
  const std::uint32_t one = 1;
  stl.append(reinterpret_cast<const char*>(&one), 4);  // x86 and arm64: little-endian
  stl.append(12, '\0');                                // the normal
  for (const Eigen::Vector3f& p : points) {
    ply.append(reinterpret_cast<const char*>(p.data()), 12);
    stl.append(reinterpret_cast<const char*>(p.data()), 12);
  }
  stl.append(2, '\0');
  WriteTextFile(folder + "/scan.ply", ply);
  WriteTextFile(folder + "/scan.stl", stl);
  const Location where{folder + "/fit.yaml", 7, 5, "measurements[0].positions.file"};
  for (const char* name : {"/scan.ply", "/scan.stl"}) {
    const PositionData data = ReadPositionFile(folder + name, where);
    EXPECT_TRUE(data.cloud) << name;
    ASSERT_EQ(data.points.size(), 3u) << name;
    for (size_t k = 0; k < points.size(); ++k) {
      EXPECT_EQ(data.points[k], points[k].cast<double>()) << name << " point " << k;
    }
  }
  WriteTextFile(folder + "/cut.ply", ply.substr(0, ply.size() - 5));
  try {
    ReadPositionFile(folder + "/cut.ply", where);
    ADD_FAILURE() << "a truncated PLY was read";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("fit.yaml:7:5: "), std::string::npos) << message;
    EXPECT_NE(message.find("cut.ply: byte "), std::string::npos) << message;
    EXPECT_NE(message.find("the vertex data ends early"), std::string::npos) << message;
  }
}

TEST(FitFileTest, LoadsEveryExampleFitFile) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourcePath("configs/fit"))) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("fit", 0) != 0 || entry.path().extension() != ".yaml") continue;
    EXPECT_NO_THROW(LoadFitFile(entry.path().string())) << name;
    ++count;
  }
  EXPECT_GE(count, 5);
}

// drape's own nodes.csv is a measurement of positions: the free nodes' ids and positions (the
// nodes fixed in all three directions left out), so that a fit can start from drape's output.
TEST(FitFileTest, ReadsDrapesOwnNodesCsvAsPositions) {
  const std::string path = WriteFitFolder("own_nodes", R"(scene: base.yaml
parameters:
  - {key: material.finite_volume.D_warp, initial: 1.0e-5, bounds: [1.0e-7, 1.0e-3], log: true}
measurements:
  - positions: {file: solved/nodes.csv}
)");
  const std::string folder = std::filesystem::path(path).parent_path().string();
  std::ostringstream stdout_text, stderr_text;
  ASSERT_EQ(RunCommand({"solve", folder + "/base.yaml", "--out", folder + "/solved"}, stdout_text,
                       stderr_text),
            0)
      << stderr_text.str();
  const FitSpec spec = LoadFitFile(path);
  const PositionData& data = spec.specimens[0].measurements[0].positions;
  const Model model = BuildModel(LoadConfig("configs/fit/drape_fv.yaml"));
  std::vector<int> free;
  for (int k = 0; k < model.num_nodes; ++k) {
    if (!model.fully_fixed(k)) free.push_back(k);
  }
  EXPECT_FALSE(data.cloud);
  EXPECT_EQ(data.ids, free);
  ASSERT_EQ(data.points.size(), free.size());
  for (const Eigen::Vector3d& point : data.points) EXPECT_TRUE(point.allFinite());
  EXPECT_EQ(data.lines.front(), free.front() + 2);  // line 1 is the header
}

// A fit solves each equilibrium with its loads at once: a scene that asks for the incremental
// friction's load path is refused, located at its finite_volume map.
TEST(FitFileTest, RefusesTheIncrementalFriction) {
  try {
    LoadFitFile(SourcePath("configs/fit/fit_friction.yaml"),
                {"material.finite_volume.friction_load_steps=3"});
    ADD_FAILURE() << "a fit took friction_load_steps";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("drape_fv_friction.yaml:"), std::string::npos) << message;
    EXPECT_NE(message.find("friction_load_steps"), std::string::npos) << message;
  }
}

TEST(FitFileTest, CommandRejectsABadFitFileAndWritesNothing) {
  const std::string path = WriteFitFolder("cli", R"(scene: base.yaml
parameters:
  - {key: material.finite_volume.D_warp, initial: -1, bounds: [1.0e-7, 1.0e-3], log: true}
measurements:
  - drape_coefficient: {value: 0.62}
)");
  const std::string out = std::filesystem::path(path).parent_path().string() + "/out";
  std::ostringstream stdout_text, stderr_text;
  const int status = RunCommand({"fit", path, "--out", out}, stdout_text, stderr_text);
  EXPECT_EQ(status, kExitBadInput);
  EXPECT_NE(stderr_text.str().find("fit.yaml:3:"), std::string::npos) << stderr_text.str();
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace drape::testing
