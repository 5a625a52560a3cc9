"""Operating points (TOML) and linear models (JSON, CSV) of :mod:`hydroservo.analysis.linear`.

An operating-point file names state values with their units::

    # the arm moving at 36.8 % valve signal
    "cyl.pA" = "6.5 bar"
    "cyl.pB" = "8.7 bar"
    "load.v" = "0.073 m/s"

States not named keep their initial values.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.errors import ParameterError
from hydroservo.io.toml import read_toml

if TYPE_CHECKING:
    from hydroservo.analysis.linear import LinearModel

__all__ = ["read_operating_point", "write_linear_model"]


def read_operating_point(path: str | Path) -> dict[str, Any]:
    """State name -> value (a number in SI or a quantity with its unit), as the file gives them."""
    data = read_toml(path, "operating-point file")
    table = data.get("states", data)
    if not isinstance(table, dict) or not table:
        raise ParameterError(
            f'operating-point file {str(path)!r}: expected state = value lines, e.g. "cyl.pA" = "6.5 bar"'
        )
    for key, value in table.items():
        if not isinstance(value, (int, float, str)) or isinstance(value, bool):
            raise ParameterError(
                f"operating-point file {str(path)!r}: {key} = {value!r}: expected a number (SI) or a quantity, e.g. \"6.5 bar\""
            )
    return dict(table)


def write_linear_model(lin: LinearModel, path: str | Path, extra: dict[str, Any] | None = None) -> Path:
    """The linear model as JSON: named matrices, operating point, modes (``LinearModel.to_dict``) and ``extra``."""
    path = Path(path)
    path.write_text(json.dumps({**lin.to_dict(), **(extra or {})}, indent=2, default=float) + "\n", encoding="utf-8")
    return path
