# Type stubs of the package drape (PEP 484, PEP 561: py.typed beside it). The runtime is
# __init__.py over the extension _drape; python/tests/test_packaging.py checks that this file names
# what the module has (stubtest where mypy is installed, names and parameters otherwise).
import os
from typing import Any, Callable, Sequence

import numpy as np
import pandas  # type: ignore[import]  # optional at run time; Debian's pandas has no stubs
from numpy.typing import ArrayLike, NDArray

__all__ = ["InputError", "DrapeWarning", "Scene", "Result", "DropsResult", "FitResult",
           "FabricsResult", "load", "loads", "from_dict", "solve", "drops", "fit", "sweep",
           "fabrics", "sensitivities", "__version__"]

# PEP 440, from the build's `git describe` where it was built from a clone: "0.1+g407930e.dirty".
__version__: str

_Path = str | os.PathLike[str]
_Overrides = dict[str, Any] | None          # {"mesh.spacing": 0.005}, drape solve --set's keys
# (vertices (n, 3) in m, faces (m, 3) or (m, 4) node ids): a mesh given as arrays.
_Mesh = tuple[ArrayLike, ArrayLike] | None
# A progress callback: each line drape prints while it runs; None for silence. The default
# prints the lines to sys.stderr.
_Progress = Callable[[str], object] | None
# A CSV file of drape's: a pandas DataFrame where pandas is installed, else its rows as dicts.
_Table = pandas.DataFrame | list[dict[str, Any]]

class DrapeWarning(UserWarning): ...

class InputError(ValueError):
    """Bad input, located as the CLI locates it: `file:line:column: key: problem`."""

    file: str
    line: int
    column: int
    key: str
    problem: str
    def __init__(self, message: str, file: str = "", line: int = 0, column: int = 0,
                 key: str = "", problem: str = "") -> None: ...

class Scene:
    """A loaded, checked scene (the `drape check` of it is `check()`)."""

    @property
    def name(self) -> str: ...
    @property
    def file(self) -> str: ...
    def check(self) -> dict[str, Any]: ...

def load(path: _Path, set: _Overrides = None, mesh: _Mesh = None) -> Scene: ...
def loads(text: str, set: _Overrides = None, directory: _Path = ".", mesh: _Mesh = None) -> Scene: ...
def from_dict(scene: dict[str, Any], set: _Overrides = None, directory: _Path = ".",
              mesh: _Mesh = None) -> Scene: ...

class Result:
    """A solved scene: NumPy arrays of the final state and the figures of summary.json."""

    @property
    def positions(self) -> NDArray[np.float64]: ...          # (n, 3) m
    @property
    def initial_positions(self) -> NDArray[np.float64]: ...  # (n, 3) m
    @property
    def reactions(self) -> NDArray[np.float64]: ...          # (n, 3) N, on fixed coordinates
    @property
    def contact_forces(self) -> NDArray[np.float64]: ...     # (n, 3) N
    @property
    def fixed(self) -> NDArray[np.bool_]: ...                # (n, 3)
    @property
    def faces(self) -> NDArray[np.int32]: ...                # (m, 3) node ids
    @property
    def converged(self) -> bool: ...
    @property
    def stable(self) -> bool: ...
    @property
    def state(self) -> str: ...
    @property
    def termination(self) -> str: ...
    @property
    def iterations(self) -> int: ...
    @property
    def energy(self) -> dict[str, float]: ...                # J, per term type and "total"
    @property
    def drape_coefficient(self) -> float | None: ...
    @property
    def drape_coefficient_error(self) -> float | None: ...
    @property
    def summary(self) -> dict[str, Any]: ...                 # summary.json's dict
    @property
    def interrupted(self) -> bool: ...
    def write(self, directory: _Path) -> None: ...

def solve(scene: Scene | _Path | dict[str, Any], solver: str | None = None, set: _Overrides = None,
          start: Result | ArrayLike | None = None, mesh: _Mesh = None,
          progress: _Progress = ...) -> Result: ...

class DropsResult:
    """Repeated drops (`drape solve --drops N`): summary.json's dict and drops.csv's table."""

    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def table(self) -> _Table: ...
    @property
    def line(self) -> str: ...
    @property
    def drops(self) -> int: ...
    @property
    def counted(self) -> int: ...
    @property
    def mean(self) -> float | None: ...
    @property
    def standard_deviation(self) -> float | None: ...
    @property
    def folds_histogram(self) -> dict[int, int]: ...
    @property
    def most_frequent_folds(self) -> list[int]: ...
    @property
    def mesh_rule(self) -> dict[str, Any] | None: ...

# directory= (in drops, fit and sweep) is the former name of out=: a DeprecationWarning.
def drops(scene: Scene | _Path | dict[str, Any], drops: int | None = None, set: _Overrides = None,
          out: _Path | None = None, threads: int = 0, progress: _Progress = ...,
          directory: _Path | None = None) -> DropsResult: ...

class FitResult:
    """What `drape fit` writes: fit.json's dict (`table`) and history.csv's table (`history`)."""

    @property
    def table(self) -> dict[str, Any]: ...
    @property
    def history(self) -> _Table: ...
    @property
    def converged(self) -> bool: ...
    @property
    def parameters(self) -> dict[str, float]: ...
    @property
    def standard_errors(self) -> dict[str, float]: ...
    @property
    def identifiability(self) -> list[str]: ...
    @property
    def measurements(self) -> list[dict[str, Any]]: ...
    @property
    def termination(self) -> str: ...
    @property
    def warnings(self) -> list[str]: ...

def fit(fit_file: _Path | dict[str, Any], set: _Overrides = None, method: str | None = None,
        out: _Path | None = None, threads: int = 1, base: _Path = ".",
        progress: _Progress = ..., directory: _Path | None = None) -> FitResult: ...
def sweep(sweep_file: _Path, out: _Path | None = None, threads: int = 0, plots: bool = False,
          progress: _Progress = ..., directory: _Path | None = None) -> _Table: ...

class FabricsResult:
    """What `drape fabrics` writes: fabrics.csv's table and fabrics.json's dict."""

    @property
    def table(self) -> _Table: ...
    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def line(self) -> str: ...
    @property
    def statistics(self) -> dict[str, Any] | None: ...

def fabrics(table: _Path, scene: _Path | None = None, set: _Overrides = None,
            drops: int | None = None, out: _Path | None = None, threads: int = 0,
            progress: _Progress = ..., calibration: _Path | None = None) -> FabricsResult: ...

# d positions / d key for each key: shape (nodes, 3, len(keys)).
def sensitivities(scene: Scene | _Path | dict[str, Any], keys: str | Sequence[str], set: _Overrides = None,
                  solver: str | None = None, mesh: _Mesh = None,
                  progress: _Progress = ...) -> NDArray[np.float64]: ...
