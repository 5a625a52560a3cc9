"""Units at the edges, SI inside.

Every dimensional value that enters hydroservo from a user (a model file, the
``--set`` option, a keyword argument given as a string) passes through
:func:`to_si`, which checks its dimension against the one the parameter
declares and returns a plain float in SI base units.  Inside the package all
numbers are SI floats; only results and files carry unit names again.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import pint

from hydroservo.errors import UnitError

__all__ = ["ureg", "to_si", "from_si", "si_unit", "format_quantity", "parse_quantity"]

ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
# Hydraulic shorthands that pint does not define under these names.
ureg.define("lpm = liter / minute = L_min")
ureg.define("cps = hertz")


@functools.lru_cache(maxsize=512)
def _unit(unit: str) -> pint.Unit:
    try:
        return ureg.Unit(unit)
    except Exception as exc:  # pint raises several exception types
        raise UnitError(f"unknown unit {unit!r}: {exc}") from None


def parse_quantity(value: Any, *, what: str = "value") -> pint.Quantity:
    """Read ``value`` (number, ``"1500 psi"``, pint quantity) as a quantity."""
    if isinstance(value, pint.Quantity):
        return value
    if isinstance(value, bool):
        raise UnitError(f"{what}: expected a number or a quantity such as '3 bar', got {value!r}")
    if isinstance(value, (int, float)):
        return ureg.Quantity(float(value), "")
    if isinstance(value, str):
        text = value.strip()
        try:
            q = ureg.Quantity(text)
        except Exception as exc:
            raise UnitError(
                f"{what}: cannot read {value!r} as a quantity ({exc}); "
                "expected a number followed by a unit, e.g. '1500 psi' or '25.5 L/min'"
            ) from None
        if not isinstance(q, pint.Quantity):  # a bare number in a string
            q = ureg.Quantity(float(q), "")
        return q
    raise UnitError(f"{what}: expected a number or a quantity such as '3 bar', got {value!r}")


def to_si(value: Any, unit: str, *, what: str = "value") -> float:
    """Convert ``value`` to the SI magnitude of ``unit``'s dimension.

    Parameters
    ----------
    value : float, str or pint.Quantity
        A bare number (also in a string, ``"0.5"``) is taken to be already in
        the SI unit ``unit``; a quantity such as ``"1500 psi"`` is converted.
    unit : str
        The SI unit expected, e.g. ``"Pa"``, ``"m^3/s"``, ``""`` for dimensionless.
    what : str
        Name of the parameter, used in error messages.

    Returns
    -------
    float
        Magnitude in ``unit``.
    """
    q = parse_quantity(value, what=what)
    target = _unit(unit)
    if q.unitless:  # a bare number, given as such or in a string, is SI
        return float(q.magnitude)
    try:
        out = float(q.to(target).magnitude)
    except pint.DimensionalityError:
        expected = "dimensionless" if target.dimensionless else f"{target:~P} ({ureg.get_dimensionality(target)})"
        raise UnitError(f"{what}: {value!r} has the wrong dimension; expected {expected}") from None
    if math.isnan(out):
        raise UnitError(f"{what}: {value!r} is not a number")
    return out


def from_si(value: float, unit: str, to: str) -> float:
    """Convert an SI magnitude in ``unit`` to unit ``to``."""
    return float(ureg.Quantity(value, _unit(unit)).to(_unit(to)).magnitude)


def si_unit(unit: str) -> str:
    """Short printable form of a unit string (``"m^3/s"`` -> ``"m³/s"``)."""
    if unit == "":
        return "-"
    return f"{_unit(unit):~P}"


def format_quantity(value: float, unit: str) -> str:
    """``value`` and ``unit`` as a string that :func:`to_si` reads back exactly."""
    if unit == "":
        return repr(float(value))
    return f"{float(value)!r} {unit}"
