"""Files of the valve tools: datasheets, component parameter files, measured curves.

Datasheet (TOML)::

    [datasheet]
    name = "Vickers KBSDG4V-3"
    Q_n = "25.5 L/min"      # nominal flow at P_n per metering edge
    P_n = "35 bar"
    K_q0 = "28 L/min"       # flow gain at null per unit x_s, at P_n per edge
    K_p0 = 36.5             # relative pressure gain at null per unit x_s
    q_lk0 = "1.36 L/min"    # leakage at null, at P_s
    P_s = "70 bar"

Component parameter file (TOML), as written by ``hydroservo valve fit`` and
``valve fit-dynamics``; a model file uses it with
``[components.valve] file = "valve.toml"`` (keys given there override it)::

    [component]
    type = "PseudoSectionValve"
    structure = "variable"
    k = 36.5
    gamma = "6.0578e-09 m^3/s/Pa^0.5"

Measured static curves (CSV, units in brackets in the header): ``x_s [-]``,
``P_L [-]`` and ``q_lk [L/min]`` (blocked ports, at the datasheet's P_s), and
optionally ``Q_L [L/min]`` (connected ports, P_n per edge). Empty cells are
allowed.
"""

from __future__ import annotations

import csv
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.identification.datasheet import Datasheet
from hydroservo.units import format_quantity, from_si, to_si

__all__ = [
    "VALVES",
    "read_datasheet",
    "read_toml",
    "read_component_file",
    "component_toml",
    "read_static_curves",
    "read_csv_table",
]


def _valves() -> dict[str, dict[str, Any]]:
    from hydroservo.parameters import ferreira_000 as f

    return {
        "KBSDG4V-3": {
            "source": "seed 000 (Ferreira, Gomes de Almeida & Quintas), section 5 and 6",
            "datasheet": f.DATASHEET,
            "variable": f.VARIABLE,
            "fixed": f.FIXED,
            "dynamics": f.DYNAMICS,
        }
    }


#: Built-in valve parameter sets, by name.
VALVES = _valves()


def read_toml(path: str | Path, what: str) -> dict[str, Any]:
    """Parse a TOML file; errors are :class:`ParameterError` naming ``what`` and the path."""
    from hydroservo.modelfile import read_toml as _read

    return _read(path, what, ParameterError)


def read_datasheet(source: str | Path) -> Datasheet:
    """A datasheet from a TOML file (``[datasheet]`` table) or a built-in valve name (:data:`VALVES`)."""
    key = str(source)
    if key in VALVES:
        return Datasheet.from_mapping(VALVES[key]["datasheet"], where=f"built-in {key}")
    if not Path(key).exists() and not key.lower().endswith(".toml"):
        raise ParameterError(f"datasheet {key!r}: neither a TOML file nor a built-in valve ({', '.join(VALVES)})")
    data = read_toml(key, "datasheet")
    if "datasheet" not in data or not isinstance(data["datasheet"], dict):
        raise ParameterError(f"datasheet {key!r}: expected a [datasheet] table with Q_n, P_n, P_s, K_p0, K_q0, q_lk0")
    return Datasheet.from_mapping(data["datasheet"], where=f"{key} [datasheet]")


def read_component_file(path: str | Path) -> dict[str, Any]:
    """The ``[component]`` table of a component parameter file (``type`` and parameters with units)."""
    data = read_toml(path, "component file")
    comp = data.get("component")
    if not isinstance(comp, dict) or "type" not in comp:
        raise ParameterError(f"component file {str(path)!r}: expected a [component] table with a 'type'")
    return dict(comp)


def _fmt(value: Any, unit: str) -> str:
    if isinstance(value, str):
        return f'"{value}"'
    if unit in ("", "-"):
        return repr(float(value))
    return f'"{format_quantity(value, unit)}"'


