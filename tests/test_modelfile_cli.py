"""Model files (TOML) and the command-line interface."""

from __future__ import annotations

import json

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.cli import main
from hydroservo.data import example_files
from hydroservo.errors import ModelFileError
from hydroservo.io import model_to_toml, read_model

VALVE_CYLINDER = example_files()["valve_cylinder.toml"]


@pytest.fixture
def vc_file(tmp_path):
    path = tmp_path / "vc.toml"
    path.write_text(VALVE_CYLINDER)
    return path


def test_user_model_file_runs(vc_file) -> None:
    s = read_model(vc_file)
    r = s.simulate()
    assert r["load.v"][-1] > 0.05  # extends at a steady speed after the step
    assert r["x_mm"][-1] == pytest.approx(1000 * r["load.x"][-1])


def test_round_trip_builtin_and_user_model(tmp_path, vc_file) -> None:
    for system in (hs.load_model("flight-simulator"), read_model(vc_file)):
        path = tmp_path / "exported.toml"
        path.write_text(model_to_toml(system))
        again = read_model(path)
        r1, r2 = system.simulate(), again.simulate()
        for name in r1.names:
            np.testing.assert_array_equal(r1[name], r2[name])


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda t: t.replace('p = "210 bar"', 'p = "210 bar'), "malformed TOML"),
        (lambda t: t.replace('type = "Tank"', 'type = "Sink"'), r"\[components.tank\]: unknown component type 'Sink'"),
        (
            lambda t: t.replace('A_A = "19.63 cm^2"', 'A_A = "3 bar"'),
            r"\[components.cyl\]: cyl.A_A: '3 bar' has the wrong dimension",
        ),
        (lambda t: t.replace('m = "250 kg"', 'm = "-250 kg"'), r"load.m = '-250 kg'.*expected > 0 kg"),
        (lambda t: t.replace('V_A0 = "0.3 L"', 'V_A0 = "-0.3 L"'), r"cyl.V_A0 = '-0.3 L'"),
        (lambda t: t.replace('"cyl.x" = "load.x"', '"cyl.x" = "load.position"'), "has no output 'position'"),
        (lambda t: t.replace('B = "2000 N*s/m"', 'Bee = "2000 N*s/m"'), "unknown parameter"),
    ],
)
def test_bad_model_files(tmp_path, edit, message) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(edit(VALVE_CYLINDER))
    with pytest.raises(ModelFileError, match=message):
        read_model(path)


def test_cli_simulate_json(tmp_path, capsys) -> None:
    code = main(
        ["simulate", "flight-simulator", "--set", "load.W=3000 lbf", "--t-end", "0.5", "--out", str(tmp_path), "--json"]
    )
    assert code == 0
    out = json.loads(capsys.readouterr().out)
    assert out["signals"]["p2"]["unit"] == "Pa"
    assert out["signals"]["p2"]["max"] > 0
    assert "nsteps" in out["solver"] and out["wall_time_s"] > 0
    assert (tmp_path / "flight-simulator.csv").exists() and (tmp_path / "flight-simulator.png").exists()
    first = (tmp_path / "flight-simulator.csv").read_text().splitlines()[0]
    assert "y [m]" in first and "p2 [Pa]" in first


def test_cli_export_then_simulate(tmp_path, capsys) -> None:
    assert main(["export", "flight-simulator"]) == 0
    text = capsys.readouterr().out
    path = tmp_path / "fs.toml"
    path.write_text(text)
    assert main(["simulate", str(path), "--t-end", "0.2", "--out", str(tmp_path)]) == 0
    assert "simulated 'flight-simulator'" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["simulate", "flight-simulator", "--set", "cyl.A_A=3 bar"], "wrong dimension"),
        (["simulate", "flight-simulator", "--set", "cyl.V_A0=-3 in^3"], "expected > 0"),
        (["simulate", "flight-simulator", "--set", "load.mass=3 kg"], "has no parameter 'mass'"),
        (["simulate", "flight-simulator", "--set", "nope.m=3 kg"], "no component 'nope'"),
        (["simulate", "flight-simulator", "--set", "load.m"], "expected COMPONENT.PARAMETER=VALUE"),
        (["simulate", "no-such-model"], "neither a built-in model"),
        (["simulate", "flight-simulator", "--t-end", "2 bar"], "--t-end"),
        (["validate", "nothing"], "no validation"),
    ],
)
def test_cli_bad_input_exit_2(argv, message, capsys, tmp_path) -> None:
    code = main([*argv, "--out", str(tmp_path)] if argv[0] == "simulate" else argv)
    assert code == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_cli_models_and_validate(capsys) -> None:
    assert main(["models"]) == 0
    assert "flight-simulator" in capsys.readouterr().out
    assert main(["validate", "flight-simulator", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["flight-simulator"]
    assert {r["verdict"] for r in rows} >= {"reproduced", "NOT reproduced"}
