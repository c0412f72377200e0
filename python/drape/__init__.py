"""drape in Python: load, check and solve fabric scenes with the code `drape solve` runs.

    import drape
    result = drape.solve("configs/examples/hanging_sheet.yaml", set={"mesh.nodes": [9, 9]})
    result.positions          # (n, 3) float64, m
    result.drape_coefficient  # a drape test's, else None

Scenes come from a file (`load`), YAML text (`loads`) or a dict (`from_dict`); `set=` takes the
overrides `drape solve --set` takes, as a dict of key paths to values. Bad input raises
`drape.InputError` with the CLI's message and its `file`, `line`, `column` and `key` (a dict's
errors are located by `key` alone: `<dict>: mesh.sides: ...`, line and column 0). A solve
releases the GIL; Ctrl-C stops it and raises KeyboardInterrupt whose `result` is the last iterate.
docs/python.md walks through it.
"""

import csv
import json
import os
import shutil
import tempfile

from . import _drape

__all__ = ["InputError", "Scene", "Result", "DropsResult", "FitResult", "load", "loads",
           "from_dict", "solve", "drops", "fit", "sweep", "__version__"]

__version__ = _drape.version()


class InputError(ValueError):
    """Bad input, located as the CLI locates it: `file:line:column: key: problem`."""

    def __init__(self, message, file="", line=0, column=0, key="", problem=""):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.problem = problem or message


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


def _loaded(scene, set):
    """A Scene as given, or the scene file at a path loaded with `set` overrides."""
    if not isinstance(scene, Scene):
        return load(scene, set=set)
    if set is not None:
        raise TypeError("set: give the overrides to drape.load (the scene is already loaded)")
    return scene


def _interrupted(message, result):
    """The KeyboardInterrupt of a run that Ctrl-C stopped, with what it finished as `result`."""
    interrupt = KeyboardInterrupt(message)
    interrupt.result = result
    return interrupt


class Scene:
    """A loaded, checked scene (the `drape check` of it is `check()`)."""

    def __init__(self, handle):
        self._handle = handle

    @property
    def name(self):
        return self._handle.name

    @property
    def file(self):
        return self._handle.file

    def check(self):
        """What `drape check` prints, as data: nodes, free dofs, terms by type, SI material."""
        return self._handle.check()

    def __repr__(self):
        return f"drape.Scene({self.name!r}, file={self.file!r})"


def load(path, set=None):
    """The scene of a YAML file, with `set` overrides ({'key.path': value})."""
    return Scene(_drape.load(os.fspath(path), _overrides(set)))


def loads(text, set=None, directory="."):
    """The scene of YAML text; its relative paths are taken from `directory`."""
    return Scene(_drape.loads(text, "<string>", os.fspath(directory), _overrides(set)))


def _located_by_key(error, label):
    """An InputError in the JSON text made from a dict, located by its key path alone: the text's
    lines and columns are not the caller's."""
    where = f"{label}: {error.key}: " if error.key else f"{label}: "
    return InputError(where + error.problem, label, 0, 0, error.key, error.problem)


def from_dict(scene, set=None, directory="."):
    """The scene of a dict with the YAML file's structure (JSON is YAML)."""
    try:
        return Scene(_drape.loads(json.dumps(scene, indent=1), "<dict>", os.fspath(directory),
                                  _overrides(set)))
    except InputError as error:
        if error.file != "<dict>":
            raise
        raise _located_by_key(error, "<dict>") from None


class Result:
    """A solved scene: NumPy arrays of the final state and the figures of summary.json."""

    def __init__(self, solved):
        self._solved = solved
        arrays = solved.arrays()
        figures = solved.figures()
        self.positions = arrays["positions"]                # (n, 3) m
        self.initial_positions = arrays["initial_positions"]  # (n, 3) m
        self.reactions = arrays["reactions"]                # (n, 3) N, on fixed coordinates
        self.contact_forces = arrays["contact_forces"]      # (n, 3) N
        self.fixed = arrays["fixed"]                        # (n, 3) bool
        self.faces = arrays["faces"]                        # (m, 3) node ids, for plotting
        self.converged = figures["converged"]
        self.stable = figures["stable"]
        self.state = figures["state"]
        self.termination = figures["termination"]
        self.iterations = figures["iterations"]
        self.energy = figures["energy"]                     # J, per term type and "total"
        self.drape_coefficient = figures["drape_coefficient"]
        # The error bar of drape solve's line: the levels' (widened to the mesh rule's), else the
        # mesh rule's; None for a scene without a support disc or rule.
        self.drape_coefficient_error = figures["drape_coefficient_error"]
        self.summary = json.loads(figures["summary_json"])  # summary.json's dict
        self.interrupted = figures["interrupted"]

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


