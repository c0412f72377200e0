"""drape in Python: load, check and solve fabric scenes with the code `drape solve` runs.

    import drape
    result = drape.solve("configs/examples/hanging_sheet.yaml", set={"mesh.nodes": [9, 9]})
    result.positions          # (n, 3) float64, m
    result.drape_coefficient  # a drape test's, else None

Scenes come from a file (`load`), YAML text (`loads`) or a dict (`from_dict`), with their mesh
from the scene or from arrays (`mesh=(vertices, faces)`); `set=` takes the overrides
`drape solve --set` takes, as a dict of key paths to values. Bad input raises `drape.InputError`
with the CLI's message and its `file`, `line`, `column` and `key` (a dict's errors are located by
`key` alone: `<dict>: mesh.sides: ...`); a file that is not there raises FileNotFoundError.
drape's warnings are `warnings.warn` with the category `drape.DrapeWarning`; progress lines go to
`progress=` (a callable taking a line; default: printed to `sys.stderr`; None: silent). A solve
releases the GIL; Ctrl-C stops it and raises KeyboardInterrupt whose `result` is the last iterate.
Long runs (`drops`, `fit`, `sweep`, `fabrics`) run the commands the command line runs
(src/commands/) and write their files into `out=`, else a temporary folder removed after reading.
docs/python.md walks through it.
"""

import csv
import errno
import json
import os
import shutil
import sys
import tempfile
import warnings

from . import _drape
from ._version import pep440_version

__all__ = ["DrapeWarning", "InputError", "Scene", "Result", "DropsResult", "FitResult",
           "FabricsResult", "load", "loads", "from_dict", "solve", "drops", "fit", "sweep",
           "fabrics", "sensitivities", "__version__"]

__version__ = pep440_version(_drape.version())


class DrapeWarning(UserWarning):
    """A warning of drape's (a mesh coarser than the fabric needs, a fit's doubtful measurement):
    filter it with warnings.filterwarnings("ignore", category=drape.DrapeWarning)."""


class InputError(ValueError):
    """Bad input, located as the CLI locates it: `file:line:column: key: problem`."""

    def __init__(self, message, file="", line=0, column=0, key="", problem=""):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.problem = problem or message


def _print_to_stderr(line):
    """The default `progress`: each line to the current sys.stderr (so that a notebook shows it and
    contextlib.redirect_stderr captures it)."""
    print(line, file=sys.stderr, flush=True)


def _progress(progress):
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected a callable taking a line of text, or None")
    return progress


def _warn(lines, stacklevel=3):
    """drape's warnings as DrapeWarning, attributed to the user's call (`stacklevel` frames up)."""
    for line in lines:
        warnings.warn(line, DrapeWarning, stacklevel=stacklevel)


def _override_value(value):
    """A --set value as YAML: booleans as true/false, lists and dicts as flow YAML (JSON)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple, dict)):
        return json.dumps(value)
    if hasattr(value, "tolist"):  # NumPy scalars and arrays
        return _override_value(value.tolist())
    return str(value)


def _overrides(set):
    if set is None:
        return []
    if not isinstance(set, dict):
        raise TypeError("set: expected a dict of key paths to values, e.g. {'mesh.spacing': 0.005}")
    return [f"{key}={_override_value(value)}" for key, value in set.items()]


def _existing(path, what):
    """`path` as a str; FileNotFoundError (with the path) if there is no such file."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(errno.ENOENT, f"no {what} here", path)
    return path


def _mesh(mesh):
    if mesh is None:
        return None
    if not isinstance(mesh, (tuple, list)) or len(mesh) != 2:
        raise TypeError("mesh: expected (vertices, faces): an (n, 3) float array and an (m, 3) "
                        "or (m, 4) integer array")
    return tuple(mesh)


