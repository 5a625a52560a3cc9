"""``hydroservo export-fmu``: the FMU file, its JSON report, and bad input (exit 2, nothing written)."""

from __future__ import annotations

import json
import zipfile

import pytest

from hydroservo.system.native import has_compiler


@pytest.mark.skipif(not has_compiler(), reason="no C compiler")
def test_export_fmu_writes_the_fmu_into_a_folder_of_its_own_and_reports_it(tmp_path, cli, monkeypatch) -> None:
    # the rule of every command that writes files: a new hydroservo-NAME-KIND[-N] folder unless --out names one
    monkeypatch.chdir(tmp_path)
    code, text, err = cli("export-fmu", "servo-solenoid-cylinder", "--inputs", "valve.u", "--set", "load.m=60 kg",
                          "--method", "bdf2", "--step", "0.2 ms", "--json")  # fmt: skip
    assert code == 0, err
    report = json.loads(text)
    assert report["fmu"] == "hydroservo-servo-solenoid-cylinder-fmu/servo_solenoid_cylinder.fmu"
    assert report["platform"] == "linux64"
    assert report["co_simulation"] == {"method": "bdf2", "step_s": 2e-4}
    mass = next(v for v in report["variables"] if v["name"] == "load.m")
    assert mass["start"] == 60.0 and mass["unit"] == "kg" and mass["variability"] == "tunable"
    valve = next(v for v in report["variables"] if v["name"] == "valve.u")
    assert valve["kind"] == "input" and valve["value_reference"] == len([v for v in report["variables"]
                                                                         if v["kind"] == "parameter"])  # fmt: skip
    folder = tmp_path / "hydroservo-servo-solenoid-cylinder-fmu"
    assert [p.name for p in tmp_path.iterdir()] == [folder.name]
    assert [p.name for p in folder.iterdir()] == ["servo_solenoid_cylinder.fmu"]
    with zipfile.ZipFile(folder / "servo_solenoid_cylinder.fmu") as archive:
        assert sorted(archive.namelist()) == sorted(report["files"])
        assert "binaries/linux64/servo_solenoid_cylinder.so" in archive.namelist()


def test_export_fmu_sources_only_and_renamed_outputs(tmp_path, cli) -> None:
    code, text, err = cli("export-fmu", "flight-simulator", "--sources-only", "--name", "fs", "--out", str(tmp_path))
    assert code == 0, err
    assert "sources only (no binary)" in text and "supply.p (output) -> supply.p_out" in text
    with zipfile.ZipFile(tmp_path / "fs.fmu") as archive:
        assert not any(n.startswith("binaries/") for n in archive.namelist())
        assert "sources/fs_fmi2.c" in archive.namelist()


def test_export_fmu_replaces_a_file_only_with_force(tmp_path, cli) -> None:
    args = ("export-fmu", "flight-simulator", "--sources-only", "--out", str(tmp_path))
    (tmp_path / "flight_simulator.fmu").write_text("mine")
    code, _, err = cli(*args)
    assert code == 2 and "--out" in err and "flight_simulator.fmu already exist" in err and "--force" in err
    assert (tmp_path / "flight_simulator.fmu").read_text() == "mine"
    assert cli(*args, "--force")[0] == 0 and zipfile.is_zipfile(tmp_path / "flight_simulator.fmu")


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--step", "0"], "--step '0': expected a positive, finite step"),
        (["--step", "2 bar"], "--step: '2 bar' has the wrong dimension"),
        (["--method", "euler"], "argument --method: invalid choice: 'euler'"),
        (["--inputs", "valve.q"], "--inputs 'valve.q': 'valve' has no input 'q'; expected one of"),
        (["--name", "9lives"], "--name '9lives': expected a C identifier"),
        (["--set", "load.m=3 bar"], "wrong dimension"),
        (["--accuracy", "1e-3"], "--accuracy 1e-3: only for a variable-step co-simulation method"),
        (["--method", "ros23", "--accuracy", "2"], "--accuracy 2: expected a relative accuracy between"),
    ],
)
def test_export_fmu_bad_input_exit_2_nothing_written(tmp_path, cli, capsys, monkeypatch, argv, message) -> None:
    monkeypatch.chdir(tmp_path)
    try:
        code, _, err = cli("export-fmu", "flight-simulator", *argv)
    except SystemExit as exc:  # argparse's own errors
        code, err = exc.code, capsys.readouterr().err
    assert code == 2 and message in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_export_fmu_without_a_compiler_writes_nothing(tmp_path, cli, monkeypatch) -> None:
    monkeypatch.setenv("CC", "")
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    monkeypatch.setattr("sysconfig.get_config_var", lambda name: None)
    code, _, err = cli("export-fmu", "flight-simulator", "--out", str(tmp_path / "out"))
    assert code == 2 and "C compiler: none found" in err and "--sources-only" in err
    assert list(tmp_path.iterdir()) == []
