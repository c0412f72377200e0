// The scene schema as JSON (`drape schema --json`) and as a JSON Schema (`drape schema
// --json-schema`): every shipped scene validates against it, and scenes the loader refuses for a
// key, a type, a bound or a choice are refused by it too (tests/validate_scenes.py, with Debian's
// python3-jsonschema and python3-yaml).
#include "src/output/scene_json_schema.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/scene/scene_schema.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

std::string ShellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// tests/validate_scenes.py's lines for `scenes`, and its exit status.
struct Validation {
  int status = -1;
  std::string lines;
};

Validation Validate(const std::string& schema_file, const std::vector<std::string>& scenes) {
  std::string command = "python3 " + ShellQuoted(testing::SourcePath("tests/validate_scenes.py")) +
                        " " + ShellQuoted(schema_file);
  for (const std::string& scene : scenes) command += " " + ShellQuoted(scene);
  Validation validation;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
  if (!pipe) return validation;
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe.get())) validation.lines += buffer;
  const int status = pclose(pipe.release());
  validation.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return validation;
}

class SceneJsonSchemaTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("python3 -c 'import jsonschema, yaml' > /dev/null 2>&1") != 0) {
      GTEST_SKIP() << "python3-jsonschema and python3-yaml are not installed (.ci/run installs "
                      "them)";
    }
    scratch_.emplace("scene_json_schema");
    schema_ = (scratch_->path() / "scene.schema.json").string();
    std::ofstream(schema_) << SceneJsonSchema();
  }

  std::string Scene(const std::string& name, const std::string& text) {
    const std::string path = (scratch_->path() / name).string();
    std::ofstream(path) << text;
    return path;
  }

  std::optional<testing::ScratchFolder> scratch_;
  std::string schema_;
};

TEST_F(SceneJsonSchemaTest, EveryShippedSceneIsValid) {
  const auto scenes = testing::ShippedSceneFiles();
  ASSERT_GE(scenes.size(), 6u);
  const Validation validation = Validate(schema_, scenes);
  EXPECT_EQ(validation.status, 0) << validation.lines;
}

constexpr char kSchemaSheet[] = R"(mesh: {kind: grid, nodes: [3, 3]}
material: {density: 0.2, springs: {structural: 100}}
)";

TEST_F(SceneJsonSchemaTest, RefusesWhatTheLoaderRefuses) {
  const std::string sheet = kSchemaSheet;
  struct Bad {
    std::string name, text, where;
  };
  const std::vector<Bad> bad = {
      {"unknown_key", sheet + "solver: {tolerence: 1e-6}\n", "solver"},
      {"below_bound", sheet + "solver: {tolerance: 0}\n", "solver.tolerance"},
      {"not_integer", sheet + "solver: {max_iterations: 2.5}\n", "solver.max_iterations"},
      {"bad_choice", sheet + "output: {obj_up: x}\n", "output.obj_up"},
      {"bad_kind", sheet + "output: {write: [summary, nodez]}\n", "output.write[1]"},
      {"repeat", sheet + "output: {write: [summary, summary]}\n", "output.write"},
      {"point", sheet + "loads: {gravity: [0, -9.81]}\n", "loads.gravity"},
      {"selection", sheet + "fixed: [{nodes: {edge: middle}}]\n", "fixed[0].nodes.edge"},
      {"obstacle", sheet + "obstacles: [{sphere: {center: [0, 0, 0], radius: -1}}]\n",
       "obstacles[0].sphere.radius"},
      {"method_option", sheet + "solver: {ceres-lbfgs: {memory: 0}}\n",
       "solver.ceres-lbfgs.memory"},
      {"missing", "material: {density: 0.2}\n", "(top)"},
  };
  std::vector<std::string> paths;
  for (const Bad& scene : bad) {
    paths.push_back(Scene(scene.name + ".yaml", scene.text));
    EXPECT_THROW(LoadScene(paths.back()), InputError) << scene.name;  // the loader refuses it
  }
  const Validation validation = Validate(schema_, paths);  // one run of Python for them all
  EXPECT_EQ(validation.status, 1) << validation.lines;
  for (size_t k = 0; k < bad.size(); ++k) {
    EXPECT_NE(validation.lines.find("invalid " + paths[k] + ": " + bad[k].where + ":"),
              std::string::npos)
        << bad[k].name << "\n"
        << validation.lines;
  }
}

TEST_F(SceneJsonSchemaTest, NumbersAreNumbersAndDefaultsAreTheRows) {
  const YAML::Node rows = YAML::Load(SceneSchemaRowsJson())["rows"];
  ASSERT_EQ(rows.size(), SceneSchema().size());
  for (size_t k = 0; k < rows.size(); ++k) {
    const SchemaRow& row = SceneSchema()[k];
    SCOPED_TRACE(row.Path());
    EXPECT_EQ(rows[k]["path"].as<std::string>(), row.Path());
    if (const auto& bounds = row.bounds) {
      const bool lower = std::isfinite(bounds->lower);
      const std::string key = bounds->lower_inclusive ? "minimum" : "exclusiveMinimum";
      if (lower) {
        EXPECT_EQ(rows[k][key].as<double>(), bounds->lower);
      }
    }
    const std::string& literal = row.default_yaml;
    if (!literal.empty()) {
      ASSERT_TRUE(rows[k]["default"].IsDefined()) << row.default_text;
      EXPECT_EQ(YAML::Dump(rows[k]["default"]), YAML::Dump(YAML::Load(literal)));
    }
  }
}

}  // namespace
}  // namespace drape
