"""The example files ``hydroservo examples`` hands out are what their generator makes, and they load.

``docs/examples/make_example_files.py`` generates the synthetic data files from
published models (each file says so in its first lines); regenerating them
must give the shipped files back, numbers compared to 1e-9 relative (the
text is formatted to 6 significant digits, so any real change shows).
"""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

from hydroservo.data import example_files
from hydroservo.io import read_bench_curves, read_bode, read_datasheet, read_model, read_staged_slot_valve
from hydroservo.io.records import read_record

GENERATOR = Path(__file__).resolve().parents[2] / "docs" / "examples" / "make_example_files.py"
NUMBER = re.compile(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")


def _generator():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("make_example_files", GENERATOR)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# slow: regenerates every example file by simulation
@pytest.mark.slow
def test_generated_files_are_the_shipped_ones(tmp_path: Path) -> None:
    generated = _generator().example_data(tmp_path)
    shipped = example_files()
    for name, text in generated.items():
        assert name in shipped, name
        new, old = text.splitlines(), shipped[name].splitlines()
        assert len(new) == len(old), name
        for a, b in zip(new, old, strict=True):
            assert NUMBER.sub("#", a) == NUMBER.sub("#", b), (name, a, b)
            x, y = (np.array([float(v) for v in NUMBER.findall(s)]) for s in (a, b))
            # a rig record is rounded to its sensors' resolution (0.001 bar, 0.001 mm): an integration that differs
            # in the last digits on another machine may round a sample to the next step, never further
            atol = 1.0001e-3 if name.startswith("arm_") else 0.0
            np.testing.assert_allclose(x, y, rtol=1e-9, atol=atol, err_msg=f"{name}: {a!r}")


def test_every_example_file_loads(tmp_path: Path) -> None:
    for name, text in example_files().items():
        (tmp_path / name).write_text(text)
    for name in ("valve_cylinder.toml", "servo_solenoid_cylinder.toml", "staged_slot_valve_cylinder.toml"):
        assert read_model(tmp_path / name).components, name
    assert read_datasheet(tmp_path / "my_valve.toml").K_p0 == pytest.approx(36.5)
    assert read_bode(tmp_path / "bode.csv").gain_db.shape == (3, 30)
    curves = read_bench_curves([tmp_path / "flow_gain.csv", tmp_path / "blocked_ports.csv"])
    assert curves.temperature == -15.0 and curves.Q_L is not None and curves.P_1 is not None
    valve, bench = read_staged_slot_valve(tmp_path / "guess.toml")
    assert bench is None and valve.values["c"] > 0
    step = read_record([tmp_path / "arm_step-200Hz.csv", tmp_path / "arm_step-40Hz.csv"])
    assert step.name == "arm_step" and set(step.names) == {"load.x", "command.y", "cyl.pA", "cyl.pB"}
