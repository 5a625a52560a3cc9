"""``hydroservo export-c``: the C stepper's folder, its JSON report, ``--build``, and bad input (exit 2, nothing written)."""

from __future__ import annotations

import ctypes
import json

import pytest

from hydroservo.system.native import has_compiler


def test_export_c_writes_the_folder_and_reports_it(tmp_path, cli) -> None:
    out = tmp_path / "c"
    code, text, err = cli("export-c", "servo-solenoid-cylinder", "--step", "0.1 ms", "--method", "bdf2",
                          "--inputs", "valve.u", "--set", "load.m=60 kg", "--out", str(out), "--json")  # fmt: skip
    assert code == 0, err
    report = json.loads(text)
    assert report["name"] == "servo_solenoid_cylinder" and report["method"] == "bdf2" and report["step_s"] == 1e-4
    assert report["inputs"] == [{"index": 0, "name": "valve.u", "unit": ""}]
    assert report["states"][4] == {"index": 4, "name": "cyl.pA", "unit": "Pa"}
    mass = next(p for p in report["parameters"] if p["name"] == "load.m")
    assert mass["default"] == 60.0 and mass["unit"] == "kg"
    assert "library" not in report
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(report["files"]) == sorted(
        ["Makefile", "README.md", "servo_solenoid_cylinder.c", "servo_solenoid_cylinder.h",
         "servo_solenoid_cylinder_model.c", "servo_solenoid_cylinder_model.h"]  # fmt: skip
    )
    header = (out / "servo_solenoid_cylinder.h").read_text()
    assert "#define SERVO_SOLENOID_CYLINDER_STEP 0.0001" in header and '_METHOD "bdf2"' in header
    assert "int servo_solenoid_cylinder_step(servo_solenoid_cylinder_instance *m);" in header
    assert "| `load.m` | 60.0 | `kg` |" in (out / "README.md").read_text()


def test_export_c_default_folders_never_collide(tmp_path, cli, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    for _ in range(2):
        code, text, _ = cli("export-c", "flight-simulator", "--step", "1e-4")
        assert code == 0 and "flight_simulator.h" in text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hydroservo-flight-simulator-c", "hydroservo-flight-simulator-c-2"]


@pytest.mark.skipif(not has_compiler(), reason="no C compiler")
def test_export_c_build_gives_a_library_that_steps(tmp_path, cli) -> None:
    code, text, err = cli("export-c", "flight-simulator", "--step", "1e-4", "--build", "--name", "fs",
                          "--out", str(tmp_path), "--json")  # fmt: skip
    assert code == 0, err
    library = json.loads(text)["library"]
    lib = ctypes.CDLL(library)
    lib.fs_new.restype = ctypes.c_void_p
    lib.fs_time.restype = lib.fs_get_state.restype = ctypes.c_double
    lib.fs_time.argtypes = [ctypes.c_void_p]
    lib.fs_get_state.argtypes = [ctypes.c_void_p, ctypes.c_int]
    lib.fs_step.argtypes = lib.fs_free.argtypes = [ctypes.c_void_p]
    m = lib.fs_new()
    for _ in range(100):
        assert lib.fs_step(m) == 0
    assert lib.fs_time(m) == pytest.approx(0.01) and lib.fs_get_state(m, 0) > 0  # the RC network charging
    lib.fs_free(m)


def test_export_c_replaces_files_only_with_force(tmp_path, cli) -> None:
    args = ("export-c", "flight-simulator", "--step", "1e-4", "--out", str(tmp_path))
    assert cli(*args)[0] == 0
    (tmp_path / "flight_simulator.c").write_text("mine")
    code, _, err = cli(*args)
    assert code == 2 and "already exist" in err and "--force" in err
    assert (tmp_path / "flight_simulator.c").read_text() == "mine"
    assert cli(*args, "--force")[0] == 0 and "flight_simulator_step" in (tmp_path / "flight_simulator.c").read_text()


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--step=-1e-4"], "--step '-1e-4': expected a positive, finite step"),
        (["--step", "0"], "--step '0': expected a positive, finite step"),
        (["--step", "2 bar"], "--step: '2 bar' has the wrong dimension"),
        (["--step", "1e-4", "--method", "euler"], "argument --method: invalid choice: 'euler'"),
        (["--step", "1e-4", "--inputs", "valve.q"], "--inputs 'valve.q': 'valve' has no input 'q'; expected one of"),
        (["--step", "1e-4", "--inputs", "lever.u"], "--inputs 'lever.u': no component 'lever'"),
        (["--step", "1e-4", "--inputs", ","], "--inputs ',': expected comma-separated component inputs"),
        (["--step", "1e-4", "--name", "9lives"], "--name '9lives': expected a C identifier"),
        (["--step", "1e-4", "--set", "load.m=3 bar"], "wrong dimension"),
        ([], "--step: missing; expected the fixed step"),
    ],
)
def test_export_c_bad_input_exit_2_nothing_written(tmp_path, cli, capsys, monkeypatch, argv, message) -> None:
    monkeypatch.chdir(tmp_path)
    try:
        code, _, err = cli("export-c", "flight-simulator", *argv)
    except SystemExit as exc:  # argparse's own errors
        code, err = exc.code, capsys.readouterr().err
    assert code == 2 and message in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_export_c_build_without_a_compiler_writes_nothing(tmp_path, cli, monkeypatch) -> None:
    monkeypatch.setenv("CC", "")
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    monkeypatch.setattr("sysconfig.get_config_var", lambda name: None)
    code, _, err = cli("export-c", "flight-simulator", "--step", "1e-4", "--build", "--out", str(tmp_path / "c"))
    assert code == 2 and "C compiler: none found" in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not has_compiler(), reason="no C compiler")
