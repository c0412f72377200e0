"""The Python module against the command line: the same positions to the last digit, warm starts,
located errors, Ctrl-C, and the scene as data. Run by CTest (PythonModule) with PYTHONPATH at the
build tree's package, DRAPE_SOURCE_DIR at the clone and DRAPE_BINARY at the built drape."""

import contextlib
import csv
import ctypes
import io
import json
import os
import signal
import subprocess
import threading
import warnings

import numpy as np
import pytest

import drape

SOURCE = os.environ.get("DRAPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("DRAPE_BINARY", os.path.join(SOURCE, "build", "drape"))


def config(relative):
    return os.path.join(SOURCE, "configs", relative)


def module_blas_core():
    """The OpenBLAS kernels this process loaded (the module cannot restart itself with faster ones,
    as `drape` does where OpenBLAS takes the CPU for a Prescott: src/numerics/library_threads.cc)."""
    summary = drape.solve(config("examples/chain.yaml")).summary
    return summary["blas_kernels"].split(" ")[0]


def cli_solve(scene, folder, *overrides):
    """`drape solve` into `folder`, on the OpenBLAS kernels this process runs (another core's
    kernels round differently): its nodes.csv positions and summary.json."""
    command = [BINARY, "solve", scene, "--out", str(folder)]
    for override in overrides:
        command += ["--set", override]
    environment = dict(os.environ, OPENBLAS_CORETYPE=module_blas_core())
    subprocess.run(command, check=True, capture_output=True, env=environment)
    with open(os.path.join(folder, "nodes.csv")) as nodes:
        rows = list(csv.DictReader(nodes))
    positions = np.array([[float(row[c]) for c in ("x_m", "y_m", "z_m")] for row in rows])
    with open(os.path.join(folder, "summary.json")) as summary:
        return positions, json.load(summary)


@pytest.mark.parametrize("scene", ["examples/hanging_sheet.yaml", "examples/chain.yaml",
                                   "examples/pulled_sheet.yaml"])
def test_positions_are_the_clis_to_the_last_digit(scene, tmp_path):
    positions, summary = cli_solve(config(scene), tmp_path)
    result = drape.solve(config(scene))
    assert result.converged == summary["converged"]
    assert result.positions.shape == positions.shape
    assert result.positions.dtype == np.float64
    assert np.array_equal(result.positions, positions)  # nodes.csv holds exact numbers
    assert result.summary["energy"] == summary["energy"]
    assert set(result.summary) == set(summary)


def test_a_drape_test_gives_its_coefficient_and_arrays(tmp_path):
    overrides = {"mesh.spacing": 0.02}
    _, summary = cli_solve(config("fv/drape_tester_cotton_30.yaml"), tmp_path, "mesh.spacing=0.02")
    result = drape.solve(config("fv/drape_tester_cotton_30.yaml"), set=overrides)
    assert result.drape_coefficient == summary["drape_coefficient"]
    # At 2 cm no coarser level: the error bar is the mesh rule's.
    assert result.drape_coefficient_error == summary["mesh_rule"]["expected_drape_coefficient_error"]
    n = len(result.positions)
    assert result.fixed.shape == (n, 3) and result.fixed.dtype == np.bool_
    assert result.reactions.shape == result.contact_forces.shape == (n, 3)
    assert result.faces.shape[1] == 3 and result.faces.max() < n
    # Reactions and contact forces balance the weight: Σ = m g upwards (to the solve's residual).
    mass = summary["mass_kg"]
    upward = result.reactions[:, 2].sum() + result.contact_forces[:, 2].sum()
    assert upward == pytest.approx(mass * 9.81, rel=1e-6)
    result.write(tmp_path / "written")
    assert (tmp_path / "written" / "summary.json").is_file()


def test_a_warm_start_begins_at_the_answer():
    scene = drape.load(config("examples/hanging_sheet.yaml"))
    cold = drape.solve(scene)
    warm = drape.solve(scene, start=cold)
    assert warm.converged and warm.iterations <= 1
    assert np.allclose(warm.positions, cold.positions, atol=1e-9)
    from_array = drape.solve(scene, start=cold.positions.copy())
    assert np.array_equal(from_array.positions, warm.positions)
    with pytest.raises(ValueError, match=r"shape \(225, 3\)"):
        drape.solve(scene, start=np.zeros((3, 3)))


def test_drops_are_the_command_lines(tmp_path):
    scene = config("fv/drape_tester_polyester_24.yaml")
    spacing = {"mesh.spacing": 0.02}
    lab = drape.drops(scene, drops=2, set=spacing, threads=1)
    assert (lab.drops, lab.counted) == (2, 2)
    values = list(lab.table["drape_coefficient"])
    assert lab.mean == pytest.approx(np.mean(values), rel=1e-12)
    assert lab.standard_deviation == pytest.approx(np.std(values, ddof=1), rel=1e-12)
    assert sum(lab.folds_histogram.values()) == 2
    assert lab.mesh_rule["coarse"] and lab.line.startswith("2 drops: drape coefficient ")
    out = tmp_path / "out"
    command = subprocess.run([BINARY, "solve", scene, "--drops", "2", "--threads", "1",
                              "--set", "mesh.spacing=0.02", "--out", str(out)],
                             capture_output=True, text=True, check=True)
    assert command.stdout.startswith(lab.line)
    with open(out / "drops.csv") as file:
        rows = list(csv.DictReader(file))
    assert [float(row["drape_coefficient"]) for row in rows] == values
    with pytest.raises(drape.InputError, match="needs a drape test"):
        drape.drops(config("examples/hanging_sheet.yaml"), drops=2)
    with pytest.raises(drape.InputError, match="whole number"):
        drape.drops(scene, drops=0)
    with pytest.raises(drape.InputError, match="threads: expected a whole number >= 0"):
        drape.drops(scene, drops=2, threads=-1)
    with pytest.raises(drape.InputError, match="from 1 to 10000, got 10001"):
        drape.drops(scene, drops=10001)


def test_bad_input_is_located():
    with pytest.raises(drape.InputError) as error:
        drape.load(config("examples/hanging_sheet.yaml"), set={"mesh.nodez": [3, 3]})
    assert (error.value.file, error.value.line, error.value.key) == ("--set", 1, "mesh.nodez")
    assert "did you mean 'nodes'" in str(error.value)
    text = "name: x\nmesh: {kind: grid, size: [1, 1], nodes: [3, 3]}\n" \
           "material: {model: springs, density: -1}\n"
    with pytest.raises(drape.InputError) as error:
        drape.loads(text)
    assert (error.value.file, error.value.line, error.value.column) == ("<string>", 3, 37)
    assert error.value.key == "material.density"
    with pytest.raises(drape.InputError) as error:
        drape.from_dict({"mesh": {"kind": "grid", "sides": 3}})
    assert error.value.file == "<dict>" and error.value.key == "mesh.sides"
    assert (error.value.line, error.value.column) == (0, 0)  # the dict has no lines
    assert str(error.value).startswith("<dict>: mesh.sides: unknown key 'sides'")
    with pytest.raises(drape.InputError, match="unknown solver"):
        drape.solve(config("examples/chain.yaml"), solver="newtn")


def test_a_scene_from_a_dict_is_the_files():
    chain = {  # configs/examples/chain.yaml as a dict
        "name": "chain", "dimension": 2,
        "mesh": {"kind": "chain", "length": 1.0, "nodes": 11, "direction": [1, 0, 0]},
        "material": {"model": "springs", "node_mass": 0.01, "springs": {"structural": 50}},
        "fixed": [{"nodes": {"ids": [0]}, "move": [0.1, 0, 0]},
                  {"nodes": {"ids": [10]}, "move": [-0.1, 0, 0]}],
        "loads": {"gravity": [0, 0, -9.81]},
        "solver": {"method": "newton", "tolerance": 1.0e-9, "max_iterations": 100000},
    }
    from_dict = drape.solve(drape.from_dict(chain))
    from_file = drape.solve(config("examples/chain.yaml"))
    assert np.array_equal(from_dict.positions, from_file.positions)
    # Every entry point takes the dict itself, as drape.fit does.
    assert np.array_equal(drape.solve(chain).positions, from_file.positions)
    derivatives = drape.sensitivities(chain, "material.springs.structural")
    assert derivatives.shape == (11, 3, 1) and np.all(np.isfinite(derivatives))


def test_a_fabric_through_itself_is_no_stable_minimum(tmp_path):
    """Two 3 x 3 squares of one mesh file held by their borders, one standing across the other:
    the solve converges with the fabric through itself, which is no stable minimum."""
    vertices = [(0.5 * i, 0.5 * j, 0.0) for i in range(3) for j in range(3)]
    vertices += [(0.7, 0.1 + 0.25 * i, -0.5 + 0.5 * j) for i in range(3) for j in range(3)]
    faces = []
    for base in (1, 10):  # OBJ counts from 1
        for i in range(2):
            for j in range(2):
                a = base + 3 * i + j
                faces += [(a, a + 3, a + 4), (a, a + 4, a + 1)]
    path = tmp_path / "crossed.obj"
    path.write_text("".join("v %g %g %g\n" % v for v in vertices) +
                    "".join("f %d %d %d\n" % f for f in faces))
    borders = [k for k in range(18) if k not in (4, 13)]
    result = drape.solve(drape.from_dict({
        "name": "crossed", "mesh": {"kind": "file", "path": str(path)},
        "material": {"model": "springs", "density": 0.2, "springs": {"structural": 1000}},
        "fixed": [{"nodes": {"ids": borders}}], "loads": {"gravity": [0, 0, -9.81]},
        "solver": {"method": "newton", "tolerance": 1.0e-9}}))
    assert result.converged
    assert not result.stable
    assert result.state.startswith("fabric through itself (")
    assert result.summary["self_intersections"]["crossings"] > 0


def test_check_is_the_scene_as_data():
    data = drape.load(config("fv/drape_tester_cotton_30.yaml"), set={"mesh.spacing": 0.01}).check()
    assert data["nodes"] == 709 and data["model"] == "finite_volume"
    assert data["material_si"]["density"] == (pytest.approx(0.12), "kg/m^2")
    assert sum(data["terms"].values()) == 7201
    assert data["terms"]["fv_cell_shear"] == data["terms"]["fv_twist"]  # one of each per cell
    assert "coarse" in data["warning"]


def test_ctrl_c_stops_a_solve_at_its_last_iterate():
    scene = drape.load(config("fv/drape_tester_cotton_30.yaml"),
                       set={"mesh.spacing": 0.005, "material.finite_volume.kes.2HB_warp": 0.1,
                            "material.finite_volume.kes.2HB_weft": 0.1})
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as interrupt:
            drape.solve(scene)
    finally:
        timer.cancel()
    result = interrupt.value.result
    assert result.interrupted and not result.converged
    assert result.positions.shape == (2821, 3) and np.isfinite(result.positions).all()


def test_ctrl_c_in_the_progress_callable_stops_a_solve_with_its_result():
    """Python's SIGINT handler can raise in the progress callable (which runs with the GIL, a line
    a second): that is the same Ctrl-C, and the solve's last iterate comes with it."""
    scene = drape.load(config("fv/drape_tester_cotton_30.yaml"),
                       set={"mesh.spacing": 0.005, "material.finite_volume.kes.2HB_warp": 0.1,
                            "material.finite_volume.kes.2HB_weft": 0.1})

    def ctrl_c(line):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt) as interrupt:
        drape.solve(scene, progress=ctrl_c)
    result = interrupt.value.result
    assert result.interrupted and not result.converged
    assert np.isfinite(result.positions).all()


