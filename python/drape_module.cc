// drape's Python module, _drape (the package python/drape wraps it): the scene loader, the model
// builder and SolveAndReport that `drape solve` runs, with NumPy arrays for the results and for a
// mesh given as arrays; the commands of src/commands/ (fit, repeated drops, sweep, a table of
// fabrics), which the command line runs too, with their progress and warnings sent to Python as
// lines (a `progress` callable, and warnings returned for warnings.warn); the sensitivities of an
// equilibrium (src/run/sensitivity.h). The package's __init__.py turns `set=` dicts into --set
// overrides, raises KeyboardInterrupt after an interrupted solve, emits the warnings and gives
// the classes their Python face; this file holds only what needs C++.
#include <Python.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <signal.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "src/analysis/mesh_rule.h"
#include "src/cli/cli.h"
#include "src/cli/progress.h"
#include "src/commands/commands.h"
#include "src/fit/fit_solver.h"
#include "src/model/model.h"
#include "src/numerics/library_threads.h"
#include "src/output/json.h"
#include "src/output/scene_json.h"
#include "src/output/version.h"
#include "src/output/writers.h"
#include "src/run/sensitivity.h"
#include "src/run/solve_report.h"
#include "src/run/state_text.h"
#include "src/scene/drape_tester.h"
#include "src/scene/material_models.h"
#include "src/scene/scene.h"
#include "src/scene/scene_loader.h"
#include "src/scene/solver_methods.h"
#include "src/solvers/solver.h"
#include "src/sweep/drops.h"
#include "src/sweep/fabrics.h"
#include "src/sweep/sweep.h"

namespace py = pybind11;

namespace drape {
namespace {

// A loaded scene, the overrides it was loaded with (for the result's provenance) and how to load
// it again with more (a sensitivity's parameter moved: the same file or text, the same mesh).
struct PyScene {
  Scene scene;
  std::vector<std::string> overrides;
  std::function<Scene(const std::vector<std::string>&)> reload;
};

// Where a command's lines go: each whole line to Python, with the GIL. A warning ("…warning: …")
// is kept for warnings.warn after the command; any other line is progress, handed to the
// `progress` callable (None: dropped). An exception from the callable is kept, stops the command
// (RequestInterrupt) and is raised when it returns.
class PythonLines : public std::streambuf {
 public:
  explicit PythonLines(py::object progress) : progress_(std::move(progress)) {}
  ~PythonLines() override = default;  // destroyed with the GIL held (PythonLog's owner holds it)
  PythonLines(const PythonLines&) = delete;
  PythonLines& operator=(const PythonLines&) = delete;

  std::vector<std::string> warnings() const { return warnings_; }
  // Whether the callable's exception is a KeyboardInterrupt (Ctrl-C while it ran, Python's
  // handler raising in it): then it is taken, for the caller to report as an interrupted run with
  // its result. With the GIL held.
  bool TakeKeyboardInterrupt() {
    if (!error_ || !error_->matches(PyExc_KeyboardInterrupt)) return false;
    error_.reset();
    return true;
  }
  // Raises the callable's exception, if it raised one (with the GIL held).
  void RaiseIfFailed() {
    if (error_) {
      py::error_already_set error = std::move(*error_);
      error_.reset();
      throw error;
    }
  }

 protected:
  int_type overflow(int_type c) override {
    if (c == traits_type::eof()) return c;
    if (c == '\n') {
      Emit();
    } else {
      line_ += static_cast<char>(c);
    }
    return c;
  }
  int sync() override { return 0; }

 private:
  void Emit() {
    const std::string line = std::move(line_);
    line_.clear();
    py::gil_scoped_acquire gil;
    if (line.find("warning: ") != std::string::npos) {
      warnings_.push_back(line);
      return;
    }
    if (progress_.is_none() || error_) return;
    try {
      progress_(line);
    } catch (py::error_already_set& error) {
      error_.emplace(std::move(error));
      RequestInterrupt();
    }
  }

