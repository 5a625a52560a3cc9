"""Valve datasheets (TOML): the static values a manufacturer prints.

::

    [datasheet]
    name = "Vickers KBSDG4V-3"
    Q_n = "25.5 L/min"      # nominal flow at P_n per metering edge
    P_n = "35 bar"
    K_q0 = "28 L/min"       # flow gain at null per unit x_s, at P_n per edge
    K_p0 = 36.5             # relative pressure gain at null per unit x_s
    q_lk0 = "1.36 L/min"    # leakage at null, at P_s
    P_s = "70 bar"

A built-in valve's datasheet is read by its name (:data:`BUILTIN_VALVES`).
"""

from __future__ import annotations

from pathlib import Path

from hydroservo.data import parameter_set
from hydroservo.errors import ParameterError
from hydroservo.identification.datasheet import Datasheet
from hydroservo.io.toml import read_toml

__all__ = ["BUILTIN_VALVES", "read_datasheet"]

#: Built-in valves by name: name -> parameter set of the package (with [datasheet] and [dynamics] tables).
BUILTIN_VALVES = {"KBSDG4V-3": "FerreiraND"}


def read_datasheet(source: str | Path) -> Datasheet:
    """A datasheet from a TOML file (``[datasheet]`` table) or a built-in valve name (:data:`BUILTIN_VALVES`)."""
    key = str(source)
    if key in BUILTIN_VALVES:
        return Datasheet.from_mapping(parameter_set(BUILTIN_VALVES[key]).table("datasheet"), where=f"built-in {key}")
    if not Path(key).exists() and not key.lower().endswith(".toml"):
        raise ParameterError(
            f"datasheet {key!r}: neither a TOML file nor a built-in valve ({', '.join(BUILTIN_VALVES)})"
        )
    data = read_toml(key, "datasheet")
    if "datasheet" not in data or not isinstance(data["datasheet"], dict):
        raise ParameterError(f"datasheet {key!r}: expected a [datasheet] table with Q_n, P_n, P_s, K_p0, K_q0, q_lk0")
    return Datasheet.from_mapping(data["datasheet"], where=f"{key} [datasheet]")
