"""What a component is: declared parameters, states, inputs, outputs, equations.

A component is a small class. At the top it declares

* ``PARAMETERS``: name -> :class:`Param` (default in SI, unit, allowed range),
* ``STATES``: name -> :class:`State` (unit, initial value, nominal magnitude),
* ``ALGEBRAIC``: name -> :class:`Algebraic`, unknowns defined implicitly by
  an equation rather than by a rate (a flapper tip bent by the very jets it
  throttles; the pressure of a junction without volume),
* ``INPUTS``: name -> :class:`Port` (unit; a default if it may stay unconnected),
* ``OUTPUTS``: name -> :class:`Output` (unit),
* ``OPTIONS``: name -> :class:`Option` (structural choices, such as a
  bulk-modulus law, that change the equations rather than a number in them),
* ``LIMITS``: signal -> :class:`Limit` (bounds no real circuit crosses, such
  as a chamber pressure below vacuum or a piston beyond its stops; every run
  is checked against them),
* ``HYDRAULIC``: port name -> :class:`Hydraulic`, the places where oil enters
  or leaves: each pairs a pressure and a flow signal, so that a user connects
  a port to a port once (``system.connect("valve.A", "cyl.A")``) and the
  system works out which side gives the pressure and which the flow
  (:mod:`hydroservo.system.nodes`),
* ``MECHANICAL``: port name -> :class:`Mechanical`, the places where a
  component pushes or is pushed along a line: each names a position, a
  velocity and a force signal, and is connected port to port in the same way
  (``system.connect("cyl.R", "load.P1")``),

and below it writes two methods with CasADi expressions:

* ``output_equations(t, x, u, p)`` returns the outputs; it may read only the
  inputs that the outputs really depend on (the system resolves inputs lazily,
  so an output computed from states alone never creates an algebraic loop);
* ``state_equations(t, x, u, p, y)`` returns the time derivative of every state
  (``y`` holds this component's own outputs);
* with algebraic unknowns, ``residual_equations(t, x, u, p)`` returns for each
  the residual that vanishes at its solution (in the unknown's own unit where
  the equation allows, ``z - g(z)``), and ``guess_equations(t, x, u, p)`` an
  explicit approximation of it from the states (Newton starts there:
  :mod:`hydroservo.system.implicit`). ``x`` then holds the algebraic unknowns
  beside the states, and every equation may read them.

``x``, ``u``, ``p`` and ``y`` are mappings from the declared names to
expressions. A component never sees another component: only its inputs.
The equations call the published laws of :mod:`hydroservo.laws`; a component
adds only what makes a law a part (ports, states, saturations, options).

A parameter that was renamed keeps its old name as an alias (``RENAMED``):
model files written before the rename still load, with a warning.
"""

from __future__ import annotations

import copy
import functools
import keyword
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any, ClassVar, Self

from hydroservo.data import parameter_set
from hydroservo.errors import ParameterError, RenamedWarning, UnitError, did_you_mean, shorten
from hydroservo.units import check_unit, coherent_unit, is_absolute_pressure, is_bare_number, si_unit, to_si

__all__ = [
    "FromSet",
    "Param",
    "State",
    "Algebraic",
    "Port",
    "Output",
    "Option",
    "Limit",
    "Hydraulic",
    "Mechanical",
    "Component",
    "SIGNAL",
    "REGISTRY",
    "register",
    "RenamedWarning",
    "MAX_NAME",
    "name_problem",
]

#: The longest component name [characters]: a name is written into expressions (aliases, initial values) that
#: are read back, and into every file that names signals.
MAX_NAME = 100


