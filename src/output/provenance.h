// How an output was made, recorded the same way in every output of drape: drape's version, the
// OpenBLAS kernels (the iterates' rounding depends on them), the command as run and its `--set`
// overrides. As JSON members in summary.json, fit.json, sweep.json, compare.json and a drops
// run's summary.json; as one line of text in mesh.vtk's title, mesh.obj's and scene.yaml's first
// comment, report.md and the HTML reports; the PNG pictures carry the version (png_text.h). CSV
// files carry none: each is read beside its folder's JSON file, which does (pandas reads a CSV
// with a comment line only when told to skip it).
#ifndef DRAPE_SRC_OUTPUT_PROVENANCE_H_
#define DRAPE_SRC_OUTPUT_PROVENANCE_H_

#include <string>
#include <utility>
#include <vector>

namespace drape {

struct Provenance {
  Provenance() = default;
  Provenance(std::string command, std::vector<std::string> set,  // NOLINT: {a, b} reads as before
             std::string applied_calibration = "")
      : command_line(std::move(command)),
        overrides(std::move(set)),
        calibration(std::move(applied_calibration)) {}

  std::string command_line;            // the command as run, shell-quoted
  std::vector<std::string> overrides;  // the --set key.path=value overrides, in order
  // the calibration applied (--calibration: "FILE (bending_scale 1.5)"); "" for none
  std::string calibration;
};

// `"key": JSON value` pairs, in order: drape_version, blas_kernels, command_line, overrides, and
// calibration where one was applied.
std::vector<std::pair<std::string, std::string>> ProvenanceMembers(const Provenance& provenance);

// The same as text on one line: "drape 0.1 (git 4bf4acd); command: drape solve a.yaml --set
// solver.method=newton" (then "; overrides: ..." when the command line does not hold them, as
// from Python). No line break: it fits a comment or a title line.
std::string ProvenanceLine(const Provenance& provenance);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_PROVENANCE_H_