  py::object progress_;
  std::string line_;
  std::vector<std::string> warnings_;
  std::optional<py::error_already_set> error_;
};

// A command's log stream into Python (PythonLines) and what the command gives back with it.
struct PythonLog {
  explicit PythonLog(py::object progress) : lines(std::move(progress)), stream(&lines) {}
  PythonLines lines;
  std::ostream stream;
};

// A solved scene: what Result's arrays and write() are made from.
struct PySolved {
  Scene scene;
  Model model;
  SolveReport report;
  Provenance provenance;
  bool interrupted = false;           // stopped by Ctrl-C: the last iterate
  std::vector<std::string> warnings;  // for warnings.warn (the mesh rule's)
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
  py::dict given;  // the kes, fast and bending_length keys as the scene gives them
  for (const GivenMeasurement& value : loaded.scene.material.finite_volume.measured) {
    given[py::str(value.key)] = py::make_tuple(value.value, value.unit);
  }
  data["material_as_given"] = given;
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

// A method name given to solve(): one of `drape solvers`, else an InputError at `solver`.
void RequireSolverName(const std::string& name) {
  if (!FindSolver(name)) {
    throw InputError(Location{"solver", 0, 0, ""}, UnknownSolverText(name));
  }
}

// Solves as `drape solve` does (SolveAndReport), without the GIL; each iteration takes it back
// briefly to run Python's signal handlers, so that Ctrl-C stops the solve at its last iterate,
// and a progress line goes to `progress` every second of a long solve.
std::shared_ptr<PySolved> Solve(const PyScene& loaded, const std::optional<std::string>& solver,
                                const std::optional<py::array_t<double>>& start,
                                const py::object& progress) {
  if (solver) RequireSolverName(*solver);
  auto solved = std::make_shared<PySolved>();
  solved->scene = loaded.scene;
  if (solver) solved->scene.solver.method = *solver;
  RequireKnownSolver(solved->scene);  // as drape solve: before the model is built
  solved->model = BuildModel(solved->scene);
  if (start) WarmStart(*start, &solved->model);
  if (const std::optional<MeshAdvice> advice = AdviseMesh(solved->scene, solved->model);
      advice && advice->coarse) {
    solved->warnings.push_back(CoarseMeshWarning(*advice));
  }
  solved->provenance = Provenance{"python: drape.solve", loaded.overrides};
  PythonLog log(progress);
  ProgressLine line(log.stream, 1.0, /*plain=*/true);
  bool interrupted = false;
  const auto on_iteration = [&interrupted, &line](const IterationRecord& record) {
    line.Update(record);
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {  // the handler raised KeyboardInterrupt: kept for later
      PyErr_Clear();
      interrupted = true;
    }
    return !interrupted && !InterruptRequested();
  };
  {
    py::gil_scoped_release release;
    const LibrariesHeldOnOneThread held;  // NumPy's OpenBLAS threads given back at the end
    ClearInterrupt();
    solved->report = SolveAndReport(solved->scene, solved->model, solved->scene.solver.method,
                                    on_iteration, /*automatic_levels=*/!start.has_value());
    ClearInterrupt();
  }
  // Ctrl-C that Python's handler raised inside the progress callable stopped the solve as Ctrl-C
  // between iterations does: an interrupted result, not a bare KeyboardInterrupt.
  if (log.lines.TakeKeyboardInterrupt()) interrupted = true;
  log.lines.RaiseIfFailed();
  solved->interrupted = interrupted;
  const std::optional<AccuracyOutcome> accuracy = AccuracyOf(solved->scene, solved->report);
  if (!interrupted && accuracy && accuracy->Failed(solved->report.result.converged)) {
    solved->warnings.push_back(AccuracyFailure(*accuracy, solved->report.result.converged));
  }
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
  figures["stable"] = result.converged && result.stability.computed && result.stability.stable &&
                      !result.PassesThrough();
  figures["state"] = StateText(result);
  figures["termination"] = result.summary.termination;
  figures["iterations"] = result.summary.iterations;
  figures["interrupted"] = solved.interrupted;
  figures["warnings"] = solved.warnings;
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

// What every command gives back to Python: its warnings (for warnings.warn) and whether a signal
// stopped it.
void AddLogOutcome(const PythonLog& log, bool interrupted, py::dict* outcome) {
  (*outcome)["warnings"] = log.lines.warnings();
  (*outcome)["interrupted"] = interrupted;
}

// Runs `command` without the GIL, with drape's own signal handling (InterruptScope) and NumPy's
// OpenBLAS threads given back at the end; then raises what the progress callable raised.
template <typename Command>
auto RunCommandForPython(PythonLog* log, const Command& command) {
  decltype(command()) outcome;
  {
    py::gil_scoped_release release;
    const LibrariesHeldOnOneThread held;
    const InterruptScope scope;
    outcome = command();
  }
  log->lines.RaiseIfFailed();
  return outcome;
}

// The command layer's option errors as InputError (drape.InputError in Python).
template <typename Command>
auto WithOptionErrors(const Command& command) {
  try {
    return command();
  } catch (const CommandOptionError& error) {
    throw InputError(error.what());
  }
}

// `drape fit` (src/commands/commands.h): the fit file with --set overrides and --method, its
// files written into `directory`.
py::dict Fit(const std::string& path, const std::vector<std::string>& overrides,
             const std::optional<std::string>& method, const std::string& directory, int threads,
             const py::object& progress) {
  FitCommand command{path, overrides, method, directory, threads};
  PythonLog log(progress);
  const FitCommandResult result = WithOptionErrors([&] {
    return RunCommandForPython(&log, [&] {
      return RunFitCommand(command, CommandContext{log.stream, "python: drape.fit"});
    });
  });
  if (!result.written) throw std::runtime_error(result.line);
  py::dict outcome;
  outcome["converged"] = result.result.converged;
  outcome["line"] = result.line;
  AddLogOutcome(log, result.interrupted, &outcome);
  return outcome;
}

// `drape sweep`: the sweep file's tasks solved into `out` (empty: the sweep file's own folder).
py::dict Sweep(const std::string& path, const std::string& out, int threads, bool plots,
               const py::object& progress) {
  SweepCommand command;
  command.file = path;
  command.out = out;
  command.threads = threads;
  command.plots = plots;
  PythonLog log(progress);
  const SweepCommandResult result = WithOptionErrors([&] {
    return RunCommandForPython(&log, [&] {
      return RunSweepCommand(command, CommandContext{log.stream, "python: drape.sweep"});
    });
  });
  py::dict outcome;
  outcome["directory"] = result.summary.directory;
  outcome["line"] = result.line;
  AddLogOutcome(log, result.summary.interrupted, &outcome);
  return outcome;
}

// `drape solve --drops N`: the loaded drape test's drops (N ≥ 1; 0: the scene's drape_test.drops)
// solved into `directory`.
py::dict Drops(const PyScene& loaded, int drops, const std::string& directory, int threads,
               const py::object& progress) {
  DropsCommand command;
  command.drops = drops;
  command.threads = threads;
  command.directory = directory;
  command.overrides = loaded.overrides;
  PythonLog log(progress);
  const DropsCommandResult result = WithOptionErrors([&] {
    return RunCommandForPython(&log, [&] {
      return RunDropsCommand(loaded.scene, command,
                             CommandContext{log.stream, "python: drape.drops"});
    });
  });
  py::dict outcome;
  outcome["line"] = DropsLine(result.summary.statistics, result.summary.mesh_advice);
  AddLogOutcome(log, result.interrupted, &outcome);
  return outcome;
}

// `drape fabrics`: the table solved on the base scene (empty: the standard tester) into `out`.
py::dict Fabrics(const std::string& table, const std::string& scene,
                 const std::vector<std::string>& overrides, std::optional<int> drops,
                 const std::string& out, int threads, const py::object& progress,
                 const std::string& calibration) {
  FabricsOptions options;
  options.table = table;
  options.calibration_file = calibration;
  options.scene = scene;
  options.overrides = overrides;
  options.drops = drops;
  options.out = out;
  options.threads = threads;
  PythonLog log(progress);
  const FabricsCommandResult result = WithOptionErrors([&] {
    return RunCommandForPython(&log, [&] {
      return RunFabricsCommand(options, CommandContext{log.stream, "python: drape.fabrics"});
    });
  });
  py::dict outcome;
  outcome["directory"] = result.summary.directory;
  outcome["line"] = result.line;
  AddLogOutcome(log, result.summary.interrupted, &outcome);
  return outcome;
}

// The value a scene key has in `scene_json`, the loaded scene as scene.yaml would write it
// (SceneJson's {"value": …}); an InputError naming the key when it is not a number there.
double SceneValue(const YAML::Node& scene_json, const std::string& key) {
  // Read through const nodes and reset(), never assignment: yaml-cpp's operator= on a node writes
  // into the tree it refers to, and non-const operator[] inserts keys. A missing key gives an
  // invalid node, which reset() refuses: the walk stops before it.
  YAML::Node node;
  node.reset(scene_json);
  std::string rest = key;
  bool missing = false;
  while (!rest.empty() && !missing) {
    const size_t dot = rest.find('.');
    const std::string step = rest.substr(0, dot);
    rest = dot == std::string::npos ? "" : rest.substr(dot + 1);
    const size_t bracket = step.find('[');
    const YAML::Node& parent = node;
    const YAML::Node child =
        parent.IsMap() ? parent[step.substr(0, bracket)] : YAML::Node(YAML::NodeType::Undefined);
    missing = !child;
    if (missing) break;
    node.reset(child);
    if (bracket != std::string::npos) {
      const YAML::Node& list = node;
      const size_t index = std::stoul(step.substr(bracket + 1));
      missing = !list.IsSequence() || index >= list.size();
      if (!missing) node.reset(list[index]);
    }
  }
  if (missing) node.reset(YAML::Node(YAML::NodeType::Undefined));
  const YAML::Node& found = node;
  // A key given as one number for both directions (`structural: 1000`) is written per direction
  // ({warp: …, weft: …}): the same number in each.
  std::optional<double> same;
  bool one_number = found && found.IsMap() && !found["value"] && found.size() > 0;
  for (const auto& entry : one_number ? found : YAML::Node()) {
    const YAML::Node value = entry.second["value"];
    if (!value || !value.IsScalar() || (same && *same != value.as<double>())) {
      one_number = false;
      break;
    }
    same = value.as<double>();
  }
  if (one_number && same) return *same;
  if (!found || !found.IsMap() || !found["value"] || !found["value"].IsScalar()) {
    throw InputError(Location{"keys", 0, 0, key},
                     "not a number of the scene as solved (drape check --json lists them; a "
                     "measurement such as kes.B_warp is its SI key, D_warp)");
  }
  return found["value"].as<double>();
}

// dx*/dp (nodes, 3, keys) at the scene's equilibrium (src/run/sensitivity.h): one solve, one
// factorisation, per key two models with the key moved by ± δ and one linear solve.
py::array_t<double> Sensitivities(const PyScene& loaded, const std::vector<std::string>& keys,
                                  const std::optional<std::string>& solver,
                                  const py::object& progress) {
  const YAML::Node scene_json = YAML::Load(SceneJson(loaded.scene));  // once, for every key
  std::vector<ParameterModels> parameters;
  for (const std::string& key : keys) {
    const double value = SceneValue(scene_json, key);
    ParameterModels parameter;
    parameter.key = key;
    parameter.step = SensitivityStep(value);
    std::vector<std::string> minus = loaded.overrides, plus = loaded.overrides;
    minus.push_back(key + "=" + FormatNumber(value - parameter.step));
    plus.push_back(key + "=" + FormatNumber(value + parameter.step));
    parameter.minus = BuildModel(loaded.reload(minus));
    parameter.plus = BuildModel(loaded.reload(plus));
    parameters.push_back(std::move(parameter));
  }
  const std::shared_ptr<PySolved> solved = Solve(loaded, solver, std::nullopt, progress);
  if (solved->interrupted) throw py::error_already_set();
  std::vector<std::vector<double>> derivatives;
  try {
    derivatives = PositionSensitivities(solved->model, solved->report.result, parameters);
  } catch (const SensitivityError& error) {
    throw InputError(Location{"sensitivities", 0, 0, ""}, error.what());
  }
  const int nodes = solved->model.num_nodes;
  py::array_t<double> array(
      {static_cast<py::ssize_t>(nodes), py::ssize_t{3}, static_cast<py::ssize_t>(keys.size())});
  auto view = array.mutable_unchecked<3>();
  for (size_t k = 0; k < keys.size(); ++k) {
    for (int i = 0; i < 3 * nodes; ++i)
      view(i / 3, i % 3, static_cast<py::ssize_t>(k)) = derivatives[k][i];
  }
  return array;
}

// The mesh of `mesh=(vertices, faces)`: vertices (n, 3) finite floats, faces (m, 3) or (m, 4)
// integers; checked here for their shapes and types, then built and checked as a file's.
std::shared_ptr<const MeshSpec::Arrays> MeshArrays(const py::object& vertices_object,
                                                   const py::object& faces_object) {
  const py::array vertices = py::array::ensure(vertices_object);
  const py::array faces = py::array::ensure(faces_object);
  if (!vertices || vertices.ndim() != 2 || vertices.shape(1) != 3) {
    throw InputError(Location{"mesh arrays", 0, 0, "vertices"},
                     "expected an array of shape (n, 3)");
  }
  if (!faces || faces.ndim() != 2 || (faces.shape(1) != 3 && faces.shape(1) != 4)) {
    throw InputError(Location{"mesh arrays", 0, 0, "faces"},
                     "expected an array of shape (m, 3) or (m, 4): triangles or quads");
  }
  const char kind = faces.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw InputError(Location{"mesh arrays", 0, 0, "faces"},
                     std::string("expected integer vertex indices, got dtype ") +
                         py::str(faces.dtype()).cast<std::string>());
  }
  const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  const auto f = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(faces);
  auto arrays = std::make_shared<MeshSpec::Arrays>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) {
    const Eigen::Vector3d p(v.at(i, 0), v.at(i, 1), v.at(i, 2));
    if (!p.allFinite()) {
      throw InputError(Location{"mesh arrays", 0, 0, "vertices[" + std::to_string(i) + "]"},
                       "a coordinate is not finite");
    }
    arrays->vertices.push_back(p);
  }
  for (py::ssize_t i = 0; i < f.shape(0); ++i) {
    std::vector<int> face;
    for (py::ssize_t c = 0; c < f.shape(1); ++c) {
      const long long index = f.at(i, c);
      face.push_back(index < 0 || index > 2147483647LL ? -1 : static_cast<int>(index));
    }
    arrays->faces.push_back(face);
  }
  return arrays;
}

// A scene loaded with `overrides` and, where given, the mesh arrays in place of its mesh.
std::shared_ptr<PyScene> LoadedScene(
    const std::function<Scene(const std::vector<std::string>&)>& load,
    std::vector<std::string> overrides, const std::optional<py::tuple>& mesh) {
  std::shared_ptr<const MeshSpec::Arrays> arrays;
  if (mesh) {
    if (mesh->size() != 2) {
      throw InputError(Location{"mesh", 0, 0, ""}, "expected (vertices, faces)");
    }
    arrays = MeshArrays((*mesh)[0], (*mesh)[1]);
    overrides.push_back("mesh={kind: file, path: '(mesh arrays)'}");
  }
  auto reload = [load, arrays](const std::vector<std::string>& with) {
    Scene scene = load(with);
    if (arrays) scene.mesh.arrays = arrays;
    return scene;
  };
  return std::make_shared<PyScene>(PyScene{reload(overrides), overrides, reload});
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
      [](const std::string& path, const std::vector<std::string>& overrides,
         const std::optional<py::tuple>& mesh) {
        return LoadedScene(
            [path](const std::vector<std::string>& with) { return LoadScene(path, with); },
            overrides, mesh);
      },
      py::arg("path"), py::arg("overrides"), py::arg("mesh"));
  module.def(
      "loads",
      [](const std::string& text, const std::string& label, const std::string& directory,
         const std::vector<std::string>& overrides, const std::optional<py::tuple>& mesh) {
        return LoadedScene(
            [text, label, directory](const std::vector<std::string>& with) {
              return LoadSceneText(text, label, directory, with);
            },
            overrides, mesh);
      },
      py::arg("text"), py::arg("label"), py::arg("directory"), py::arg("overrides"),
      py::arg("mesh"));
  module.def("solve", &Solve, py::arg("scene"), py::arg("solver"), py::arg("start"),
             py::arg("progress"));
  module.def("fit", &Fit, py::arg("path"), py::arg("overrides"), py::arg("method"),
             py::arg("directory"), py::arg("threads"), py::arg("progress"));
  module.def("drops", &Drops, py::arg("scene"), py::arg("drops"), py::arg("directory"),
             py::arg("threads"), py::arg("progress"));
  module.def("sweep", &Sweep, py::arg("path"), py::arg("out"), py::arg("threads"), py::arg("plots"),
             py::arg("progress"));
  module.def("fabrics", &Fabrics, py::arg("table"), py::arg("scene"), py::arg("overrides"),
             py::arg("drops"), py::arg("out"), py::arg("threads"), py::arg("progress"),
             py::arg("calibration"));
  module.def("sensitivities", &Sensitivities, py::arg("scene"), py::arg("keys"), py::arg("solver"),
             py::arg("progress"));
  module.def("version", &DrapeVersion);
}
