// drape's Python module, _drape (the package python/drape wraps it): the scene loader, the model
// builder and SolveAndReport that `drape solve` runs, with NumPy arrays for the results, and the
// repeated drops, the fit and the sweep that `drape solve --drops`, `drape fit` and `drape sweep`
// run, writing their files. The package's __init__.py turns `set=` dicts into --set overrides,
// raises KeyboardInterrupt after an interrupted solve and gives the classes their Python face;
// this file holds only what needs C++.
#include <Python.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <signal.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/analysis/mesh_rule.h"
#include "src/cli/cli.h"
#include "src/fit/fit_file.h"
#include "src/fit/fit_methods.h"
#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"
#include "src/fit/fit_writer.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/output/version.h"
#include "src/output/writers.h"
#include "src/run/solve_report.h"
#include "src/run/state_text.h"
#include "src/scene/drape_test.h"
#include "src/scene/material_models.h"
#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solver.h"
#include "src/sweep/drops.h"
#include "src/sweep/sweep.h"
#include "src/sweep/sweep_file.h"

namespace py = pybind11;

namespace drape {
namespace {

// A loaded scene and the overrides it was loaded with (for the result's provenance).
struct PyScene {
  Scene scene;
  std::vector<std::string> overrides;
};

// A solved scene: what Result's arrays and write() are made from.
struct PySolved {
  Scene scene;
  Model model;
  SolveReport report;
  Provenance provenance;
  bool interrupted = false;  // stopped by Ctrl-C: the last iterate
};

// (n, 3) float64 array of 3 values per node.
py::array_t<double> NodeArray(const std::vector<double>& values) {
  py::array_t<double> array({static_cast<py::ssize_t>(values.size() / 3), py::ssize_t{3}});
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::dict CheckData(const PyScene& loaded) {
  const Model model = BuildModel(loaded.scene);
  py::dict data;
  data["name"] = loaded.scene.name;
  data["nodes"] = model.num_nodes;
  data["free_dofs"] = model.num_free_dofs();
  data["terms"] = model.TermCounts();
  data["solver"] = loaded.scene.solver.method;
  py::dict material;
  for (const MaterialValue& value : MaterialSiValues(loaded.scene.material)) {
    material[py::str(value.key)] = py::make_tuple(value.value, value.unit);
  }
  data["material_si"] = material;
  data["model"] = MaterialModelName(loaded.scene.material.model);
  if (const std::optional<MeshAdvice> advice = AdviseMesh(loaded.scene, model);
      advice && advice->coarse) {
    data["warning"] = CoarseMeshWarning(*advice);
  }
  return data;
}

// The free coordinates of `start` ((n, 3) positions) in the model: a warm start.
void WarmStart(const py::array_t<double>& start, Model* model) {
  const auto view = start.unchecked<2>();
  if (view.shape(0) != model->num_nodes || view.shape(1) != 3) {
    throw py::value_error("start: expected an array of shape (" + std::to_string(model->num_nodes) +
                          ", 3), got (" + std::to_string(view.shape(0)) + ", " +
                          std::to_string(view.shape(1)) + ")");
  }
  for (int node = 0; node < model->num_nodes; ++node) {
    for (int c = 0; c < 3; ++c) {
      if (!model->fixed[3 * node + c]) model->positions[3 * node + c] = view(node, c);
    }
  }
}

// Solves as `drape solve` does (SolveAndReport), without the GIL; each iteration takes it back
// briefly to run Python's signal handlers, so that Ctrl-C stops the solve at its last iterate.
std::shared_ptr<PySolved> Solve(const PyScene& loaded, const std::optional<std::string>& solver,
                                const std::optional<py::array_t<double>>& start) {
  auto solved = std::make_shared<PySolved>();
  solved->scene = loaded.scene;
  if (solver) solved->scene.solver.method = *solver;
  RequireKnownSolver(solved->scene);  // as drape solve: before the model is built
  solved->model = BuildModel(solved->scene);
  if (start) WarmStart(*start, &solved->model);
  solved->provenance = Provenance{"python: drape.solve", loaded.overrides};
  bool interrupted = false;
  const auto on_iteration = [&interrupted](const IterationRecord&) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {  // the handler raised KeyboardInterrupt: kept for later
      PyErr_Clear();
      interrupted = true;
    }
    return !interrupted;
  };
  {
    py::gil_scoped_release release;
    const LibrariesHeldOnOneThread held;  // NumPy's OpenBLAS threads given back at the end
    solved->report = SolveAndReport(solved->scene, solved->model, solved->scene.solver.method,
                                    on_iteration, /*automatic_levels=*/!start.has_value());
  }
  solved->interrupted = interrupted;
  return solved;
}

py::dict ResultArrays(const PySolved& solved) {
  const Model& model = solved.model;
  const RunResult& result = solved.report.result;
  py::dict arrays;
  arrays["positions"] = NodeArray(model.positions);
  arrays["initial_positions"] = NodeArray(model.initial);
  arrays["reactions"] = NodeArray(NodeReactions(model, result));
  arrays["contact_forces"] = NodeArray(NodeContactForces(model, result));
  py::array_t<bool> fixed({static_cast<py::ssize_t>(model.num_nodes), py::ssize_t{3}});
  for (int k = 0; k < model.num_dofs(); ++k) fixed.mutable_data()[k] = model.fixed[k] != 0;
  arrays["fixed"] = fixed;
  py::array_t<int> faces({static_cast<py::ssize_t>(model.triangles.size()), py::ssize_t{3}});
  for (size_t t = 0; t < model.triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) faces.mutable_data()[3 * t + c] = model.triangles[t][c];
  }
  arrays["faces"] = faces;
  return arrays;
}

py::dict ResultFigures(const PySolved& solved) {
  const RunResult& result = solved.report.result;
  py::dict figures;
  figures["converged"] = result.converged;
  figures["stable"] = result.converged && result.stability.computed && result.stability.stable;
  figures["state"] = StateText(result);
  figures["termination"] = result.summary.termination;
  figures["iterations"] = result.summary.iterations;
  figures["interrupted"] = solved.interrupted;
  py::dict energy;
  energy["total"] = result.certificate.energy;
  for (const auto& [type, value] : result.certificate.energy_by_type) energy[py::str(type)] = value;
  figures["energy"] = energy;
  const double coefficient = ReportedDrapeCoefficient(solved.report);
  figures["drape_coefficient"] =
      std::isfinite(coefficient) ? py::object(py::float_(coefficient)) : py::object(py::none());
  const std::optional<double> error = ReportedDrapeCoefficientError(solved.report);
  figures["drape_coefficient_error"] =
      error ? py::object(py::float_(*error)) : py::object(py::none());
  figures["summary_json"] =
      SummaryJsonText(solved.scene, solved.model, solved.report, solved.provenance);
  return figures;
}

void Write(const PySolved& solved, const std::string& directory) {
  CheckOutputWritable(directory);
  WriteOutputs(solved.scene, solved.model, solved.report, directory, solved.provenance);
}

// While alive, SIGINT and SIGTERM stop drape's loops (RequestInterrupt: a fit at its next
// evaluation, a sweep at its next task) instead of running Python's handlers, which are put back
// at the end. For the fit and the sweep, whose loops have no per-iteration hook into Python.
class InterruptScope {
 public:
  InterruptScope() {
    sigaction(SIGINT, nullptr, &interrupt_);
    sigaction(SIGTERM, nullptr, &terminate_);
    ClearInterrupt();
    InstallInterruptHandler();
  }
  ~InterruptScope() {
    sigaction(SIGINT, &interrupt_, nullptr);
    sigaction(SIGTERM, &terminate_, nullptr);
    ClearInterrupt();
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  struct sigaction interrupt_ {};
  struct sigaction terminate_ {};
};

// A thread count as the command line's --threads takes it: a whole number ≥ 0 (0: the cores).
void RequireThreadCount(int threads) {
  if (threads < 0) {
    throw InputError("threads: expected a whole number >= 0 (0: the machine's cores), got " +
                     std::to_string(threads));
  }
}

// `drape fit` without its command line: the fit file (with --set overrides and --method) solved,
// its files written into `directory`. Returns whether it converged and whether it was interrupted.
py::dict Fit(const std::string& path, const std::vector<std::string>& overrides,
             const std::optional<std::string>& method, const std::string& directory, int threads) {
  RequireThreadCount(threads);
  FitSpec spec = LoadFitFile(path, overrides);
  if (method) {
    if (!FindFitMethod(*method)) {
      throw InputError("method: unknown fit method '" + *method + "' (known: " + FitMethodList() +
                       ")");
    }
    spec.method = *method;
  }
  spec.output_directory = directory;
  CheckOutputWritable(directory);  // before any solve
  FitProblem problem(spec, threads);
  FitResult result;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    const LibrariesHeldOnOneThread held;  // NumPy's OpenBLAS threads given back at the end
    const InterruptScope scope;
    result = RunFit(problem);
    interrupted = InterruptRequested();
  }
  if (result.parameters.empty()) throw std::runtime_error("drape fit: " + result.termination);
  WriteFitOutputs(problem, result, directory, Provenance{"python: drape.fit", overrides});
  py::dict outcome;
  outcome["converged"] = result.converged;
  outcome["interrupted"] = interrupted;
  return outcome;
}

// `drape sweep` without its command line: the sweep file's tasks solved into `out` (empty: the
// sweep file's own output folder). Returns the sweep's counts and folder.
py::dict Sweep(const std::string& path, const std::string& out, int threads, bool plots) {
  RequireThreadCount(threads);
  const SweepSpec spec = LoadSweepFile(path);
  SweepOptions options;
  options.out = out;
  options.threads = threads;
  options.plots = plots;
  options.command_line = "python: drape.sweep";
  SweepSummary summary;
  {
    py::gil_scoped_release release;
    const LibrariesHeldOnOneThread held;  // NumPy's OpenBLAS threads given back at the end
    const InterruptScope scope;
    summary = RunSweep(spec, options, std::cerr);
  }
  py::dict outcome;
  outcome["directory"] = summary.directory;
  outcome["tasks"] = summary.tasks;
  outcome["solved"] = summary.solved;
  outcome["skipped"] = summary.skipped;
  outcome["rows"] = summary.rows;
  outcome["converged"] = summary.converged;
  outcome["interrupted"] = summary.interrupted;
  return outcome;
}

// `drape solve --drops N` without its command line: the loaded drape test's drops (N ≥ 1; 0: the
// scene's drape_test.drops) solved into `directory` on `threads` threads (0: the cores). Returns
// the stdout line and whether Ctrl-C stopped it.
py::dict Drops(const PyScene& loaded, int drops, const std::string& directory, int threads) {
  if (!loaded.scene.drape_test) {
    throw InputError(
        "drops: needs a drape test: give the scene a drape_test block (docs/reference.md, "
        "\"`drape_test`\")");
  }
  if (drops < 0 || drops > kMostDrops) {
    throw InputError("drops: expected a whole number from 1 to " + std::to_string(kMostDrops) +
                     ", got " + std::to_string(drops));
  }
  RequireThreadCount(threads);
  DropsOptions options;
  options.drops = drops > 0 ? drops : loaded.scene.drape_test->drops;
  options.threads = threads;
  options.directory = directory;
  options.command_line = "python: drape.drops";
  options.overrides = loaded.overrides;
  DropsSummary summary;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    const LibrariesHeldOnOneThread held;  // NumPy's OpenBLAS threads given back at the end
    const InterruptScope scope;
    summary = RunDrops(loaded.scene, options, std::cerr);
    interrupted = InterruptRequested();
  }
  py::dict outcome;
  outcome["line"] = DropsLine(summary.statistics, summary.mesh_advice);
  outcome["interrupted"] = interrupted;
  return outcome;
}

