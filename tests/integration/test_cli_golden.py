"""Every command's output keeps its shape: the printed text, the JSON keys, the files written and the exit code.

Each case runs one ``hydroservo`` command in a folder holding the example files and compares what it
printed with the record in ``cli_golden/`` after masking what may differ from run to run or machine to
machine: numbers (each becomes ``#``), GUIDs (a hash of an FMU's contents), runs of spaces, and the temporary
folder's path, and the length of a table's rule (as wide as its widest entry). A change of
wording, of a JSON key, of a file's name or of an exit code fails here; a change of a value does not (the
command's own tests check the values).

After a deliberate change of a command's output, rewrite the records and review their diff::

    HYDROSERVO_GOLDEN=update python -m pytest tests/integration/test_cli_golden.py
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import re
from pathlib import Path
from typing import Any

import pytest

from hydroservo.cli import main
from hydroservo.data import example_files
from hydroservo.system.native import has_compiler

GOLDEN = Path(__file__).with_name("cli_golden")

#: (record name, argv): fast options, so that all of them run in about 20 s.
CASES: list[tuple[str, list[str]]] = [
    ("models", ["models"]),
    ("simulate", ["simulate", "flight-simulator", "--t-end", "0.2", "--points", "51", "--out", "sim"]),
    ("simulate-json", ["simulate", "flight-simulator", "--t-end", "0.2", "--points", "51", "--json"]),
    ("simulate-write", ["simulate", "flight-simulator", "--t-end", "0.2", "--json", "--write", "csv,mat", "--out", "w"]),
    ("simulate-warnings", ["simulate", "position-servo", "--t-end", "0.3", "--points", "61", "--write", "none"]),
    ("simulate-warnings-json", ["simulate", "position-servo", "--t-end", "0.3", "--points", "61", "--json"]),
    ("simulate-strict", ["simulate", "position-servo", "--t-end", "0.3", "--strict", "--out", "strict"]),
    ("simulate-pump-circuit", ["simulate", "pump_circuit.toml", "--t-end", "0.5", "--out", "pump"]),
    ("export", ["export", "flight-simulator"]),
    ("export-c", ["export-c", "flight-simulator", "--step", "1e-4", "--out", "c"]),
    ("export-c-json", ["export-c", "robot-arm", "--step", "1e-3", "--method", "bdf2", "--out", "c2", "--json"]),
    ("export-fmu", ["export-fmu", "flight-simulator", "--sources-only", "--out", "fmu"]),
    ("export-fmu-json", ["export-fmu", "flight-simulator", "--sources-only", "--out", "fmu2", "--json"]),
    ("linearize", ["linearize", "robot-arm", "--t", "0.35", "--free", "load.x", "--out", "lin"]),
    ("linearize-json", ["linearize", "robot-arm", "--t", "0.35", "--free", "load.x", "--inputs", "spool.u",
                        "--outputs", "load.v", "--frequencies", "5,20", "--json"]),
    ("linearize-simulate", ["linearize", "robot-arm", "--t", "0.35", "--free", "load.x", "--inputs", "spool.u",
                            "--outputs", "load.v", "--frequencies", "5,20", "--simulate", "0.003", "--out", "lins"]),
    ("ladder", ["ladder", "robot-arm", "--steps", "36.8", "--models", "nonlinear,linear", "--points", "101",
                "--out", "lad"]),
    ("ladder-json", ["ladder", "robot-arm", "--steps", "36.8", "--models", "nonlinear,simplified", "--points", "101",
                     "--out", "lad2", "--json"]),
    ("sensitivity-oat", ["sensitivity", "robot-arm", "--vary", "valve.c_v=1e-4..2e-4", "--levels", "3",
                         "--points", "101", "--out", "oat"]),
    ("sensitivity-oat-json", ["sensitivity", "robot-arm", "--vary", "cyl.bulk_modulus=lee,constant",
                              "--points", "101", "--out", "oat2", "--json"]),
    ("sensitivity-sobol", ["sensitivity", "robot-arm", "--method", "sobol", "--n", "4", "--vary",
                           "valve.c_v=1e-4..2e-4", "--vary", "load.m=15kg..35kg", "--points", "101", "--threads", "1",
                           "--out", "sob"]),
    ("sensitivity-morris-json", ["sensitivity", "robot-arm", "--method", "morris", "--n", "3", "--vary",
                                 "valve.c_v=1e-4..2e-4", "--vary", "load.m=15kg..35kg", "--points", "101",
                                 "--threads", "1", "--out", "mor", "--json"]),
    ("components", ["components"]),
    ("components-json", ["components", "--json"]),
    ("describe", ["describe", "Cylinder"]),
    ("describe-json", ["describe", "FourWayValve", "--json"]),
    ("valve-fit", ["valve", "fit", "KBSDG4V-3", "--out", "fit"]),
    ("valve-fit-json", ["valve", "fit", "my_valve.toml", "--structure", "fixed", "--match", "pressure-gain,flow-gain",
                        "--out", "fit2", "--json"]),
    ("valve-fit-curves", ["valve", "fit", "my_valve.toml", "--curves", "measured.csv", "--out", "fit3"]),
    ("valve-bode", ["valve", "bode", "KBSDG4V-3", "--amplitudes", "5,50", "--frequencies", "10:190:60", "--out", "bode"]),
    ("valve-bode-json", ["valve", "bode", "KBSDG4V-3", "--amplitudes", "25", "--frequencies", "10,50,200",
                         "--out", "bode2", "--json"]),
    ("valve-fit-dynamics", ["valve", "fit-dynamics", "bode.csv", "--model", "first-order", "--out", "dyn"]),
    ("valve-fit-dynamics-json", ["valve", "fit-dynamics", "bode.csv", "--model", "second-order", "--out", "dyn2",
                                 "--json"]),
    ("valve-characteristics", ["valve", "characteristics", "aerospace-example", "--temperature", "-15,32",
                               "--points", "41", "--out", "char"]),
    ("valve-characteristics-json", ["valve", "characteristics", "aerospace-example", "--temperature", "32",
                                    "--points", "41", "--out", "char2", "--json"]),
    ("servovalve-bench", ["servovalve", "bench", "--tests", "static,threshold", "--points", "5", "--out", "sv"]),
    ("servovalve-bench-json", ["servovalve", "bench", "--tests", "static", "--points", "5", "--set", "K_f=2100 N/m",
                               "--out", "sv2", "--json"]),
    ("fluid", ["fluid", "all", "--fluid", "skydrol", "--temperature", "-40,20", "--pressure", "0,30 MPa"]),
    ("fluid-json", ["fluid", "density", "--temperature", "20", "--json"]),
    ("validate", ["validate", "flight-simulator"]),
    ("validate-json", ["validate", "position-servo", "--json"]),
    ("validate-markdown", ["validate", "position-servo", "--markdown"]),
    ("examples", ["examples", "ex"]),
    ("report", ["report", "position-servo", "--t-end", "0.3", "--out", "rep"]),
    ("report-json", ["report", "flight-simulator", "--t-end", "0.2", "--no-validation", "--out", "rep2", "--json"]),
    ("report-result", ["report", "sim/flight-simulator.csv", "--out", "rep3"]),
    ("draw", ["draw", "pump_circuit.toml", "--format", "svg,pdf", "--out", "drw"]),
    ("draw-json", ["draw", "robot-arm", "--names-only", "--out", "drw2", "--json"]),
    ("bad-format", ["draw", "robot-arm", "--format", "jpg"]),
    ("rig", ["rig", "robot-arm", "--sensor", "load.x=200 Hz,0.02 mm", "--sensor", "cyl.pA=40 Hz,0.05 bar,0.001 bar",
             "--t-end", "0.5", "--seed", "1", "--out", "rig"]),
    ("calibrate", ["calibrate", "robot-arm", "--record", "arm_step-200Hz.csv,arm_step-40Hz.csv", "--input", "command.y",
                   "--fit", "spool.tau=5 ms..100 ms", "--fit", "load.B", "--fit", "valve.c_v", "--fit", "cyl.C_Li",
                   "--fit", "load.F_c0", "--noise", "load.x=0.02 mm", "--noise", "cyl.pA=0.05 bar,cyl.pB=0.05 bar",
                   "--validate", "arm_check-200Hz.csv,arm_check-40Hz.csv", "--out", "cal"]),
    ("calibrate-json", ["calibrate", "robot-arm", "--record", "arm_step-200Hz.csv,arm_step-40Hz.csv", "--input",
                        "command.y", "--fit", "load.B", "--fit", "valve.c_v", "--initial", "model", "--out", "cal2",
                        "--json"]),
    ("calibrate-plan", ["calibrate", "robot-arm", "--record", "arm_step-200Hz.csv,arm_step-40Hz.csv", "--input",
                        "command.y", "--fit", "load.B", "--fit", "load.F_c0", "--noise",
                        "load.x=0.02 mm,cyl.pA=0.05 bar,cyl.pB=0.05 bar", "--plan"]),
    ("identify-friction", ["identify", "friction", "arm_friction-200Hz.csv,arm_friction-40Hz.csv", "--model",
                           "robot-arm", "--out", "fr"]),
    ("identify-leakage-json", ["identify", "leakage", "arm_locked-200Hz.csv,arm_locked-40Hz.csv", "--model", "robot-arm",
                               "--out", "lk", "--json"]),
    ("identify-flow-coefficient", ["identify", "flow-coefficient", "arm_sweep_out-200Hz.csv,arm_sweep_out-40Hz.csv",
                                   "arm_sweep_in-200Hz.csv,arm_sweep_in-40Hz.csv", "--model", "robot-arm", "--out", "kh"]),
    ("bad-record", ["calibrate", "robot-arm", "--record", "arm_step-40Hz.csv", "--fit", "spool.tua"]),
    ("bad-sensor", ["rig", "robot-arm", "--sensor", "cyl.pAA=40 Hz"]),
    # refusals: one message, exit 2, nothing written
    ("bad-model", ["simulate", "no-such-model"]),
    ("bad-set", ["simulate", "flight-simulator", "--set", "load.mass=3 kg"]),
    ("bad-unit", ["simulate", "flight-simulator", "--set", "load.W=3 bar"]),
    ("bad-tests", ["servovalve", "bench", "--tests", "static,nope"]),
    ("bad-vary", ["sensitivity", "robot-arm", "--vary", "load.m"]),
    ("bad-amplitudes", ["valve", "bode", "KBSDG4V-3", "--amplitudes", "0"]),
    ("bad-at", ["linearize", "robot-arm", "--at", "cyl.pA"]),
]

_NUMBER = re.compile(r"(?<![A-Za-z_])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


_GUID = re.compile(r"\{[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{12}\}")


#: a table's rule under its header, as long as its widest entry: a time of 9.8 ms or 10.2 ms widens it
_RULE = re.compile(r"-{2,}")


def _mask(text: str, folder: Path) -> str:
    text = _GUID.sub("{GUID}", text.replace(str(folder), "<tmp>"))
    text = _NUMBER.sub("#", text)
    text = _RULE.sub("--", text)
    return "\n".join(" ".join(line.split()) for line in text.splitlines())


def _shape(value: Any, folder: Path) -> Any:
    """The JSON's keys and kinds: every number is "num", every list of numbers "[N num]"."""
    if isinstance(value, dict):
        return {_mask(str(k), folder): _shape(v, folder) for k, v in value.items()}
    if isinstance(value, list):
        if value and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
            return f"[{len(value)} num]"
        return [_shape(v, folder) for v in value]
    if isinstance(value, bool) or value is None:
        return value
    if isinstance(value, (int, float)):
        return "num"
    return _mask(str(value), folder)