def test_a_fit_gives_its_tables(tmp_path):
    fitted = drape.fit(config("fit/fit_drape_coefficient.yaml"))
    assert fitted.converged
    d_warp = fitted.parameters["material.finite_volume.D_warp"]
    assert d_warp == pytest.approx(1e-4, rel=1e-4)  # the value the example's DC was made with
    assert fitted.standard_errors["material.finite_volume.D_warp"] > 0
    assert len(fitted.history) == fitted.table["evaluations"]
    # The files drape fit writes, where asked, and drape's nodes.csv as measured positions.
    folder = tmp_path / "fit"
    drape.fit(config("fit/fit_drape_coefficient.yaml"), out=folder)
    assert (folder / "fit.json").is_file() and (folder / "history.csv").is_file()
    with pytest.raises(drape.InputError, match="unknown fit method"):
        drape.fit(config("fit/fit_drape_coefficient.yaml"), method="bobyqaa")


def _mapped_library_with(symbol):
    """The first library mapped into this process that exports `symbol`, or None."""
    with open("/proc/self/maps") as maps:
        paths = {line.split()[-1] for line in maps if ".so" in line}
    for path in sorted(paths):
        try:
            library = ctypes.CDLL(path)
        except OSError:
            continue
        if hasattr(library, symbol):
            return library
    return None


