"""Units at the edges, SI inside.

Every dimensional value that enters hydroservo from a user (a model file, the
``--set`` option, a keyword argument given as a string) passes through
:func:`to_si`, which checks its dimension against the one the parameter
declares and returns a plain float in SI base units. Inside the package all
numbers are SI floats; only results and files carry unit names again.

The unit registry (pint) is built on first use, not on import: a bare number
never needs it, so ``import hydroservo`` and the command line's ``--help``
stay fast. ``hydroservo.units.ureg`` is that registry.

Quantity strings are read by a small grammar before pint sees them, so that no
input can make the parser evaluate unbounded arithmetic (pint alone would
evaluate ``"10**10**10 kg"`` and never return): a quantity is one finite
number followed by a unit; a unit is names (``psi``, ``L``, ``degC``, ``%``),
numbers as factors (``1/s``), ``*``, ``/``, ``^`` or ``**`` with a plain
exponent of magnitude at most 12, and parentheses nested at most 4 deep;
200 characters at most.
"""

from __future__ import annotations

import functools
import math
import re
from typing import TYPE_CHECKING, Any

from hydroservo.errors import UnitError, shorten

if TYPE_CHECKING:
    import pint

__all__ = [
    "VACUUM",
    "ABSOLUTE_ZERO",
    "registry",
    "to_si",
    "from_si",
    "si_unit",
    "format_quantity",
    "parse_quantity",
    "is_bare_number",
    "TEMPERATURE_UNITS",
    "split_quantity",
    "check_unit",
    "same_dimension",
]

#: Gauge pressure of a perfect vacuum [Pa]: pressures are gauge inside hydroservo, and none lies below this.
VACUUM = -101325.0
#: Absolute zero in degrees Celsius, the unit of temperatures inside hydroservo: none lies at or below it.
ABSOLUTE_ZERO = -273.15


@functools.cache
def registry() -> pint.UnitRegistry:
    """The unit registry, built on first use (about 0.3 s: pint and its definitions)."""
    import pint

    reg: pint.UnitRegistry[Any] = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    # Hydraulic shorthands that pint does not define under these names.
    reg.define("lpm = liter / minute = L_min")
    reg.define("cps = hertz")
    reg.define("rev = revolution")
    # Absolute pressures (hydroservo's pressures are gauge): the atmosphere is 101325 Pa.
    reg.define("Pa_abs = Pa; offset: -101325")
    reg.define("bar_abs = 100000 * Pa; offset: -101325 = bara")
    reg.define("psia = 6894.757293168361 * Pa; offset: -101325")
    return reg


def __getattr__(name: str) -> Any:
    if name == "ureg":
        return registry()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: The longest quantity or unit text read [characters].
MAX_TEXT = 200
#: The largest exponent a unit may carry (``m^3``, ``Pa^0.5``).
MAX_EXPONENT = 12
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_TOKEN = re.compile(r"\s+|\*\*|\^|\*|/|\(|\)|[-+]|(?:\d+\.?\d*|\.\d+)|[^\W\d][\w°µΩ]*|[%°µΩ]")


def _unit_tokens(unit: str) -> list[str]:
    """The tokens of a unit text, or a UnitError if it is not a unit of the grammar (module notes)."""
    if len(unit) > MAX_TEXT:
        raise UnitError(f"unit {unit[:40]!r}...: {len(unit)} characters; expected at most {MAX_TEXT}")
    tokens: list[str] = []
    pos = 0
    while pos < len(unit):
        match = _TOKEN.match(unit, pos)
        if match is None:
            raise UnitError(f"unit {unit!r}: unexpected {unit[pos]!r} at character {pos + 1}")
        if not match.group().isspace():
            tokens.append(match.group())
        pos = match.end()
    depth = 0
    for i, tok in enumerate(tokens):
        if tok in ("-", "+") and (i == 0 or tokens[i - 1] not in ("**", "^")):
            raise UnitError(f"unit {unit!r}: a sign may stand only before an exponent")
        depth += (tok == "(") - (tok == ")")
        if depth < 0 or depth > 4:
            raise UnitError(f"unit {unit!r}: unbalanced or too deeply nested parentheses")
        if tok in ("**", "^"):
            rest = tokens[i + 1 : i + 3]
            sign = bool(rest) and rest[0] in ("-", "+")
            exponent = rest[1] if sign and len(rest) > 1 else (rest[0] if rest else "")
            follows = tokens[i + 3] if sign and len(tokens) > i + 3 else (tokens[i + 2] if len(tokens) > i + 2 else "")
            if not _NUMBER.fullmatch(exponent) or abs(float(exponent)) > MAX_EXPONENT or follows in ("**", "^"):
                raise UnitError(
                    f"unit {unit!r}: expected a plain exponent of magnitude at most {MAX_EXPONENT} after {tok!r}"
                )
    if depth != 0:
        raise UnitError(f"unit {unit!r}: unbalanced parentheses")
    for i, tok in enumerate(tokens):  # a number is an exponent, or a factor joined by * or /: never a second quantity
        if _NUMBER.fullmatch(tok) and not (i > 0 and tokens[i - 1] in ("**", "^", "-", "+")):
            before = tokens[i - 1] if i > 0 else None
            after = tokens[i + 1] if i + 1 < len(tokens) else None
            if before not in (None, "(", "*", "/") or after not in (None, ")", "*", "/") or before == after is None:
                raise UnitError(f"unit {unit!r}: the number {tok!r} stands alone; expected one number, then a unit")
    return tokens


