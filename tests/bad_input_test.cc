// Bad input, end to end through the `drape` command (drape_tests::kDrapeBinary): every scene in
// tests/data/bad/ is rejected by `drape check` and `drape solve` with exit status 2, a message
// "FILE:LINE:COLUMN: key.path: what is wrong" on stderr, and nothing written.
//
// Each fixture states what it expects on its first line:
//   # expect: LINE:COLUMN: key.path: the start of the message
//   # expect: LINE:COLUMN: key.path: ... words later in the message
// and the test looks for a stderr line with "FILE:" followed by that text (and the words after
// " ... " further along the same line).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/run_program.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using testing::DrapeCommand;
using testing::ProgramOutcome;
using testing::ReadText;
using testing::RunProgram;
using testing::ShellQuoted;

const fs::path kBadFolder = fs::path(drape_tests::kSourceDir) / "tests" / "data" / "bad";

// The fixtures, by file stem.
std::vector<std::string> BadScenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kBadFolder)) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// What a fixture expects after "FILE:", from its first line.
std::string Expectation(const fs::path& scene) {
  std::ifstream file(scene);
  std::string first;
  std::getline(file, first);
  const std::string marker = "# expect: ";
  return first.rfind(marker, 0) == 0 ? first.substr(marker.size()) : "";
}

// Does some line of `text` hold `expected`, followed later by `later`?
bool HasLine(const std::string& text, const std::string& expected, const std::string& later) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const size_t at = line.find(expected);
    if (at != std::string::npos && line.find(later, at + expected.size()) != std::string::npos) {
      return true;
    }
  }
  return false;
}

// Does some line of `text` start with "FILE:LINE:COLUMN: " (the located-message shape)?
bool HasLocatedLine(const std::string& text, const std::string& file) {
  std::istringstream lines(text);
  std::string line;
  const std::string prefix = file + ":";
  while (std::getline(lines, line)) {
    if (line.rfind(prefix, 0) != 0) continue;
    if (std::regex_search(line.substr(prefix.size()), std::regex("^[0-9]+:[0-9]+: \\S"))) {
      return true;
    }
  }
  return false;
}

class BadInputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_folder_.emplace("bad_input");
    scratch_ = scratch_folder_->path();
    out_ = scratch_ / "out";  // must never be created
  }
  void TearDown() override { scratch_folder_.reset(); }

  ProgramOutcome Drape(const std::vector<std::string>& args) const {
    return RunProgram(DrapeCommand(args), scratch_);
  }

  // `drape check` and `drape solve --out` both reject `scene` with exit 2, a stderr line holding
  // `expected` (then `later`, if given), and write nothing.
  void ExpectRejected(const std::string& scene, const std::string& expected,
                      const std::vector<std::string>& extra = {}, const std::string& later = "") {
    std::vector<std::string> check = {"check", scene};
    std::vector<std::string> solve = {"solve", scene, "--out", out_.string()};
    check.insert(check.end(), extra.begin(), extra.end());
    solve.insert(solve.end(), extra.begin(), extra.end());
    for (const auto& args : {check, solve}) {
      SCOPED_TRACE(args[0]);
      const ProgramOutcome outcome = Drape(args);
      EXPECT_EQ(outcome.exit_status, 2) << outcome.err;
      EXPECT_TRUE(HasLine(outcome.err, expected, later))
          << "expected '" << expected << "'" << (later.empty() ? "" : " ... '" + later + "'")
          << " on stderr, got:\n"
          << outcome.err;
      EXPECT_FALSE(fs::exists(out_)) << "a rejected scene wrote " << out_;
    }
  }

  std::optional<testing::ScratchFolder> scratch_folder_;
  fs::path scratch_;
  fs::path out_;
};

class BadSceneFileTest : public BadInputTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(BadSceneFileTest, IsRejectedWithALocatedMessageAndNothingWritten) {
  const fs::path scene = kBadFolder / (GetParam() + ".yaml");
  std::string expected = Expectation(scene), later;
  ASSERT_FALSE(expected.empty()) << scene << " has no '# expect: ' first line";
  ASSERT_TRUE(std::regex_search(expected, std::regex("^[0-9]+:[0-9]+: ")))
      << "the expectation of " << scene << " starts with no LINE:COLUMN";
  const size_t gap = expected.find(" ... ");
  if (gap != std::string::npos) {
    later = expected.substr(gap + 5);
    expected = expected.substr(0, gap + 1);
  }
  ExpectRejected(scene.string(), scene.string() + ":" + expected, {}, later);
  const ProgramOutcome outcome = Drape({"check", scene.string()});
  EXPECT_TRUE(HasLocatedLine(outcome.err, scene.string())) << outcome.err;
  // Nothing lands next to the scene either (its default output folder).
  EXPECT_FALSE(fs::exists(kBadFolder / "out"));
}

