"""Files in and out, safely: text that must be text, names that stay in their folder, outputs all or nothing.

* :func:`read_text` reads a user's file as UTF-8 text and refuses a binary
  file, a file that is not UTF-8, a folder or a missing file with one message
  naming the file.
* :func:`safe_name` turns a name from a file (a model's ``[model] name``) into
  a plain file name: no path separators, no leading dot, never empty.
* :class:`OutputFolder` collects a command's outputs in a hidden staging
  folder next to the requested one and moves them into place only when the
  whole command succeeded: a failure leaves nothing behind (not even an empty
  folder), and a file that already exists is replaced only when asked
  (``force``).
"""

from __future__ import annotations

import os
import re
import shutil
import tempfile
from pathlib import Path
from types import TracebackType

from hydroservo.errors import HydroservoError, ParameterError

__all__ = ["read_text", "csv_rows", "safe_name", "OutputFolder"]


def read_text(path: str | Path, what: str, error: type[HydroservoError] = ParameterError) -> str:
    """The text of file ``path``; ``error`` naming ``what`` and the path if it is missing, a folder, binary or not UTF-8."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except IsADirectoryError:
        raise error(f"{what} {str(path)!r}: is a folder; expected a file") from None
    except OSError as exc:
        raise error(f"{what} {str(path)!r}: cannot read ({exc.strerror})") from None
    if b"\x00" in data:
        raise error(f"{what} {str(path)!r}: a binary file; expected UTF-8 text")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise error(f"{what} {str(path)!r}: not UTF-8 text (byte {exc.start + 1}); expected UTF-8 text") from None


def csv_rows(text: str) -> list[list[str]]:
    """The rows of a CSV text as every CSV reader of hydroservo takes them (the csv module parses quoting):
    blank lines and whole-line comments (``#`` first) left out. A ``#`` inside a line is data, as in Hopsan's
    variable names (``Valve#PA#Pressure``), which is why no reader cuts lines at a ``#`` (pandas' ``comment``
    would).

    >>> csv_rows('# a comment\\n\\nt [s],"Valve#PA#Pressure [Pa]"\\n0,1e5\\n')
    [['t [s]', 'Valve#PA#Pressure [Pa]'], ['0', '1e5']]
    """
    import csv

    lines = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    return [row for row in csv.reader(lines) if any(cell.strip() for cell in row)]


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
