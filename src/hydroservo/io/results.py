"""Result files: CSV with the units in the column headers, MATLAB .mat files."""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from hydroservo.io.text import comment_lines, one_line
from hydroservo.units import si_unit

if TYPE_CHECKING:
    import numpy as np

__all__ = ["write_csv", "write_mat", "read_csv", "csv_header", "write_table", "write_frame"]


class Result(Protocol):
    """What the writers read of a result (:class:`hydroservo.system.Result` is one)."""

    t: np.ndarray
    units: dict[str, str]

    @property
    def data(self) -> dict[str, np.ndarray]: ...

    def shown_units(self, units: Any = None) -> dict[str, str]: ...

    def get(self, name: str, unit: str | None = None) -> np.ndarray: ...


#: ASCII spellings of the characters unit names may hold beyond ASCII.
_ASCII_UNITS = str.maketrans({"µ": "u", "μ": "u", "Ω": "ohm", "°": "deg", "²": "^2", "³": "^3", "·": "*", "⋅": "*"})


def csv_header(name: str, unit: str, ascii: bool = False) -> str:
    """A column's header, ``name [unit]``: the unit printed (``m³/s``), or with ``ascii`` as unit text in ASCII
    that the unit parser reads back (``m^3/s``, ``um``, ``degC``); every CSV hydroservo writes names its columns so.

    >>> csv_header("valve.QA", "m^3/s"), csv_header("valve.QA", "m^3/s", ascii=True), csv_header("eps", "")
    ('valve.QA [m³/s]', 'valve.QA [m^3/s]', 'eps [-]')
    >>> csv_header("load.x", "µm", ascii=True), csv_header("oil.T", "degC", ascii=True)
    ('load.x [um]', 'oil.T [degC]')
    """
    if ascii:
        text = unit.strip().translate(_ASCII_UNITS) or "-"
        return f"{name} [{text}]"
    return f"{name} [{si_unit(unit)}]"


def csv_header_row(columns: list[str]) -> str:
    """The header row of a CSV (with its line end): each column's name on one line (a line break or a control
    character written as its escape, :func:`hydroservo.io.text.one_line`), quoted where a comma or a quote needs
    it; every CSV hydroservo writes heads its columns so.

    >>> print(csv_header_row(["t [s]", 'a,"b"\\nc [m]']), end="")
    t [s],"a,""b""\\nc [m]"
    """
    import csv
    import io

    text = io.StringIO()
    csv.writer(text, lineterminator="\n").writerow([one_line(str(c)) for c in columns])
    return text.getvalue()


def csv_comments(lines: list[str] | tuple[str, ...] | str) -> str:
    """``lines`` (or a text of lines) as the comment lines (``#`` and a space) that head a CSV (with their line ends), each on
    one line whatever it holds (:func:`hydroservo.io.text.comment_lines`)."""
    texts = [lines] if isinstance(lines, str) else list(lines)
    return "".join(f"{c}\n" for text in texts for c in (comment_lines(text) or ["#"]))


def write_table(
    path: str | Path,
    columns: list[str],
    rows: Any,
    comments: list[str] | tuple[str, ...] = (),
    digits: int | None = None,
) -> Path:
    """Write a CSV table as every CSV of hydroservo is laid out: ``# `` comment lines first (what the table is,
    its conditions), a header row of ``name [unit]`` columns, then one row per line; commas without spaces,
    numbers at full precision (``repr``) or to ``digits`` significant digits, NaN as an empty cell, text quoted
    only where it must be. UTF-8, with a byte-order mark only if the table holds characters beyond ASCII (so
    that spreadsheets read them right).

    ``rows`` is rows of numbers and text, or a 2-D array of numbers (written by NumPy: a result's thousand
    rows without a Python loop over cells).
    """
    import csv
    import io
    import math

    import numpy as np

    def cell(value: Any) -> str:
        if value is None:
            return ""
        if isinstance(value, str):
            return value
        if isinstance(value, int) and not isinstance(value, bool):
            return str(value)
        v = float(value)
        return "" if math.isnan(v) else (f"{v:.{digits}g}" if digits else repr(v))

    text = io.StringIO()
    text.write(csv_comments(comments))
    text.write(csv_header_row(columns))
    writer = csv.writer(text, lineterminator="\n")
    if isinstance(rows, np.ndarray) and rows.ndim == 2 and rows.dtype.kind == "f":
        body = io.StringIO()
        np.savetxt(body, rows, fmt=f"%.{digits or 17}g", delimiter=",")
        text.write(re.sub(r"(?<![\w.])-?nan(?![\w])", "", body.getvalue()))
    else:
        writer.writerows([cell(v) for v in row] for row in rows)
    whole = text.getvalue()
    path = Path(path)
    path.write_text(whole, encoding="utf-8" if whole.isascii() else "utf-8-sig", newline="")
    return path


def write_frame(frame: Any, path: str | Path, comments: list[str] | tuple[str, ...] = (), index: bool = False) -> Path:
    """Write a pandas DataFrame (a study's table, a ladder's) as :func:`write_table` lays out every CSV; its
    columns are named ``name [unit]`` already, and with ``index`` its index is the first column."""
    if index:
        frame = frame.reset_index()
    return write_table(path, [str(c) for c in frame.columns], frame.itertuples(index=False, name=None), comments)