@functools.lru_cache(maxsize=512)
def _unit(unit: str) -> pint.Unit:
    _unit_tokens(unit)
    try:
        return registry().Unit(unit)
    except Exception as exc:  # pint raises several exception types
        raise UnitError(f"unknown unit {unit!r}: {exc}") from None


def check_unit(unit: str) -> None:
    """Raise :class:`UnitError` unless ``unit`` is a unit ("" is dimensionless)."""
    if unit:
        _unit(unit)


def same_dimension(a: str, b: str) -> bool:
    """Whether units ``a`` and ``b`` have the same dimension ("" for dimensionless)."""
    if a == b:
        return True
    return bool(_unit(a).dimensionality == _unit(b).dimensionality)


def is_bare_number(value: Any) -> bool:
    """True for a number, or a string holding only a number (``"0.5"``)."""
    if isinstance(value, bool):
        return False
    if isinstance(value, (int, float)):
        return True
    if isinstance(value, str):
        try:
            float(value)
        except ValueError:
            return False
        return True
    return False


def split_quantity(text: str, *, what: str = "value") -> tuple[float, str]:
    """``"1500 psi"`` -> ``(1500.0, "psi")``: a finite number and the unit text after it (module notes)."""
    stripped = text.strip()
    if len(stripped) > MAX_TEXT:
        raise UnitError(f"{what}: {stripped[:40]!r}... has {len(stripped)} characters; expected at most {MAX_TEXT}")
    match = _NUMBER.match(stripped)
    if match is None:
        raise UnitError(
            f"{what}: cannot read {shorten(text)!r} as a quantity; expected a number followed by a unit, "
            "e.g. '1500 psi' or '25.5 L/min'"
        )
    magnitude = float(match.group())
    if not math.isfinite(magnitude):
        raise UnitError(f"{what}: {text!r}: the number is not finite; expected a finite number")
    return magnitude, stripped[match.end() :].strip()


def parse_quantity(value: Any, *, what: str = "value") -> pint.Quantity:
    """Read ``value`` (number, ``"1500 psi"``, pint quantity) as a quantity."""
    reg = registry()
    if isinstance(value, reg.Quantity):
        return value
    if isinstance(value, bool):
        raise UnitError(f"{what}: expected a number or a quantity such as '3 bar', got {value!r}")
    if isinstance(value, (int, float)):
        return reg.Quantity(float(value), "")
    if isinstance(value, str):
        magnitude, unit = split_quantity(value, what=what)
        try:
            q: pint.Quantity[Any] = reg.Quantity(magnitude, _unit(unit) if unit else "")
        except UnitError as exc:
            raise UnitError(
                f"{what}: cannot read {shorten(value)!r} as a quantity ({exc}); expected a number followed by a unit, "
                "e.g. '1500 psi'"
            ) from None
        if not isinstance(q, reg.Quantity):  # a bare number in a string
            q = reg.Quantity(float(q), "")
        return q
    raise UnitError(f"{what}: expected a number or a quantity such as '3 bar', got {value!r}")


#: Absolute-pressure units (offset from hydroservo's gauge pressures by the atmosphere).
ABSOLUTE_PRESSURE_UNITS = ("Pa_abs", "bar_abs", "bara", "psia")


def is_absolute_pressure(unit: str) -> bool:
    """True if ``unit`` names an absolute pressure (``"bar_abs"``): a value, not a unit a signal can be carried in."""
    return any(token in ABSOLUTE_PRESSURE_UNITS for token in re.findall(r"[A-Za-z_]+", unit))


#: Units of temperature parameters (kept in degC inside): a value for one must carry its unit.
TEMPERATURE_UNITS = ("degC",)


