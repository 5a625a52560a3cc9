"""Bounded reads (issue 37): one reader of users' files that reads only regular files, at most a stated cap per kind;
CSV rows one at a time with an over-long cell refused; plain decimal numbers only; large records thinned, saying so."""

from __future__ import annotations

import os
import signal
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from hydroservo.data import example_files
from hydroservo.errors import ModelFileError, ParameterError, UnitError
from hydroservo.identification.records import MAX_SAMPLES, Channel, Record, thinned
from hydroservo.io.files import CAPS, csv_rows, iter_csv_rows, read_bytes, read_text, size_cap
from hydroservo.io.hopsan import read_hmf
from hydroservo.io.records import read_record
from hydroservo.units import is_bare_number, plain_number, to_si


@pytest.fixture(autouse=True)
def _no_hang() -> Iterator[None]:
    """A FIFO opened for reading blocks until a writer comes: a guard that turns that hang into a failure."""

    def handler(signum: int, frame: object) -> None:
        raise TimeoutError("hung: the reader waited on the file")

    old = signal.signal(signal.SIGALRM, handler)
    signal.alarm(30)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


# -- read_bytes: only regular files, at most the cap -----------------------------------------------------------
def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path: Path) -> None:
    fifo = tmp_path / "model.toml"
    os.mkfifo(fifo)
    with pytest.raises(ParameterError, match=r"model file '.*model\.toml': a FIFO \(named pipe\), not a regular file"):
        read_text(fifo, "model file")


@pytest.mark.parametrize("device", ["/dev/null", "/dev/zero"])
def test_a_device_is_refused_before_anything_is_read(device: str) -> None:
    with pytest.raises(ParameterError, match=rf"record '{device}': a character device, not a regular file; expected a file"):
        read_bytes(device, "record", kind="record")


def test_a_folder_and_a_missing_file_are_named(tmp_path: Path) -> None:
    with pytest.raises(ParameterError, match=r"is a folder; expected a file"):
        read_bytes(tmp_path, "table")
    with pytest.raises(ParameterError, match=r"'.*nothing\.csv': cannot read \(No such file"):
        read_bytes(tmp_path / "nothing.csv", "table")


def test_the_cap_of_each_kind_is_stated_and_changed_by_its_variable(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assert {k: c.default for k, c in CAPS.items()} == {"model": 20_000_000, "table": 20_000_000, "record": 256_000_000}
    path = tmp_path / "r.csv"
    path.write_bytes(b"x" * 1000)
    monkeypatch.setenv("HYDROSERVO_MAX_RECORD_MB", "0.001")  # exactly 1000 bytes: read
    assert size_cap("record") == 1000 and len(read_bytes(path, "record", kind="record")) == 1000
    monkeypatch.setenv("HYDROSERVO_MAX_RECORD_MB", "0.000999")
    with pytest.raises(ParameterError) as info:
        read_bytes(path, "record", kind="record")
    message = str(info.value)
    for part in ("r.csv", "(1000 bytes)", "at most 0.000999 MB (999 bytes)", "the cap of record files",
                 "environment variable HYDROSERVO_MAX_RECORD_MB"):
        assert part in message, message
    assert size_cap("model") == 20_000_000  # the other kinds keep theirs


@pytest.mark.parametrize("given", ["0", "-5", "abc", "nan", "inf", "2_0", "1e30"])
def test_a_cap_variable_that_is_no_size_is_refused(given: str, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("HYDROSERVO_MAX_TABLE_MB", given)
    with pytest.raises(ParameterError, match=r"environment variable HYDROSERVO_MAX_TABLE_MB = .*positive number of megabytes"):
        size_cap("table")


def test_no_more_than_the_cap_and_one_byte_is_read_of_a_file_that_says_it_is_empty(monkeypatch: pytest.MonkeyPatch) -> None:
    # /proc files are regular and report a size of 0: the cap still bounds the read
    status = Path("/proc/self/status")
    if not status.is_file() or status.stat().st_size != 0:
        pytest.skip("needs Linux's /proc")
    monkeypatch.setenv("HYDROSERVO_MAX_MODEL_MB", "0.0001")
    with pytest.raises(ParameterError, match=r"status': more than 100 bytes; expected at most 0\.0001 MB \(100 bytes\)"):
        read_bytes(status, "model file")


# -- CSV rows -------------------------------------------------------------------------------------------------
def test_csv_rows_keep_their_line_numbers_and_skip_comments_and_blank_lines() -> None:
    text = "# head\n\nt [s],x [m]\n  # indented comment\n0,1\n,\n1,2\r\n"
    assert list(iter_csv_rows(text)) == [(3, ["t [s]", "x [m]"]), (5, ["0", "1"]), (7, ["1", "2"])]
    assert csv_rows("a,b\r0,1\r") == [["a", "b"], ["0", "1"]]  # old Mac line ends, as str.splitlines reads them


def test_a_cell_over_the_csv_field_limit_is_refused_naming_the_line() -> None:
    text = "t [s],x [m]\n0,1\n1," + "2" * 131_073 + "\n"
    with pytest.raises(ParameterError, match=r"record 'a\.csv': line 3: a cell of more than 131072 characters"):
        csv_rows(text, "record 'a.csv'")


# -- plain numbers --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(("text", "value"), [("0.5", 0.5), (" -1.5e-3 ", -1.5e-3), ("1E+05", 1e5), (".5", 0.5),
                                             ("5.", 5.0), ("+2", 2.0), ("inf", np.inf), ("-Infinity", -np.inf)])
