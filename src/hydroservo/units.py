"""Units at the edges, SI inside.

Every dimensional value that enters hydroservo from a user (a model file, the
``--set`` option, a keyword argument given as a string) passes through
:func:`to_si`, which checks its dimension against the one the parameter
declares and returns a plain float in SI base units. Inside the package all
numbers are SI floats; only results and files carry unit names again.

The unit registry (pint) is built on first use, not on import: a bare number
never needs it, so ``import hydroservo`` and the command line's ``--help``
stay fast. ``hydroservo.units.ureg`` is that registry.

Nor does a unit the package knows: the conversions of every unit its
components declare, its own files use, and engineers commonly write
(:data:`COMMON_UNITS`) ship in ``data/units.json``, computed by pint and
checked against it by the tests (``scripts/unit_table.py`` writes it). A
conversion between two such units, a dimension check of an alias and the
printed form of a unit read the table; anything else (and every error
message) goes to pint. A command-line run thus never builds the registry
(about 0.3 s) for the built-in models.

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

from hydroservo.errors import UnitError, did_you_mean, shorten

if TYPE_CHECKING:
    import pint

__all__ = [
    "VACUUM",
    "convert",
    "ABSOLUTE_ZERO",
    "registry",
    "unit_table",
    "to_si",
    "from_si",
    "si_unit",
    "si_definition",
    "SI_BASE",
    "format_quantity",
    "parse_quantity",
    "is_bare_number",
    "plain_number",
    "TEMPERATURE_UNITS",
    "split_quantity",
    "check_unit",
    "same_dimension",
    "COMMON_UNITS",
    "Dimension",
    "dimension",
    "pint_entry",
    "QUANTITIES",
    "UnitChoice",
    "inferred_units",
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
    reg.define("rev = revolution")
    reg.define("gpm = gallon / minute")  # US gallons
    # Absolute pressures (hydroservo's pressures are gauge): the atmosphere is 101325 Pa.
    reg.define("Pa_abs = Pa; offset: -101325")
    reg.define("bar_abs = 100000 * Pa; offset: -101325 = bara")
    reg.define("psia = 6894.757293168361 * Pa; offset: -101325")
    return reg


def __getattr__(name: str) -> Any:
    if name == "ureg":
        return registry()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: Units engineers commonly write, shipped with their conversions beside the units the package itself uses.
COMMON_UNITS = (
    # pressure
    "Pa", "kPa", "MPa", "GPa", "bar", "mbar", "psi", "ksi", "atm", "Pa_abs", "bar_abs", "bara", "psia",
    # flow and displacement
    "m^3/s", "L/min", "l/min", "lpm", "L/s", "cm^3/s", "mm^3/s", "in^3/s", "gpm", "m^3/rev", "cm^3/rev", "in^3/rev",
    # length, area, volume
    "m", "cm", "mm", "um", "µm", "in", "ft", "m^2", "cm^2", "mm^2", "in^2", "m^3", "L", "l", "mL", "cm^3", "mm^3",
    "in^3", "gal",
    # mass, force, torque, stiffness, damping, inertia
    "kg", "g", "t", "lb", "N", "kN", "lbf", "N*m", "kN*m", "lbf*in", "N/m", "kN/m", "N/mm", "lbf/in", "N*s/m",
    "kN*s/m", "lbf*s/in", "kg*m^2",
    # time, frequency, speed, acceleration
    "s", "ms", "us", "µs", "min", "h", "Hz", "kHz", "rad/s", "rpm", "1/s", "m/s", "mm/s", "in/s", "m/s^2",
    # angle
    "rad", "deg", "mrad",
    # temperature
    "degC", "degF", "K",
    # fluid properties
    "kg/m^3", "g/cm^3", "cSt", "mm^2/s", "m^2/s", "Pa*s", "mPa*s", "cP", "1/Pa", "1/bar", "1/K",
    # electrics
    "A", "mA", "V", "mV", "ohm", "W", "kW", "J",
    # orifice coefficients
    "m^3/s/Pa^0.5", "L/min/bar^0.5", "m^3/s/Pa", "L/min/bar", "m^2/s/Pa^0.5",
    # pure numbers
    "%", "",
)  # fmt: skip

#: A shipped unit: factor and offset to the SI base unit, dimension, coherent unit, printed form.
Shipped = tuple[float, float, tuple[tuple[str, float], ...], str, str]


@functools.cache
def unit_table() -> dict[str, Any]:
    """``data/units.json``: ``{"pint": version, "units": {text: {factor, offset, dimension, coherent, printed}}}``.

    This module is its one reader (a package resource; :mod:`hydroservo.data`, which converts parameter sets
    with :func:`to_si`, is not imported for it: the two would import each other).
    """
    import json
    from importlib import resources

    return dict(json.loads(resources.files("hydroservo").joinpath("data", "units.json").read_text(encoding="utf-8")))


@functools.cache
def _shipped() -> dict[str, Shipped]:
    """The conversions of ``data/units.json`` (module notes), by unit text."""
    return {
        text: (e["factor"], e["offset"], tuple((d, float(x)) for d, x in e["dimension"]), e["coherent"], e["printed"])
        for text, e in unit_table()["units"].items()
    }


def pint_entry(unit: str) -> dict[str, Any]:
    """What ``data/units.json`` records of ``unit``, computed by pint (``scripts/unit_table.py``, the tests)."""
    u = _unit(unit) if unit else registry().Unit("")
    reg = registry()
    zero = float(reg.Quantity(0.0, u).to_base_units().magnitude)
    one = float(reg.Quantity(1.0, u).to_base_units().magnitude)
    dims = sorted((str(d), float(x)) for d, x in reg.get_dimensionality(u).items())  # type: ignore[arg-type]
    return {
        "factor": one - zero,
        "offset": zero,
        "dimension": [list(d) for d in dims],
        "coherent": _coherent_pint(unit),
        "printed": _printed_pint(unit),
    }


class Dimension:
    """A quantity of magnitude one reduced to its dimension, for checking expressions without the registry.

    Arithmetic as on pint quantities: numbers are dimensionless, a sum needs
    like dimensions (a ``ValueError`` otherwise), a power takes a number.
    """

    __slots__ = ("exponents",)

    def __init__(self, exponents: Any = ()) -> None:
        self.exponents: tuple[tuple[str, float], ...] = tuple(sorted((d, x) for d, x in dict(exponents).items() if x))

    @staticmethod
    def of(value: Any) -> Dimension:
        if isinstance(value, Dimension):
            return value
        if isinstance(value, (int, float)):
            return Dimension()
        raise TypeError(f"not a number or a dimension: {value!r}")

    def _combine(self, other: Any, sign: float) -> Dimension:
        exps = dict(self.exponents)
        for d, x in Dimension.of(other).exponents:
            exps[d] = exps.get(d, 0.0) + sign * x
        return Dimension(exps)

    def __add__(self, other: Any) -> Dimension:
        if Dimension.of(other).exponents != self.exponents:
            raise ValueError(f"cannot add {self} and {Dimension.of(other)}")
        return self

    __radd__ = __sub__ = __rsub__ = __add__

    def __mul__(self, other: Any) -> Dimension:
        return self._combine(other, 1.0)

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> Dimension:
        return self._combine(other, -1.0)

    def __rtruediv__(self, other: Any) -> Dimension:
        return Dimension.of(other)._combine(self, -1.0)

    def __pow__(self, exponent: Any) -> Dimension:
        if not isinstance(exponent, (int, float)):
            raise TypeError("an exponent of a dimension check must be a number")
        return Dimension({d: x * exponent for d, x in self.exponents})

    def __neg__(self) -> Dimension:
        return self

    __pos__ = __neg__

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Dimension) and other.exponents == self.exponents

    def __hash__(self) -> int:
        return hash(self.exponents)

    def __repr__(self) -> str:
        return " * ".join(f"{d}^{x:g}" for d, x in self.exponents) or "dimensionless"


def dimension(unit: str) -> Dimension | None:
    """The dimension of ``unit`` from the shipped table, or None if the table does not hold it."""
    known = _shipped().get(unit)
    return None if known is None else Dimension(known[2])


#: The longest quantity or unit text read [characters].
MAX_TEXT = 200
#: The largest exponent a unit may carry (``m^3``, ``Pa^0.5``).
MAX_EXPONENT = 12
_NUMBER = re.compile(r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")
_TOKEN = re.compile(r"\s+|\*\*|\^|\*|/|\(|\)|[-+]|(?:[0-9]+\.?[0-9]*|\.[0-9]+)|[^\W\d][\w°µΩ]*|[%°µΩ]")


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
        detail = "" if f"{unit!r} is not defined" in str(exc) else f": {exc}"  # pint's words where they add a part
        raise UnitError(f"unknown unit {unit!r}{did_you_mean(unit, _shipped())}{detail}") from None


def check_unit(unit: str) -> None:
    """Raise :class:`UnitError` unless ``unit`` is a unit ("" is dimensionless)."""
    if unit and unit not in _shipped():
        _unit(unit)


def same_dimension(a: str, b: str) -> bool:
    """Whether units ``a`` and ``b`` have the same dimension ("" for dimensionless)."""
    if a == b:
        return True
    known_a, known_b = _shipped().get(a), _shipped().get(b)
    if known_a is not None and known_b is not None:
        return known_a[2] == known_b[2]
    return bool(_unit(a).dimensionality == _unit(b).dimensionality)


def plain_number(text: str) -> float | None:
    """The number a text holds as a plain decimal (``"0.5"``, ``" -1.5e-3 "``, ``"inf"``, ``"nan"``), else None.

    Python's ``float`` also takes digit groups (``"2_0.0"`` is 20) and digits of other scripts (``"٢٠"``); a
    value in a file or an option is a plain decimal, so neither is a number here.

    >>> plain_number("2.5e3"), plain_number("2_0.0"), plain_number("20 kg"), plain_number(" -inf ")
    (2500.0, None, None, -inf)
    """
    stripped = text.strip()
    try:
        value = float(stripped)
    except ValueError:
        return None
    if "_" in stripped or not stripped.isascii():
        return None
    return value


def is_bare_number(value: Any) -> bool:
    """True for a number, or a string holding only a plain decimal number (``"0.5"``; :func:`plain_number`)."""
    if isinstance(value, bool):
        return False
    if isinstance(value, (int, float)):
        return True
    if isinstance(value, str):
        return plain_number(value) is not None
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
    if stripped[match.end() : match.end() + 1] == "_":
        raise UnitError(
            f"{what}: {shorten(text)!r}: digits grouped with '_' are not read; expected a plain number, "
            "e.g. '20.0 kg' or '1500 psi'"
        )
    magnitude = float(match.group())
    if not math.isfinite(magnitude):
        raise UnitError(f"{what}: {text!r}: the number is not finite; expected a finite number")
    return magnitude, stripped[match.end() :].strip()


def parse_quantity(value: Any, *, what: str = "value") -> pint.Quantity:
    """Read ``value`` (number, ``"1500 psi"``, pint quantity) as a quantity."""
    if isinstance(value, str):  # text that is no quantity is refused before the registry is built
        magnitude, unit = split_quantity(value, what=what)
        try:
            parsed = _unit(unit) if unit else ""
            q: pint.Quantity[Any] = registry().Quantity(magnitude, parsed)
        except UnitError as exc:
            raise UnitError(
                f"{what}: cannot read {shorten(value)!r} as a quantity ({exc}); expected a number followed by a unit, "
                "e.g. '1500 psi'"
            ) from None
        if not isinstance(q, registry().Quantity):  # a bare number in a string
            q = registry().Quantity(float(q), "")
        return q
    reg = registry()
    if isinstance(value, reg.Quantity):
        return value
    if isinstance(value, bool):
        raise UnitError(f"{what}: expected a number or a quantity such as '3 bar', got {value!r}")
    if isinstance(value, (int, float)):
        return reg.Quantity(float(value), "")
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
        out = float(value) if not isinstance(value, str) else plain_number(value)
        if out is None or math.isnan(out):
            raise UnitError(f"{what}: {value!r} is not a number")
        return out
    if isinstance(value, str):  # two shipped units of one dimension: no registry (module notes)
        magnitude, text = split_quantity(value, what=what)
        source, target_known = _shipped().get(text), _shipped().get(unit)
        if text and source is not None and target_known is not None and source[2] == target_known[2]:
            return (magnitude * source[0] + source[1] - target_known[1]) / target_known[0]
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
    known_source, known_target = _shipped().get(unit), _shipped().get(to)
    if known_source is not None and known_target is not None and known_source[2] == known_target[2]:
        return (float(value) * known_source[0] + known_source[1] - known_target[1]) / known_target[0]
    source, target = _unit(unit), _unit(to)
    try:
        return float(registry().Quantity(value, source).to(target).magnitude)
    except Exception as exc:  # pint.DimensionalityError, offset-unit errors
        raise UnitError(f"cannot express {si_unit(unit)} in {to!r}: {type(exc).__name__}") from None


def convert(values: Any, unit: str, to: str) -> Any:
    """``values`` (a number or an array) in ``unit`` expressed in ``to``, offsets included: the conversion is
    linear, ``a * value + b``, ``b`` the offset of temperatures and absolute pressures (``"Pa"`` to
    ``"bar_abs"``). A :class:`UnitError` if the dimensions differ.

    >>> convert(2e5, "Pa", "bar"), round(convert(0.0, "Pa", "bar_abs"), 5), round(convert(100.0, "degC", "degF"), 9)
    (2.0, 1.01325, 212.0)
    """
    if unit == to:
        return values
    offset = from_si(0.0, unit, to)
    return (from_si(1.0, unit, to) - offset) * values + offset


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
    known = _shipped().get(unit)
    return known[3] if known is not None else _coherent_pint(unit)


def _power(name: str, exponent: float) -> str:
    """``name`` raised to ``exponent`` as unit text: ``("m^3/s", 2)`` -> ``"(m^3/s)^2"``."""
    if exponent == 1:
        return name
    return f"({name})^{exponent:g}" if any(c in name for c in "*/^") else f"{name}^{exponent:g}"


def _coherent_pint(unit: str) -> str:
    if unit == "" or unit in ("degC", "degF", "K"):
        return unit
    u = _unit(unit)
    base = (1.0 * u).to_base_units()
    if abs(base.magnitude - 1.0) < 1e-12:
        return unit
    factors = list(u._units.items())  # a product of units: make each coherent
    if len(factors) > 1 or (factors and factors[0][1] != 1):
        parts = [(_coherent_pint(name), exp) for name, exp in factors]
        parts = [(name, exp) for name, exp in parts if name]  # a percent is a pure number
        return "*".join(_power(name, float(exp)) for name, exp in parts)  # type: ignore[arg-type]
    dims = registry().get_dimensionality(u)
    for name in _COHERENT:
        if registry().get_dimensionality(_unit(name)) == dims:
            return name
    return f"{base.units:~C}".replace("**", "^")


#: pint's base dimensions -> the SI base unit each is measured in.
SI_BASE = {
    "[mass]": "kg",
    "[length]": "m",
    "[time]": "s",
    "[current]": "A",
    "[temperature]": "K",
    "[substance]": "mol",
    "[luminosity]": "cd",
}


@functools.lru_cache(maxsize=512)
def si_definition(unit: str) -> tuple[float, float, dict[str, float]]:
    """``unit`` against the SI base units: ``factor``, ``offset`` and the exponent of each base unit, with
    value in base units = factor * value + offset (as an FMU's unit definitions declare it).

    Examples
    --------
    >>> si_definition("bar")
    (100000.0, 0.0, {'m': -1.0, 'kg': 1.0, 's': -2.0})
    >>> si_definition("degC")
    (1.0, 273.15, {'K': 1.0})
    >>> si_definition("%")
    (0.01, 0.0, {})
    """
    known = _shipped().get(unit)
    if known is not None:
        factor, offset, dims = known[0], known[1], known[2]
    else:
        entry = pint_entry(unit)
        factor, offset, dims = entry["factor"], entry["offset"], tuple((d, x) for d, x in entry["dimension"])
    return float(factor), float(offset), {SI_BASE.get(d, d): float(x) for d, x in dims}


@functools.lru_cache(maxsize=512)
def si_unit(unit: str) -> str:
    """Short printable form of a unit string (``"m^3/s"`` -> ``"m³/s"``)."""
    known = _shipped().get(unit)
    return known[4] if known is not None else _printed_pint(unit)


def _printed_pint(unit: str) -> str:
    """pint's short printed form, with the litre written ``L`` as engineers write it (pint prints ``l``)."""
    if unit == "":
        return "-"
    return re.sub(r"(?<![\w°µΩ])([mcdµ]?)l(?![\w°µΩ])", r"\1L", f"{_unit(unit):~P}")


def format_quantity(value: float, unit: str) -> str:
    """``value`` and ``unit`` as a string that :func:`to_si` reads back exactly."""
    if unit == "":
        return repr(float(value))
    return f"{float(value)!r} {unit}"


# -- display units ---------------------------------------------------------------------------------------------

#: Names of quantities a unit choice may key a unit by (``"p=bar"``), each standing for the dimension of its
#: SI unit: every signal of that dimension is shown in the unit given.
QUANTITIES = {
    "p": "Pa", "pressure": "Pa",
    "x": "m", "length": "m", "position": "m",
    "v": "m/s", "velocity": "m/s",
    "a": "m/s^2", "acceleration": "m/s^2",
    "Q": "m^3/s", "flow": "m^3/s",
    "F": "N", "force": "N",
    "volume": "m^3", "area": "m^2", "mass": "kg", "torque": "N*m",
    "angle": "rad", "speed": "rad/s", "current": "A", "voltage": "V", "power": "W",
}


#: Names of angle units: pint counts an angle as no dimension (``rad/s`` is ``1/s``, ``cm^3/rev`` a volume), but a
#: signal per radian is no signal per second, nor a displacement per revolution a volume: a choice of display
#: units keeps them apart (:func:`_dimension_key`).
_ANGLES = ("rad", "radian", "rev", "revolution", "deg", "degree", "turn", "cycle", "rpm", "grad", "arcmin", "arcsec")
_FACTOR = re.compile(r"([/*]?)\s*([^\W\d][\w°µΩ]*)(?:\s*(?:\^|\*\*)\s*\(?([-+]?[\d.]+)\)?)?")


def _angle_exponent(unit: str) -> float:
    """The power of angle in ``unit`` as written: ``rad/s`` 1, ``cm^3/rev`` -1, ``rpm`` 1, ``Hz`` 0."""
    total = 0.0
    for sign, name, power in _FACTOR.findall(unit):
        if name in _ANGLES:
            total += (-1.0 if sign == "/" else 1.0) * (float(power) if power else 1.0)
    return total


def _dimension_key(unit: str) -> tuple[tuple[str, float], ...]:
    """The dimension of ``unit`` as a hashable key: the exponents of the SI base units, and of angle."""
    dims = dict(si_definition(unit)[2])
    angle = _angle_exponent(unit)
    if angle:
        dims["angle"] = angle
    return tuple(sorted(dims.items()))


class UnitChoice:
    """Units to show signals in: by signal name, and by dimension (every pressure in ``psi``).

    Read from text as the ``--units`` option takes it: items separated by commas, each a unit that applies to
    every signal of its dimension (``"bar"``), a quantity and its unit (``"p=bar"``, ``"Q=L/min"``; the names
    of :data:`QUANTITIES`), or a signal and its unit (``"cyl.pA=psi"``). A length unit brings velocities and
    accelerations in that length per second (squared) unless they are chosen too. A signal's own unit wins over its
    dimension's; :meth:`over` puts one choice before another (the user's before the model's). ``si`` shows
    every signal in SI. Signals with no unit chosen are shown in SI, as hydroservo carries them.

    Examples
    --------
    >>> choice = UnitChoice.parse("p=bar, mm, cyl.pA=psi")
    >>> choice.unit("cyl.pA", "Pa"), choice.unit("cyl.pB", "Pa"), choice.unit("load.x", "m"), choice.unit("load.v", "m/s")
    ('psi', 'bar', 'mm', 'mm/s')
    >>> UnitChoice.parse("L/min").over(UnitChoice.parse("Q=gal/min, bar")).unit("valve.QA", "m^3/s")
    'L/min'
    """

    def __init__(
        self,
        signals: dict[str, str] | None = None,
        dimensions: dict[tuple[tuple[str, float], ...], str] | None = None,
        si: bool = False,
    ) -> None:
        self.signals: dict[str, str] = dict(signals or {})
        self.dimensions: dict[tuple[tuple[str, float], ...], str] = dict(dimensions or {})
        self.si = si

    SI: UnitChoice  # every signal in SI (set below)

    @classmethod
    def parse(cls, spec: Any, *, what: str = "--units") -> UnitChoice:
        """A choice from ``spec``: None (none), ``"si"``, text as above, a mapping of names (signals or
        quantities) to units, a list of items, or a :class:`UnitChoice` (returned as it is)."""
        if spec is None:
            return cls()
        if isinstance(spec, UnitChoice):
            return spec
        if isinstance(spec, str):
            if spec.strip().lower() == "si":
                return cls.SI
            items: list[tuple[str | None, str]] = []
            for item in (part.strip() for part in spec.split(",")):
                if not item:
                    continue
                left, sep, right = item.partition("=")
                items.append((left.strip(), right.strip()) if sep else (None, item))
        elif isinstance(spec, dict) or hasattr(spec, "items"):
            items = [(str(k), str(v)) for k, v in spec.items()]
        elif isinstance(spec, (list, tuple)):
            return functools.reduce(lambda a, b: a.over(b), (cls.parse(s, what=what) for s in spec), cls()) if spec else cls()
        else:
            raise UnitError(f"{what}: {spec!r}: expected units such as 'p=bar, mm, cyl.pA=psi', or 'si'")
        choice = cls()
        for key, unit in items:
            if not unit:
                raise UnitError(f"{what}: {shorten(str(spec))!r}: {key!r} has no unit; expected NAME=UNIT, e.g. 'p=bar'")
            try:
                check_unit(unit)
                dims = _dimension_key(unit)
            except UnitError as exc:
                raise UnitError(f"{what}: {exc}") from None
            if key is not None and key in QUANTITIES and dims != _dimension_key(QUANTITIES[key]):
                raise UnitError(
                    f"{what}: {key}={unit}: {unit!r} is not a unit of {key} (expected one like {QUANTITIES[key]!r})"
                )
            if key is not None and key not in QUANTITIES:
                before, thing = choice.signals.get(key), f"signal {key!r}"
                choice.signals[key] = unit
            else:
                before, thing = choice.dimensions.get(dims), "quantity"
                choice.dimensions[dims] = unit
            if before is not None and before != unit:  # two units for one thing: which one was meant?
                raise UnitError(f"{what}: {shorten(str(spec))!r}: two units for the same {thing}, {before!r} and "
                                f"{unit!r}; give one")
        _derive_speeds(choice.dimensions)
        return choice

    def over(self, other: UnitChoice) -> UnitChoice:
        """This choice, completed by ``other`` where it chooses nothing: for each signal, this choice's unit of
        the signal, else of its dimension, else ``other``'s. If this is :attr:`SI`, the result is; if only
        ``other`` is, this choice stands alone (what it does not choose is SI)."""
        if self.si:
            return UnitChoice.SI
        if other.si:
            return UnitChoice(self.signals, self.dimensions)
        merged = UnitChoice(other.signals, other.dimensions)
        for name in list(merged.signals):  # a dimension chosen here beats a signal's unit there
            if _dimension_key(merged.signals[name]) in self.dimensions:
                del merged.signals[name]
        merged.signals.update(self.signals)
        merged.dimensions.update(self.dimensions)
        return merged

    def unit(self, name: str, unit: str) -> str:
        """The unit signal ``name``, carried in SI ``unit``, is shown in (``unit`` itself if none is chosen)."""
        if self.si:
            return unit
        chosen = self.signals.get(name)
        if chosen is not None and same_dimension(chosen, unit):
            return chosen
        return self.dimensions.get(_dimension_key(unit), unit) if unit else unit

    def shown(self, name: str, value: float, unit: str) -> tuple[float, str]:
        """``value`` of signal ``name``, carried in SI ``unit``, in the unit it is shown in, and that unit.

        >>> value, unit = UnitChoice.parse("psi").shown("cyl.pA", 6.894757e6, "Pa")
        >>> round(value, 3), unit
        (1000.0, 'psi')
        """
        to = self.unit(name, unit)
        return (float(value) if to == unit else float(convert(value, unit, to))), to

    def scale(self, name: str, unit: str) -> tuple[float, str]:
        """``(factor, shown unit)`` for a difference of signal ``name`` (a rate, a spread, an error): no offset,
        so a difference of absolute pressures or of temperatures scales without one.

        >>> UnitChoice.parse("bar_abs").scale("cyl.pA", "Pa")
        (1e-05, 'bar_abs')
        """
        to = self.unit(name, unit)
        if to == unit:
            return 1.0, unit
        return si_definition(unit)[0] / si_definition(to)[0], to

    def units(self, signal_units: dict[str, str]) -> dict[str, str]:
        """The unit each signal is shown in: ``signal_units`` maps signal names to their SI units."""
        return {name: self.unit(name, unit) for name, unit in signal_units.items()}

    def check(self, signal_units: dict[str, str], what: str = "units") -> None:
        """Refuse a unit chosen for a signal that ``signal_units`` (signal name -> its SI unit) does not hold, or
        of another dimension than the signal's, with ``what`` (the option) naming the choice.

        Raises
        ------
        ParameterError
            Naming the option, the signal and its unit, with close matches for an unknown name.
        """
        from hydroservo.errors import ParameterError, did_you_mean

        for name, unit in self.signals.items():
            if name not in signal_units:
                raise ParameterError(f"{what} {name}={unit}: no signal {name!r}{did_you_mean(name, signal_units)}")
            own = signal_units[name]
            try:
                alike = same_dimension(unit, own)
            except UnitError as exc:
                raise ParameterError(f"{what} {name}={unit}: {exc}") from None
            if not alike:
                raise ParameterError(
                    f"{what} {name}={unit}: {name} is in {si_unit(own)}; expected a unit of that dimension"
                )

    def items(self) -> list[str]:
        """The choice as the items of its text (``["cyl.pA=psi", "bar"]``)."""
        if self.si:
            return ["si"]
        return [f"{name}={unit}" for name, unit in self.signals.items()] + list(self.dimensions.values())

    def __repr__(self) -> str:
        return f"UnitChoice({', '.join(self.items())!r})"


UnitChoice.SI = UnitChoice(si=True)


def inferred_units(texts: Any) -> UnitChoice:
    """The units a set of quantities (``["1500 psi", "2 in", "0.5 in"]``) were written in: for each dimension,
    the unit used most often (the first of equals). Only plain units count (at most two names, none twice:
    ``in*lbf/in`` is a force but no unit to show one in); absolute pressures, temperatures, times and bare
    numbers are left aside. Velocities and accelerations follow the length unit per second (squared) when none
    was written.

    >>> choice = inferred_units(["1500 psi", "2 in", "0.5 in", "1 mm", "25 degC", "0.3", "1 in*lbf/in", "2 in*lbf/in"])
    >>> choice.unit("cyl.pA", "Pa"), choice.unit("load.x", "m"), choice.unit("load.v", "m/s"), choice.unit("cyl.F", "N")
    ('psi', 'in', 'in/s', 'N')
    """
    counts: dict[tuple[tuple[str, float], ...], dict[str, int]] = {}
    for text in texts:
        try:
            _, unit = split_quantity(str(text))
            if not unit or unit in TEMPERATURE_UNITS or is_absolute_pressure(unit) or "%" in unit:
                continue
            names = re.findall(r"[^\W\d][\w°µΩ]*", unit)
            if len(names) > 2 or len(set(names)) < len(names):
                continue
            check_unit(unit)
            key = _dimension_key(unit)
        except (UnitError, ValueError):
            continue
        if not key or key == _dimension_key("s"):
            continue
        found = counts.setdefault(key, {})
        found[unit] = found.get(unit, 0) + 1
    chosen = {key: max(units, key=lambda u: units[u]) for key, units in counts.items()}  # first of equals
    _derive_speeds(chosen)
    return UnitChoice(dimensions={k: u for k, u in chosen.items() if u != coherent_unit(u)})


def _derive_speeds(chosen: dict[tuple[tuple[str, float], ...], str]) -> None:
    """Velocities and accelerations in the chosen length unit per second (squared), unless chosen themselves."""
    length = chosen.get(_dimension_key("m"))
    if length is not None and length != "m" and re.fullmatch(r"[^\W\d][\w°µΩ]*", length):
        chosen.setdefault(_dimension_key("m/s"), f"{length}/s")
        chosen.setdefault(_dimension_key("m/s^2"), f"{length}/s^2")