def to_si(value: Any, unit: str, *, what: str = "value") -> float:
    """Convert ``value`` to the SI magnitude of ``unit``'s dimension.

    Parameters
    ----------
    value : float, str or pint.Quantity
        A bare number (also in a string, ``"0.5"``) is taken to be already in
        the SI unit ``unit``; a quantity such as ``"1500 psi"`` is converted.
        A temperature (``unit`` degC) has no bare number: ``"40 degC"`` or
        ``"313.15 K"``, never ``40``, which SI would read as kelvin.
    unit : str
        The SI unit expected, e.g. ``"Pa"``, ``"m^3/s"``, ``""`` for dimensionless.
    what : str
        Name of the parameter, used in error messages.

    Returns
    -------
    float
        Magnitude in ``unit``.

    Examples
    --------
    >>> round(to_si("1500 psi", "Pa"))
    10342136
    >>> to_si(0.5, "m")
    0.5
    """
    if is_bare_number(value):  # a bare number, given as such or in a string, is SI: no registry needed
        if unit in TEMPERATURE_UNITS:
            raise UnitError(
                f"{what}: {value!r}: a temperature needs its unit, e.g. '{value} degC' or '{value} K' (bare numbers "
                "are SI, and kelvin is rarely what is meant)"
            )
        out = float(value)
        if math.isnan(out):
            raise UnitError(f"{what}: {value!r} is not a number")
        return out
    q = parse_quantity(value, what=what)
    target = _unit(unit)
    if str(q.units) == "dimensionless":  # no unit at all (a percent is a unit: "5 %" is 0.05)
        return float(q.magnitude)
    try:
        out = float(q.to(target).magnitude)
    except Exception as exc:  # pint.DimensionalityError
        if type(exc).__name__ != "DimensionalityError":
            raise
        expected = (
            "dimensionless" if target.dimensionless else f"{target:~P} ({registry().get_dimensionality(target)})"
        )
        raise UnitError(f"{what}: {value!r} has the wrong dimension; expected {expected}") from None
    if math.isnan(out):
        raise UnitError(f"{what}: {value!r} is not a number")
    return out


def from_si(value: float, unit: str, to: str) -> float:
    """Convert an SI magnitude in ``unit`` to unit ``to``; a UnitError if their dimensions differ."""
    if unit == to:
        return float(value)
    source, target = _unit(unit), _unit(to)
    try:
        return float(registry().Quantity(value, source).to(target).magnitude)
    except Exception as exc:  # pint.DimensionalityError, offset-unit errors
        raise UnitError(f"cannot express {si_unit(unit)} in {to!r}: {type(exc).__name__}") from None


#: Coherent SI units by name, for :func:`coherent_unit` to prefer over pint's base-unit products.
_COHERENT = ("m", "Pa", "N", "m^3/s", "m/s", "m/s^2", "m^3", "m^2", "s", "kg", "A", "V", "ohm", "N*m", "rad/s", "W", "J")


@functools.lru_cache(maxsize=512)
def coherent_unit(unit: str) -> str:
    """The coherent SI unit of ``unit``'s dimension, in which hydroservo carries a signal inside.

    ``"mm"`` -> ``"m"``, ``"bar"`` -> ``"Pa"``, ``"L/min"`` -> ``"m^3/s"``; a unit
    that is coherent already (``"V"``, ``"N*m"``, ``"V/m"``) and temperatures
    (``"degC"``, the package's convention) are returned as given.

    Examples
    --------
    >>> coherent_unit("mm"), coherent_unit("bar"), coherent_unit("V/m"), coherent_unit("")
    ('m', 'Pa', 'V/m', '')
    """
    if unit == "" or unit in ("degC", "degF", "K"):
        return unit
    u = _unit(unit)
    base = (1.0 * u).to_base_units()
    if abs(base.magnitude - 1.0) < 1e-12:
        return unit
    factors = list(u._units.items())  # a product of units: make each coherent
    if len(factors) > 1 or (factors and factors[0][1] != 1):
        parts = [(coherent_unit(name), exp) for name, exp in factors]
        parts = [(name, exp) for name, exp in parts if name]  # a percent is a pure number
        return "*".join(name + ("" if exp == 1 else f"^{exp:g}") for name, exp in parts)
    dims = registry().get_dimensionality(u)
    for name in _COHERENT:
        if registry().get_dimensionality(_unit(name)) == dims:
            return name
    return f"{base.units:~C}".replace("**", "^")


@functools.lru_cache(maxsize=512)
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
