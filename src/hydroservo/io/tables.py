"""Time tables: a CSV whose first column is time [s] and another column the values (a recorded signal); lookup
tables: two columns of a CSV as a table's breakpoints and values, read as Hopsan's Signal1DLookupTable reads them."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hydroservo.errors import ParameterError, shorten
from hydroservo.io.files import csv_rows, plain_float, read_text

__all__ = [
    "read_time_table", "read_lookup_table", "parse_lookup_table", "read_plo_table", "parse_plo_table",
    "read_lookup_table_2d", "parse_lookup_table_2d", "read_lookup_table_3d", "parse_lookup_table_3d",
]


def read_time_table(path: str | Path, column: str | int = 1, what: str = "table") -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and values from a CSV file: column 0 is time, ``column`` (name or index, default 1) the values.

    A header row is optional; lines starting with ``#`` are comments. ``what``
    names the reader in error messages (e.g. the component that asked).
    """
    path = Path(path)
    text = read_text(path, f"{what}.file", kind="table")
    rows = csv_rows(text, f"{what}.file {str(path)!r}")
    if not rows:
        raise ParameterError(f"{what}.file: {str(path)!r} is empty")
    header = rows[0]
    try:
        plain_float(header[0])
        data, names = rows, None
    except ValueError:
        data, names = rows[1:], [h.strip() for h in header]
    if isinstance(column, str):
        if names is None or column not in names:
            raise ParameterError(f"{what}.column: {column!r} is not a column of {str(path)!r}; columns: {names}")
        col = names.index(column)
    else:
        col = int(column)
    try:
        arr = np.array([[plain_float(r[0]), plain_float(r[col])] for r in data])
    except (ValueError, IndexError):
        raise ParameterError(
            f"{what}.file: {str(path)!r} needs numbers in column 0 (time, s) and column {col}"
        ) from None
    return arr[:, 0], arr[:, 1]


def read_lookup_table(
    path: str | Path,
    index_column: int = 0,
    value_column: int = 1,
    separator: str = ",",
    skip: int = 0,
    comment: str = "",
    what: str = "table",
) -> tuple[np.ndarray, np.ndarray]:
    """Breakpoints and values from the CSV file ``path``, read as Hopsan reads a lookup table
    (:func:`parse_lookup_table`); at most the cap of tables (:data:`hydroservo.io.files.CAPS`), UTF-8 text."""
    path = Path(path)
    text = _table_text(path, what)
    return parse_lookup_table(text, index_column, value_column, separator, skip, comment, f"{what}: {str(path)!r}")


def _table_text(path: Path, what: str) -> str:
    """The text of a table file: UTF-8, at most the cap of tables (:data:`hydroservo.io.files.CAPS`)."""
    return read_text(path, f"{what}: table file", kind="table")


def parse_lookup_table(
    text: str,
    index_column: int = 0,
    value_column: int = 1,
    separator: str = ",",
    skip: int = 0,
    comment: str = "",
    what: str = "table",
) -> tuple[np.ndarray, np.ndarray]:
    """Breakpoints (column ``index_column``, 0-based) and values (``value_column``) of a lookup table in CSV
    text, read as Hopsan's Signal1DLookupTable reads its file ([Hopsan2026]
    Signal/Non-Linearities/Signal1DLookupTable.hpp and HopsanCore's CSVParserNG): the first ``skip`` lines are
    left out, then the lines that start with ``comment`` (one character, or none); every other line is a row of
    fields split at ``separator`` (one character), each a number (a decimal comma is read as a point, as
    Hopsan's parser does where the separator is not a comma); blank lines are left out. The rows are sorted by
    their breakpoints, which must then be strictly increasing; at least two rows.

    Raises
    ------
    ParameterError
        Naming ``what`` and the line: a separator or comment of more than one character, a column out of
        range, a field that is no finite number, fewer than two rows, two rows with the same breakpoint.

    Examples
    --------
    >>> parse_lookup_table("# x; y\\n2;4,5\\n0;0\\n1;1\\n", separator=";", comment="#")
    (array([0., 1., 2.]), array([0. , 1. , 4.5]))
    """
    if len(separator) != 1:
        raise ParameterError(f"{what}: separator {separator!r}: expected one character")
    if len(comment) > 1:
        raise ParameterError(f"{what}: comment character {comment!r}: expected one character (or none)")
    if index_column < 0 or value_column < 0:
        raise ParameterError(f"{what}: columns {index_column} and {value_column}: expected 0-based indexes, 0 or more")
    rows = _numeric_rows(text, (index_column, value_column), separator, skip, comment, what)
    index = [row[0] for _, row in rows]
    values = [row[1] for _, row in rows]
    return _sorted_table(index, values, what)


