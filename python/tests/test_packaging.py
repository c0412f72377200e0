"""The package as pip installs it: its type stubs (python/drape/__init__.pyi) against the module,
its PEP 440 version, and, where DRAPE_TEST_VENV_INSTALL=1 (.ci/run; it builds drape, minutes),
`pip install .` into a virtual environment. Run by CTest (PythonModule) with PYTHONPATH at the
build tree's package and DRAPE_SOURCE_DIR at the clone."""

import ast
import builtins
import importlib.util
import inspect
import json
import os
import re
import shutil
import subprocess
import sys
import time

import pytest

import drape

SOURCE = os.path.abspath(os.environ.get("DRAPE_SOURCE_DIR",
                                        os.path.join(os.path.dirname(__file__), "..", "..")))
PACKAGE = os.path.join(SOURCE, "python", "drape")
STUB = os.path.join(PACKAGE, "__init__.pyi")
# Names stubtest may report that are not errors, with the reason on the line above each.
STUBTEST_ALLOWLIST = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                  "stubtest_allowlist.txt")


def stub_module():
    with open(STUB) as file:
        return ast.parse(file.read(), STUB)


def assigned_names(node):
    """The names a top-level or class-level statement of the stub defines."""
    if isinstance(node, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
        return [node.name]
    if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
        return [node.target.id]
    if isinstance(node, ast.Assign):
        return [target.id for target in node.targets if isinstance(target, ast.Name)]
    return []


def public(name):
    return not name.startswith("_") or name == "__version__"


def stub_all(module):
    for node in module.body:
        if isinstance(node, ast.Assign) and "__all__" in assigned_names(node):
            return ast.literal_eval(node.value)
    return None


def stub_classes(module):
    return [node for node in module.body if isinstance(node, ast.ClassDef)]


def is_property(function):
    return any(isinstance(decorator, ast.Name) and decorator.id == "property"
               for decorator in function.decorator_list)


def test_the_stubs_name_what_the_package_exports():
    module = stub_module()
    defined = {name for node in module.body for name in assigned_names(node) if public(name)}
    assert sorted(set(drape.__all__) - defined) == [], "in drape.__all__, not in __init__.pyi"
    assert sorted(defined - set(drape.__all__)) == [], "in __init__.pyi, not in drape.__all__"
    assert sorted(stub_all(module)) == sorted(drape.__all__)


def test_the_package_has_every_attribute_the_stubs_give_a_class():
    missing = []
    for node in stub_classes(stub_module()):
        runtime = getattr(drape, node.name)
        assert inspect.isclass(runtime), node.name
        for base in node.bases:  # the builtin ones (UserWarning, ValueError)
            builtin = getattr(builtins, base.id, None) if isinstance(base, ast.Name) else None
            if inspect.isclass(builtin):
                assert issubclass(runtime, builtin), f"{node.name} is not a {base.id}"
        # An exception's attributes are its instances' (set in __init__).
        instance = runtime("a message") if issubclass(runtime, BaseException) else None
        for member in node.body:
            for name in assigned_names(member):
                if name.startswith("_"):
                    continue
                if isinstance(member, ast.AnnAssign) and instance is not None:
                    found = hasattr(instance, name)
                else:  # properties and methods: on the class
                    found = hasattr(runtime, name)
                if not found:
                    missing.append(f"{node.name}.{name}")
    assert missing == [], "named in __init__.pyi, not in the package"


def stub_parameters(function):
    """A stub function's parameters: [(name, has a default)], `self` left out."""
    arguments = function.args
    positional = arguments.posonlyargs + arguments.args
    defaults = [False] * (len(positional) - len(arguments.defaults)) + [True] * len(arguments.defaults)
    parameters = [(a.arg, d) for a, d in zip(positional, defaults)]
    parameters += [(a.arg, d is not None) for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)]
    if arguments.vararg:
        parameters.append(("*" + arguments.vararg.arg, False))
    if arguments.kwarg:
        parameters.append(("**" + arguments.kwarg.arg, False))
    return [p for p in parameters if p[0] != "self"]


def runtime_parameters(function):
    parameters = []
    for parameter in inspect.signature(function).parameters.values():
        name = {inspect.Parameter.VAR_POSITIONAL: "*", inspect.Parameter.VAR_KEYWORD: "**"}.get(
            parameter.kind, "") + parameter.name
        parameters.append((name, parameter.default is not inspect.Parameter.empty))
    return [p for p in parameters if p[0] != "self"]


def test_the_stubs_parameters_are_the_functions():
    """Every function's and method's parameters, in order, and which have defaults (stubtest, where
    mypy is installed, checks the defaults' values and the kinds too)."""
    module = stub_module()
    functions = [(node.name, getattr(drape, node.name), node) for node in module.body
                 if isinstance(node, ast.FunctionDef)]
    for cls in stub_classes(module):
        functions += [(f"{cls.name}.{node.name}", getattr(getattr(drape, cls.name), node.name), node)
                      for node in cls.body if isinstance(node, ast.FunctionDef)
                      and not is_property(node) and (public(node.name) or node.name == "__init__")]
    differences = []
    for name, runtime, node in functions:
        if stub_parameters(node) != runtime_parameters(runtime):
            differences.append(f"{name}: stub {stub_parameters(node)}, "
                               f"module {runtime_parameters(runtime)}")
    assert differences == []