def write_csv(result: Result, path: str | Path, units: Any = None, ascii: bool = False) -> Path:
    """Write ``result`` as CSV (:func:`write_table`): a time column ``t [s]``, then one column ``signal [unit]``
    per signal, in the units the result shows (:meth:`~hydroservo.system.result.Result.shown_units`: the
    model's, ``units`` over them, ``"si"`` for SI), ten significant digits.

    Units are printed (``m³/s``), with the byte-order mark that lets spreadsheet programs read them right; with
    ``ascii``, written as ASCII unit text (``m^3/s``) and no mark. ``pandas.read_csv`` and :func:`read_csv` read
    either back.
    """
    import numpy as np

    shown = result.shown_units(units)
    header = ["t [s]", *(csv_header(n, u, ascii) for n, u in shown.items())]
    columns = np.column_stack([result.t, *(result.get(n, u) for n, u in shown.items())])
    return write_table(path, header, np.asarray(columns, dtype=float), digits=10)


def write_mat(result: Result, path: str | Path) -> Path:
    """Write ``result`` as a MATLAB .mat file: one variable per signal (dots become underscores), ``t`` and ``units``."""
    from scipy.io import savemat

    path = Path(path)
    content: dict[str, Any] = {"t": result.t}
    units = {}
    for n, v in result.data.items():
        key = n.replace(".", "_")
        content[key] = v
        units[key] = si_unit(result.units.get(n, ""))
    content["units"] = units
    savemat(path, content)
    return path


_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⋅", "0123456789-.")


def parseable_unit(printed: str) -> str:
    """A unit as :func:`hydroservo.units.si_unit` prints it (``m³/Pa⁰⋅⁵/s``, ``m·N``, ``-``) in the form the
    unit parser reads (``m^3/Pa^0.5/s``, ``m*N``, ``""``).

    >>> parseable_unit("m³/Pa⁰⋅⁵/s"), parseable_unit("m·N"), parseable_unit("-"), parseable_unit("kg/m^3")
    ('m^3/Pa^0.5/s', 'm*N', '', 'kg/m^3')
    """
    text = printed.strip()
    if text in ("-", ""):
        return ""
    text = re.sub(r"[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⋅]+", lambda m: "^" + m.group(0).translate(_SUPERSCRIPTS), text)
    return text.replace("·", "*")


def read_csv(path: str | Path, model: str | None = None) -> Any:
    """A result read back from a CSV with a time column ``t [s]`` and columns ``signal [unit]``, as
    :func:`write_csv` writes it (or a rig's record in that form): a :class:`hydroservo.system.result.Result`,
    in SI as every result is inside (each column converted from its unit; the units it was written in are kept
    as the result's :attr:`~hydroservo.system.result.Result.unit_choice`).

    Empty cells and ``nan`` are NaN; lines starting with ``#`` are comments. ``model`` names the result (default:
    the file's name).
    """

    import numpy as np

    from hydroservo.errors import HydroservoError, ParameterError
    from hydroservo.io.files import csv_rows, plain_float, read_text
    from hydroservo.system.result import Result as RunResult

    path = Path(path)
    text = read_text(path, "result file", kind="record")
    rows = csv_rows(text, f"result file {str(path)!r}")
    if len(rows) < 3:
        raise ParameterError(f"result file {str(path)!r}: {max(len(rows) - 1, 0)} row(s); expected a header and at "
                             "least two times")
    header = [h.strip() for h in rows[0]]
    names, units = [], []
    for h in header:
        if not (h.endswith("]") and " [" in h):
            raise ParameterError(f"result file {str(path)!r}: column {h!r}: expected 'name [unit]', e.g. 'cyl.pA [Pa]'")
        name, unit = h[:-1].split(" [", 1)
        names.append(name.strip())
        units.append(parseable_unit(unit))
    if names[0] not in ("t", "time") or units[0] != "s":
        raise ParameterError(f"result file {str(path)!r}: first column {header[0]!r}: expected the time, 't [s]'")
    try:
        values = np.array([[plain_float(c) if c.strip() else np.nan for c in r] for r in rows[1:] if r], dtype=float)
    except ValueError as exc:
        raise ParameterError(f"result file {str(path)!r}: {exc}; expected numbers") from None
    if values.ndim != 2 or values.shape[1] != len(names):
        raise ParameterError(f"result file {str(path)!r}: every row needs {len(names)} cells, as the header")
    t = values[:, 0]
    if not np.all(np.diff(t) > 0):
        raise ParameterError(f"result file {str(path)!r}: the time column must increase from row to row")
    from hydroservo.units import UnitChoice, coherent_unit, convert

    data, si_units, written = {}, {}, {}
    for i, (name, unit) in enumerate(zip(names, units)):
        if not i:
            continue
        unit = {"°C": "degC", "°F": "degF", "degree_Celsius": "degC", "degree_Fahrenheit": "degF"}.get(unit, unit)
        try:
            si = "degC" if unit in ("degC", "degF", "K") else coherent_unit(unit)  # temperatures are degC inside
            data[name] = convert(values[:, i], unit, si)
        except HydroservoError as exc:
            raise ParameterError(f"result file {str(path)!r}: column {header[i]!r}: {exc}") from None
        si_units[name] = si
        if unit != si:
            written[name] = unit
    result = RunResult(t, data, si_units, {}, {}, {}, model or path.stem)
    result.unit_choice = UnitChoice(written)
    return result
