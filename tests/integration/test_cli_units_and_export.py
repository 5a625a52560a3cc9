"""The units of linearize, ladder and sensitivity (the model's by default, ``--units``, ``--si``), and ``export``
keeping a model file's comments (issue 25)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

import hydroservo as hs
from hydroservo.io import load_model, read_model
from hydroservo.units import convert


def _row(text: str, name: str) -> list[str]:
    line = next(line for line in text.splitlines() if line.split() and line.split()[0] == name)
    return line.split()


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_linearize_shows_the_operating_point_and_valve_coefficients_in_the_models_units(tmp_path, cli) -> None:
    # flight-simulator's file is in psi and in: the trim's chamber pressure is shown in psi, the same value as SI
    code, psi, _ = cli("linearize", "flight-simulator", "--out", str(tmp_path / "a"))
    assert code == 0
    code, si, _ = cli("linearize", "flight-simulator", "--si", "--out", str(tmp_path / "b"))
    assert code == 0
    value_psi, unit_psi = _row(psi, "cyl.pA")[1:3]
    value_pa, unit_pa = _row(si, "cyl.pA")[1:3]
    assert (unit_psi, unit_pa) == ("psi", "Pa")
    assert float(value_psi) == pytest.approx(convert(float(value_pa), "Pa", "psi"), rel=1e-4)
    # K_px = dp/dx: Pa/m in SI, psi/in in the model's units, the same coefficient
    k_si, k_psi = _row(si, "K_px_A"), _row(psi, "K_px_A")
    assert k_si[-1] == "Pa/m" and k_psi[-1] == "psi/in"
    assert float(k_psi[1]) == pytest.approx(float(k_si[1]) * 0.0254 / 6894.757, rel=1e-3)
    assert _row(psi, "K_Qx_A")[-1] == "in²/s"
    # a user's units over the model's, and the JSON in SI with its matrices
    code, bar, _ = cli("linearize", "flight-simulator", "--units", "p=bar", "--out", str(tmp_path / "c"))
    assert _row(bar, "cyl.pA")[2] == "bar" and _row(bar, "load.x")[2] == "in"
    point = json.loads((tmp_path / "c" / "flight-simulator-linear.json").read_text())
    assert "Pa" in json.dumps(point) and code == 0


def test_unit_options_are_refused_together_and_checked(cli) -> None:
    code, _, err = cli("linearize", "robot-arm", "--si", "--units", "bar")
    assert code == 2 and "give one of them" in err
    code, _, err = cli("sensitivity", "robot-arm", "--vary", "load.m=15 kg..35 kg", "--units", "cyl.pA=mm")
    assert code == 2 and "cyl.pA" in err and "expected a unit of that dimension" in err


def test_sensitivity_metrics_in_the_models_units_in_table_csv_and_json(tmp_path, cli) -> None:
    args = ["sensitivity", "flight-simulator", "--vary", "load.W=2000 lbf..4000 lbf", "--levels", "2",
            "--metric", "final(xv)", "--metric", "rise_time(y)"]
    code, out, _ = cli(*args, "--out", str(tmp_path / "in"))
    assert code == 0 and "final(xv) [in]" in out and "rise_time(y) [s]" in out
    code, _, _ = cli(*args, "--si", "--out", str(tmp_path / "si"))
    lines = {p: (tmp_path / p / "oat.csv").read_text().splitlines() for p in ("in", "si")}
    assert "final(xv) [in]" in lines["in"][0] and "final(xv) [m]" in lines["si"][0]
    x_in = float(lines["in"][1].split(",")[2])
    x_m = float(lines["si"][1].split(",")[2])
    assert x_in == pytest.approx(x_m / 0.0254, rel=1e-9)
    code, text, _ = cli(*args, "--json", "--units", "x=mm", "--out", str(tmp_path / "mm"))
    row = json.loads(text)["table"][0]
    assert row["final(xv) [mm]"] == pytest.approx(1e3 * x_m, rel=1e-9)


def test_ladder_displacements_in_the_unit_asked_for(tmp_path, cli) -> None:
    args = ["ladder", "robot-arm", "--steps", "36.8", "--models", "nonlinear,linear", "--points", "101"]
    code, out, _ = cli(*args, "--units", "x_mm=in", "--out", str(tmp_path / "a"))
    assert code == 0
    shown = re.search(r"change of x_mm \[in\]: ([-\d.e+]+)", out)
    assert shown is not None
    header, first = (tmp_path / "a" / "ladder.csv").read_text().splitlines()[:2]
    assert "displacement 36.8 % [in]" in header
    code, text, _ = cli(*args, "--json", "--out", str(tmp_path / "b"))
    mm = json.loads(text)["models"][0]["displacement 36.8 % [mm]"]
    assert float(first.split(",")[1]) == pytest.approx(mm / 25.4, rel=1e-9)


def test_export_keeps_a_files_comments_and_writes_the_values_set_as_given(tmp_path: Path, cli) -> None:
    path = tmp_path / "rig.toml"
    text = (Path(__file__).parent.parent.parent / "src/hydroservo/data/models/robot-arm.toml").read_text()
    path.write_text("# my copy of the robot arm\n" + text)
    code, out, _ = cli("export", str(path), "--set", "load.m=30 kg", "--set", "cyl.bulk_modulus=constant")
    assert code == 0
    assert out.startswith("# my copy of the robot arm\n")
    before, after = text.splitlines(), out.splitlines()[1:]
    changed = [(a, b) for a, b in zip(before, after, strict=True) if a != b]  # same lines, two of them changed
    assert len(changed) == 2, changed
    assert any('"30 kg"' in b for _, b in changed) and any('"constant"' in b for _, b in changed)
    edited = tmp_path / "edited.toml"
    edited.write_text(out)
    system = read_model(edited)
    assert system["load"].values["m"] == 30.0 and system["cyl"].option("bulk_modulus") == "constant"


def test_export_writes_former_names_as_now_called_in_place_with_their_comments(tmp_path: Path, cli) -> None:
    path = tmp_path / "old.toml"
    text = (Path(__file__).parent.parent.parent / "src/hydroservo/data/models/robot-arm.toml").read_text()
    old = text.replace('tau = "30 ms"  # T63', 'T = "30 ms"  # T63')
    assert old != text
    path.write_text(old)
    code, out, _ = cli("export", str(path), "--set", "spool.tau=20 ms")
    assert code == 0
    assert 'tau = "20 ms"  # T63 of the spool' in out and "\nT = " not in out
    assert out.splitlines().index('tau = "20 ms"  # T63 of the spool (eq. 3.27; the thesis\'s example, Fig. 3.5)') == \
        text.splitlines().index('tau = "30 ms"  # T63 of the spool (eq. 3.27; the thesis\'s example, Fig. 3.5)')


def test_export_of_a_builtin_model_keeps_its_source_notes_and_full_lists_every_parameter(cli) -> None:
    from hydroservo.data import model_text

    code, out, _ = cli("export", "flight-simulator")
    assert code == 0 and out == model_text("flight-simulator")
    code, full, _ = cli("export", "flight-simulator", "--full")
    assert code == 0 and full.startswith("# hydroservo model file: flight-simulator")
    # the full form lists parameters the file leaves at their defaults, each with its description
    assert "offset" in full and "offset" not in out.split("[components.summer]")[1].split("[components.rc]")[0]


def test_export_of_a_system_changed_in_python_writes_the_whole_model() -> None:
    from hydroservo.workflows.export import model_file

    system = load_model("robot-arm")
    system.set("load.m", 31.0)
    text = model_file(system).text
    assert text.startswith("# hydroservo model file") and "31" in text


@pytest.mark.parametrize("units", ["bar,psi", "p=bar,p=psi", "cyl.pA=psi,cyl.pA=bar"])
def test_two_units_for_one_quantity_or_signal_are_refused(units: str, cli) -> None:
    # 'bar,psi' showed bar (the first won) and 'p=bar,p=psi' psi (the last won)
    code, _, err = cli("linearize", "robot-arm", "--units", units)
    assert code == 2 and "two units for the same" in err


def test_sobol_names_its_metrics_in_the_units_shown_and_ladder_json_alone_writes_nothing(tmp_path, cli,
                                                                                          monkeypatch) -> None:
    code, out, _ = cli("sensitivity", "robot-arm", "--method", "sobol", "--n", "4", "--vary", "valve.c_v=1e-4..2e-4",
                       "--vary", "load.m=15 kg..35 kg", "--units", "p=psi", "--out", str(tmp_path / "s"))
    assert code == 0 and "peak(cyl.pB) [psi]" in out and "[Pa]" not in out
    assert "peak(cyl.pB) [psi]" in (tmp_path / "s" / "indices.csv").read_text()
    monkeypatch.chdir(tmp_path)
    code, _, _ = cli("ladder", "robot-arm", "--steps", "36.8", "--models", "nonlinear", "--points", "101", "--json")
    assert code == 0 and not list(tmp_path.glob("hydroservo-*"))


def test_an_exported_file_that_changes_the_model_scopes_its_notes(cli, tmp_path) -> None:
    """position-servo's note gives its default run's peaks (55 and 86 MPa for 100 kg): a file exported with
    another mass carried it as true, and every run of that file printed it so (issue 37's review)."""
    scope = "[measured on the model's default run; this file changes load.m, so it may not hold here] "
    for extra in ([], ["--full"]):
        code, text, err = cli("export", "position-servo", "--set", "load.m=10 kg", *extra)
        assert code == 0, err
        path = tmp_path / "light.toml"
        path.write_text(text, encoding="utf-8")
        system = hs.load_model(path)
        assert system.notes and all(note.startswith(scope) for note in system.notes), system.notes
    code, text, _ = cli("export", "position-servo")
    assert code == 0 and "[measured on" not in text  # the model itself: its notes as they are
