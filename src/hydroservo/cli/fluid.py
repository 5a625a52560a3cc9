"""``hydroservo fluid``: quick look-ups of fluid properties (thin shell over :mod:`hydroservo.fluids`)."""

from __future__ import annotations

import argparse
import json
import warnings
from typing import Any

from hydroservo.errors import ParameterError
from hydroservo.units import from_si, parse_quantity, to_si

__all__ = ["add_parsers"]

#: Display units of each property.
_SHOW = {
    "density": "kg/m^3",
    "specific_volume": "L/kg",
    "kinematic_viscosity": "cSt",
    "dynamic_viscosity": "mPa*s",
    "bulk_modulus": "MPa",
}


def _values(text: str, unit: str, default_unit: str, what: str) -> list[float]:
    """Comma-separated values; a unit written once at the end applies to all bare numbers."""
    items = [t.strip() for t in text.split(",") if t.strip()]
    if not items:
        raise ParameterError(f"{what} {text!r}: expected comma-separated values, e.g. '-40,20,70' or '0,30 MPa'")
    trailing = default_unit
    last = items[-1].split(maxsplit=1)
    if len(last) == 2:
        trailing = last[1]
    out = []
    for item in items:
        q = item if len(item.split(maxsplit=1)) == 2 else f"{item} {trailing}"
        try:
            if unit == "degC":
                out.append(float(parse_quantity(q, what=what).to("degC").magnitude))
            else:
                out.append(to_si(q, unit, what=what))
        except ParameterError:
            raise
        except Exception as exc:  # pint: dimensionality, parsing
            raise ParameterError(f"{what} {item!r}: {exc}") from None
    return out


def cmd_fluid(args: argparse.Namespace) -> int:
    import numpy as np

    from hydroservo.fluids import PROPERTIES, get_fluid

    fluid = get_fluid(args.fluid)
    props = list(PROPERTIES) if args.property == "all" else [args.property.replace("-", "_")]
    for p in props:
        if p not in PROPERTIES:
            raise ParameterError(f"property {args.property!r}: expected one of {', '.join(PROPERTIES)} or all")
    temps = _values(args.temperature, "degC", "degC", "--temperature")
    press = _values(args.pressure, "Pa", "Pa", "--pressure")
    T, P = np.meshgrid(temps, press, indexing="ij")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            fluid.check_range(P, T, strict=args.strict)
        except ParameterError as exc:
            raise ParameterError(f"--temperature {args.temperature!r}, --pressure {args.pressure!r}: {exc}") from None
    with np.errstate(all="ignore"):
        values = {p: np.asarray(getattr(fluid, p)(P, T), dtype=float) for p in props}
    for p in props:
        bad = ~np.isfinite(values[p]) | (values[p] <= 0)
        if bad.any():
            i, j = np.argwhere(bad)[0]
            raise ParameterError(
                f"fluid {fluid.name!r}: no physical {p.replace('_', ' ')} at {temps[i]:g} degC and {press[j]:g} Pa "
                f"(the model gives {values[p][i, j]:g}); --temperature and --pressure are far outside its range"
            )
    shown = {p: values[p] * from_si(1.0, PROPERTIES[p], _SHOW[p]) for p in props}
    if args.json:
        rows: list[dict[str, Any]] = []
        for i, t in enumerate(temps):
            for j, pr in enumerate(press):
                rows.append({"temperature_degC": t, "pressure_Pa": pr, **{p: float(shown[p][i, j]) for p in props}})
        print(
            json.dumps(
                {
                    "fluid": fluid.name,
                    "description": fluid.description,
                    "units": {p: _SHOW[p] for p in props},
                    "values": rows,
                    "warnings": [str(w.message) for w in caught],
                },
                indent=2,
            )
        )
        return 0
    print(f"{fluid.name}: {fluid.description}")
    head = ["T [degC]", "p [MPa]"] + [f"{p} [{_SHOW[p]}]" for p in props]
    print("  ".join(f"{h:>14}" for h in head))
    for i, t in enumerate(temps):
        for j, pr in enumerate(press):
            cells = [f"{t:>14g}", f"{pr / 1e6:>14g}"] + [f"{shown[p][i, j]:>14.5g}" for p in props]
            print("  ".join(cells))
    for w in caught:
        print(f"warning: {w.message}")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``fluid``."""
    p = sub.add_parser("fluid", help="fluid properties against temperature and pressure (skydrol, iso-vg32, iso-vg46)")
    p.add_argument(
        "property", help="density, specific-volume, kinematic-viscosity, dynamic-viscosity, bulk-modulus or all"
    )
    p.add_argument("--fluid", default="skydrol", help="built-in fluid (default skydrol)")
    p.add_argument(
        "--temperature", default="20", metavar="T,...", help="temperatures; bare numbers in degC (default 20)"
    )
    p.add_argument(
        "--pressure",
        default="0",
        metavar="P,...",
        help="gauge pressures; bare numbers in Pa, or a unit once at the end: '0,10,30 MPa' (default 0)",
    )
    p.add_argument(
        "--strict", action="store_true", help="refuse values outside the fluid model's range (default: warn)"
    )
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fluid)