def name_problem(name: str) -> str | None:
    """Why ``name`` cannot name a component, or None: a component name is an identifier (letters, digits, _, not
    starting with a digit), not a Python keyword (expressions such as ``-class.x`` could not be read) and at most
    :data:`MAX_NAME` characters. The one rule: a model file's loader and every writer of names check by it.

    >>> name_problem("load"), name_problem("class"), name_problem("4_3")
    (None, "a Python keyword, which expressions of its signals could not name; expected another name, e.g. 'class_'", 'expected a Python identifier (letters, digits, _; not starting with a digit)')
    """
    if not isinstance(name, str) or not name.isidentifier():
        return "expected a Python identifier (letters, digits, _; not starting with a digit)"
    if keyword.iskeyword(name):
        return f"a Python keyword, which expressions of its signals could not name; expected another name, e.g. {name + '_'!r}"
    if len(name) > MAX_NAME:
        return f"{len(name)} characters; expected at most {MAX_NAME}"
    return None

#: Placeholder unit of signal blocks (sources, sums, gains): replaced by the
#: block's ``unit`` argument, or by "" (dimensionless) when none is given.
SIGNAL = "@"


@dataclass(frozen=True)
class FromSet:
    """A default taken from a parameter set of :mod:`hydroservo.data`: one source for published values.

    Converted to the parameter's SI unit on first use (the package's TOML files
    and the unit registry are read then, not on import).
    """

    set_name: str
    table: str
    key: str


@functools.cache
def _from_set(ref: FromSet, unit: str) -> float:
    return parameter_set(ref.set_name).si(ref.table, ref.key, unit)


@dataclass(frozen=True)
class Param:
    """A numeric parameter: symbolic in the compiled model, so it can be swept or fitted.

    ``default`` is an SI number, or a :class:`FromSet` reference to a published
    (or example) parameter set of the package. ``fluid`` names the property of
    the circuit's fluid the parameter is (``density``, ``kinematic_viscosity``,
    ``bulk_modulus``): in a system with a fluid the parameter takes its value
    from it, unless it is set on the component.
    """

    default: float | FromSet
    unit: str
    description: str
    min: float | None = None
    max: float | None = None
    min_inclusive: bool = True
    max_inclusive: bool = True
    fluid: str | None = None

    def expected(self) -> str:
        lo = "" if self.min is None else ("[" if self.min_inclusive else "(") + f"{self.min:g}"
        hi = "" if self.max is None else f"{self.max:g}" + ("]" if self.max_inclusive else ")")
        if self.min is not None and self.max is not None:
            rng = f"in {lo}, {hi}"
        elif self.min is not None:
            rng = ("≥ " if self.min_inclusive else "> ") + f"{self.min:g}"
        elif self.max is not None:
            rng = ("≤ " if self.max_inclusive else "< ") + f"{self.max:g}"
        else:
            rng = "any finite value"
        unit = si_unit(self.unit)
        return f"{rng} {unit}" if unit != "-" else rng

    def si_default(self) -> float:
        """The default in SI (a :class:`FromSet` resolved)."""
        if isinstance(self.default, FromSet):
            return _from_set(self.default, self.unit)
        return float(self.default)

    def check(self, value: float, what: str, given: Any = None) -> float:
        ok = math.isfinite(value)
        if ok and self.min is not None:
            ok = value >= self.min if self.min_inclusive else value > self.min
        if ok and self.max is not None:
            ok = value <= self.max if self.max_inclusive else value < self.max
        if not ok:
            shown = f"{value:g} {si_unit(self.unit)}".replace(" -", "")
            if isinstance(given, str):
                shown = f"{given!r} (= {shown})"
            raise ParameterError(f"{what} = {shown}: expected {self.expected()} ({self.description})")
        return value


@dataclass(frozen=True)
class State:
    """A state variable; ``nominal`` is its typical magnitude, used to scale the solver."""

    unit: str
    description: str
    initial: float | str = 0.0
    nominal: float = 1.0


@dataclass(frozen=True)
class Algebraic:
    """An algebraic unknown: defined by a residual equation (``residual_equations``), not by a rate.

    ``nominal`` is its typical magnitude: the solution is accepted when Newton's last correction is below
    :data:`hydroservo.system.implicit.TOLERANCE` times it.
    """

    unit: str
    description: str
    nominal: float = 1.0


@dataclass(frozen=True)
class Port:
    """An input; ``default`` is used when it is left unconnected (None: must be connected)."""

    unit: str
    description: str
    default: float | None = None


@dataclass(frozen=True)
class Output:
    unit: str
    description: str