def _sorted_table(index: list[float], values: list[float], what: str) -> tuple[np.ndarray, np.ndarray]:
    """The rows sorted by their breakpoints (stable, as Hopsan's LookupTable1D::sortIncreasing), which must then be
    strictly increasing; at least two rows."""
    if len(index) < 2:
        raise ParameterError(f"{what}: {len(index)} row(s) of data; a lookup table needs at least two")
    x, y = np.asarray(index, dtype=float), np.asarray(values, dtype=float)
    order = np.argsort(x, kind="stable")
    x, y = x[order], y[order]
    same = np.flatnonzero(np.diff(x) <= 0)
    if same.size:
        raise ParameterError(f"{what}: two rows have the breakpoint {x[same[0]]:g}; expected each once")
    return x, y


def read_plo_table(path: str | Path, invar: str = "Time", outvar: str = "Data", what: str = "table") -> tuple[np.ndarray, np.ndarray]:
    """Breakpoints and values from the PLO file ``path`` (:func:`parse_plo_table`); at most
    the cap of tables (:data:`hydroservo.io.files.CAPS`), UTF-8 text."""
    path = Path(path)
    return parse_plo_table(_table_text(path, what), invar, outvar, f"{what}: {str(path)!r}")


def parse_plo_table(text: str, invar: str = "Time", outvar: str = "Data", what: str = "table") -> tuple[np.ndarray, np.ndarray]:
    """Breakpoints (the column named ``invar``) and values (``outvar``) of a lookup table in Hopsan's PLO text,
    read as Hopsan's Signal1DPLOLookupTable reads it ([Hopsan2026] Signal/Non-Linearities/Signal1DPLOLookupTable.hpp
    and HopsanCore's PLOParser.cpp): ``'VERSION'`` and the version (1 or 2), the rest of that line and the next
    (a title) left out, the numbers of columns and rows, the columns' quoted names (a first column ``'Time'`` or
    ``'Frequency'`` is not counted in the number), one plot scale per column, then the numbers row by row; what
    follows (the DAT line, the model's name) is left out. The rows are sorted by their breakpoints, which must then
    be strictly increasing; at least two rows.

    Raises
    ------
    ParameterError
        Naming ``what``: no PLO text (no ``'VERSION'``, a version other than 1 or 2), too few numbers, a name not
        among the columns.

    Examples
    --------
    >>> parse_plo_table("'VERSION'\\n1\\n'title'\\n1 3\\n'Time',  'Data'\\n1 1\\n0 0\\n1 2\\n2 8\\n")
    (array([0., 1., 2.]), array([0., 2., 8.]))
    """
    lines = text.splitlines()
    tokens = [(k, token) for k, line in enumerate(lines) for token in line.split()]
    if not tokens or tokens[0][1] != "'VERSION'" or len(tokens) < 2:
        raise ParameterError(f"{what}: not a PLO table: it does not begin with 'VERSION'")
    try:
        version = int(tokens[1][1])
    except ValueError:
        version = 0
    if version not in (1, 2):
        raise ParameterError(f"{what}: PLO version {shorten(tokens[1][1])!r}: expected 1 or 2")
    # the rest of the version's line and the next line (the title) are skipped, as Hopsan's getline twice
    rest = [token for k, token in tokens if k > tokens[1][0] + 1]

    def numbers(count: int, start: int, kind: str) -> list[float]:
        if len(rest) < start + count:
            raise ParameterError(f"{what}: {max(len(rest) - start, 0)} {kind} where the header announces {count}")
        try:
            out = [plain_float(t) for t in rest[start:start + count]]
        except ValueError:
            raise ParameterError(f"{what}: {kind}: a field that is no number") from None
        if not all(np.isfinite(out)):
            raise ParameterError(f"{what}: {kind}: a field that is no finite number")
        return out

    n_cols_f, n_rows_f = numbers(2, 0, "numbers of columns and rows")
    n_cols, n_rows = int(n_cols_f), int(n_rows_f)
    if n_cols < 1 or n_rows < 1 or n_cols != n_cols_f or n_rows != n_rows_f:
        raise ParameterError(f"{what}: {n_cols_f:g} columns and {n_rows_f:g} rows: expected whole numbers, 1 or more")
    if len(rest) > 2 and rest[2] in ("'Time',", "'Frequency',"):
        n_cols += 1  # PLO 1 and 2 do not count a first column of time or frequency
    if len(rest) < 2 + n_cols:
        raise ParameterError(f"{what}: fewer column names than the {n_cols} columns")
    names = [t.replace("',", "").replace("'", "") for t in rest[2:2 + n_cols]]
    data = numbers(n_cols * n_rows, 2 + 2 * n_cols, "numbers of data")  # after one plot scale per column
    for name in (invar, outvar):
        if name not in names:
            raise ParameterError(f"{what}: no column {name!r}; its columns: {', '.join(names)}")
    i, o = names.index(invar), names.index(outvar)
    return _sorted_table(data[i::n_cols], data[o::n_cols], what)


