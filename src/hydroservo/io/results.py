"""Result files: CSV with the units in the column headers, MATLAB .mat files."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from hydroservo.units import si_unit

if TYPE_CHECKING:
    import numpy as np

__all__ = ["write_csv", "write_mat"]


class Result(Protocol):
    """What the writers read of a result (:class:`hydroservo.system.Result` is one)."""

    t: np.ndarray
    units: dict[str, str]

    @property
    def data(self) -> dict[str, np.ndarray]: ...


def write_csv(result: Result, path: str | Path) -> Path:
    """Write ``result`` as CSV: a time column ``t [s]``, then one column ``signal [unit]`` per signal (SI).

    Ten significant digits; written by NumPy, so that a command-line run does
    not load pandas (``pandas.read_csv`` reads it back, ``nan`` as NaN).
    """
    import csv

    import numpy as np

    path = Path(path)
    data = result.data
    header = ["t [s]", *(f"{n} [{si_unit(result.units.get(n, ''))}]" for n in data)]
    with path.open("w", encoding="utf-8", newline="") as f:
        csv.writer(f, lineterminator="\n").writerow(header)
        np.savetxt(f, np.column_stack([result.t, *data.values()]), fmt="%.10g", delimiter=",")
    return path


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