def test_numpys_threads_are_given_back():
    """drape holds OpenBLAS and OpenMP on one thread for a call's duration only."""
    openblas = _mapped_library_with("openblas_get_num_threads")
    openmp = _mapped_library_with("omp_get_max_active_levels")
    if openblas is None or openmp is None:
        pytest.skip("OpenBLAS or OpenMP is not loaded in this process")
    openblas.openblas_set_num_threads(2)
    openmp.omp_set_max_active_levels(3)
    result = drape.solve(config("examples/hanging_sheet.yaml"), set={"mesh.nodes": [6, 6]})
    assert result.converged
    assert openblas.openblas_get_num_threads() == 2
    assert openmp.omp_get_max_active_levels() == 3


def test_a_sweep_gives_its_table(tmp_path):
    table = drape.sweep(config("sweep/sweep_small.yaml"), out=tmp_path / "sweep", threads=1)
    rows = table.to_dict("records") if hasattr(table, "to_dict") else table
    assert len(rows) == 4
    assert all(isinstance(row["converged"], (bool, np.bool_)) and row["converged"] for row in rows)
    assert (tmp_path / "sweep" / "sweep.csv").is_file()


def test_a_fit_from_a_dict_is_the_files():
    spec = {  # configs/fit/fit_drape_coefficient.yaml as a dict, its paths from configs/fit
        "scene": "drape_fv.yaml",
        "parameters": [{"key": "material.finite_volume.D_warp", "initial": 6.0e-5,
                        "bounds": [1.0e-6, 1.0e-3], "log": True}],
        "measurements": [{"drape_coefficient": {"value": 0.520392974, "disc_radius": 0.06,
                                                "sigma": 0.005}}],
    }
    from_dict = drape.fit(spec, base=config("fit"))
    from_file = drape.fit(config("fit/fit_drape_coefficient.yaml"))
    assert from_dict.parameters == from_file.parameters
    spec["parameters"][0]["bounds"] = [1.0, 0.5]
    with pytest.raises(drape.InputError) as error:
        drape.fit(spec, base=config("fit"))
    assert error.value.file == "<dict>" and error.value.key == "parameters[0].bounds"
    assert str(error.value).startswith("<dict>: parameters[0].bounds: ") and error.value.line == 0


