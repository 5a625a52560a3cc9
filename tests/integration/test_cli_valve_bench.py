"""``hydroservo valve characteristics`` and ``valve identify`` on the staged-slot valve of MareAttarND.

The valve is hydroservo's example aerospace geometry (the parameter set
``MareAttarND_example``; the paper publishes none): properties of the tools, not published values.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from hydroservo.analysis.static_bench import Bench
from hydroservo.components import StagedSlotValve
from hydroservo.io import read_staged_slot_valve, staged_slot_valve_toml


@pytest.mark.slow
def test_characteristics_and_identify_cli(
    tmp_path: Path, cli, aerospace_valve: StagedSlotValve, aerospace_bench: Bench, staged_slot_start: StagedSlotValve
) -> None:
    code, out, _ = cli(
        "valve", "characteristics", "aerospace-example", "--temperature", "-15,-40", "--points", "101",
        "--out", str(tmp_path / "ch"), "--json",
    )  # fmt: skip
    assert code == 0
    data = json.loads(out)
    assert set(data["metrics"]) == {"-15", "-40"} and data["reference_degC"] == -15
    assert data["change_from_reference"]["-40"]["max_leakage"] < 0  # colder: less leakage
    for f in data["files"].values():
        assert Path(f).stat().st_size > 0
    start = tmp_path / "start.toml"
    start.write_text(staged_slot_valve_toml(staged_slot_start, None))
    code, out, _ = cli(
        "valve", "identify", data["files"]["T-15_flow_gain"], data["files"]["T-15_blocked_ports"],
        "--start", str(start), "--predict", "-40", "--out", str(tmp_path / "id"), "--json",
    )  # fmt: skip
    assert code == 0
    res = json.loads(out)
    assert res["identified"]["c"] == pytest.approx(aerospace_valve.values["c"], rel=1e-3)
    comp, bench = read_staged_slot_valve(res["files"]["parameters"])
    assert comp.values["Cq_inf"] == pytest.approx(aerospace_valve.values["Cq_inf"], rel=1e-3)
    assert bench.P_s == pytest.approx(aerospace_bench.P_s, rel=1e-14)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["valve", "characteristics", "aerospace-example", "--temperature", "-80", "--strict"], r"temperature -80"),
        (["valve", "characteristics", "nothing.toml"], r"cannot read|not found|No such"),
        (["valve", "characteristics", "aerospace-example", "--temperature", "20 degC"], r"bare numbers in degC"),
        (["valve", "identify", "missing.csv", "--start", "aerospace-example"], r"missing\.csv"),
    ],
)
def test_spool_cli_bad_input_exits_2(argv: list[str], message: str, cli, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, _, err = cli(*argv)
    assert code == 2 and err.startswith("hydroservo: error:")
    assert re.search(message, err), err


def test_wrong_sign_lap_in_a_parameter_file_exits_2(
    tmp_path: Path, cli, aerospace_valve: StagedSlotValve, aerospace_bench: Bench
) -> None:
    path = tmp_path / "v.toml"
    path.write_text(staged_slot_valve_toml(aerospace_valve.replace(check=False, X_b0H=3e-6), aerospace_bench))
    code, _, err = cli("valve", "characteristics", str(path), "--out", str(tmp_path))
    assert code == 2 and "X_b0H" in err and "expected ≤ 0" in err
    curves = tmp_path / "c.csv"
    curves.write_text("# temperature = -15 degC\n# P_s = 200 bar\n# X_n = 0.4 mm\nX [um], P_1 [bar]\n0, 100\n")
    code, _, err = cli("valve", "identify", str(curves), "--start", "aerospace-example")
    assert code == 2 and "P_1 and P_2" in err
