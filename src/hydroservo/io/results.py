"""Result files: CSV with the units in the column headers, MATLAB .mat files."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.units import si_unit

if TYPE_CHECKING:
    from hydroservo.system.result import Result

__all__ = ["write_csv", "write_mat"]


def write_csv(result: Result, path: str | Path) -> Path:
    """Write ``result`` as CSV: a time column ``t [s]``, then one column ``signal [unit]`` per signal (SI)."""
    path = Path(path)
    result.to_pandas().to_csv(path, float_format="%.10g")
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