def _numeric_rows(
    text: str, columns: tuple[int, ...], separator: str, skip: int, comment: str, what: str
) -> list[tuple[int, list[float]]]:
    """The (line number, numbers in ``columns``) of each row of CSV text as Hopsan's CSVParserNG reads it: the
    first ``skip`` lines left out, then the lines starting with ``comment``, blank lines left out, fields split at
    ``separator``, a decimal comma read as a point."""
    lines = text.splitlines()[max(skip, 0):]
    first = 0
    while comment and first < len(lines) and lines[first].startswith(comment):
        first += 1
    rows: list[tuple[int, list[float]]] = []
    for number, line in enumerate(lines[first:], start=max(skip, 0) + first + 1):
        if not line.strip():
            continue
        fields = line.split(separator)
        row = []
        for col in columns:
            if col >= len(fields):
                raise ParameterError(
                    f"{what}, line {number}: {len(fields)} column(s); expected column {col} (0-based) there"
                )
            field = fields[col].strip().replace(",", ".", 1)
            try:
                value = plain_float(field)
            except ValueError:
                value = float("nan")
            if not np.isfinite(value):
                raise ParameterError(f"{what}, line {number}, column {col}: {shorten(fields[col].strip())!r} is no finite number")
            row.append(value)
        rows.append((number, row))
    return rows


def read_lookup_table_2d(path: str | Path, comment: str = "", what: str = "table") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Row and column breakpoints and values from the CSV file ``path``, read as Hopsan reads a two-dimensional
    lookup table (:func:`parse_lookup_table_2d`); at most the cap of tables (:data:`hydroservo.io.files.CAPS`), UTF-8 text."""
    path = Path(path)
    return parse_lookup_table_2d(_table_text(path, what), comment, f"{what}: {str(path)!r}")


def parse_lookup_table_2d(text: str, comment: str = "", what: str = "table") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Row and column breakpoints and the values (a matrix, rows by columns) of a two-dimensional lookup table in
    CSV text, read as Hopsan's Signal2DLookupTable reads it ([Hopsan2026]
    Signal/Non-Linearities/Signal2DLookupTable.hpp): three comma-separated fields per line (after the initial lines
    starting with ``comment``), line i nC + j holding row i's breakpoint (read from j = 0), column j's breakpoint
    (read from i = 0) and the value at (i, j); a last line gives the numbers of rows and columns nR, nC (and a
    third field). The breakpoints must be listed strictly increasing, at least two of each: Hopsan sorts breakpoints
    listed out of order but leaves the values as listed (its run pairs the sorted breakpoints with the values in
    the file's order), which no reading of the file as a table reproduces.

    Raises
    ------
    ParameterError
        Naming ``what`` and the line: a line of fewer than three fields or a field that is no finite number, a last
        line that is no whole numbers, a count of lines other than nR nC + 1, breakpoints not strictly increasing.

    Examples
    --------
    >>> rows, cols, v = parse_lookup_table_2d("0,0,1\\n0,10,2\\n1,0,3\\n1,10,5\\n2,2,0\\n")
    >>> rows, cols, v.tolist()
    (array([0., 1.]), array([ 0., 10.]), [[1.0, 2.0], [3.0, 5.0]])
    """
    rows = _numeric_rows(text, (0, 1, 2), ",", 0, comment, what)
    if not rows:
        raise ParameterError(f"{what}: no data")
    number, last = rows[-1]
    n_rows, n_cols = last[0], last[1]
    if n_rows != int(n_rows) or n_cols != int(n_cols) or n_rows < 2 or n_cols < 2:
        raise ParameterError(
            f"{what}, line {number}: {n_rows:g} rows and {n_cols:g} columns: expected whole numbers, 2 or more (the "
            "last line gives the table's numbers of rows and columns)"
        )
    nr, nc = int(n_rows), int(n_cols)
    data = [row for _, row in rows[:-1]]
    if len(data) != nr * nc:
        raise ParameterError(f"{what}: {len(data)} lines of data where the last line announces {nr} x {nc} = {nr * nc}")
    r = np.array([data[i * nc][0] for i in range(nr)])
    c = np.array([data[j][1] for j in range(nc)])
    v = np.array([row[2] for row in data]).reshape(nr, nc)
    for name, index in (("row", r), ("column", c)):
        down = np.flatnonzero(np.diff(index) <= 0)
        if down.size:
            raise ParameterError(
                f"{what}: the {name} breakpoints {index[down[0]]:g}, {index[down[0] + 1]:g}: expected them strictly "
                "increasing as listed (Hopsan sorts a 2D table's breakpoints but leaves its values in the order "
                "listed, which pairs them otherwise than the file does)"
            )
    return r, c, v