// drape's InputError as the package's drape.InputError(message, file, line, column, key).
// By value: pybind11's ExceptionTranslator type.
void TranslateInputError(
    std::exception_ptr pointer) {  // NOLINT(performance-unnecessary-value-param)
  try {
    if (pointer) std::rethrow_exception(pointer);
  } catch (const InputError& error) {
    const py::object type = py::module_::import("drape").attr("InputError");
    const Location& where = error.where();
    const py::object value =
        type(error.what(), where.file, where.line, where.column, where.key, error.problem());
    PyErr_SetObject(type.ptr(), value.ptr());
  }
}

}  // namespace
}  // namespace drape

PYBIND11_MODULE(_drape, module) {
  using namespace drape;
  module.doc() = "drape's C++ core: load, check and solve scenes (use the package drape)";
  py::register_exception_translator(&TranslateInputError);
  py::class_<PyScene, std::shared_ptr<PyScene>>(module, "Scene")
      .def_property_readonly("name", [](const PyScene& s) { return s.scene.name; })
      .def_property_readonly("file", [](const PyScene& s) { return s.scene.file; })
      .def_property_readonly("overrides", [](const PyScene& s) { return s.overrides; })
      .def("check", &CheckData);
  py::class_<PySolved, std::shared_ptr<PySolved>>(module, "Solved")
      .def("arrays", &ResultArrays)
      .def("figures", &ResultFigures)
      .def("write", &Write, py::arg("directory"));
  module.def(
      "load",
      [](const std::string& path, const std::vector<std::string>& overrides) {
        return std::make_shared<PyScene>(PyScene{LoadScene(path, overrides), overrides});
      },
      py::arg("path"), py::arg("overrides"));
  module.def(
      "loads",
      [](const std::string& text, const std::string& label, const std::string& directory,
         const std::vector<std::string>& overrides) {
        return std::make_shared<PyScene>(
            PyScene{LoadSceneText(text, label, directory, overrides), overrides});
      },
      py::arg("text"), py::arg("label"), py::arg("directory"), py::arg("overrides"));
  module.def("solve", &Solve, py::arg("scene"), py::arg("solver"), py::arg("start"));
  module.def("fit", &Fit, py::arg("path"), py::arg("overrides"), py::arg("method"),
             py::arg("directory"), py::arg("threads"));
  module.def("drops", &Drops, py::arg("scene"), py::arg("drops"), py::arg("directory"),
             py::arg("threads"));
  module.def("sweep", &Sweep, py::arg("path"), py::arg("out"), py::arg("threads"),
             py::arg("plots"));
  module.def("version", &DrapeVersion);
}
