// The output kinds a scene's `output.write` may name: one row each, the single owner of a kind's
// name, the files it writes, its documentation and whether a run writes it by default. The scene
// loader checks `output.write` against it and takes its defaults from it; the result folder
// removes the files of an earlier run by it (src/output/result_folder.h); `drape solvers` and
// docs/reference.md name the trace file by it. The code that writes each file is registered under
// the same kind in src/output/writers.cc (OutputFileWriters), which the scene layer cannot see.
//
// Adding a kind: a value in OutputKind, one row in OutputKinds() (src/scene/output_kinds.cc), its
// writer in OutputFileWriters() and a test that reads the file back (tests/writers_test.cc), and
// its row in docs/reference.md's table of output kinds plus a paragraph `**`<file>`**` under
// "## Outputs". tests/output_kinds_test.cc fails until each of these is there.
#ifndef DRAPE_SRC_SCENE_OUTPUT_KINDS_H_
#define DRAPE_SRC_SCENE_OUTPUT_KINDS_H_

#include <string>
#include <vector>

namespace drape {

enum class OutputKind {
  kSummary,
  kNodes,
  kHistory,
  kVtk,
  kObj,
  kGltf,
  kPng,
  kKinetic,
  kProfile,
  kShadow
};

// In a file name, the solver method's name: the trace's columns differ between methods.
constexpr const char* kMethodPlaceholder = "<method>";

struct OutputKindRow {
  OutputKind kind;
  std::string name;                // in `output.write`
  std::vector<std::string> files;  // every file it may write (kMethodPlaceholder in a pattern)
  std::string doc;                 // docs/reference.md's table of output kinds: when and what
  bool by_default = false;         // in the default `output.write`
  bool for_drape_test = false;     // added to the default `output.write` of a drape test
};

// Every kind, in the order of the reference's table.
const std::vector<OutputKindRow>& OutputKinds();
const OutputKindRow& OutputKindOf(OutputKind kind);
// The row named `name`; null for a name that is no kind.
const OutputKindRow* FindOutputKind(const std::string& name);
std::vector<std::string> OutputKindNames();

// The default `output.write`: the kinds written by default, then for a drape test its figures.
std::vector<std::string> DefaultOutputWrite(bool drape_test);

// The file the method `solver` writes for `pattern` (kMethodPlaceholder replaced).
std::string OutputFileName(const std::string& pattern, const std::string& solver);
// The per-step trace of a method that records one: kinetic_<method>.csv.
std::string TraceFileName(const std::string& solver);

// The file written into every result folder besides the kinds': the scene as solved.
constexpr const char* kSolvedSceneFile = "scene.yaml";

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_OUTPUT_KINDS_H_