@dataclass(frozen=True)
class Option:
    """A structural choice among named alternatives."""

    default: str
    choices: tuple[str, ...]
    description: str


@dataclass(frozen=True)
class Limit:
    """A physical bound on one of the component's states, outputs or inputs, checked after every run.

    ``kind`` is

    * ``"source"``: a pressure a source imposes; the highest of all sources over
      the run is the circuit's pressure ceiling;
    * ``"relief"``: a relief valve's setting, which bounds a circuit fed by a
      flow source (a source of flow whatever the pressure): with one in the
      circuit, the highest setting joins the sources for the ceiling;
    * ``"flow-source"``: a flow imposed whatever the pressure (its presence is
      what counts);
    * ``"pressure"``: the pressure of a closed volume, flagged above the ceiling
      or below vacuum by more than the margins;
    * ``"travel"``: a position between the parameters named ``lower`` and
      ``upper`` (end stops), flagged beyond them by more than the margin;
    * ``"volume"``: flagged at or below zero.

    ``hint`` is added to the warning: what in the component lets the bound be crossed.
    The margins are stated in :mod:`hydroservo.system.plausibility`.
    """

    kind: str
    lower: str | None = None
    upper: str | None = None
    hint: str = ""

    def __post_init__(self) -> None:
        if self.kind not in ("source", "relief", "flow-source", "pressure", "travel", "volume"):
            raise ValueError(f"Limit kind {self.kind!r}: expected source, pressure, travel or volume")
        if (self.kind == "travel") != (self.lower is not None and self.upper is not None):
            raise ValueError("a travel limit needs lower and upper parameters, and only a travel limit has them")


@dataclass(frozen=True)
class Hydraulic:
    """A hydraulic port: the pressure ``p`` and the flow ``Q`` at one place of a component.

    Which of the two the component computes decides the port's causality:

    * ``p`` an input and ``Q`` an output: a **flow port** (an orifice, a
      valve's metering edges, a pump): it takes the pressure of the node and
      gives the flow;
    * ``p`` an output (usually a state) and ``Q`` an input: a **pressure
      port** (a volume, a cylinder chamber, an accumulator, a pressure
      source): it takes the sum of the flows of the node and gives its pressure.

    ``into`` says the direction in which ``Q`` is counted: True if positive
    ``Q`` enters the component at this port, False if it leaves it.
    """

    p: str
    Q: str
    description: str
    into: bool = True

    @property
    def sign(self) -> float:
        """+1 if ``Q`` is counted into the component, -1 if out of it."""
        return 1.0 if self.into else -1.0


@dataclass(frozen=True)
class Mechanical:
    """A mechanical port of one-dimensional motion: position ``x``, velocity ``v`` and force ``F`` at one place.

    Which signals the component computes decides the port's causality, as for :class:`Hydraulic`:

    * ``x`` and ``v`` outputs, ``F`` an input: a **motion port** (a mass, a fixed point, a velocity source): it
      gives the motion of the node and takes the sum of the forces acting on it there;
    * ``x`` and ``v`` inputs, ``F`` an output: a **force port** (a cylinder's rod, a spring, a damper, a force
      source): it takes the motion of the node and gives the force it exerts there.

    ``x``, ``v`` and ``F`` are counted in the component's own direction at that port: ``outward`` is True if
    that direction points out of the component (a mass's end 2, a cylinder's rod), False if into it (Hopsan's
    convention at the ports of its springs). Two connected ports face each other, so the one's outward is the
    other's inward (:func:`hydroservo.system.nodes.resolve`). ``kind`` keeps translational ports (m, m/s, N)
    apart from rotational ones (rad, rad/s, N m).
    """

    x: str
    v: str
    F: str
    description: str
    outward: bool = True
    kind: str = "translational"

    @property
    def sign(self) -> float:
        """+1 if the port's direction points out of the component, -1 if into it."""
        return 1.0 if self.outward else -1.0


