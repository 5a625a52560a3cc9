"""Rig records: CSV files with a time column and ``name [unit]`` signal columns.

One experiment is one or more files; each file has its own time column, so a
logger that samples at several rates writes one file per rate ([Efe2014]
Table 5.1)::

    # robot arm, step of 36.8 %, logged at 40 Hz
    t [s],cyl.pA [bar],cyl.pB [bar],supply.p [bar]
    0,1.22,2.0,30.1
    0.025,1.25,,30.0

Column names are the model's signal names (states, outputs, aliases); a
results file written by hydroservo is a record too. Lines starting with ``#``
are comments; empty cells and ``nan`` are missing samples. A cell is a plain
decimal number: ``inf`` and ``2_0.0`` (which Python's ``float`` reads as 20)
are refused with the file, the row and the column. Values keep the unit of
their header: the record is converted where it meets a model. A file is read
up to the cap of records (:data:`hydroservo.io.files.CAPS`).
"""

from __future__ import annotations

import io
import math
from collections.abc import Iterator, Sequence
from pathlib import Path

import numpy as np

from hydroservo.errors import ParameterError, UnitError, shorten
from hydroservo.identification.records import Channel, Record
from hydroservo.io.files import OutputFolder, iter_csv_rows, read_text
from hydroservo.io.results import csv_comments, csv_header_row, parseable_unit
from hydroservo.units import check_unit, plain_number, same_dimension, si_definition

__all__ = ["read_record", "write_record", "record_files"]

_TIME_NAMES = ("t", "time")


def _header(cell: str, where: str, k: int) -> tuple[str, str]:
    text = cell.strip().lstrip("\ufeff")
    if not (text.endswith("]") and " [" in text):
        raise ParameterError(f"{where}: column {k + 1} {text!r}: expected 'name [unit]', e.g. 'cyl.pA [bar]' or 'command.y [-]'")
    name, unit = text[:-1].split(" [", 1)
    unit = parseable_unit(unit)
    try:
        check_unit(unit)
    except UnitError as exc:
        raise UnitError(f"{where}: column {name.strip()!r}: unit {unit!r} is not a unit ({exc})") from None
    return name.strip(), unit