INSTANTIATE_TEST_SUITE_P(BadInput, BadSceneFileTest, ::testing::ValuesIn(BadScenes()),
                         [](const auto& test) { return test.param; });

TEST(BadInput, EveryKindOfBadInputHasAFixture) {
  const auto names = BadScenes();
  for (const char* name :
       {"unknown_key",      "wrong_type",         "list_expected",   "missing_mesh",
        "missing_mass",     "negative_stiffness", "zero_mass",       "nan",
        "infinity",         "duplicate_key",      "octal",           "bad_number",
        "syntax_error",     "one_node_grid",      "one_node_circle", "repeated_coordinate",
        "coincident_nodes", "empty_selection",    "id_out_of_range", "ij_out_of_range",
        "unreadable_mesh",  "no_support",         "unknown_dof",     "dimension",
        "unknown_method"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
}

TEST_F(BadInputTest, UnreadableSceneFile) {
  const std::string missing = (scratch_ / "no_such_scene.yaml").string();
  ExpectRejected(missing, missing + ": cannot read");
}

// A valid scene, so that only the override is wrong.
std::string WriteValidScene(const fs::path& folder) {
  const fs::path scene = folder / "valid.yaml";
  std::ofstream(scene) << "mesh: {kind: chain, length: 0.4, nodes: 5}\n"
                          "material: {node_mass: 0.01, springs: {structural: 50}}\n"
                          "fixed:\n  - nodes: {ids: [0, 4]}\n"
                          "loads: {gravity: [0, 0, -9.81]}\n"
                          "solver: {method: ceres-lbfgs, max_iterations: 100}\n";
  return scene.string();
}

TEST_F(BadInputTest, MalformedOverride) {
  ExpectRejected(WriteValidScene(scratch_), "--set:1:1: ", {"--set", "mesh.nodes"});
}

TEST_F(BadInputTest, OverrideThroughAValue) {
  ExpectRejected(WriteValidScene(scratch_), "--set:1:11: ", {"--set", "mesh.kind.x=1"});
}

TEST_F(BadInputTest, OverrideWithABadValueIsLocatedInTheOverride) {
  ExpectRejected(WriteValidScene(scratch_), "--set:2:20: material.node_mass: must be positive",
                 {"--set", "solver.tolerance=1e-6", "--set", "material.node_mass=-1"});
}

TEST_F(BadInputTest, SolverOptionOutOfRangeInAnOverride) {
  ExpectRejected(WriteValidScene(scratch_),
                 "--set:1:27: solver.ceres-lbfgs.memory: must be an integer in [1, 1000], got -5",
                 {"--set", "solver.ceres-lbfgs.memory=-5"});
}

TEST_F(BadInputTest, UnknownMethodInAnOverride) {
  ExpectRejected(WriteValidScene(scratch_), "--set:1:15: solver.method: unknown method 'newtn'",
                 {"--set", "solver.method=newtn"});
}

// A run whose explicit step diverges (a stiff chain, dt at the top of its range): its positions
// overflowed to inf and were written to nodes.csv, mesh.vtk and mesh.obj; then it was refused
// (exit 2, nothing written). Now its last finite iterate is written, marked not converged (exit
// 1), the termination says where the values stopped being finite, and no file holds NaN or inf.
TEST_F(BadInputTest, ARunThatStopsBeingFiniteSavesItsLastFiniteIterate) {
  const fs::path scene = scratch_ / "diverging.yaml";
  std::ofstream(scene) << "mesh: {kind: chain, length: 0.4, nodes: 5}\n"
                          "material: {node_mass: 0.001, springs: {structural: 1e6}}\n"
                          "fixed:\n  - nodes: {ids: [0, 4]}\n"
                          "loads: {gravity: [0, 0, -9.81]}\n"
                          "solver: {method: explicit-euler, explicit-euler: {dt: 100}}\n";
  const ProgramOutcome outcome = Drape({"solve", scene.string(), "--out", out_.string()});
  EXPECT_EQ(outcome.exit_status, 1) << outcome.err;
  const std::string summary = ReadText(out_ / "summary.json");
  EXPECT_NE(summary.find("\"termination\": \"non-finite state: explicit-euler produced a "
                         "non-finite"),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("the last finite iterate (iteration "), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"converged\": false"), std::string::npos) << summary;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(out_)) {
    if (entry.path().filename().string()[0] == '.') continue;
    ++files;
    std::string text = ReadText(entry.path());
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_EQ(std::regex_search(text, std::regex("\\bnan\\b|\\binf\\b|infinity")), false)
        << entry.path();
  }
  EXPECT_GE(files, 5);  // summary, nodes, history, vtk, obj
}

