"""The Python module against the command line: the same positions to the last digit, warm starts,
located errors, Ctrl-C, and the scene as data. Run by CTest (PythonModule) with PYTHONPATH at the
build tree's package, DRAPE_SOURCE_DIR at the clone and DRAPE_BINARY at the built drape."""

import csv
import ctypes
import json
import os
import signal
import subprocess
import threading

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


def test_check_is_the_scene_as_data():
    data = drape.load(config("fv/drape_tester_cotton_30.yaml"), set={"mesh.spacing": 0.01}).check()
    assert data["nodes"] == 709 and data["model"] == "finite_volume"
    assert data["material_si"]["density"] == (pytest.approx(0.12), "kg/m^2")
    assert sum(data["terms"].values()) == 6553
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


def test_a_fit_gives_its_tables(tmp_path):
    fitted = drape.fit(config("fit/fit_drape_coefficient.yaml"))
    assert fitted.converged
    d_warp = fitted.parameters["material.finite_volume.D_warp"]
    assert d_warp == pytest.approx(1e-4, rel=1e-4)  # the value the example's DC was made with
    assert fitted.standard_errors["material.finite_volume.D_warp"] > 0
    assert len(fitted.history) == fitted.table["evaluations"]
    # The files drape fit writes, where asked, and drape's nodes.csv as measured positions.
    folder = tmp_path / "fit"
    drape.fit(config("fit/fit_drape_coefficient.yaml"), directory=folder)
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
    table = drape.sweep(config("sweep/sweep_small.yaml"), directory=tmp_path / "sweep", threads=1)
    rows = table.to_dict("records") if hasattr(table, "to_dict") else table
    assert len(rows) == 4
    assert all(isinstance(row["converged"], (bool, np.bool_)) and row["converged"] for row in rows)
    assert (tmp_path / "sweep" / "sweep.csv").is_file()


def test_a_fit_from_a_dict_is_the_files():
    spec = {  # configs/fit/fit_drape_coefficient.yaml as a dict, its paths from configs/fit
        "scene": "drape_fv.yaml",
        "parameters": [{"key": "material.finite_volume.D_warp", "initial": 6.0e-5,
                        "bounds": [1.0e-6, 1.0e-3], "log": True}],
        "measurements": [{"drape_coefficient": {"value": 0.525460090, "disc_radius": 0.06,
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