def read_lookup_table_3d(
    path: str | Path, comment: str = "", what: str = "table"
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Row, column and plane breakpoints and values from the CSV file ``path``, read as Hopsan reads a
    three-dimensional lookup table (:func:`parse_lookup_table_3d`); at most the cap of tables (:data:`hydroservo.io.files.CAPS`), UTF-8 text."""
    path = Path(path)
    return parse_lookup_table_3d(_table_text(path, what), comment, f"{what}: {str(path)!r}")


def parse_lookup_table_3d(
    text: str, comment: str = "", what: str = "table"
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Row, column and plane breakpoints and the values (rows by columns by planes) of a three-dimensional lookup
    table in CSV text, read as Hopsan's Signal3DLookupTable reads it ([Hopsan2026]
    Signal/Non-Linearities/Signal3DLookupTable.hpp): four comma-separated fields per line (after the initial lines
    starting with ``comment``), line (i nC + j) nP + k holding row i's breakpoint (read from j = k = 0), column
    j's (read from i = 0, k = 0), plane k's (read from i = j = 0) and the value at (i, j, k); a last line gives
    the numbers of rows, columns and planes (and a fourth field). The breakpoints must be listed strictly
    increasing, at least two of each, as for the two-dimensional table (:func:`parse_lookup_table_2d`).

    Raises
    ------
    ParameterError
        Naming ``what`` and the line: a line of fewer than four fields or a field that is no finite number, a last
        line that is no whole numbers, a count of lines other than nR nC nP + 1, breakpoints not strictly
        increasing.

    Examples
    --------
    >>> text = "0,0,0,1\\n0,0,1,2\\n0,1,0,3\\n0,1,1,4\\n1,0,0,5\\n1,0,1,6\\n1,1,0,7\\n1,1,1,8\\n2,2,2,0\\n"
    >>> rows, cols, planes, v = parse_lookup_table_3d(text)
    >>> v[1, 0, 1], v[0, 1, 0]
    (np.float64(6.0), np.float64(3.0))
    """
    rows = _numeric_rows(text, (0, 1, 2, 3), ",", 0, comment, what)
    if not rows:
        raise ParameterError(f"{what}: no data")
    number, last = rows[-1]
    counts = last[:3]
    if any(n != int(n) or n < 2 for n in counts):
        raise ParameterError(
            f"{what}, line {number}: {counts[0]:g} rows, {counts[1]:g} columns and {counts[2]:g} planes: expected "
            "whole numbers, 2 or more (the last line gives the table's numbers of rows, columns and planes)"
        )
    nr, nc, nq = (int(n) for n in counts)
    data = [row for _, row in rows[:-1]]
    if len(data) != nr * nc * nq:
        raise ParameterError(
            f"{what}: {len(data)} lines of data where the last line announces {nr} x {nc} x {nq} = {nr * nc * nq}"
        )
    r = np.array([data[i * nc * nq][0] for i in range(nr)])
    c = np.array([data[j * nq][1] for j in range(nc)])
    q = np.array([data[k][2] for k in range(nq)])
    v = np.array([row[3] for row in data]).reshape(nr, nc, nq)
    for name, index in (("row", r), ("column", c), ("plane", q)):
        down = np.flatnonzero(np.diff(index) <= 0)
        if down.size:
            raise ParameterError(
                f"{what}: the {name} breakpoints {index[down[0]]:g}, {index[down[0] + 1]:g}: expected them strictly "
                "increasing as listed (Hopsan sorts a 3D table's breakpoints but leaves its values in the order "
                "listed, which pairs them otherwise than the file does)"
            )
    return r, c, q, v