def test_plain_numbers_are_what_they_were(text: str, value: float) -> None:
    assert plain_number(text) == value and is_bare_number(text)


@pytest.mark.parametrize("text", ["2_0.0", "1_000", "1e1_0", "\u0662\u0660", "\uff12\uff10", "20 kg", "", "0x10"])
def test_digit_groups_and_other_scripts_digits_are_no_plain_number(text: str) -> None:
    assert plain_number(text) is None and not is_bare_number(text)


@pytest.mark.parametrize("text", ["2_0.0", "2_0.0 kg", " 1_000 kg"])
def test_a_quantity_with_digit_groups_is_refused(text: str) -> None:
    with pytest.raises(UnitError, match=r"digits grouped with '_' are not read; expected a plain number"):
        to_si(text, "kg", what="load.m")


def test_quantities_read_as_before() -> None:
    assert to_si("20 kg", "kg") == 20.0 and to_si("0.5", "m") == 0.5 and to_si("1500 psi", "Pa") == pytest.approx(1.0342e7, rel=1e-4)
    assert to_si("3 m^3/s", "m^3/s") == 3.0 and to_si("2 bar_abs", "Pa") == pytest.approx(2e5 - 101325.0)


# -- records --------------------------------------------------------------------------------------------------
def _record(tmp_path: Path, cell: str) -> Path:
    path = tmp_path / "rec.csv"
    path.write_text(f"t [s],load.x [mm]\n0,20\n0.005,{cell}\n0.01,20\n", encoding="utf-8")
    return path


@pytest.mark.parametrize(("cell", "message"), [
    ("inf", r"data row 2, column 'load\.x': inf is infinite; expected a finite number \(an empty cell or nan"),
    ("-inf", r"data row 2, column 'load\.x': -inf is infinite"),
    ("2_0.0", r"data row 2, column 'load\.x': '2_0\.0' is not a number; digits grouped with '_' are not read"),
    ("\uff12\uff10", r"data row 2, column 'load\.x': '\uff12\uff10' is not a number"),
])
def test_a_record_cell_that_is_no_plain_finite_number_is_refused(tmp_path: Path, cell: str, message: str) -> None:
    with pytest.raises(ParameterError, match=r"record '.*rec\.csv': " + message):
        read_record(_record(tmp_path, cell))