// Whether this is built with AddressSanitizer: GCC says so with __SANITIZE_ADDRESS__, clang 14
// (the sanitized build of .ci/configure-sanitized) with __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define DRAPE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DRAPE_ADDRESS_SANITIZER 1
#endif
#endif

// Memory runs out while the model is built (a 9-million-node grid allowed by mesh.max_nodes,
// under a 1 GB address-space limit): a message and exit 2, never a signal. Not under
// AddressSanitizer, which reserves far more address space than the limit allows.
TEST_F(BadInputTest, OutOfMemoryIsAMessageAndExitStatus2) {
#if defined(DRAPE_ADDRESS_SANITIZER)
  GTEST_SKIP() << "an address-space limit and AddressSanitizer do not mix";
#else
  const fs::path scene = scratch_ / "huge.yaml";
  std::ofstream(scene) << "mesh: {nodes: [3000, 3000], max_nodes: 10000000}\n"
                          "material: {density: 0.2, springs: {structural: 100}}\n"
                          "fixed:\n  - nodes: {edge: top}\n"
                          "loads: {gravity: [0, 0, -9.81]}\n";
  const fs::path err = scratch_ / "stderr.txt";
  const std::string command = "ulimit -v 1000000; " + ShellQuoted(drape_tests::kDrapeBinary) +
                              " check " + ShellQuoted(scene.string()) + " > /dev/null 2> " +
                              ShellQuoted(err.string());
  const int status = std::system(("bash -c " + ShellQuoted(command)).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << ReadText(err);
  EXPECT_NE(ReadText(err).find("drape: out of memory"), std::string::npos) << ReadText(err);
#endif
}

// `drape fit` with a scene that does not exist: located in the fit file (it named only the
// scene's path before).
TEST_F(BadInputTest, FitWithAMissingSceneIsLocatedInTheFitFile) {
  const fs::path fit = scratch_ / "fit.yaml";
  std::ofstream(fit) << "scene: no_such_scene.yaml\n"
                        "parameters:\n  - {key: material.springs.structural, initial: 20, "
                        "bounds: [1, 1000]}\n"
                        "measurements:\n  - positions: {file: nodes.csv}\n";
  std::ofstream(scratch_ / "nodes.csv") << "id,x,y,z\n0,0,0,0\n";
  const ProgramOutcome outcome = Drape({"fit", fit.string(), "--out", out_.string()});
  EXPECT_EQ(outcome.exit_status, 2) << outcome.err;
  EXPECT_TRUE(HasLine(outcome.err, fit.string() + ":1:8: scene: cannot read the scene file",
                      "no such file"))
      << outcome.err;
  EXPECT_FALSE(fs::exists(out_));
}

// `drape compare` refuses, with exit 2 and no report, a scene that is missing or broken, a bad
// --set, a --repeat that is not a whole number and a --time-limit that is not finite (it wrote
// a report with exit 0, and read "2x" as 2, before).
TEST_F(BadInputTest, CompareRefusesBadScenesAndArguments) {
  const std::string valid = WriteValidScene(scratch_);
  const std::string broken = (kBadFolder / "option_negative_memory.yaml").string();
  const std::string missing = (scratch_ / "no_such_scene.yaml").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{missing}, missing + ": cannot read"},
      {{broken}, broken + ":16:25: solver.nlopt-lbfgs.memory: must be"},
      {{valid, "--set", "mesh.nodes"}, "--set:1:1: "},
      {{valid, "--set", "material.node_mass=-1"}, "--set:1:20: material.node_mass"},
      {{valid, "--repeat", "2x"}, "--repeat: expected a whole number"},
      {{valid, "--repeat", "0"}, "--repeat: expected a whole number"},
      {{valid, "--time-limit", "inf"}, "--time-limit: expected a finite number"},
      {{valid, "--time-limit", "5s"}, "--time-limit: expected a finite number"},
  };
  for (const auto& [extra, expected] : cases) {
    std::vector<std::string> args = {"compare", "--solvers",   "ceres-lbfgs",
                                     "--out",   out_.string(), "--no-plots"};
    args.insert(args.end(), extra.begin(), extra.end());
    SCOPED_TRACE(extra.back());
    const ProgramOutcome outcome = Drape(args);
    EXPECT_EQ(outcome.exit_status, 2) << outcome.err;
    EXPECT_NE(outcome.err.find(expected), std::string::npos) << outcome.err;
    EXPECT_FALSE(fs::exists(out_ / "report.md"));
  }
}

}  // namespace
}  // namespace drape
