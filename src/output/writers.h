// Result files: summary.json, nodes.csv, history.csv, kinetic_<method>.csv, mesh.vtk, mesh.obj,
// drape.glb (src/output/gltf.h), profile.csv, drape.png, shadow.png (the pictures drawn by
// src/output/render.h), scene.yaml: the files of the output kinds of src/scene/output_kinds.h, each
// written by its row of OutputFileWriters(). Each is written to a temporary name in the output
// folder and renamed, so no half-written file is ever left.
#ifndef DRAPE_SRC_OUTPUT_WRITERS_H_
#define DRAPE_SRC_OUTPUT_WRITERS_H_

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "src/analysis/mesh_rule.h"
#include "src/model/model.h"
#include "src/output/provenance.h"
#include "src/run/solve_report.h"
#include "src/scene/scene.h"

namespace drape {

// Creates `directory` if needed and checks that a file can be written into it (before a solve, so
// that an unwritable folder costs no solving). Throws std::runtime_error saying why not. A file
// where the folder or a folder above it would be is the fault of what named the folder: an
// InputError at `key` where a key of an input file did (a scene's output.directory; line 0: no
// key), else an error that names `option` where an option did ("--out"; empty: none).
void CheckOutputWritable(const std::string& directory, const Location& key = {},
                         const std::string& option = "");

// The version of the result files' layout (summary.json's `format_version`, for every file of the
// folder); raised whenever a file changes its columns, its keys or the form of its values.
constexpr int kResultFormatVersion = 4;

// One material parameter in SI units, as the model uses it (after any KES or Peirce conversion).
struct MaterialValue {
  std::string key;   // the scene key under material (density, E_warp, structural.warp, ...)
  double value = 0;  // SI
  std::string unit;  // "kg/m^2", "N/m", "N*m", "kg", "1"
};
std::vector<MaterialValue> MaterialSiValues(const MaterialSpec& material);

// nodes.csv's columns, in order (units in the names; booleans true/false, which pandas reads as
// booleans). `drape fit` reads a nodes.csv as measured positions by these names
// (src/fit/fit_file.cc).
const std::vector<std::string>& NodesCsvColumns();

// summary.json's `mesh_rule` object (also in a drops run's summary.json).
std::string MeshRuleJson(const MeshAdvice& advice);

// summary.json's text, as WriteOutputs writes it (the Python module's Result.summary).
std::string SummaryJsonText(const Scene& scene, const Model& model, const SolveReport& report,
                            const Provenance& provenance = {});

// nodes.csv's forces, 3 per node (N): the supports' reactions (0 on free coordinates) and the
// obstacles' contact forces (0 without obstacles; NaN where the certificate could not be made).
std::vector<double> NodeReactions(const Model& model, const RunResult& result);
std::vector<double> NodeContactForces(const Model& model, const RunResult& result);

// What a file's writer sees.
struct OutputContext {
  const Scene& scene;
  const Model& model;
  const SolveReport& report;
  const Provenance& provenance;
};

// The writer of one file of the output kinds (src/scene/output_kinds.h): every file a kind's row
// names has one (tests/output_kinds_test.cc).
struct OutputFileWriter {
  std::string file;               // as the kinds' rows name it (kMethodPlaceholder: the method)
  std::vector<OutputKind> kinds;  // written when `output.write` names one of these
  // Whether this run has the file (a drape coefficient, a trace); null: always.
  std::function<bool(const OutputContext&)> applies;
  std::function<void(const OutputContext&, std::ostream&)> write;
};
const std::vector<OutputFileWriter>& OutputFileWriters();

// Writes what scene.output.write asks for into `directory` (created if needed), as a whole
// (src/output/result_folder.h): files of an earlier run that this one does not write are removed.
// A `solver.levels` run's figures (report.levels) add the `levels` and `extrapolation` members to
// summary.json. scene.yaml (the scene as solved, src/output/scene_yaml.h) is always written;
// `provenance` goes into summary.json.
void WriteOutputs(const Scene& scene, const Model& model, const SolveReport& report,
                  const std::string& directory, const Provenance& provenance = {});

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_WRITERS_H_
