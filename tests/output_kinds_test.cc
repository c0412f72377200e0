// The output-kind registry (src/scene/output_kinds.h): every kind has the writers of its files
// (src/output/writers.cc), every file a writer writes is one the result folder cleans up, the
// reference (docs/reference.md) lists every kind and describes every file, and a solve that asks
// for every kind writes exactly the registry's files.
#include "src/scene/output_kinds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "src/model/model.h"
#include "src/output/result_folder.h"
#include "src/output/writers.h"
#include "src/run/solve_report.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "tests/scratch_folder.h"
#include "tests/test_scenes.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

std::string OutputKindsDocument(const std::string& relative) {
  std::ifstream file(testing::SourcePath(relative));
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// docs/reference.md from the line holding `begin` to the one holding `end` (excluded).
std::string OutputKindsReferencePart(const std::string& begin, const std::string& end) {
  const std::string reference = OutputKindsDocument("docs/reference.md");
  const size_t from = reference.find(begin);
  if (from == std::string::npos) return "";
  const size_t start = reference.find('\n', from) + 1;
  const size_t to = reference.find(end, start);
  return reference.substr(start, to == std::string::npos ? std::string::npos : to - start);
}

std::string OutputKindsTable() {
  std::ostringstream table;
  table << "| kind | files | default | what |\n|---|---|---|---|\n";
  for (const OutputKindRow& row : OutputKinds()) {
    std::string files;
    for (const std::string& file : row.files) files += (files.empty() ? "`" : ", `") + file + "`";
    const char* by_default = row.by_default ? "yes" : row.for_drape_test ? "a drape test" : "no";
    table << "| `" << row.name << "` | " << files << " | " << by_default << " | " << row.doc
          << " |\n";
  }
  return table.str();
}

// The files the writers write for `kind`.
std::set<std::string> WrittenFiles(OutputKind kind) {
  std::set<std::string> files;
  for (const OutputFileWriter& writer : OutputFileWriters()) {
    if (std::count(writer.kinds.begin(), writer.kinds.end(), kind)) files.insert(writer.file);
  }
  return files;
}

// The methods that record a per-step trace.
std::vector<std::string> TracingMethods() {
  std::vector<std::string> names;
  for (const SolverMethod& method : SolverMethods()) {
    if (method.records_trace) names.push_back(method.name);
  }
  return names;
}

TEST(OutputKinds, NamesAreUniqueAndEveryEnumValueHasItsRow) {
  std::set<std::string> names;
  for (const OutputKindRow& row : OutputKinds()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name << " is listed twice";
    EXPECT_EQ(&OutputKindOf(row.kind), &row) << row.name;
    EXPECT_EQ(FindOutputKind(row.name), &row) << row.name;
    EXPECT_FALSE(row.files.empty()) << row.name;
    EXPECT_FALSE(row.doc.empty()) << row.name;
  }
  EXPECT_EQ(OutputKinds().size(), static_cast<size_t>(OutputKind::kShadow) + 1)
      << "an OutputKind without its row (kShadow is the last value)";
  EXPECT_EQ(FindOutputKind("no-such-kind"), nullptr);
  EXPECT_EQ(TraceFileName("puiseux-dynamic"), "kinetic_puiseux-dynamic.csv");
}

TEST(OutputKinds, EveryKindHasAWriterForEachOfItsFiles) {
  for (const OutputKindRow& row : OutputKinds()) {
    EXPECT_EQ(WrittenFiles(row.kind), std::set<std::string>(row.files.begin(), row.files.end()))
        << "the writers of '" << row.name << "' (OutputFileWriters, src/output/writers.cc) do "
        << "not write the files of its row";
  }
  for (const OutputFileWriter& writer : OutputFileWriters()) {
    EXPECT_FALSE(writer.kinds.empty()) << writer.file << " is written for no kind";
    EXPECT_TRUE(writer.write) << writer.file;
  }
}

TEST(OutputKinds, EveryFileAWriterWritesIsCleanedUp) {
  const std::vector<std::string>& cleaned = ResultFileNames();
  auto is_cleaned = [&](const std::string& file) {
    return std::find(cleaned.begin(), cleaned.end(), file) != cleaned.end();
  };
  ASSERT_FALSE(TracingMethods().empty());
  for (const OutputFileWriter& writer : OutputFileWriters()) {
    for (const std::string& method : TracingMethods()) {
      const std::string file = OutputFileName(writer.file, method);
      EXPECT_TRUE(is_cleaned(file)) << file << " is not in ResultFileNames()";
    }
  }
  EXPECT_TRUE(is_cleaned(kSolvedSceneFile));
}

TEST(OutputKinds, TheDefaultsAreTheRowsSoMarked) {
  EXPECT_EQ(OutputSpec{}.write,
            (std::vector<std::string>{"summary", "nodes", "history", "vtk", "obj"}));
  EXPECT_EQ(DefaultOutputWrite(true),
            (std::vector<std::string>{"summary", "nodes", "history", "vtk", "obj", "gltf",
                                      "profile", "shadow"}));
}

TEST(OutputKinds, TheReferenceTableIsTheRegistry) {
  EXPECT_EQ(OutputKindsReferencePart("<!-- output-kinds:begin", "<!-- output-kinds:end"),
            OutputKindsTable())
      << "docs/reference.md's table between the output-kinds markers should read:\n"
      << OutputKindsTable();
}

// Under "## Outputs", each file has its paragraph, "**`file`** (`kind` ...", naming every kind
// that writes it.
TEST(OutputKinds, TheReferenceDescribesEveryFile) {
  const std::string outputs = OutputKindsReferencePart("\n## Outputs", "\n## ");
  ASSERT_FALSE(outputs.empty());
  for (const OutputKindRow& row : OutputKinds()) {
    for (const std::string& file : row.files) {
      const size_t at = outputs.find("\n**`" + file + "`** (");
      ASSERT_NE(at, std::string::npos) << "no paragraph **`" << file << "`** under ## Outputs";
      const std::string head = outputs.substr(at, outputs.find(')', at) - at);
      EXPECT_NE(head.find("`" + row.name + "`"), std::string::npos)
          << "the paragraph of " << file << " does not name the kind " << row.name;
    }
  }
}

// The documents name the trace file as it is written: kinetic_<method>.csv.
TEST(OutputKinds, TheDocumentsNameTheTraceFilesAsWritten) {
  std::set<std::string> written = {TraceFileName(kMethodPlaceholder)};
  for (const std::string& method : TracingMethods()) written.insert(TraceFileName(method));
  const std::regex trace_file(R"(kinetic[A-Za-z_<>.-]*\.csv)");
  for (const char* document : {"README.md", "docs/reference.md", "docs/architecture.md",
                               "docs/puiseux.md", "docs/python.md"}) {
    const std::string text = OutputKindsDocument(document);
    for (std::sregex_iterator it(text.begin(), text.end(), trace_file), end; it != end; ++it) {
      EXPECT_EQ(written.count(it->str()), 1u) << document << " names " << it->str();
    }
  }
  const std::string methods = OutputKindsReferencePart("| method | what it does |", "\n\n");
  for (const std::string& method : TracingMethods()) {
    const size_t row = methods.find("| `" + method + "` |");
    ASSERT_NE(row, std::string::npos) << method;
    const std::string line = methods.substr(row, methods.find('\n', row) - row);
    EXPECT_NE(line.find("`" + TraceFileName(method) + "`"), std::string::npos)
        << "the reference's method table does not say that " << method << " writes "
        << TraceFileName(method);
  }
}

// Every method records a trace exactly when its catalogue row says so (three iterations on a
// small hanging sheet).
TEST(OutputKinds, TheMethodsThatRecordATraceAreTheCataloguesSo) {
  const Scene scene = LoadSceneText(
      "mesh: {kind: grid, size: [0.2, 0.2], nodes: [3, 3]}\n"
      "material: {density: 0.2, springs: {structural: 100, shear: 50, flexion: 1}}\n"
      "fixed:\n  - nodes: {corner: top-left}\n  - nodes: {corner: top-right}\n"
      "loads: {gravity: [0, 0, -9.81]}\nsolver: {max_iterations: 3}\n",
      "<string>", fs::temp_directory_path().string());
  for (const SolverMethod& method : SolverMethods()) {
    Model model = BuildModel(scene);
    const RunResult result = RunSolve(scene, model, method.name);
    EXPECT_EQ(!result.summary.trace_columns.empty(), method.records_trace) << method.name;
  }
}

// A solve that asks for every kind (a circle, so it has a drape; a method with a trace) writes
// exactly the registry's files and scene.yaml.
TEST(OutputKinds, ASolveAskingForEveryKindWritesTheRegistrysFiles) {
  const testing::ScratchFolder scratch("output_kinds");
  const fs::path folder = scratch / "out";  // made by WriteOutputs
  std::string kinds;
  for (const std::string& name : OutputKindNames()) kinds += (kinds.empty() ? "" : ", ") + name;
  const Scene scene = LoadSceneText(
      "mesh: {kind: circle, radius: 0.1, spacing: 0.05}\n"
      "material: {density: 0.2, springs: {structural: 100, shear: 50, flexion: 1}}\n"
      "fixed:\n  - nodes: {within: {center: [0, 0, 0], radius: 0.01}}\n"
      "loads: {gravity: [0, 0, -9.81]}\n"
      "solver: {method: explicit-euler, max_iterations: 20}\n"
      "output: {directory: " +
          folder.string() + ", write: [" + kinds + "]}\n",
      "<string>", fs::temp_directory_path().string());
  Model model = BuildModel(scene);
  const SolveReport report = SolveAndReport(scene, model, scene.solver.method);
  ASSERT_TRUE(report.drape.has_value());
  WriteOutputs(scene, model, report, folder.string());
  std::set<std::string> expected = {kSolvedSceneFile};
  for (const OutputKindRow& row : OutputKinds()) {
    for (const std::string& file : row.files)
      expected.insert(OutputFileName(file, "explicit-euler"));
  }
  std::set<std::string> written;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name[0] != '.') written.insert(name);  // not the folder's lock
  }
  EXPECT_EQ(written, expected);
}

}  // namespace
}  // namespace drape
