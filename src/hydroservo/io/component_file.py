"""Component parameter files: one component's type and parameters, as the valve tools write them.

::

    # written by hydroservo valve fit
    [component]
    type = "PseudoSectionValve"
    structure = "variable"
    k = 36.5
    gamma = "6.0578e-09 m^3/s/Pa^0.5"  # = 0.114941 L/min/bar^0.5

    [datasheet]                 # tables after [component] are for information: readers ignore them
    Q_n = "25.5 L/min"

A model file uses one with ``[components.valve] file = "valve.toml"`` (keys
given there override it). A staged-slot valve file may carry a ``[bench]``
table with its test conditions (:func:`read_staged_slot_valve`).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from hydroservo.analysis.static_bench import Bench
from hydroservo.components.base import REGISTRY, Component
from hydroservo.components.valves.staged_slot import StagedSlotValve
from hydroservo.data import parameter_set
from hydroservo.errors import ParameterError
from hydroservo.io.toml import read_toml, toml_comments, toml_quantity, toml_string, toml_table, toml_value
from hydroservo.laws.staged_slot import BRIDGE_PARAMETERS

__all__ = [
    "read_component_file",
    "component_toml",
    "component_file_text",
    "STAGED_SLOT_VALVES",
    "read_staged_slot_valve",
    "staged_slot_valve_toml",
]


def read_component_file(path: str | Path) -> dict[str, Any]:
    """The ``[component]`` table of a component parameter file (``type`` and parameters with units)."""
    return _component_table(read_toml(path, "component file"), path)


def _component_table(data: Mapping[str, Any], path: str | Path) -> dict[str, Any]:
    comp = data.get("component")
    if not isinstance(comp, dict) or "type" not in comp:
        raise ParameterError(f"component file {str(path)!r}: expected a [component] table with a 'type'")
    return dict(comp)


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
    lines = toml_comments(header)
    entries = {"type": toml_string(type_name)}
    entries.update({k: toml_string(v) for k, v in (options or {}).items()})
    entries.update({k: toml_quantity(v, units.get(k, "")) for k, v in params.items()})
    lines += toml_table("component", entries, comments)
    for name, table in (extra or {}).items():
        lines += ["", *toml_table(name, {k: toml_value(v) for k, v in table.items()})]
    return "\n".join(lines) + "\n"


def component_file_text(
    component: Component,
    names: list[str] | None = None,
    *,
    comments: Mapping[str, str] | None = None,
    header: str = "",
    extra: Mapping[str, Mapping[str, Any]] | None = None,
) -> str:
    """A component parameter file of ``component``: its type, options and parameters ``names`` (default all)."""
    keys = list(component.PARAMETERS) if names is None else names
    return component_toml(
        type(component).__name__,
        {k: component.values[k] for k in keys},
        {k: component.PARAMETERS[k].unit for k in keys},
        options=dict(component.option_values),
        comments=comments,
        header=header,
        extra=extra,
    )


#: Built-in staged-slot valves (geometry and test bench) by name: name -> parameter set of the package.
STAGED_SLOT_VALVES = {"aerospace-example": "MareAttarND_example"}


def read_staged_slot_valve(source: str | Path) -> tuple[StagedSlotValve, Bench | None]:
    """A :class:`~hydroservo.components.StagedSlotValve` and its :class:`~hydroservo.analysis.static_bench.Bench`.

    From a component file (``[component]`` with ``type = "StagedSlotValve"``, and a
    ``[bench]`` table: P_s, X_n, optionally P_r, Q_n, T_rated, flow_ranges) or a
    built-in name (:data:`STAGED_SLOT_VALVES`). The bench is None when the file has none.
    """
    key = str(source)
    bench_data: Any  # the [bench] table as read, checked below
    if key in STAGED_SLOT_VALVES:
        pset = parameter_set(STAGED_SLOT_VALVES[key])
        values, bench_data, where = pset.table("valve"), pset.table("bench"), f"built-in {key}"
    else:
        if not Path(key).exists() and not key.lower().endswith(".toml"):
            raise ParameterError(
                f"staged-slot valve {key!r}: neither a TOML file nor a built-in valve ({', '.join(STAGED_SLOT_VALVES)})"
            )
        data = read_toml(key, "component file")
        values, bench_data, where = _component_table(data, key), data.get("bench"), key
        kind = values.pop("type")
        if REGISTRY.resolve(kind) is not StagedSlotValve:
            raise ParameterError(f"staged-slot valve {key!r}: type = {kind!r}; expected 'StagedSlotValve'")
    valve = StagedSlotValve("valve", **values)
    valve.check()
    if bench_data is not None and not isinstance(bench_data, dict):
        raise ParameterError(f"staged-slot valve {where}: [bench] must be a table (P_s, X_n, ...)")
    bench = None if bench_data is None else Bench.from_mapping(bench_data, where=f"{where} [bench]")
    return valve, bench


def staged_slot_valve_toml(valve: StagedSlotValve, bench: Bench | None, header: str = "") -> str:
    """A ``StagedSlotValve`` component file with its ``[bench]`` table (SI values with units)."""
    return component_file_text(
        valve,
        list(BRIDGE_PARAMETERS),
        header=header,
        extra=None if bench is None else {"bench": bench.to_mapping()},
    )
