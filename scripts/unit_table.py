"""Write (or check) ``src/hydroservo/data/units.json``: the unit conversions the package ships.

Run: ``python scripts/unit_table.py`` to rewrite the table, ``--check`` to exit 1
if it is stale (the tests do the same check).

The table holds every unit that:

* a component declares (parameters, states, algebraic unknowns, inputs, outputs);
* the package's own files write (``"1500 psi"`` values, ``unit``/``units`` keys);
* the built-in models' states, outputs and parameters carry (a gain's ``V/m``);
* :data:`hydroservo.units.COMMON_UNITS` lists;

and the coherent unit of each. Each entry is computed by pint
(:func:`hydroservo.units.pint_entry`): the table is a cache of pint's answers,
never a second source of them.
"""

from __future__ import annotations

import json
import sys
import tomllib
from collections.abc import Iterator
from importlib import resources
from pathlib import Path
from typing import Any

import pint

from hydroservo.components import REGISTRY
from hydroservo.data import model_names
from hydroservo.errors import UnitError
from hydroservo.io.model_file import load_model
from hydroservo.units import COMMON_UNITS, coherent_unit, pint_entry, split_quantity

TABLE = Path(__file__).resolve().parents[1] / "src" / "hydroservo" / "data" / "units.json"


def _file_units(value: Any, key: str = "") -> Iterator[str]:
    """Units written in a TOML value of the package's files."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _file_units(v, k)
    elif isinstance(value, list):
        for v in value:
            yield from _file_units(v, key)
    elif isinstance(value, str):
        if key in ("unit", "units") or key.endswith("_unit"):
            yield value
            return
        try:
            _, unit = split_quantity(value)
        except Exception:  # not a quantity: a name, a path, an expression
            return
        if unit and not any(c in unit for c in "=,;[]"):
            yield unit


def collect() -> list[str]:
    """Every unit the table must hold, sorted."""
    found = set(COMMON_UNITS)
    for cls in REGISTRY.types.values():
        for table in (cls.PARAMETERS, cls.STATES, cls.ALGEBRAIC, cls.INPUTS, cls.OUTPUTS):
            found.update(spec.unit for spec in table.values())
    root = resources.files("hydroservo.data")
    for folder in ("models", "parameters", "examples"):
        for entry in (root / folder).iterdir():
            if entry.name.endswith(".toml"):
                found.update(_file_units(tomllib.loads(entry.read_text(encoding="utf-8"))))
    for name in model_names():  # units components take from their use (a gain's V/m, a signal's mm)
        model = load_model(name).build()
        found.update(model.units.values())
        found.update(model.parameter_units.values())
    usable = set()
    for unit in found:
        try:  # text that only looked like a quantity ("2 * load.x"), or a unit pint cannot convert alone (an
            usable.update((unit, coherent_unit(unit)))  # offset unit in a product): left to pint at run time
        except UnitError:
            continue
    return sorted(usable)


def table() -> dict[str, Any]:
    return {"pint": pint.__version__, "units": {u: pint_entry(u) for u in collect()}}


def main(argv: list[str]) -> int:
    fresh = table()
    if "--check" in argv:
        shipped = json.loads(TABLE.read_text(encoding="utf-8"))
        stale = sorted(set(fresh["units"]) ^ set(shipped["units"]))
        if stale:
            print(f"{TABLE}: stale; units missing or extra: {', '.join(stale)}; run python scripts/unit_table.py")
            return 1
        print(f"{TABLE}: {len(shipped['units'])} units, up to date")
        return 0
    TABLE.write_text(json.dumps(fresh, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    print(f"wrote {TABLE}: {len(fresh['units'])} units")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