def solve(scene, solver=None, set=None, start=None):
    """Solves a Scene, or the scene file at a path, as `drape solve` does; returns a Result.

    solver: a method name (`drape solvers`); set: overrides (for a path); start: an earlier
    Result or an (n, 3) array of positions, a warm start (the free nodes start there).
    """
    scene = _loaded(scene, set)
    if isinstance(start, Result):
        start = start.positions
    result = Result(_drape.solve(scene._handle, solver, start))
    if result.interrupted:
        raise _interrupted(f"drape.solve interrupted after {result.iterations} iterations; "
                           "the last iterate is the exception's `result`", result)
    return result


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
    """What repeated drops write, as data: `summary` is summary.json's dict, `table` drops.csv's
    rows (one per drop: its offset, waviness, drape coefficient, folds, energy, counted, state).
    `mean` and `standard_deviation` are over the counted drops (None if none counted);
    `mesh_rule` the discretisation error each drop carries (summary.json's, or None); `line` what
    `drape solve --drops` prints."""

    def __init__(self, directory, line):
        with open(os.path.join(directory, "summary.json")) as file:
            self.summary = json.load(file)
        self.table = _table(os.path.join(directory, "drops.csv"))
        self.line = line
        self.drops = self.summary["drops"]
        self.counted = self.summary["drops_counted"]
        self.mean = self.summary["drape_coefficient_mean"]
        self.standard_deviation = self.summary["drape_coefficient_standard_deviation"]
        self.folds_histogram = {int(folds): count
                                for folds, count in self.summary["folds_histogram"].items()}
        self.most_frequent_folds = self.summary["most_frequent_folds"]
        self.mesh_rule = self.summary.get("mesh_rule")

    def __repr__(self):
        return f"drape.DropsResult(drops={self.drops}, mean={self.mean}, " \
               f"standard_deviation={self.standard_deviation})"


def drops(scene, drops=None, set=None, directory=None, threads=0):
    """Repeated drops of a drape test, as `drape solve --drops N` runs them; returns a DropsResult.

    scene: a Scene, or a scene file's path (with `set` overrides); it needs a drape_test block.
    drops: how many (default: the scene's drape_test.drops); threads: 0 for the machine's cores;
    directory: where the files go (drops.csv, summary.json, report.html, drops/NN/), else a
    temporary folder, removed after reading.
    """
    scene = _loaded(scene, set)
    if drops is not None and (isinstance(drops, bool) or not isinstance(drops, int) or drops < 1):
        raise InputError(f"drops: expected a whole number >= 1, got {drops!r}", key="drops")
    folder = os.fspath(directory) if directory is not None else tempfile.mkdtemp(prefix="drape_drops_")
    try:
        outcome = _drape.drops(scene._handle, drops or 0, folder, threads)
        result = DropsResult(folder, outcome["line"])
    finally:
        if directory is None:
            shutil.rmtree(folder, ignore_errors=True)
    if outcome["interrupted"]:
        raise _interrupted("drape.drops interrupted; the finished drops are `result`", result)
    return result


class FitResult:
    """What `drape fit` writes, as data: `table` is fit.json's dict, `history` history.csv's rows."""

    def __init__(self, directory, converged):
        with open(os.path.join(directory, "fit.json")) as file:
            self.table = json.load(file)
        self.history = _table(os.path.join(directory, "history.csv"))
        self.converged = converged
        self.parameters = self.table["parameters"]
        self.standard_errors = self.table["standard_errors"]
        self.identifiability = self.table["identifiability"]
        self.measurements = self.table["measurements"]
        self.termination = self.table["termination"]
        self.warnings = self.table["warnings"]  # e.g. a mesh too coarse for the measurement

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


def _run_fit(path, set, method, folder, threads, label=None):
    try:
        return _drape.fit(path, _overrides(set), method, folder, threads)
    except InputError as error:
        if label is None or error.file != path:
            raise
        raise _located_by_key(error, label) from None


def fit(fit_file, set=None, method=None, directory=None, threads=1, base="."):
    """Runs `drape fit` on a fit file, or a dict with its structure; returns a FitResult.

    set: overrides of every specimen's scene; method: a fit method (`bobyqa`, `implicit-lm`, ...);
    directory: where its files go (kept), else a temporary folder, removed after reading; base:
    the folder a dict's relative paths are taken from (a file's are taken from its own folder).
    """
    folder = os.fspath(directory) if directory is not None else tempfile.mkdtemp(prefix="drape_fit_")
    scratch = None
    try:
        if isinstance(fit_file, dict):
            scratch = tempfile.mkdtemp(prefix="drape_fit_dict_")
            path = os.path.join(scratch, "fit.yaml")
            spec = _absolute_fit_paths(json.loads(json.dumps(fit_file)), os.fspath(base))
            with open(path, "w") as file:
                json.dump(spec, file, indent=1)
            outcome = _run_fit(path, set, method, folder, threads, label="<dict>")
        else:
            outcome = _run_fit(os.fspath(fit_file), set, method, folder, threads)
        result = FitResult(folder, outcome["converged"])
    finally:
        if directory is None:
            shutil.rmtree(folder, ignore_errors=True)
        if scratch is not None:
            shutil.rmtree(scratch, ignore_errors=True)
    if outcome["interrupted"]:
        raise _interrupted("drape.fit interrupted; the best point is the exception's `result`",
                           result)
    return result


def sweep(sweep_file, directory=None, threads=0, plots=False):
    """Runs `drape sweep` on a sweep file into `directory` (else the file's own output folder, as
    the command line; a rerun skips the finished tasks); returns sweep.csv's table."""
    outcome = _drape.sweep(os.fspath(sweep_file), "" if directory is None else os.fspath(directory),
                           threads, plots)
    table = _table(os.path.join(outcome["directory"], "sweep.csv"))
    if outcome["interrupted"]:
        raise _interrupted("drape.sweep interrupted; the finished rows are `result`", table)
    return table
