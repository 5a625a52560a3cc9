"""Files in and out, safely: text that must be text, names that stay in their folder, outputs all or nothing.

* :func:`read_bytes` is the one reader of a user's file: only a regular file
  (a FIFO, a device such as ``/dev/zero``, a socket or a folder is refused
  before anything is read, and a FIFO is opened without waiting for a writer),
  and at most the cap of its kind (:data:`CAPS`: model files and Hopsan models
  20 MB, tables 20 MB, records 256 MB; the environment variable of the kind
  changes it). It never reads more than the cap and one byte, so a file that
  grows, or one that says it is empty (``/proc``), is bounded too.
* :func:`read_text` reads a user's file (through :func:`read_bytes`) as UTF-8
  text and refuses a binary file, a file that is not UTF-8, a folder or a
  missing file with one message naming the file.
* :func:`csv_rows` and :func:`iter_csv_rows` split a CSV text into rows as
  every CSV reader takes them; :func:`plain_float` reads a cell as a number
  (a plain decimal: not ``2_0.0``, which Python's ``float`` reads as 20).
* :func:`safe_name` turns a name from a file (a model's ``[model] name``) into
  a plain file name: no path separators, no leading dot, never empty.
* :class:`OutputFolder` collects a command's outputs in a hidden staging
  folder next to the requested one and moves them into place only when the
  whole command succeeded: a failure leaves nothing behind (not even an empty
  folder), and a file that already exists is replaced only when asked
  (``force``).
"""

from __future__ import annotations

import csv
import math
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path
from types import TracebackType
from typing import NamedTuple

from hydroservo.errors import HydroservoError, ParameterError, shorten
from hydroservo.units import plain_number

__all__ = [
    "CAPS", "Cap", "size_cap", "read_bytes", "read_text", "csv_rows", "iter_csv_rows", "plain_float", "safe_name",
    "OutputFolder",
]


class Cap(NamedTuple):
    """The largest file of one kind that is read [bytes], the environment variable that changes it [MB], and the
    files of the kind (for messages and docs/reliability.md)."""

    default: int
    variable: str
    files: str


#: The kinds of input file and their caps (docs/reliability.md, "Files"). ``HYDROSERVO_MAX_<KIND>_MB`` (a number of
#: megabytes, 1 MB = 10^6 bytes, fractions allowed) replaces a kind's default.
CAPS: dict[str, Cap] = {
    "model": Cap(20_000_000, "HYDROSERVO_MAX_MODEL_MB",
                 "model files, component files, datasheets, operating points and Hopsan models (.hmf)"),
    "table": Cap(20_000_000, "HYDROSERVO_MAX_TABLE_MB",
                 "tables, curves, bench and Bode files, measured responses"),
    "record": Cap(256_000_000, "HYDROSERVO_MAX_RECORD_MB", "rig records and result files read back"),
}

#: The longest CSV cell read [characters]: the csv module's own field limit, which a number never comes near.
MAX_CELL = csv.field_size_limit()


def _megabytes(size: float) -> str:
    return f"{size / 1e6:.6g} MB"


def size_cap(kind: str) -> int:
    """The cap of files of ``kind`` [bytes]: its environment variable's megabytes if set, else the default."""
    cap = CAPS[kind]
    given = os.environ.get(cap.variable)
    if given is None or not given.strip():
        return cap.default
    value = plain_number(given)
    if value is None or not math.isfinite(value) or value <= 0 or value > 1e12:
        raise ParameterError(
            f"environment variable {cap.variable} = {shorten(given)!r}: expected a positive number of megabytes "
            "(1 MB = 10^6 bytes), e.g. 500"
        )
    return max(1, int(value * 1e6))


def _oversize(path: Path, what: str, kind: str, cap: int, size: int | None, error: type[HydroservoError]) -> HydroservoError:
    variable = CAPS[kind].variable
    suggest = f"{math.ceil(2 * (size or 2 * cap) / 1e6):d}"
    told = f"{_megabytes(size)} ({size} bytes)" if size is not None else f"more than {cap} bytes"
    return error(
        f"{what} {str(path)!r}: {told}; expected at most {_megabytes(cap)} ({cap} bytes), the cap of {kind} files "
        f"({CAPS[kind].files}); to read it, raise the cap with the environment variable {variable} "
        f"(e.g. {variable}={suggest})"
    )