# ---- paths, errors, Python's channels, arrays in, sensitivities, the fabric table -------------

def test_a_fit_dicts_default_base_is_the_current_folder(monkeypatch):
    """base="." was joined to the dict's paths without being made absolute; and the warnings of a
    dict's fit named its temporary file."""
    spec = {"scene": "drape_fv.yaml",
            "parameters": [{"key": "material.finite_volume.D_warp", "initial": 6.0e-5,
                            "bounds": [1.0e-6, 1.0e-3], "log": True}],
            "measurements": [{"drape_coefficient": {"value": 0.520392974, "disc_radius": 0.06,
                                                    "sigma": 0.005}}]}
    monkeypatch.chdir(config("fit"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        fitted = drape.fit(spec, progress=None)
    assert fitted.converged
    for text in [str(w.message) for w in caught] + fitted.warnings:
        assert "drape_fit_dict_" not in text


def test_an_unknown_solver_is_blamed_on_the_argument():
    with pytest.raises(drape.InputError) as error:
        drape.solve(config("examples/chain.yaml"), solver="newtn")
    assert error.value.file == "solver"
    assert "did you mean 'newton'?" in str(error.value)
    assert "chain.yaml" not in str(error.value)


@pytest.mark.parametrize("call", [
    lambda: drape.load("no/such/scene.yaml"),
    lambda: drape.solve("no/such/scene.yaml"),
    lambda: drape.fit("no/such/fit.yaml"),
    lambda: drape.sweep("no/such/sweep.yaml"),
    lambda: drape.fabrics("no/such/fabrics.csv"),
])
def test_a_missing_file_is_a_file_not_found_error(call):
    with pytest.raises(FileNotFoundError) as error:
        call()
    assert error.value.filename.startswith("no/such/")


def test_drapes_warnings_are_python_warnings():
    coarse = {"mesh.spacing": 0.03}
    with pytest.warns(drape.DrapeWarning, match="is coarse for this fabric"):
        drape.solve(config("fv/drape_tester_cotton_30.yaml"), set=coarse)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", category=drape.DrapeWarning)
        drape.solve(config("fv/drape_tester_cotton_30.yaml"), set=coarse)  # silenced: no error


def test_an_accuracy_not_reached_is_a_warning():
    # The 2.5 cm lattice of the small polyester test expects 0.5, wider than the 0.05 asked.
    narrow = {"mesh.spacing": 0.025, "drape_test.disc_diameter": 0.2, "solver.levels": 1,
              "drape_test.accuracy": 0.05}
    with pytest.warns(drape.DrapeWarning, match=r"wider than the ±0.05 asked"):
        drape.solve(config("fv/drape_tester_polyester_24.yaml"), set=narrow)
    with warnings.catch_warnings():
        warnings.simplefilter("error", drape.DrapeWarning)
        # Reached, and the lattice is not coarse for what was asked: no warning at all.
        drape.solve(config("fv/drape_tester_polyester_24.yaml"),
                    set={**narrow, "drape_test.accuracy": 0.5})


def test_progress_goes_through_python(capfd):
    scene = drape.load(config("fv/drape_tester_cotton_30.yaml"), set={"mesh.spacing": 0.05})
    lines = []
    drape.drops(scene, drops=2, threads=1, progress=lines.append)
    assert len(lines) == 2 and lines[1].startswith("drop 2 (2 of 2 done): drape coefficient")
    captured = io.StringIO()
    with contextlib.redirect_stderr(captured):
        drape.drops(scene, drops=2, threads=1)  # the default: printed to sys.stderr
    assert captured.getvalue().count("\n") == 2 and "drop 1 (" in captured.getvalue()
    drape.drops(scene, drops=2, threads=1, progress=None)
    assert capfd.readouterr().err == ""  # nothing reached file descriptor 2 either


def test_a_progress_callable_that_raises_stops_the_command():
    scene = drape.load(config("fv/drape_tester_cotton_30.yaml"), set={"mesh.spacing": 0.05})

    def stop(line):
        raise RuntimeError("enough: " + line)

    with pytest.raises(RuntimeError, match="enough: drop 1"):
        drape.drops(scene, drops=3, threads=1, progress=stop)


def _square(n):
    """An n × n grid of 1 m as arrays: vertices and triangles."""
    xs = np.linspace(0.0, 1.0, n)
    vertices = np.array([[x, y, 0.0] for y in xs for x in xs])
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i
            faces += [[a, a + 1, a + n + 1], [a, a + n + 1, a + n]]
    return vertices, np.array(faces)


HANGING_CLOTH = """
mesh: {kind: file, path: cloth.obj}
material: {model: springs, density: 0.2, springs: {structural: 1000, flexion: 10}}
fixed: [{nodes: {ids: [0]}}, {nodes: {ids: [4]}}]
loads: {gravity: [0, 0, -9.81]}
solver: {method: newton, tolerance: 1.0e-10}
"""


def test_a_mesh_from_arrays_is_the_same_mesh_from_a_file(tmp_path):
    vertices, faces = _square(5)
    with open(tmp_path / "cloth.obj", "w") as obj:
        obj.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices)
        obj.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    from_file = drape.solve(drape.loads(HANGING_CLOTH, directory=tmp_path))
    from_arrays = drape.solve(drape.loads(HANGING_CLOTH, mesh=(vertices, faces)))
    assert np.array_equal(from_arrays.positions, from_file.positions)
    quads = np.array([[a, b, c, d] for (a, b, c), (_, _, d) in zip(faces[::2], faces[1::2])])
    assert drape.solve(drape.loads(HANGING_CLOTH, mesh=(vertices, quads))).converged


@pytest.mark.parametrize("faces, where, what", [
    ([[0, 1, 2], [0, 2, 99]], "faces[1]", "face vertex 99 is out of range"),
    ([[0, 1, 1]], "faces[0]", "uses vertex 1 twice"),
    ([[0.0, 1.0, 2.0]], "faces", "expected integer vertex indices"),
    ([[0, 1]], "faces", "expected an array of shape (m, 3) or (m, 4)"),
])
def test_bad_mesh_arrays_are_located_at_their_row(faces, where, what):
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0]], float)
    with pytest.raises(drape.InputError) as error:
        drape.solve(drape.loads(HANGING_CLOTH, mesh=(vertices, np.array(faces))))
    assert error.value.key == where and what in str(error.value)
    assert str(error.value).startswith("mesh arrays: " + where)