def _loaded(scene, set, mesh=None):
    """A Scene as given; a scene as a dict (as `from_dict` takes it, relative paths from the
    current folder) or the scene file at a path, loaded with `set` overrides (and `mesh`)."""
    if isinstance(scene, dict):
        return from_dict(scene, set=set, mesh=mesh)
    if not isinstance(scene, Scene):
        return load(scene, set=set, mesh=mesh)
    if set is not None or mesh is not None:
        raise TypeError("set, mesh: give them to drape.load (the scene is already loaded)")
    return scene


def _interrupted(message, result):
    """The KeyboardInterrupt of a run that Ctrl-C stopped, with what it finished as `result`."""
    interrupt = KeyboardInterrupt(message)
    interrupt.result = result
    return interrupt


def _run_in_folder(out, prefix, run, read, interrupted):
    """A long command run into `out`, else into a temporary folder removed after reading: `run`
    (given the folder) returns the module's outcome, `read` (given the folder and the outcome) the
    result. Its warnings are emitted as DrapeWarning at the user's call; after Ctrl-C,
    KeyboardInterrupt(`interrupted`) carries the result."""
    folder = os.fspath(out) if out is not None else tempfile.mkdtemp(prefix=prefix)
    try:
        outcome = run(folder)
        result = read(folder, outcome)
    finally:
        if out is None:
            shutil.rmtree(folder, ignore_errors=True)
    _warn(outcome["warnings"], stacklevel=4)
    if outcome["interrupted"]:
        raise _interrupted(interrupted, result)
    return result


class Scene:
    """A loaded, checked scene (the `drape check` of it is `check()`)."""

    def __init__(self, handle):
        self._handle = handle

    @property
    def name(self):
        """The scene's `name` (default: the file's stem)."""
        return self._handle.name

    @property
    def file(self):
        """The file it came from (`<string>` or `<dict>` for text and dicts)."""
        return self._handle.file

    def check(self):
        """What `drape check` prints, as data: nodes, free dofs, terms by type, the SI material
        (`material_si`) and the measurements as given (`material_as_given`: key -> (value,
        unit))."""
        return self._handle.check()

    def __repr__(self):
        return f"drape.Scene({self.name!r}, file={self.file!r})"


def load(path, set=None, mesh=None):
    """The scene of a YAML file, with `set` overrides ({'key.path': value}); `mesh=(vertices,
    faces)` replaces its mesh by a surface given as arrays (checked as a mesh file is)."""
    path = _existing(path, "scene file")
    return Scene(_drape.load(path, _overrides(set), _mesh(mesh)))


def loads(text, set=None, directory=".", mesh=None):
    """The scene of YAML text; its relative paths are taken from `directory`."""
    return Scene(_drape.loads(text, "<string>", os.fspath(directory), _overrides(set),
                              _mesh(mesh)))


def _located_by_key(error, label):
    """An InputError in the JSON text made from a dict, located by its key path alone: the text's
    lines and columns are not the caller's."""
    where = f"{label}: {error.key}: " if error.key else f"{label}: "
    return InputError(where + error.problem, label, 0, 0, error.key, error.problem)


def from_dict(scene, set=None, directory=".", mesh=None):
    """The scene of a dict with the YAML file's structure (JSON is YAML)."""
    try:
        return Scene(_drape.loads(json.dumps(scene, indent=1), "<dict>", os.fspath(directory),
                                  _overrides(set), _mesh(mesh)))
    except InputError as error:
        if error.file != "<dict>":
            raise
        raise _located_by_key(error, "<dict>") from None