_KINDS_OF_FILE = (
    (stat.S_ISFIFO, "a FIFO (named pipe)"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def _not_regular(path: Path, what: str, mode: int, error: type[HydroservoError]) -> HydroservoError:
    if stat.S_ISDIR(mode):
        return error(f"{what} {str(path)!r}: is a folder; expected a file")
    kind = next((name for test, name in _KINDS_OF_FILE if test(mode)), "not a regular file")
    return error(f"{what} {str(path)!r}: {kind}, not a regular file; expected a file")


_OPEN_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_BINARY", 0)
_CHUNK = 1 << 20


def read_bytes(
    path: str | Path, what: str, error: type[HydroservoError] = ParameterError, *, kind: str = "model"
) -> bytes:
    """The bytes of the regular file ``path``, at most the cap of ``kind`` (:data:`CAPS`); ``error`` naming ``what``
    and the path if it is missing, not a regular file (a folder, a FIFO, a device, a socket) or larger than the cap.

    Nothing but a regular file is opened for reading, and that without waiting (a FIFO swapped in between the check
    and the opening does not block); no more than the cap and one byte is read.
    """
    path = Path(path)
    cap = size_cap(kind)
    try:
        info = os.stat(path)
    except OSError as exc:
        raise error(f"{what} {str(path)!r}: cannot read ({exc.strerror})") from None
    except ValueError as exc:  # a NUL in the path
        raise error(f"{what} {shorten(str(path))!r}: cannot read ({exc})") from None
    if not stat.S_ISREG(info.st_mode):
        raise _not_regular(path, what, info.st_mode, error)
    if info.st_size > cap:
        raise _oversize(path, what, kind, cap, info.st_size, error)
    try:
        fd = os.open(path, _OPEN_FLAGS)
    except OSError as exc:
        raise error(f"{what} {str(path)!r}: cannot read ({exc.strerror})") from None
    try:
        opened = os.fstat(fd)
        if not stat.S_ISREG(opened.st_mode):  # replaced since the check
            raise _not_regular(path, what, opened.st_mode, error)
        chunks: list[bytes] = []
        total, want = 0, cap + 1
        try:
            while total < want:  # first the whole file in one read (one buffer, not copied again), then the rest
                chunk = os.read(fd, min(max(_CHUNK, opened.st_size + 1), want - total) if not chunks else min(_CHUNK, want - total))
                if not chunk:
                    break
                chunks.append(chunk)
                total += len(chunk)
        except OSError as exc:
            raise error(f"{what} {str(path)!r}: cannot read ({exc.strerror})") from None
    finally:
        os.close(fd)
    if total > cap:
        raise _oversize(path, what, kind, cap, None, error)
    return b"".join(chunks)


def read_text(
    path: str | Path, what: str, error: type[HydroservoError] = ParameterError, *, kind: str = "model"
) -> str:
    """The text of file ``path`` (:func:`read_bytes`, capped as files of ``kind``); ``error`` naming ``what`` and the
    path if it is missing, not a regular file, larger than the cap, binary or not UTF-8."""
    path = Path(path)
    data = read_bytes(path, what, error, kind=kind)
    if b"\x00" in data:
        raise error(f"{what} {str(path)!r}: a binary file; expected UTF-8 text")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise error(f"{what} {str(path)!r}: not UTF-8 text (byte {exc.start + 1}); expected UTF-8 text") from None


def iter_csv_rows(text: str, what: str = "CSV file") -> Iterator[tuple[int, list[str]]]:
    """The rows of a CSV text as every CSV reader of hydroservo takes them (the csv module parses quoting), with the
    number of the line each ends on: blank lines, rows of empty cells and whole-line comments (``#`` first) left
    out. A ``#`` inside a line is data, as in Hopsan's variable names (``Valve#PA#Pressure``), which is why no reader
    cuts lines at a ``#`` (pandas' ``comment`` would). One row at a time: a large record is never held as a list of
    lists of strings. A cell longer than :data:`MAX_CELL` characters, or text the csv module cannot split, raises a
    :class:`ParameterError` naming ``what`` and the line.
    """
    number = 0

    def lines() -> Iterator[str]:
        nonlocal number
        for line in _lines(text):
            number += 1
            first = line.lstrip()[:1]
            if first and first != "#":
                yield line

    try:
        for row in csv.reader(lines()):
            if "".join(row).strip():
                yield number, row
    except csv.Error as exc:
        if "field larger than field limit" in str(exc):
            raise ParameterError(
                f"{what}: line {number}: a cell of more than {MAX_CELL} characters; expected numbers, names and "
                "units in cells of at most that length"
            ) from None
        raise ParameterError(f"{what}: line {number}: not CSV ({exc}); expected comma-separated cells") from None


def _lines(text: str, chunk: int = 1 << 20) -> Iterator[str]:
    """The lines of ``text`` as ``str.splitlines`` gives them, a chunk of about ``chunk`` characters (cut after a
    newline) at a time: a large text is never copied whole into a list of lines (nor into a StringIO, which holds
    4 bytes a character)."""
    start, end_of_text = 0, len(text)
    while start < end_of_text:
        end = min(start + chunk, end_of_text)
        if end < end_of_text:
            cut = text.find("\n", end - 1)
            end = end_of_text if cut < 0 else cut + 1
        yield from text[start:end].splitlines()
        start = end


def csv_rows(text: str, what: str = "CSV file") -> list[list[str]]:
    """The rows of a CSV text as every CSV reader of hydroservo takes them (:func:`iter_csv_rows`).

    >>> csv_rows('# a comment\\n\\nt [s],"Valve#PA#Pressure [Pa]"\\n0,1e5\\n')
    [['t [s]', 'Valve#PA#Pressure [Pa]'], ['0', '1e5']]
    """
    return [row for _, row in iter_csv_rows(text, what)]


def plain_float(text: str) -> float:
    """``float(text)`` for a plain decimal number only (:func:`hydroservo.units.plain_number`): digit groups
    (``"2_0.0"``) and digits of other scripts raise ValueError, as any other text that is no number.

    >>> plain_float(" 1.5e3 "), plain_float("nan") != plain_float("nan")
    (1500.0, True)
    """
    value = plain_number(text)
    if value is None:
        raise ValueError(f"not a plain decimal number: {text!r}")
    return value


_UNSAFE = re.compile(r"[^A-Za-z0-9._-]+")


def safe_name(name: str, fallback: str = "model", limit: int = 100) -> str:
    """A plain file name from ``name``: only letters, digits, ``.``, ``_`` and ``-``; no leading dot or dash.

    >>> safe_name("../escaped"), safe_name("/etc/passwd"), safe_name(""), safe_name("valve cylinder")
    ('escaped', 'etc-passwd', 'model', 'valve-cylinder')
    """
    cleaned = _UNSAFE.sub("-", name).strip(".-")
    cleaned = re.sub(r"\.{2,}", ".", cleaned)
    return cleaned[:limit] or fallback


class OutputFolder:
    """The folder a command writes to, all or nothing (module notes).

    Use as a context manager: ``file(name)`` gives the path to write ``name``
    to (in the staging folder), ``final(name)`` the path it will have. On a
    clean exit the files move into ``target``; on an exception they are
    deleted. ``expect(names)`` refuses, before any work, names that already
    exist in ``target`` (unless ``force``).
    """

    def __init__(self, target: str | Path, *, force: bool = False, what: str = "--out") -> None:
        self.target = Path(target)
        self.force = force
        self.what = what
        self.staging: Path | None = None
        if self.target.exists() and not self.target.is_dir():
            raise ParameterError(f"{what} {str(self.target)!r}: exists and is not a folder; expected a folder")
        anchor = self.target.absolute()
        while not anchor.exists():
            anchor = anchor.parent
        if not anchor.is_dir():
            raise ParameterError(f"{what} {str(self.target)!r}: {str(anchor)!r} is a file, not a folder; expected a folder")
        self.anchor = anchor

    def __repr__(self) -> str:
        return f"OutputFolder({str(self.target)!r}, force={self.force})"

    def expect(self, names: list[str]) -> None:
        """Refuse now if any of ``names`` exists in the target folder and ``force`` is not set."""
        existing = [n for n in names if (self.target / n).exists()]
        if existing and not self.force:
            raise ParameterError(
                f"{self.what} {str(self.target)!r}: {', '.join(existing)} already exist(s); "
                "expected a new folder or new names (--force replaces them)"
            )

    def __enter__(self) -> OutputFolder:
        try:
            self.staging = Path(tempfile.mkdtemp(prefix=".hydroservo-", dir=self.anchor))
        except OSError as exc:
            raise ParameterError(f"{self.what} {str(self.target)!r}: cannot write there ({exc.strerror})") from None
        return self

    def file(self, name: str) -> Path:
        """Where to write the output file ``name`` (a plain name)."""
        if self.staging is None:
            raise RuntimeError("OutputFolder.file() outside its with block")
        if name != safe_name(name, fallback="", limit=255):
            raise ParameterError(f"output file name {name!r}: expected a plain name (letters, digits, . _ -)")
        return self.staging / name

    @property
    def folder(self) -> Path:
        """The staging folder, for a writer that names its files itself (plain names only)."""
        if self.staging is None:
            raise RuntimeError("OutputFolder.folder outside its with block")
        return self.staging

    def final(self, name: str) -> str:
        """The path output file ``name`` will have."""
        return str(self.target / name)

    def __exit__(
        self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        staging, self.staging = self.staging, None
        if staging is None:
            return
        try:
            if kind is None:
                self._commit(staging)
        finally:
            shutil.rmtree(staging, ignore_errors=True)

    def _commit(self, staging: Path) -> None:
        names = sorted(p.name for p in staging.iterdir())
        self.expect(names)
        try:
            self.target.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise ParameterError(f"{self.what} {str(self.target)!r}: cannot create the folder ({exc.strerror})") from None
        for name in names:
            os.replace(staging / name, self.target / name)