def _files(folder: Path, before: set[Path]) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file() and p not in before)


def _record(name: str, argv: list[str], folder: Path) -> dict[str, Any]:
    before = {p for p in folder.rglob("*") if p.is_file()}
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse's refusals
            code = int(exc.code or 0)
    record: dict[str, Any] = {"argv": argv, "exit": code}
    text = out.getvalue()
    if "--json" in argv and code == 0:
        record["json"] = _shape(json.loads(text), folder)
    else:
        record["stdout"] = _mask(text, folder).splitlines()
    record["stderr"] = _mask(err.getvalue(), folder).splitlines()
    record["files"] = _files(folder, before)
    return record


@pytest.fixture(scope="module")
def examples_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("golden")
    for name, text in example_files().items():
        (folder / name).write_text(text, encoding="utf-8")
    return folder


@pytest.mark.parametrize("name, argv", CASES, ids=[n for n, _ in CASES])
def test_command_output_keeps_its_shape(name: str, argv: list[str], examples_folder: Path,
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(examples_folder)
    record = _record(name, argv, examples_folder)
    path = GOLDEN / f"{name}.json"
    if os.environ.get("HYDROSERVO_GOLDEN") == "update":
        GOLDEN.mkdir(exist_ok=True)
        path.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
        return
    text = path.read_text(encoding="utf-8")
    if "rodas3" in text and not has_compiler():
        pytest.skip("recorded with the compiled default method (rodas3); without a C compiler simulate runs CVODES")
    assert record == json.loads(text)