class Result:
    """A solved scene: NumPy arrays of the final state and the figures of summary.json."""

    def __init__(self, solved):
        self._solved = solved
        self._arrays = solved.arrays()
        self._figures = solved.figures()
        self._summary = json.loads(self._figures["summary_json"])

    @property
    def positions(self):
        """(n, 3) float64: the final positions, m."""
        return self._arrays["positions"]

    @property
    def initial_positions(self):
        """(n, 3) float64: the positions the solve started from, m."""
        return self._arrays["initial_positions"]

    @property
    def reactions(self):
        """(n, 3) float64: the support reactions on the fixed coordinates, N (0 elsewhere)."""
        return self._arrays["reactions"]

    @property
    def contact_forces(self):
        """(n, 3) float64: the obstacles' contact forces on the nodes, N."""
        return self._arrays["contact_forces"]

    @property
    def fixed(self):
        """(n, 3) bool: the prescribed coordinates."""
        return self._arrays["fixed"]

    @property
    def faces(self):
        """(m, 3) int: the mesh's triangles (node ids), for plotting."""
        return self._arrays["faces"]

    @property
    def converged(self):
        """Whether the relative residual reached the tolerance (confirmed at the final state)."""
        return self._figures["converged"]

    @property
    def stable(self):
        """Whether the final state is a stable minimum: converged, the free Hessian positive
        definite, and the fabric through no support disk, mesh obstacle or itself."""
        return self._figures["stable"]

    @property
    def state(self):
        """The result line's words: 'stable minimum', 'saddle: …', 'not converged: …'."""
        return self._figures["state"]

    @property
    def termination(self):
        """Why the method stopped, in its words."""
        return self._figures["termination"]

    @property
    def iterations(self):
        """The method's iterations, all levels together."""
        return self._figures["iterations"]

    @property
    def energy(self):
        """dict: the energy per term type and its 'total', J."""
        return self._figures["energy"]

    @property
    def drape_coefficient(self):
        """A drape test's drape coefficient (a fraction), else None."""
        return self._figures["drape_coefficient"]

    @property
    def drape_coefficient_error(self):
        """The error bar of drape solve's line: the levels' (widened to the mesh rule's), else the
        mesh rule's; None for a scene without a support disc or rule."""
        return self._figures["drape_coefficient_error"]

    @property
    def summary(self):
        """dict: summary.json as `drape solve` writes it."""
        return self._summary

    @property
    def interrupted(self):
        """Whether Ctrl-C stopped the solve (then the positions are its last iterate)."""
        return self._figures["interrupted"]

    def write(self, directory):
        """The files `drape solve` writes (the scene's output.write), into `directory`."""
        self._solved.write(os.fspath(directory))

    def __repr__(self):
        coefficient = ("" if self.drape_coefficient is None
                       else f", drape_coefficient={self.drape_coefficient:.4g}")
        if self.drape_coefficient_error is not None:
            coefficient += f" ± {self.drape_coefficient_error:.2g}"
        return (f"drape.Result(converged={self.converged}, state={self.state!r}, "
                f"nodes={len(self.positions)}{coefficient})")


def solve(scene, solver=None, set=None, start=None, mesh=None, progress=_print_to_stderr):
    """Solves a Scene, a scene file's path or a scene as a dict, as `drape solve` does; returns
    a Result.

    solver: a method name (`drape solvers`); set, mesh: as `load` takes them (for a path); start:
    an earlier Result or an (n, 3) array of positions, a warm start (the free nodes start there);
    progress: a callable given a line every second of a long solve (None: silent). A mesh coarser
    than the fabric needs is a DrapeWarning.
    """
    scene = _loaded(scene, set, mesh)
    if isinstance(start, Result):
        start = start.positions
    result = Result(_drape.solve(scene._handle, solver, start, _progress(progress)))
    _warn(result._figures["warnings"])
    if result.interrupted:
        raise _interrupted(f"drape.solve interrupted after {result.iterations} iterations; "
                           "the last iterate is the exception's `result`", result)
    return result


def sensitivities(scene, keys, set=None, solver=None, mesh=None, progress=_print_to_stderr):
    """The derivatives of the equilibrium positions with respect to scene keys: an array of shape
    (nodes, 3, len(keys)), m per unit of each key (e.g. m/(N·m) for
    'material.finite_volume.D_warp').

    The scene is solved, its free Hessian at the equilibrium factorised once, and each key costs
    one linear solve (the implicit function theorem: H dx/dp = -dg/dp, dg/dp by central
    differences of the forces at the equilibrium). A key is a number of the scene as solved
    (`drape check --json`), in SI. Raises InputError where the equilibrium is not a converged,
    stable minimum, or a key is not such a number. scene: a Scene, a scene file's path or a scene
    as a dict.
    """
    scene = _loaded(scene, set, mesh)
    if isinstance(keys, str):
        keys = [keys]
    return _drape.sensitivities(scene._handle, list(keys), solver, _progress(progress))