@pytest.mark.parametrize("cell", ["", "nan", "NaN", " nan "])
def test_empty_and_nan_cells_are_missing_samples(tmp_path: Path, cell: str) -> None:
    assert read_record(_record(tmp_path, cell))["load.x"].valid.tolist() == [True, False, True]


def test_a_large_record_reads_into_one_array_of_its_rows(tmp_path: Path) -> None:
    n = 50_000
    t = np.arange(n) * 1e-4
    path = tmp_path / "long.csv"
    with path.open("w") as f:
        f.write("# a comment\nt [s],load.x [mm],cyl.pA [bar]\n")
        np.savetxt(f, np.column_stack([t, np.sin(t), np.cos(t)]), fmt="%.10g", delimiter=",")
    rec = read_record(path)
    np.testing.assert_allclose(rec["cyl.pA"].values, np.cos(t), rtol=1e-9)
    assert rec["load.x"].t.size == n


def test_a_hopsan_model_declaring_an_unreadable_encoding_is_refused(tmp_path: Path) -> None:
    for encoding in ("foo", "shift_jis", "rot13", "idna"):
        path = tmp_path / "m.hmf"
        path.write_text(f'<?xml version="1.0" encoding="{encoding}"?>\n<hopsanmodelfile><system name="a"/></hopsanmodelfile>\n')
        with pytest.raises(ModelFileError, match=rf"m\.hmf': its XML declaration names the encoding '{encoding}', which cannot be read"):
            read_hmf(path)


# -- thinning ---------------------------------------------------------------------------------------------------
def test_a_record_within_the_limit_is_kept_whole() -> None:
    t = np.linspace(0, 1, MAX_SAMPLES)
    rec = Record("r", {"load.x": Channel("load.x", t, t, "mm")})
    assert thinned(rec) == (rec, [])


def test_a_long_record_is_thinned_to_every_kth_sample_and_says_so() -> None:
    t = np.linspace(0, 2, 100_001)
    fast = {n: Channel(n, t, np.sin(t), "mm", "fast.csv") for n in ("load.x", "command.y")}
    slow = np.linspace(0, 2, 81)
    rec = Record("r", {**fast, "cyl.pA": Channel("cyl.pA", slow, slow, "bar", "slow.csv")})
    kept, said = thinned(rec, 30_000)
    assert kept["load.x"].t.size == 25_001 and kept["load.x"].t[1] == t[4]  # every 4th: the fewest that leaves <= 30 000
    np.testing.assert_array_equal(kept["cyl.pA"].t, slow)
    assert said == ["record 'r', fast.csv: 100001 samples at 5e+04 Hz, more than the 30000 used: every 4th kept "
                    "(25001 samples, 1.25e+04 Hz); standard errors are those of the samples kept"]


def test_identify_friction_on_a_record_over_the_limit_warns_what_it_used(tmp_path: Path) -> None:
    from hydroservo.workflows.identify import IdentifyFriction

    files = []
    for name in ("arm_friction-200Hz.csv", "arm_friction-40Hz.csv"):
        files.append(tmp_path / name)
        files[-1].write_text(example_files()[name], encoding="utf-8")
    report = IdentifyFriction("robot-arm", [files], max_samples=1500).run()
    assert report.warnings[0].startswith("record 'arm_friction', ")
    assert "1941 samples at 200 Hz, more than the 1500 used: every 2nd kept (971 samples, 100 Hz)" in report.warnings[0]
    with pytest.raises(ParameterError, match=r"max_samples 1: expected a whole number, 2 or more"):
        IdentifyFriction("robot-arm", [files], max_samples=1)


@pytest.mark.parametrize("text", ["\u0662", "2_0", "\uff12"])
def test_a_hopsan_parameter_value_is_a_plain_number(text: str) -> None:
    from hydroservo.io.hopsan import evaluate

    with pytest.raises(ValueError, match="x: "):
        evaluate(text, {}, what="x")