def _differences(scene, key, value, step):
    solve = lambda p: drape.solve(scene, set={key: p, "solver.tolerance": 1e-12},
                                  progress=None).positions
    return (solve(value + step) - solve(value - step)) / (2 * step)


@pytest.mark.parametrize("scene, key, value", [
    ("examples/hanging_sheet.yaml", "material.springs.structural", 1000.0),
    ("examples/hanging_sheet.yaml", "material.density", 0.2),
    ("fv/cantilever.yaml", "material.finite_volume.D_warp", 9.41760e-6),
    ("fv/cantilever.yaml", "material.density", 0.12),
])
def test_sensitivities_are_the_central_differences(scene, key, value):
    """The implicit function theorem against solves at p ± 1e-3 p (O(1e-6) truncation)."""
    derivative = drape.sensitivities(config(scene), [key])
    assert derivative.shape == (len(drape.solve(config(scene)).positions), 3, 1)
    expected = _differences(config(scene), key, value, 1e-3 * value)
    scale = np.abs(expected).max()
    assert scale > 0
    assert np.abs(derivative[:, :, 0] - expected).max() <= 1e-5 * scale


def test_sensitivities_are_refused_without_a_stable_equilibrium():
    with pytest.raises(drape.InputError, match="did not converge"):
        drape.sensitivities(config("examples/hanging_sheet.yaml"), ["material.density"],
                            set={"solver.max_iterations": 1}, progress=None)
    with pytest.raises(drape.InputError, match="not a number of the scene"):
        drape.sensitivities(config("examples/hanging_sheet.yaml"), ["material.nonsense"])