def _number(text):
    if text in ("true", "false"):  # drape's CSV booleans, as pandas reads them
        return text == "true"
    try:
        return int(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


def _table(path):
    """A CSV file of drape's as a pandas DataFrame where pandas is installed, else a list of dicts
    (numbers as int or float). Both read drape's shortest exact numbers back to the same doubles
    (pandas' default parser can miss the last bit: float_precision="round_trip")."""
    try:
        import pandas
        return pandas.read_csv(path, float_precision="round_trip")
    except ImportError:
        with open(path, newline="") as file:
            return [{key: _number(value) for key, value in row.items()}
                    for row in csv.DictReader(file)]


class DropsResult:
    """What repeated drops write, as data (drops.csv, summary.json)."""

    def __init__(self, directory, line):
        with open(os.path.join(directory, "summary.json")) as file:
            self._summary = json.load(file)
        self._table = _table(os.path.join(directory, "drops.csv"))
        self._line = line

    @property
    def summary(self):
        """dict: the drops' summary.json."""
        return self._summary

    @property
    def table(self):
        """drops.csv: a row per drop (its offset, waviness, drape coefficient, folds, energy,
        counted, state), as a pandas DataFrame (a list of dicts without pandas)."""
        return self._table

    @property
    def line(self):
        """What `drape solve --drops` prints."""
        return self._line

    @property
    def drops(self):
        """How many drops were solved."""
        return self._summary["drops"]

    @property
    def counted(self):
        """The drops at a stable minimum with nothing through the disc: the figures' drops."""
        return self._summary["drops_counted"]

    @property
    def mean(self):
        """The mean drape coefficient over the counted drops (None if none)."""
        return self._summary["drape_coefficient_mean"]

    @property
    def standard_deviation(self):
        """Its sample standard deviation (None if none counted)."""
        return self._summary["drape_coefficient_standard_deviation"]

    @property
    def folds_histogram(self):
        """dict: fold count -> drops."""
        return {int(folds): count for folds, count in self._summary["folds_histogram"].items()}

    @property
    def most_frequent_folds(self):
        """The most frequent fold count(s)."""
        return self._summary["most_frequent_folds"]

    @property
    def mesh_rule(self):
        """The discretisation error each drop carries (summary.json's mesh_rule), or None."""
        return self._summary.get("mesh_rule")

    def __repr__(self):
        return f"drape.DropsResult(drops={self.drops}, mean={self.mean}, " \
               f"standard_deviation={self.standard_deviation})"


def _drops_count(drops):
    if drops is not None and (isinstance(drops, bool) or not isinstance(drops, int) or drops < 1):
        raise InputError(f"drops: expected a whole number >= 1, got {drops!r}", key="drops")
    return drops


def drops(scene, drops=None, set=None, out=None, threads=0, progress=_print_to_stderr,
          directory=None):
    """Repeated drops of a drape test, as `drape solve --drops N` runs them; returns a DropsResult.

    scene: a Scene, a scene file's path or a scene as a dict (with `set` overrides); it needs a
    drape_test block.
    drops: how many (default: the scene's drape_test.drops); threads: 0 for the machine's cores;
    out: where the files go (drops.csv, summary.json, report.html, drops/NN/), else a temporary
    folder, removed after reading; progress: a callable given a line per finished drop.
    (`directory` is the former name of `out`.)
    """
    scene = _loaded(scene, set)
    count = _drops_count(drops) or 0
    return _run_in_folder(
        _renamed(out, directory), "drape_drops_",
        lambda folder: _drape.drops(scene._handle, count, folder, threads, _progress(progress)),
        lambda folder, outcome: DropsResult(folder, outcome["line"]),
        "drape.drops interrupted; the finished drops are `result`")


def _renamed(out, directory):
    if directory is None:
        return out
    if out is not None:
        raise TypeError("give out= (directory= is its former name), not both")
    warnings.warn("directory= is now out=", DeprecationWarning, stacklevel=3)
    return directory


class FitResult:
    """What `drape fit` writes, as data (fit.json, history.csv)."""

    def __init__(self, directory, converged, label=None, path=None):
        with open(os.path.join(directory, "fit.json")) as file:
            self._table = json.load(file)
        if label is not None:  # a dict's fit: its warnings name the dict, not the temporary file
            self._table["warnings"] = [w.replace(path, label) for w in self._table["warnings"]]
        self._history = _table(os.path.join(directory, "history.csv"))
        self._converged = converged

    @property
    def table(self):
        """dict: fit.json."""
        return self._table

    @property
    def history(self):
        """history.csv: a row per evaluation (a DataFrame, or a list of dicts without pandas)."""
        return self._history

    @property
    def converged(self):
        """Whether the outer method converged."""
        return self._converged

    @property
    def parameters(self):
        """dict: the fitted value of each parameter key."""
        return self._table["parameters"]

    @property
    def standard_errors(self):
        """dict: each parameter's standard error (from the Jacobian at the optimum)."""
        return self._table["standard_errors"]

    @property
    def identifiability(self):
        """fit.json's identifiability: the Jacobian's conditioning and what it says."""
        return self._table["identifiability"]

    @property
    def measurements(self):
        """fit.json's measurements: each one's residuals at the optimum."""
        return self._table["measurements"]

    @property
    def termination(self):
        """Why the outer method stopped."""
        return self._table["termination"]

    @property
    def warnings(self):
        """The fit's warnings (also emitted as DrapeWarning): e.g. a mesh too coarse for the
        measurement."""
        return self._table["warnings"]

    def __repr__(self):
        return f"drape.FitResult(converged={self.converged}, parameters={self.parameters})"


def _absolute(path, base):
    return path if os.path.isabs(path) else os.path.normpath(os.path.join(base, path))


def _absolute_fit_paths(spec, base):
    """A fit dict with its file paths (the scene, the measurement files, other specimens' scenes)
    made absolute against `base`: a fit file's are relative to its folder."""
    if isinstance(spec.get("scene"), str):
        spec["scene"] = _absolute(spec["scene"], base)
    for item in spec.get("measurements") or []:
        if not isinstance(item, dict):
            continue
        for kind, body in item.items():
            if kind == "scene" and isinstance(body, str):
                item[kind] = _absolute(body, base)
            elif isinstance(body, dict) and isinstance(body.get("file"), str):
                body["file"] = _absolute(body["file"], base)
            if isinstance(body, dict) and body.get("measurements"):
                _absolute_fit_paths({"measurements": body["measurements"]}, base)
        if item.get("measurements"):
            _absolute_fit_paths({"measurements": item["measurements"]}, base)
    return spec


def _run_fit(path, set, method, folder, threads, progress, label=None):
    try:
        return _drape.fit(path, _overrides(set), method, folder, threads, progress)
    except InputError as error:
        if label is None or error.file != path:
            raise
        raise _located_by_key(error, label) from None


def fit(fit_file, set=None, method=None, out=None, threads=1, base=".",
        progress=_print_to_stderr, directory=None):
    """Runs `drape fit` on a fit file, or a dict with its structure; returns a FitResult.

    set: overrides of every specimen's scene; method: a fit method (`bobyqa`, `implicit-lm`, ...);
    out: where its files go (kept), else a temporary folder, removed after reading; base: the
    folder a dict's relative paths are taken from (default: the current folder; a file's are
    taken from its own folder); progress: a callable given a line per evaluation. The fit's
    warnings are DrapeWarnings. (`directory` is the former name of `out`.)
    """
    progress = _progress(progress)
    interrupted = "drape.fit interrupted; the best point is the exception's `result`"
    if not isinstance(fit_file, dict):
        path = _existing(fit_file, "fit file")
        return _run_in_folder(
            _renamed(out, directory), "drape_fit_",
            lambda folder: _run_fit(path, set, method, folder, threads, progress),
            lambda folder, outcome: FitResult(folder, outcome["converged"]), interrupted)
    scratch = tempfile.mkdtemp(prefix="drape_fit_dict_")
    path = os.path.join(scratch, "fit.yaml")
    spec = _absolute_fit_paths(json.loads(json.dumps(fit_file)), os.path.abspath(os.fspath(base)))
    with open(path, "w") as file:
        json.dump(spec, file, indent=1)

    def run(folder):  # a dict's fit: its warnings name the dict, not the temporary file
        outcome = _run_fit(path, set, method, folder, threads, progress, label="<dict>")
        outcome["warnings"] = [w.replace(path, "<dict>") for w in outcome["warnings"]]
        return outcome

    try:
        return _run_in_folder(
            _renamed(out, directory), "drape_fit_", run,
            lambda folder, outcome: FitResult(folder, outcome["converged"], "<dict>", path),
            interrupted)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def sweep(sweep_file, out=None, threads=0, plots=False, progress=_print_to_stderr,
          directory=None):
    """Runs `drape sweep` on a sweep file; returns sweep.csv's table.

    out: where its files go (kept: a rerun into the same folder skips the finished tasks), else a
    temporary folder, removed after reading; progress: a callable given a line per finished task.
    (`directory` is the former name of `out`.)
    """
    path = _existing(sweep_file, "sweep file")
    return _run_in_folder(
        _renamed(out, directory), "drape_sweep_",
        lambda folder: _drape.sweep(path, folder, threads, plots, _progress(progress)),
        lambda folder, outcome: _table(os.path.join(outcome["directory"], "sweep.csv")),
        "drape.sweep interrupted; the finished rows are `result`")


class FabricsResult:
    """What `drape fabrics` writes, as data (fabrics.csv, fabrics.json)."""

    def __init__(self, directory, line):
        self._table = _table(os.path.join(directory, "fabrics.csv"))
        with open(os.path.join(directory, "fabrics.json")) as file:
            self._summary = json.load(file)
        self._line = line

    @property
    def table(self):
        """fabrics.csv: a row per fabric (its inputs, the SI parameters used, the prediction with
        its error bar, the measurement and the difference), as a pandas DataFrame (a list of dicts
        without pandas)."""
        return self._table

    @property
    def summary(self):
        """dict: fabrics.json."""
        return self._summary

    @property
    def statistics(self):
        """dict: mean |Δ|, mean Δ, RMS and how many measured values lie within the error bars,
        over the fabrics with a measurement (None if none)."""
        return self._summary["statistics"]

    @property
    def line(self):
        """What `drape fabrics` prints."""
        return self._line

    def __repr__(self):
        return f"drape.FabricsResult({self.line!r})"


def fabrics(table, scene=None, set=None, drops=None, out=None, threads=0,
            progress=_print_to_stderr, calibration=None):
    """Runs `drape fabrics` on a fabric table (CSV); returns a FabricsResult.

    scene: the base scene (a drape test), default the standard tester; set: overrides of every
    fabric's scene, after its material; drops: predict each fabric's mean over this many drops;
    out: where the files go (kept: a rerun solves only what is missing), else a temporary folder,
    removed after reading; progress: a callable given a line per finished fabric; calibration:
    a calibration.yaml that `drape fabrics --calibrate` wrote, applied to every fabric.
    """
    path = _existing(table, "fabric table")
    base = "" if scene is None else _existing(scene, "scene file")
    calibrated = "" if calibration is None else _existing(calibration, "calibration file")
    count = _drops_count(drops)
    return _run_in_folder(
        out, "drape_fabrics_",
        lambda folder: _drape.fabrics(path, base, _overrides(set), count, folder, threads,
                                      _progress(progress), calibrated),
        lambda folder, outcome: FabricsResult(folder, outcome["line"]),
        "drape.fabrics interrupted; the finished fabrics are `result`")