def _read_file(path: Path) -> dict[str, Channel]:
    where = f"record {str(path)!r}"
    text = read_text(path, "record", kind="record")
    rows = iter_csv_rows(text, where)
    first = next(rows, None)
    if first is None:
        raise ParameterError(f"{where}: no header; expected a first line such as 't [s],load.x [mm]'")
    head = first[1]
    header = [_header(c, where, k) for k, c in enumerate(head)]
    (tname, tunit), signals = header[0], header[1:]
    if tname not in _TIME_NAMES or not same_dimension(tunit, "s"):
        raise ParameterError(f"{where}: first column {head[0].strip()!r}: expected the time, e.g. 't [s]'")
    if not signals:
        raise ParameterError(f"{where}: only a time column; expected signal columns 'name [unit]' after it")
    seen: set[str] = set()
    for name, _ in signals:
        if name in seen:
            raise ParameterError(f"{where}: column {name!r} appears twice")
        seen.add(name)
    lines = text.count("\n") + 1 if "\n" in text else text.count("\r") + 1
    values = _body(rows, header, where, min(lines, len(text) // len(header) + 1))
    del text
    if len(values) < 2:
        raise ParameterError(f"{where}: {len(values)} sample(s); a record needs at least two")
    factor, offset, _ = si_definition(tunit)
    t = values[:, 0] * factor + offset
    if not np.all(np.isfinite(t)):
        k = int(np.argmax(~np.isfinite(t)))
        raise ParameterError(f"{where}: data row {k + 1} has no time; every row needs one")
    return {name: Channel(name, t, values[:, j + 1], unit, str(path)) for j, (name, unit) in enumerate(signals)}


def _body(rows: Iterator[tuple[int, list[str]]], header: list[tuple[str, str]], where: str, most: int) -> np.ndarray:
    """The data rows as an array (one row per line; NaN: a missing sample), filled row by row: a large record is
    never held as strings. A cell that is not a plain decimal number (:func:`~hydroservo.units.plain_number`: no
    ``2_0.0``) or is infinite is refused, naming the row and the column."""
    width = len(header)
    values = np.empty((max(2, most), width))  # no more rows than lines, nor than cells of ``width`` characters
    n = 0
    for _, row in rows:
        if len(row) != width:
            raise ParameterError(f"{where}: data row {n + 1} has {len(row)} cells; the header has {width}")
        if n == len(values):  # lines broken at other characters than newlines (str.splitlines)
            values = np.concatenate([values, np.empty((n, width))])
        joined = ",".join(row)
        try:
            if "_" in joined or not joined.isascii():
                raise ValueError
            values[n] = row  # NumPy reads the strings as float() does
        except ValueError:
            values[n] = [_cell(cell, where, n, header[j][0]) for j, cell in enumerate(row)]
        n += 1
    values = values[:n]
    infinite = np.isinf(values)
    if infinite.any():
        i, j = (int(k) for k in np.argwhere(infinite)[0])
        raise ParameterError(
            f"{where}: data row {i + 1}, column {header[j][0]!r}: {values[i, j]:g} is infinite; expected a finite "
            "number (an empty cell or nan for a missing sample)"
        )
    return values


def _cell(cell: str, where: str, i: int, column: str) -> float:
    """One cell: a plain decimal number, or empty / nan (a missing sample)."""
    text = cell.strip()
    if not text:
        return math.nan
    value = plain_number(text)
    if value is None:
        hint = "; digits grouped with '_' are not read" if "_" in text else ""
        raise ParameterError(
            f"{where}: data row {i + 1}, column {column!r}: {shorten(text)!r} is not a number{hint}; expected a plain "
            "decimal number, or an empty cell or nan for a missing sample"
        )
    return value


def read_record(paths: str | Path | Sequence[str | Path], name: str | None = None) -> Record:
    """One experiment from one or more CSV files (one per sample rate), each with its own time column.

    ``paths`` may also be one string of file names separated by commas, as the
    command line gives them. The record is named ``name`` (default: the first
    file's name). A signal in two files is an error naming both.
    """
    if isinstance(paths, str):
        paths = [p for p in (s.strip() for s in paths.split(",")) if p]
    elif isinstance(paths, Path):
        paths = [paths]
    files = [Path(p) for p in paths]
    if not files:
        raise ParameterError("record: no file given; expected one or more CSV files")
    channels: dict[str, Channel] = {}
    for path in files:
        for cname, channel in _read_file(path).items():
            if cname in channels:
                raise ParameterError(
                    f"record: signal {cname!r} is in both {channels[cname].source!r} and {str(path)!r}; "
                    "expected each signal in one file"
                )
            channels[cname] = channel
    return Record(name or _common_stem(files), channels)


def _common_stem(files: Sequence[Path]) -> str:
    """The name of a record of several files: what their names share (``step-40Hz``, ``step-200Hz`` -> ``step``)."""
    import os

    stems = [f.stem for f in files]
    common = os.path.commonprefix(stems).rstrip("-_. ") if len(stems) > 1 else stems[0]
    return common or stems[0]


def record_files(record: Record, stem: str | None = None, comment: str = "") -> dict[str, str]:
    """The CSV text of ``record``, one file per sample rate, by file name (``STEM-200Hz.csv``); ``comment``
    (lines of text) heads every file as ``#`` lines."""
    stem = stem or record.name
    head = csv_comments(comment) if comment else ""
    groups = record.by_rate()
    out: dict[str, str] = {}
    for rate, names in sorted(groups.items(), key=lambda kv: -kv[0]):
        label = f"{rate:g}Hz".replace(".", "p")
        fname = f"{stem}.csv" if len(groups) == 1 else f"{stem}-{label}.csv"
        first = record[names[0]]
        header = csv_header_row(["t [s]", *(f"{n} [{record[n].unit or '-'}]" for n in names)])
        cols = [first.t, *(record[n].values for n in names)]
        buffer = io.StringIO()
        np.savetxt(buffer, np.column_stack(cols), fmt="%.10g", delimiter=",")
        body = buffer.getvalue().replace("nan", "")
        out[fname] = head + header + body
    return out


def write_record(record: Record, folder: str | Path | OutputFolder, stem: str | None = None) -> list[Path]:
    """Write ``record`` as CSV files into ``folder``, one per sample rate; returns the paths.

    Into an :class:`~hydroservo.io.files.OutputFolder` the files are written through it (never
    replacing a file unasked); into a plain folder, which must exist, a file already there is an error.
    """
    texts = record_files(record, stem)
    if isinstance(folder, OutputFolder):
        written = []
        for name, text in texts.items():
            path = folder.file(name)
            path.write_text(text, encoding="utf-8")
            written.append(path)
        return written
    base = Path(folder)
    if not base.is_dir():
        raise ParameterError(f"record: folder {str(base)!r} does not exist")
    paths = [base / name for name in texts]
    existing = [str(p) for p in paths if p.exists()]
    if existing:
        raise ParameterError(f"record: {', '.join(existing)} exists already; expected a new file name")
    for p, text in zip(paths, texts.values()):
        p.write_text(text, encoding="utf-8")
    return paths

