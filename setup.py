"""`pip install .`: the Python package drape, its extension _drape built by CMake.

From a clone, with the Debian packages of README.md's first command and pybind11-dev python3-dev
(offline; setuptools, wheel and pip from Debian):

    python3 -m venv --system-site-packages V && V/bin/pip install --no-build-isolation .

pyproject.toml names setuptools as the build backend; this file adds what it cannot say:
  - the extension: build_ext configures the clone with CMake into its build_temp (a Release build
    of drape_core and _drape only: no tests, no report tools) and builds the target _drape, on all
    cores, then copies the module where setuptools packs it. The build folder is build-python/ in
    the clone (ignored by git, as build*/ is); it is kept, so a second `pip install .` compiles
    only what changed, and ccache (cmake/build_speed.cmake) reuses the compiles of build/;
  - the version, PEP 440: CMakeLists.txt's project version, with `git describe --always --dirty`
    in the local segment from a clone (0.1+g407930e, 0.1+g407930e.dirty), the conversion
    python/drape/_version.py makes of the module's own version text, so that `pip show drape`
    and `drape.__version__` agree.
Environment: CMAKE_BUILD_PARALLEL_LEVEL (jobs; default the machine's cores), DRAPE_CMAKE_ARGS
(more -D options, split on spaces, e.g. "-DDRAPE_CCACHE=OFF").
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


def _pep440_version(text):
    """python/drape/_version.py's pep440_version, run from its text (importing the package needs
    _drape; an import by path would leave its bytecode in python/drape/__pycache__)."""
    path = SOURCE / "python" / "drape" / "_version.py"
    namespace = {"__name__": "_drape_version"}
    exec(compile(path.read_text(), str(path), "exec"), namespace)
    return namespace["pep440_version"](text)


def version():
    """The version _drape.version() gives a build of these sources, as PEP 440."""
    cmake_lists = (SOURCE / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*drape\s+VERSION\s+([0-9.]+)", cmake_lists)
    if not match:
        raise RuntimeError("CMakeLists.txt: no `project(drape VERSION x.y ...)`")
    text = match.group(1)
    describe = ""
    if (SOURCE / ".git").exists():  # as cmake/git_describe.cmake
        try:
            describe = subprocess.run(["git", "describe", "--always", "--dirty"], cwd=SOURCE,
                                      capture_output=True, text=True, check=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            describe = ""
    if describe:
        text += f" (git {describe})"
    return _pep440_version(text)


class CMakeExtension(Extension):
    """An extension that CMake builds: `target` of the project at `source_dir`."""

    def __init__(self, name, target, source_dir=SOURCE):
        super().__init__(name, sources=[])
        self.target = target
        self.source_dir = Path(source_dir)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not isinstance(ext, CMakeExtension):
            return super().build_extension(ext)
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(ext.source_dir), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DDRAPE_BUILD_TESTS=OFF",   # no GoogleTest needed
            "-DDRAPE_BUILD_TOOLS=OFF",
            "-DDRAPE_PYTHON=ON",
            "-DDRAPE_PYTHON_REQUIRED=ON",  # fail here, not later, without pybind11 or the headers
            f"-DPython3_EXECUTABLE={sys.executable}",
        ] + shlex.split(os.environ.get("DRAPE_CMAKE_ARGS", ""))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or self.parallel or os.cpu_count() or 1
        compile_ = ["cmake", "--build", str(build), "--target", ext.target, f"-j{jobs}"]
        for command in (configure, compile_):
            print(" ".join(shlex.quote(part) for part in command), flush=True)
            subprocess.run(command, check=True)
        # The module lands in the build's package folder (cmake/python_module.cmake), named with
        # this Python's extension suffix, as setuptools names it.
        destination = Path(self.get_ext_fullpath(ext.name))
        built = build / "python" / "drape" / destination.name
        if not built.exists():
            found = sorted((build / "python" / "drape").glob("_drape*.so"))
            if len(found) != 1:
                raise RuntimeError(f"{built}: not built (found {[str(f) for f in found]})")
            built = found[0]
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, destination)


setup(
    version=version(),
    package_dir={"": "python"},
    packages=["drape"],
    package_data={"drape": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("drape._drape", target="_drape")],
    cmdclass={"build_ext": CMakeBuild},
    # The build folders (build_temp, build_lib, the wheel's) in build-python/, beside the clone's
    # own build/ (CMake's), not inside it.
    options={"build": {"build_base": "build-python"}},
    zip_safe=False,
)