def test_the_package_ships_its_stubs():
    folder = os.path.dirname(drape.__file__)
    for name in ("__init__.pyi", "py.typed"):
        assert os.path.isfile(os.path.join(folder, name)), f"{name} not beside {drape.__file__}"


def pep440_version(text):
    """python/drape/_version.py's function, run from the clone's file as setup.py runs it."""
    path = os.path.join(PACKAGE, "_version.py")
    with open(path) as file:
        namespace = {"__name__": "drape_version_under_test"}
        exec(compile(file.read(), path, "exec"), namespace)
    return namespace["pep440_version"](text)


@pytest.mark.parametrize("text, expected", [
    ("0.1", "0.1"),
    ("0.1 (git 407930e)", "0.1+g407930e"),
    ("0.1 (git 407930e-dirty)", "0.1+g407930e.dirty"),
    ("0.1 (git v0.1-3-g407930e)", "0.1+3.g407930e"),
    ("0.1 (git v0.1-3-g407930e-dirty)", "0.1+3.g407930e.dirty"),
    ("0.1 (git v0.1)", "0.1"),
    ("0.1 (git v0.1-dirty)", "0.1+dirty"),
    ("1.2.3 (git 0123456789abcdef0123456789abcdef01234567)",
     "1.2.3+g0123456789abcdef0123456789abcdef01234567"),
])
def test_pep440_version(text, expected):
    assert pep440_version(text) == expected
    try:
        from packaging.version import Version
    except ImportError:
        return
    assert str(Version(expected)) == expected  # valid, and already in PEP 440's normal form


@pytest.mark.parametrize("text", ["unknown", "", "v0.1 (git 407930e)"])
def test_pep440_version_refuses_what_is_not_a_version(text):
    with pytest.raises(ValueError):
        pep440_version(text)


def test_the_version_is_pep_440_and_the_projects():
    version = pytest.importorskip("packaging.version")
    parsed = version.Version(drape.__version__)
    assert str(parsed) == drape.__version__
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as file:
        project = re.search(r"project\(\s*drape\s+VERSION\s+([0-9.]+)", file.read()).group(1)
    assert parsed.release == version.Version(project).release


def test_stubtest_finds_the_stubs_true_to_the_module(tmp_path):
    """mypy's stubtest (Debian: python3-mypy): the clone's stubs (MYPYPATH, searched first) against
    the module PYTHONPATH finds (the build tree's)."""
    if importlib.util.find_spec("mypy") is None or importlib.util.find_spec("mypy.stubtest") is None:
        pytest.skip("mypy's stubtest is not installed (Debian: python3-mypy)")
    environment = dict(os.environ, MYPYPATH=os.path.dirname(PACKAGE))
    command = [sys.executable, "-m", "mypy.stubtest", "drape"]
    if os.path.exists(STUBTEST_ALLOWLIST):
        command += ["--allowlist", STUBTEST_ALLOWLIST]
    # From a scratch folder: mypy writes its cache into the working directory.
    run = subprocess.run(command, cwd=tmp_path, env=environment, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr


def git_status():
    if shutil.which("git") is None or not os.path.exists(os.path.join(SOURCE, ".git")):
        return None
    return subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"], cwd=SOURCE,
                          capture_output=True, text=True, check=True).stdout


@pytest.mark.skipif(os.environ.get("DRAPE_TEST_VENV_INSTALL") != "1",
                    reason="builds drape into a virtual environment (minutes): "
                           "DRAPE_TEST_VENV_INSTALL=1 runs it (.ci/run does)")
def test_pip_install_into_a_virtual_environment(tmp_path):
    """README's two commands, from the clone: a venv with Debian's packages, `pip install .`
    offline (Debian's setuptools and wheel, no build isolation); then drape imported in the venv
    from a folder outside the clone solves a scene, with the version pip recorded and its stubs."""
    venv = tmp_path / "V"
    environment = {key: value for key, value in os.environ.items()
                   if key not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    environment.update(PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_INPUT="1")
    before = git_status()
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    start = time.monotonic()
    subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "."], cwd=SOURCE,
                   env=environment, check=True)
    print(f"pip install: {time.monotonic() - start:.0f} s")
    assert git_status() == before, "pip install left files in the clone that git sees"

    script = """
import importlib.metadata, json, os, sys
import drape
result = drape.solve(sys.argv[1])
folder = os.path.dirname(drape.__file__)
print(json.dumps({"file": drape.__file__, "version": drape.__version__,
                  "metadata_version": importlib.metadata.version("drape"),
                  "converged": bool(result.converged), "shape": list(result.positions.shape),
                  "stubs": sorted(name for name in os.listdir(folder)
                                  if name in ("__init__.pyi", "py.typed"))}))
"""
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    run = subprocess.run([str(venv / "bin" / "python"), "-c", script,
                          os.path.join(SOURCE, "configs", "examples", "chain.yaml")],
                         cwd=outside, env=environment, capture_output=True, text=True, check=True)
    seen = json.loads(run.stdout.strip().splitlines()[-1])
    assert seen["file"].startswith(str(venv)), seen["file"]
    assert seen["version"] == seen["metadata_version"]
    assert seen["converged"]
    assert seen["shape"][1] == 3
    assert seen["stubs"] == ["__init__.pyi", "py.typed"]