def test_the_standalone_simulator_runs_without_python_and_agrees_with_simulate(tmp_path, cli) -> None:
    """export-c --main --build: a command that takes parameters (arguments and a file), runs a variable-step
    method and writes CSV in hydroservo's header form; its result is simulate's with the same method to
    rounding, and bad input gets exit 2 with the option and value named."""
    import subprocess

    import numpy as np

    import hydroservo as hs

    out = tmp_path / "sim"
    code, text, err = cli("export-c", "flight-simulator", "--main", "--build", "--name", "fs", "--out", str(out),
                          "--json")  # fmt: skip
    assert code == 0, err
    program = json.loads(text)["executable"]
    (tmp_path / "p.txt").write_text("# a parameter file\nload.W = 13344.6648  # 3000 lbf, in N\n\n")
    csv = tmp_path / "run.csv"
    done = subprocess.run([program, "--params", str(tmp_path / "p.txt"), "--t-end", "0.5", "--points", "51",
                           "--method", "ros23", "--accuracy", "1e-4", "--output", str(csv)],
                          capture_output=True, text=True, timeout=60)  # fmt: skip
    assert done.returncode == 0, done.stderr
    header = csv.read_text().splitlines()[0].split(",")
    assert header[0] == "t [s]" and "y [m]" in header
    data = np.loadtxt(csv, delimiter=",", skiprows=1)
    system = hs.load_model("flight-simulator")
    ref = system.simulate(t_end=0.5, n_points=51, params={"load.W": 13344.6648}, method="ros23")
    np.testing.assert_allclose(data[:, header.index("y [m]")], ref["y"], rtol=0, atol=1e-12)
    # refused: an existing output, an unknown parameter, a value that is not a number, an unknown option
    for args, words in (
        (["--output", str(csv)], "does not exist yet"),
        (["load.nothing=1"], "a parameter of the model"),
        (["load.W=3000 lbf"], "a finite number"),
        (["--method", "euler"], "ros23 or dopri5"),
        (["--points", "1"], "from 2 to"),
    ):
        done = subprocess.run([program, *args], capture_output=True, text=True, timeout=60)
        assert done.returncode == 2 and words in done.stderr and "Traceback" not in done.stderr, (args, done.stderr)
    done = subprocess.run([program, "--help"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and "--accuracy" in done.stdout


def test_export_c_needs_a_step_unless_it_writes_the_simulator(tmp_path, cli) -> None:
    code, _, err = cli("export-c", "flight-simulator", "--out", str(tmp_path / "x"))
    assert code == 2 and "--step: missing" in err and not (tmp_path / "x").exists()


@pytest.mark.skipif(not has_compiler(), reason="no C compiler")
def test_the_standalone_simulator_writes_nothing_when_the_solver_stops(tmp_path, cli) -> None:
    """A run that stops (here: a step budget of 10) exits 1 with the reason and leaves no file, partial or whole."""
    import subprocess

    code, text, err = cli("export-c", "flight-simulator", "--main", "--build", "--name", "fs", "--out",
                          str(tmp_path / "sim"), "--json")  # fmt: skip
    assert code == 0, err
    program = json.loads(text)["executable"]
    done = subprocess.run([program, "--max-steps", "10", "--output", str(tmp_path / "run.csv")],
                          capture_output=True, text=True, timeout=60)  # fmt: skip
    assert done.returncode == 1 and "step budget of 10 steps" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sim"]
    done = subprocess.run([program, "--max-steps", "10"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 1 and done.stdout == ""