def test_fabrics_in_python_are_the_command_lines(tmp_path):
    table = tmp_path / "fabrics.csv"
    table.write_text("name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft,measured_dc\n"
                     "cotton,12,0.12,0.08,0.9,4,7,0.70\n")
    result = drape.fabrics(table, set={"mesh.spacing": 0.05}, threads=1, progress=None)
    subprocess.run([BINARY, "fabrics", str(table), "--set", "mesh.spacing=0.05", "--threads", "1",
                    "-o", str(tmp_path / "cli")], check=True, capture_output=True,
                   env=dict(os.environ, OPENBLAS_CORETYPE=module_blas_core()))
    with open(tmp_path / "cli" / "fabrics.csv") as file:
        cli = next(csv.DictReader(file))
    rows = result.table.to_dict("records") if hasattr(result.table, "to_dict") else result.table
    assert rows[0]["predicted_dc"] == float(cli["predicted_dc"])
    assert result.statistics["fabrics_compared"] == 1
    assert result.line.startswith("1 fabric: 1 predicted")

    calibration = tmp_path / "calibration.yaml"
    calibration.write_text("calibration: {bending_scale: 2}\n")
    calibrated = drape.fabrics(table, set={"mesh.spacing": 0.05}, threads=1, progress=None,
                               calibration=calibration)
    subprocess.run([BINARY, "fabrics", str(table), "--set", "mesh.spacing=0.05", "--threads", "1",
                    "--calibration", str(calibration), "-o", str(tmp_path / "calibrated")],
                   check=True, capture_output=True,
                   env=dict(os.environ, OPENBLAS_CORETYPE=module_blas_core()))
    with open(tmp_path / "calibrated" / "fabrics.csv") as file:
        cli = next(csv.DictReader(file))
    calibrated_rows = (calibrated.table.to_dict("records")
                       if hasattr(calibrated.table, "to_dict") else calibrated.table)
    assert calibrated_rows[0]["predicted_dc"] == float(cli["predicted_dc"])
    assert calibrated_rows[0]["si.D_warp [N*m]"] == 2 * rows[0]["si.D_warp [N*m]"]
    calibration.write_text("calibration: {bending_scale: -1}\n")
    with pytest.raises(drape.InputError, match="calibration.bending_scale: must be in"):
        drape.fabrics(table, calibration=calibration, progress=None)


def test_every_long_command_writes_into_a_temporary_folder_unless_told(tmp_path):
    before = set(os.listdir(config("sweep")))
    drape.sweep(config("sweep/sweep_small.yaml"), threads=1, progress=None)
    assert set(os.listdir(config("sweep"))) == before  # nothing beside the sweep file
    with pytest.warns(DeprecationWarning, match="directory= is now out="):
        drape.sweep(config("sweep/sweep_small.yaml"), directory=tmp_path / "old", threads=1,
                    progress=None)
    assert (tmp_path / "old" / "sweep.csv").is_file()