class Component:
    """Base class of all components. See the module docstring."""

    PARAMETERS: ClassVar[dict[str, Param]] = {}
    STATES: ClassVar[dict[str, State]] = {}
    ALGEBRAIC: ClassVar[dict[str, Algebraic]] = {}
    INPUTS: ClassVar[dict[str, Port]] = {}
    OUTPUTS: ClassVar[dict[str, Output]] = {}
    OPTIONS: ClassVar[dict[str, Option]] = {}
    LIMITS: ClassVar[dict[str, Limit]] = {}
    HYDRAULIC: ClassVar[dict[str, Hydraulic]] = {}
    MECHANICAL: ClassVar[dict[str, Mechanical]] = {}
    #: Former parameter names -> current names (accepted with a :class:`RenamedWarning`).
    RENAMED: ClassVar[dict[str, str]] = {}

    def __init__(self, name: str, unit: str | None = None, **values: Any) -> None:
        problem = name_problem(name)
        if problem is not None:
            raise ParameterError(f"component name {shorten(str(name))!r}: {problem}")
        self.name = name
        self.unit = unit
        self._bind_signal_unit(unit or "")
        self.values: dict[str, float] = {k: v.si_default() for k, v in self.PARAMETERS.items()}
        #: The text each parameter was given as, when it carried a unit ("1500 psi"): model files keep it.
        self.given: dict[str, str] = {}
        #: Parameters set on this component (not defaults): a circuit's fluid does not override them.
        self.explicit: set[str] = set()
        self.option_values: dict[str, str] = {k: v.default for k, v in self.OPTIONS.items()}
        self.set(**values)
        self.options_changed()

    def options_changed(self) -> None:
        """Hook, called once the component is made and whenever an option is set: a component whose states or
        outputs depend on its options (a chamber's cavity state) declares them here, on the instance."""

    def _bind_signal_unit(self, unit: str) -> None:
        """Give signal blocks a unit: every declared unit "@" becomes the coherent SI unit of ``unit``
        (a block given ``unit="mm"`` carries metres inside, as every signal does; ``self.unit`` keeps "mm")."""
        try:
            check_unit(unit)
        except UnitError:
            raise ParameterError(f"{self.name}.unit = {unit!r}: not a unit") from None
        if is_absolute_pressure(unit):
            raise ParameterError(
                f"{self.name}.unit = {unit!r}: an absolute pressure is a value, not a signal's unit; use 'bar' or 'Pa' "
                "(signals are gauge pressures) and give absolute values as '2 bar_abs'"
            )
        unit = coherent_unit(unit)

        def sub(u: str) -> str:
            if SIGNAL not in u:
                return u
            if unit == "":
                return u.replace(SIGNAL + "/", "1/").replace(SIGNAL + "*", "").replace(SIGNAL, "")
            return u.replace(SIGNAL, unit if unit.isidentifier() else f"({unit})")

        self.PARAMETERS = {k: replace(v, unit=sub(v.unit)) for k, v in self.PARAMETERS.items()}  # type: ignore[misc]
        self.INPUTS = {k: replace(v, unit=sub(v.unit)) for k, v in self.INPUTS.items()}  # type: ignore[misc]
        self.OUTPUTS = {k: replace(v, unit=sub(v.unit)) for k, v in self.OUTPUTS.items()}  # type: ignore[misc]
        self.STATES = {k: replace(v, unit=sub(v.unit)) for k, v in self.STATES.items()}  # type: ignore[misc]
        self.ALGEBRAIC = {k: replace(v, unit=sub(v.unit)) for k, v in self.ALGEBRAIC.items()}  # type: ignore[misc]

    # -- parameters -----------------------------------------------------
    def set(self, **values: Any) -> None:
        """Set parameters (numbers in SI, or strings/quantities with units) and options."""
        for key, value in values.items():
            key = self.current_name(key)
            if key in self.OPTIONS:
                self.set_option(key, value)
            else:
                self.values[key] = self.parse(key, value)
                self.explicit.add(key)
                if isinstance(value, str) and not is_bare_number(value):
                    self.given[key] = value.strip()
                else:
                    self.given.pop(key, None)
        self.changed()

    def changed(self) -> None:
        """Called after parameter values change (by :meth:`set`, or a circuit's fluid); override to
        re-derive what depends on them (a line's number of segments)."""

    def structure_key(self) -> tuple[Any, ...]:
        """Structural settings besides options and tables (override): a change rebuilds the model."""
        return ()

    def current_name(self, key: str) -> str:
        """``key``, or the current name of a renamed parameter (with a :class:`RenamedWarning`)."""
        if key in self.RENAMED and key not in self.PARAMETERS and key not in self.OPTIONS:
            new = self.RENAMED[key]
            warnings.warn(
                f"{self.name}.{key}: {type(self).__name__}'s parameter {key!r} is now called {new!r}",
                RenamedWarning,
                stacklevel=3,
            )
            return new
        return key

    def replace(self, *, check: bool = True, **values: float) -> Self:
        """A copy with some parameters replaced by SI values, checked against their ranges unless ``check`` is False
        (an optimiser's trial points)."""
        new = copy.copy(self)
        new.values = dict(self.values)
        new.given = {k: v for k, v in self.given.items() if k not in values}
        new.option_values = dict(self.option_values)
        new.explicit = self.explicit | set(values)
        for key, value in values.items():
            if key not in self.PARAMETERS:
                raise ParameterError(
                    f"{self.name}.{key}: unknown parameter of {type(self).__name__}{did_you_mean(key, self.PARAMETERS)}"
                )
            value = float(value)
            new.values[key] = self.PARAMETERS[key].check(value, f"{self.name}.{key}") if check else value
        return new

    def parse(self, key: str, value: Any) -> float:
        """Check and convert one parameter value to SI."""
        key = self.current_name(key)
        what = f"{self.name}.{key}"
        if key not in self.PARAMETERS:
            known = ", ".join(sorted(self.PARAMETERS) + sorted(self.OPTIONS))
            hint = did_you_mean(key, [*self.PARAMETERS, *self.OPTIONS])
            raise ParameterError(f"{what}: unknown parameter of {type(self).__name__}{hint}; known: {known}")
        spec = self.PARAMETERS[key]
        try:
            si = to_si(value, spec.unit, what=what)
        except UnitError as exc:
            raise ParameterError(f"{exc} ({spec.description})") from None
        return spec.check(si, what, value)

    def set_option(self, key: str, value: Any) -> None:
        spec = self.OPTIONS[key]
        if value not in spec.choices:
            raise ParameterError(
                f"{self.name}.{key} = {value!r}: expected one of {', '.join(spec.choices)} ({spec.description})"
            )
        self.option_values[key] = str(value)
        self.options_changed()

    def option(self, key: str) -> str:
        return self.option_values[key]

    # -- equations --------------------------------------------------------
    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {}

    def residual_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        """The residual of each algebraic unknown (zero at its solution)."""
        return {}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """Where this component's equations have a kink or a jump: name -> (an expression that changes sign
        there, its nominal magnitude in SI). An end stop reached, a lap edge passed, a valve cracking, a
        source's step. The compiled variable-step solvers end a step at each sign change (events), so that no
        step straddles a kink; the equations themselves are unchanged. Default: none."""
        return {}

    def guess_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        """An explicit first guess of each algebraic unknown (from states, inputs and parameters; default 0)."""
        return {k: 0.0 for k in self.ALGEBRAIC}

    def check(self) -> None:
        """Cross-parameter checks (override); raise ParameterError."""

    def config(self) -> dict[str, Any]:
        """Constructor arguments other than parameters and options (tables, files), for model files."""
        return {}

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"


@dataclass
class Registry:
    """Component types by class name, and former names of renamed types."""

    types: dict[str, type[Component]] = field(default_factory=dict)
    renamed: dict[str, str] = field(default_factory=dict)

    def register(self, cls: type[Component]) -> type[Component]:
        self.types[cls.__name__] = cls
        return cls

    def resolve(self, name: str) -> type[Component] | None:
        """The type registered as ``name`` (or under its former name), or None."""
        return self.types.get(self.renamed.get(name, name))


REGISTRY = Registry()
register = REGISTRY.register