def component_toml(
    type_name: str,
    params: Mapping[str, float],
    units: Mapping[str, str],
    *,
    options: Mapping[str, str] | None = None,
    comments: Mapping[str, str] | None = None,
    header: str = "",
    extra: Mapping[str, Mapping[str, Any]] | None = None,
) -> str:
    """A component parameter file: SI values with units (full precision), optional comments per key.

    ``extra`` tables are written after ``[component]`` for information (what
    the parameters were fitted to, the reproduced characteristics); readers
    ignore them.
    """
    lines = [f"# {line}" if line else "#" for line in header.splitlines()]
    lines += ["[component]", f'type = "{type_name}"']
    for k, v in (options or {}).items():
        lines.append(f'{k} = "{v}"')
    for k, v in params.items():
        note = (comments or {}).get(k)
        lines.append(f"{k} = {_fmt(v, units.get(k, ''))}" + (f"  # {note}" if note else ""))
    for name, table in (extra or {}).items():
        lines += ["", f"[{name}]"]
        for k, v in table.items():
            if isinstance(v, (list, tuple)):
                lines.append(f"{k} = [" + ", ".join(f'"{x}"' if isinstance(x, str) else repr(x) for x in v) + "]")
            elif isinstance(v, str):
                lines.append(f'{k} = "{v}"')
            else:
                lines.append(f"{k} = {float(v)!r}")
    return "\n".join(lines) + "\n"


_CURVE_COLUMNS = {"x_s": "", "P_L": "", "q_lk": "m^3/s", "Q_L": "m^3/s"}


def read_csv_table(
    path: str | Path, columns: Mapping[str, str], what: str = "curves file"
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """Columns ``name [unit]`` of a CSV file in SI, and its ``# key = value`` comment lines.

    ``columns`` maps the known column names to their SI unit ("" dimensionless);
    other columns are ignored; a dimensional column without a unit, or a cell
    that is not a number, is an error naming the file, row and column. Empty
    cells become NaN.
    """
    path = Path(path)
    where = f"{what} {str(path)!r}"
    try:
        lines = [line for line in path.read_text().splitlines() if line.strip()]
    except OSError as exc:
        raise ParameterError(f"{where}: cannot read ({exc.strerror})") from None
    meta: dict[str, str] = {}
    for line in lines:
        if line.startswith("#") and "=" in line:
            key, _, value = line[1:].partition("=")
            meta[key.strip()] = value.split("#")[0].strip()
    rows = list(csv.reader(line for line in lines if not line.startswith("#")))
    if len(rows) < 2:
        raise ParameterError(f"{where}: expected a header and data rows")
    cols: dict[str, tuple[int, str]] = {}
    for i, head in enumerate(rows[0]):
        name = head.split("[")[0].strip()
        unit = head.split("[")[1].split("]")[0].strip() if "[" in head else None
        if name in columns:
            if unit is None and columns[name]:
                raise ParameterError(
                    f"{where}, column {head.strip()!r}: expected a unit in brackets, e.g. '{name} [{columns[name]}]'"
                )
            cols[name] = (i, unit or "")
    out: dict[str, np.ndarray] = {}
    for name, (i, unit) in cols.items():
        vals = []
        for lineno, row in enumerate(rows[1:], start=2):
            cell = row[i].strip() if i < len(row) else ""
            try:
                vals.append(float(cell) if cell else np.nan)
            except ValueError:
                raise ParameterError(f"{where}, row {lineno}, column {name}: {cell!r} is not a number") from None
        scale = 1.0 if unit in ("", "-") else to_si(f"1 {unit}", columns[name], what=f"{where}, column {name}")
        out[name] = np.array(vals) * scale
    return out, meta


def read_static_curves(path: str | Path) -> dict[str, np.ndarray]:
    """Measured static curves (CSV with ``name [unit]`` headers), values in SI; see the module docstring."""
    out, _ = read_csv_table(path, _CURVE_COLUMNS)
    missing = [c for c in ("x_s", "P_L", "q_lk") if c not in out]
    if missing:
        raise ParameterError(
            f"curves file {str(path)!r}: missing column(s) {', '.join(missing)}; expected 'x_s [-], P_L [-], "
            "q_lk [L/min]' and optionally 'Q_L [L/min]'"
        )
    if np.any(out["q_lk"][np.isfinite(out["q_lk"])] < 0):
        raise ParameterError(f"curves file {str(path)!r}: negative leakage flow in q_lk; expected >= 0")
    if np.any(np.abs(out["x_s"][np.isfinite(out["x_s"])]) > 1):
        raise ParameterError(f"curves file {str(path)!r}: x_s outside [-1, 1]; expected the normalised spool position")
    return out


def paper_unit_comment(value: float, unit: str, paper_unit: str) -> str:
    """``= 0.1149 L/min/bar^0.5``-style comment."""
    return f"= {from_si(value, unit, paper_unit):.6g} {paper_unit}" if paper_unit else ""
