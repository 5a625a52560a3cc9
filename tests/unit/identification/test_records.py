"""Rig records: one experiment in one or more CSV files, each with its own time column; bad records refused."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.errors import ParameterError, UnitError
from hydroservo.identification.calibration import prepare
from hydroservo.identification.records import Channel, Record, derivatives
from hydroservo.io.records import read_record, record_files, write_record


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def test_multi_rate_record_round_trips(tmp_path: Path, step_record: Record) -> None:
    paths = write_record(step_record, tmp_path)
    assert sorted(p.name for p in paths) == ["step-3-200Hz.csv", "step-3-40Hz.csv"]
    back = read_record(paths)
    assert back.name == "step-3"
    assert back.names == ["load.x", "command.y", "cyl.pA", "cyl.pB"]
    for name in step_record.names:
        a, b = step_record[name], back[name]
        assert b.unit == a.unit
        np.testing.assert_allclose(b.t, a.t, rtol=1e-9)
        np.testing.assert_allclose(b.values, a.values, rtol=1e-9)
    assert back["cyl.pA"].rate == pytest.approx(40.0)
    assert back["load.x"].rate == pytest.approx(200.0)
    assert back["cyl.pA"].si()[0] == pytest.approx(1e5 * step_record["cyl.pA"].values[0])


def test_comma_list_comments_bom_and_missing_cells(tmp_path: Path) -> None:
    a = _write(tmp_path, "a.csv", "\ufeff# logger 7, 40 Hz\nt [s],cyl.pA [bar]\n0,1\n0.025,\n0.05,nan\n0.075,2\n")
    b = _write(tmp_path, "b.csv", "time [ms],load.x [mm]\n0,20\n5,20.5\n")
    rec = read_record(f"{a},{b}")
    assert np.isnan(rec["cyl.pA"].values[1]) and np.isnan(rec["cyl.pA"].values[2])
    assert rec["cyl.pA"].valid.sum() == 2
    np.testing.assert_allclose(rec["load.x"].t, [0.0, 0.005])


def test_results_file_is_a_record(tmp_path: Path) -> None:
    result = hs.load_model("robot-arm").simulate(t_end=0.2, n_points=21)
    path = result.to_csv(tmp_path / "run.csv")
    rec = read_record(path)
    assert "cyl.pA" in rec and rec["cyl.pA"].unit == "bar"  # the model's units, read as written
    assert rec["cyl.pA"].si() == pytest.approx(result["cyl.pA"], rel=1e-9)
    assert rec["x_mm"].unit == "mm"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("t [s],cyl.pA [bar]\n0,1\n0,2\n", "time does not increase at sample 2"),
        ("t [s],cyl.pA [bar]\n0,1\n", "1 sample(s); a record needs at least two"),
        ("t [s],cyl.pA [quux]\n0,1\n1,2\n", "'quux'"),
        ("t [s],cyl.pA\n0,1\n1,2\n", "expected 'name [unit]'"),
        ("x [mm],cyl.pA [bar]\n0,1\n1,2\n", "expected the time"),
        ("t [s],cyl.pA [bar]\n0,1\n1,two\n", "data row 2, column 'cyl.pA': 'two' is not a number"),
        ("t [s],cyl.pA [bar]\n0,1\n1\n", "data row 2 has 1 cells"),
        ("t [s],cyl.pA [bar],cyl.pA [bar]\n0,1,1\n1,2,2\n", "appears twice"),
        ("t [s]\n0\n1\n", "only a time column"),
    ],
)
def test_bad_records_are_refused_with_the_file_named(tmp_path: Path, text: str, message: str) -> None:
    path = _write(tmp_path, "bad.csv", text)
    with pytest.raises((ParameterError, UnitError)) as info:
        read_record(path)
    assert message in str(info.value)
    assert "bad.csv" in str(info.value)


def test_a_signal_in_two_files_is_refused(tmp_path: Path) -> None:
    a = _write(tmp_path, "a.csv", "t [s],cyl.pA [bar]\n0,1\n1,2\n")
    b = _write(tmp_path, "b.csv", "t [s],cyl.pA [bar]\n0,1\n1,2\n")
    with pytest.raises(ParameterError, match="in both"):
        read_record([a, b])


def test_records_meet_the_model_with_clear_errors() -> None:
    arm = hs.load_model("robot-arm")
    t = np.linspace(0.0, 1.0, 11)
    unknown = Record("r", {"cyl.pAA": Channel("cyl.pAA", t, t, "bar", "r.csv")})
    with pytest.raises(ParameterError, match=r"'cyl.pAA' is not a signal of 'robot-arm'; did you mean cyl.pA"):
        prepare(arm, unknown)
    wrong = Record("r", {"cyl.pA": Channel("cyl.pA", t, t, "mm", "r.csv")})
    with pytest.raises(UnitError, match=r"r.csv: column 'cyl.pA': unit 'mm' is not of the dimension"):
        prepare(arm, wrong)
    only_input = Record("r", {"command.y": Channel("command.y", t, t, "", "r.csv")})
    with pytest.raises(ParameterError, match="no column to compare with the model"):
        prepare(arm, only_input, ["command.y"])
    with pytest.raises(ParameterError, match="no column 'supply.p' to drive the model"):
        prepare(arm, only_input, ["supply.p"])
    with pytest.raises(ParameterError, match="only a signal source or a pressure source"):
        prepare(arm, Record("r", {"spool.xv": Channel("spool.xv", t, t, "m"), "load.x": Channel("load.x", t, t, "m")}), ["spool.xv"])


def test_record_files_one_per_rate(step_record: Record) -> None:
    texts = record_files(step_record)
    assert list(texts) == ["step-3-200Hz.csv", "step-3-40Hz.csv"]
    assert texts["step-3-40Hz.csv"].splitlines()[0] == "t [s],cyl.pA [bar],cyl.pB [bar]"


def test_derivatives_have_no_lag() -> None:
    t = np.arange(0.0, 2.0, 0.005)
    x = 0.1 * np.sin(2 * np.pi * t)
    v, a = derivatives(t, x, 0.05)
    inner = slice(20, -20)
    np.testing.assert_allclose(v[inner], 0.2 * np.pi * np.cos(2 * np.pi * t[inner]), atol=2e-4 * 0.2 * np.pi)
    np.testing.assert_allclose(a[inner], -0.4 * np.pi**2 * np.sin(2 * np.pi * t[inner]), atol=1e-2 * 0.4 * np.pi**2)
