"""The example files (hydroservo.data examples, ``hydroservo examples``) run as the README says."""

from __future__ import annotations

from pathlib import Path

import pytest

from hydroservo.data import example_files
from hydroservo.io import read_model


def test_user_model_file_runs(valve_cylinder_file: Path) -> None:
    s = read_model(valve_cylinder_file)
    r = s.simulate()
    assert r["load.v"][-1] > 0.05  # extends at a steady speed after the step
    assert r["x_mm"][-1] == pytest.approx(1000 * r["load.x"][-1])


def test_parameter_file_drops_into_a_model(tmp_path: Path, cli) -> None:
    assert cli("valve", "fit", "KBSDG4V-3", "--out", str(tmp_path))[0] == 0
    text = example_files()["servo_solenoid_cylinder.toml"]
    text = text.replace('file = "kbsdg4v3_valve.toml"', f'file = "{tmp_path / "valve.toml"}"')
    (tmp_path / "model.toml").write_text(text)
    system = read_model(tmp_path / "model.toml")
    assert type(system["valve"]).__name__ == "ServoSolenoidValve"
    res = system.simulate(n_points=101)
    assert res.get("x_mm")[-1] == pytest.approx(50.0, abs=0.5)


def test_example_model_file_simulates_the_valve_in_a_circuit(tmp_path: Path) -> None:
    path = tmp_path / "model.toml"
    path.write_text(example_files()["staged_slot_valve_cylinder.toml"])
    system = read_model(path)
    res = system.simulate(n_points=301)
    A_A = system["cyl"].values["A_A"]
    v_end, QA_end = res.get("load.v")[-1], res.get("valve.QA")[-1]
    assert v_end > 0 and v_end * A_A == pytest.approx(QA_end, rel=1e-3)  # steady: the valve's flow moves the piston
    assert res.get("valve.QS")[0] > 0  # leakage at null before the step
