// Result files: summary.json, nodes.csv, history.csv, kinetic.csv, mesh.vtk, mesh.obj, profile.csv,
// drape.png, shadow.png (the pictures drawn by src/output/render.h). Each is written to a temporary
// name in the output folder and renamed, so no half-written file is ever left.
#ifndef DRAPE_SRC_OUTPUT_WRITERS_H_
#define DRAPE_SRC_OUTPUT_WRITERS_H_

#include <string>

#include "src/analysis/solve_report.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

// Creates `directory` if needed and checks that a file can be written into it (before a solve, so
// that an unwritable folder costs no solving). Throws std::runtime_error saying why not.
void CheckOutputWritable(const std::string& directory);

// Writes what scene.output.write asks for into `directory` (created if needed), as a whole
// (src/output/result_folder.h): files of an earlier run that this one does not write are removed.
// A `solver.levels` run's figures (report.levels) add the `levels` and `extrapolation` members to
// summary.json.
void WriteOutputs(const Scene& scene, const Model& model, const SolveReport& report,
                  const std::string& directory);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_WRITERS_H_
