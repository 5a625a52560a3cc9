"""Time tables: a CSV whose first column is time [s] and another column the values (a recorded signal)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.io.files import csv_rows, read_text

__all__ = ["read_time_table"]


def read_time_table(path: str | Path, column: str | int = 1, what: str = "table") -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and values from a CSV file: column 0 is time, ``column`` (name or index, default 1) the values.

    A header row is optional; lines starting with ``#`` are comments. ``what``
    names the reader in error messages (e.g. the component that asked).
    """
    path = Path(path)
    text = read_text(path, f"{what}.file")
    rows = csv_rows(text)
    if not rows:
        raise ParameterError(f"{what}.file: {str(path)!r} is empty")
    header = rows[0]
    try:
        float(header[0])
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
        arr = np.array([[float(r[0]), float(r[col])] for r in data])
    except (ValueError, IndexError):
        raise ParameterError(
            f"{what}.file: {str(path)!r} needs numbers in column 0 (time, s) and column {col}"
        ) from None
    return arr[:, 0], arr[:, 1]
