"""The Hopsan model that ships with the package (``hydroservo examples`` writes ``hopsan_servo.hmf``) imports, and
the model file the import writes loads and runs as the circuit it describes.

``hopsan_servo.hmf`` is hydroservo's own small position servo in Hopsan's format (not one of Hopsan's files): a
101 bar absolute supply, a critically lapped 4/3 valve (2 mm bore, 1 mm stroke), a double-rod cylinder of 12 cm²
moving 50 kg, and a P controller stepping the mass from 50 mm to 200 mm at 0.5 s. Hopsan runs it too: its result
(``hopsan_example/``, with how it was made) is compared with the imported model's.
"""

from __future__ import annotations

import contextlib
import io
import math
from pathlib import Path

import numpy as np
import pytest

from hydroservo.cli import main
from hydroservo.data import example_files

NAME = "hopsan_servo.hmf"


def _run(argv: list[str]) -> tuple[int, str]:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(argv)
    return code, out.getvalue()


def test_examples_write_the_hopsan_model_and_say_how_to_import_it(tmp_path: Path) -> None:
    code, out = _run(["examples", str(tmp_path / "ex")])
    assert code == 0
    assert (tmp_path / "ex" / NAME).read_text(encoding="utf-8") == example_files()[NAME]
    assert f"hydroservo import-hopsan {NAME}" in out


def test_the_shipped_hopsan_model_is_our_own_circuit(tmp_path: Path) -> None:
    """Our own circuit, saying so, of components the importer maps."""
    from hydroservo.io.hopsan import read_hmf

    text = example_files()[NAME]
    assert "written for hydroservo's examples" in text and "none of Hopsan's own files" in text
    (tmp_path / NAME).write_text(text, encoding="utf-8")
    model = read_hmf(tmp_path / NAME)
    assert (model.start, model.stop, model.timestep) == (0.0, 2.0, 1e-4)
    assert sorted(c.typename for c in model.components) == sorted([
        "HydraulicPressureSourceC", "HydraulicTankC", "Hydraulic43Valve", "HydraulicCylinderC",
        "MechanicTranslationalMass", "MechanicForceTransformer", "MechanicPositionSensor", "SignalStep",
        "SignalSubtract", "SignalGain", "SignalSink",
    ])


def _saturated_speed() -> float:
    """The piston's speed with the spool at its stroke, from the circuit's values: each edge passes
    c_v x_vmax sqrt(Δp_edge) with c_v = C_q π d sqrt(2/ρ); equal areas make the two edges' drops equal, so each is
    (p_s - p_t - p_L)/2, and in steady motion the load pressure holds the damping, p_L A = (B + B_p) v."""
    c_v = 0.67 * math.pi * 0.002 * math.sqrt(2.0 / 870.0)
    x_vmax, area, damping, dp = 0.001, 0.0012, 200.0 + 500.0, 100e5
    v = c_v * x_vmax * math.sqrt(dp / 2.0) / area
    for _ in range(50):  # fixed point of v A = c_v x_vmax sqrt((Δp - (B + B_p) v / A) / 2)
        v = c_v * x_vmax * math.sqrt((dp - damping * v / area) / 2.0) / area
    return v


# slow: the imported model is compiled and run
@pytest.mark.slow
def test_the_shipped_hopsan_model_imports_and_its_model_file_runs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from hydroservo.io.model_file import load_model

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("HYDROSERVO_CACHE", str(tmp_path / "cache"))
    assert _run(["examples", "ex"])[0] == 0
    code, out = _run(["import-hopsan", f"ex/{NAME}", "--out", "servo"])
    assert code == 0, out
    assert "Servo_Valve (Hydraulic43Valve)" in out and "wrote servo/hopsan_servo.toml" in out
    system = load_model("servo/hopsan_servo.toml")
    assert system.t_end == 2.0
    assert system.plots == [["Reference.out.Value", "Position.out.Value"]]  # Hopsan's scope, as the plot

    result = system.simulate(t_eval=np.linspace(0.0, 2.0, 2001))
    x, v = result.get("Load.P2.Position"), result.get("Load.P2.Velocity")
    assert np.allclose(result.get("Position.out.Value"), x)  # the sensor reads its node
    before = result.t < 0.5
    assert np.max(np.abs(x[before] - 0.05)) < 1e-6  # starts at rest where the reference is (consistent start values)
    assert abs(x[-1] - 0.2) < 1e-4  # P control of an integrating plant: no steady error
    # the move from 50 to 200 mm runs with the spool at its stroke, once the start's oscillation has died away at
    # the speed the valve's law gives (0.372 m/s; the peak of the start is 2 % above it)
    moving = (result.t > 0.65) & (result.t < 0.8)
    assert np.allclose(v[moving], _saturated_speed(), rtol=1e-4, atol=0)
    # the CLI runs the written file too
    code, out = _run(["simulate", "servo/hopsan_servo.toml", "--write", "csv", "--out", "run"])
    assert code == 0, out
    assert (tmp_path / "run" / "Small_Servo.csv").is_file()


# slow: the imported model is compiled and run
@pytest.mark.slow
def test_the_shipped_hopsan_model_runs_as_hopsan_runs_it(tmp_path: Path) -> None:
    """Against Hopsan's own run of the file at 1e-6 s (hopsan_example/README.md): every trace within 0.05 % of its
    range (measured: 0.012 % at most, the pressures; Hopsan's own step halving moves them by 0.037 %)."""
    from hydroservo.io.hopsan_library import read_hopsan

    (tmp_path / NAME).write_text(example_files()[NAME], encoding="utf-8")
    header, *rows = (Path(__file__).parent / "hopsan_example" / "hopsan_servo.csv").read_text().splitlines()
    values = np.array([[float(v) for v in row.split(",")] for row in rows])
    reference = dict(zip(header.split(","), values.T))
    result = read_hopsan(tmp_path / NAME).simulate(t_eval=reference["t"])
    names = [n for n in reference if n != "t"]
    assert len(names) == 6 and len(reference["t"]) == 201
    for name in names:
        ours, theirs = result.get(name.replace("#", ".")), reference[name]
        assert np.max(np.abs(ours - theirs)) < 5e-4 * np.ptp(theirs), name
