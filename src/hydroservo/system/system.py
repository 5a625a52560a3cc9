"""Systems: components connected into one ODE ``dx/dt = f(t, x, p)``.

A :class:`System` holds components, connections (an output of one component
feeds an input of another), hydraulic links (a port to a port; links that
share a port form one node, :mod:`hydroservo.system.nodes`), aliases (named expressions of signals, with a
unit) and initial conditions. :meth:`System.build` assembles one CasADi
expression graph with every parameter a symbol, and returns a
:class:`~hydroservo.system.model.Model`; the model is rebuilt only when the
structure changes, never when a parameter value does.
"""

from __future__ import annotations

import copy
import re
from collections import OrderedDict
from collections.abc import Callable, Collection, Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.components.base import Component, Hydraulic, Mechanical
from hydroservo.errors import BareNumberWarning, HydroservoError, ModelError, ParameterError, UnitError, did_you_mean
from hydroservo.system.assembly import assemble
from hydroservo.system.integration import batch_columns
from hydroservo.system.model import Model
from hydroservo.system.nodes import Node, nodes, port_kind, port_of, port_signals, resolve
from hydroservo.units import (
    UnitChoice,
    check_unit,
    coherent_unit,
    inferred_units,
    is_bare_number,
    same_dimension,
    split_quantity,
    to_si,
)

if TYPE_CHECKING:
    from pathlib import Path

    from hydroservo.plotting.schematic import Schematic
    from hydroservo.system.result import BatchResult, Result

__all__ = ["System", "Alias", "CircuitFluid", "split_name"]

#: How many compiled models are kept across systems (:meth:`System.build`).
BUILT_KEPT = 32
_BUILT: OrderedDict[Any, Model] = OrderedDict()


@dataclass(frozen=True)
class Alias:
    """A named signal: an expression of other signals, with its unit."""

    expr: str
    unit: str
    description: str = ""


@dataclass(frozen=True)
class CircuitFluid:
    """The oil of a circuit: a fluid of :mod:`hydroservo.fluids` at a temperature and a pressure.

    Components take their density, viscosity and bulk modulus parameters
    (those declared with ``Param(fluid=...)``) from it unless they are set on
    the component. ``bulk_modulus``, if given, replaces the fluid's: the
    *effective* bulk modulus of a circuit, with entrained air and hose
    compliance, is usually well below the oil's own ([Merritt1967] section 2.6).
    ``given`` keeps the text of each value given with a unit, for model files.
    """

    name: str
    temperature: float  #: [degC]
    pressure: float = 0.0  #: [Pa] gauge, where the properties are evaluated
    bulk_modulus: float | None = None  #: [Pa] effective, replacing the fluid's
    given: tuple[tuple[str, str], ...] = ()

    def properties(self) -> dict[str, float]:
        """Density, kinematic and dynamic viscosity and bulk modulus (SI) at the circuit's temperature and pressure."""
        from hydroservo.fluids import get_fluid

        props = {k: float(v) for k, v in get_fluid(self.name).properties(self.pressure, self.temperature).items()}
        if self.bulk_modulus is not None:
            props["bulk_modulus"] = self.bulk_modulus
        return props

    def describe(self) -> str:
        text = dict(self.given)
        out = f"{self.name} at {text.get('temperature', f'{self.temperature:g} degC')}"
        if self.pressure:
            out += f", {text.get('pressure', f'{self.pressure:g} Pa')}"
        return out


def _laws_called(build: Callable[[], object]) -> list[Callable[..., object]]:
    """The functions of :mod:`hydroservo.laws` that ``build()`` calls (directly or through others), in call order."""
    import sys

    called: dict[Callable[..., object], None] = {}

    def profile(frame: Any, event: str, arg: object) -> None:
        if event == "call" and frame.f_globals.get("__name__", "").startswith("hydroservo.laws."):
            function = frame.f_globals.get(frame.f_code.co_name)
            if callable(function) and getattr(function, "__code__", None) is frame.f_code:
                called[function] = None

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        build()
    finally:
        sys.setprofile(previous)
    return list(called)


def split_name(ref: str, what: str) -> tuple[str, str]:
    """``"comp.name"`` -> ``("comp", "name")``; a ModelError naming ``what`` otherwise."""
    parts = str(ref).split(".")
    if len(parts) != 2 or not all(parts):
        raise ModelError(f"{what}: {ref!r} is not of the form 'component.signal'")
    return parts[0], parts[1]


def model_unit(comp: Component, pname: str, value: Any) -> str | None:
    """The unit the model gives parameter ``pname`` of ``comp`` in (``"lbf"`` for ``load.W = "6400 lbf"``), where
    ``value`` is a bare number (``3000``, ``"3000"``), which is taken in SI, and that unit is not SI; None for a
    value with its unit, zero (nothing in any unit without an offset), a parameter given in SI or without a unit.
    The CLI refuses such a number (``--set load.W=3000``); the Python API warns (:meth:`System.simulate`)."""
    spec = comp.PARAMETERS.get(pname)
    given = comp.given.get(pname)
    if spec is None or not spec.unit or given is None or not is_bare_number(value):
        return None
    if float(value) == 0.0 and spec.unit not in ("degC",):
        return None
    unit = split_quantity(given)[1]
    return unit if unit and unit != coherent_unit(unit) else None


class System:
    """Components connected into one model.

    Examples
    --------
    >>> from hydroservo import System, components as c
    >>> s = System("spring-mass")
    >>> _ = s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0))
    >>> r = s.simulate(t_end=0.05)
    >>> round(float(r["load.x"][-1]) * 1e3, 3)  # x0 cos(20 rad/s * 0.05 s), in mm
    5.403
    """

    def __init__(self, name: str = "system", description: str = "", t_end: float = 1.0) -> None:
        self.name = name
        self.description = description
        self.t_end = float(t_end)
        self.components: dict[str, Component] = {}
        self.connections: dict[str, str] = {}
        #: hydraulic links, pairs of ports ("comp.port") in the order they were made
        self.links: list[tuple[str, str]] = []
        self.aliases: dict[str, Alias] = {}
        self.initial: dict[str, str | float] = {}
        #: the text an initial value was given as, when it carried a unit ("50 bar"): model files keep it
        self.initial_given: dict[str, str] = {}
        #: where the system file came from (path, or "built-in:NAME")
        self.source: str | None = None
        #: citation key of its source, "published" or "example", and its validation status
        self.meta: dict[str, str] = {}
        #: panels for plots of a run (lists of signal names) and the units to show them in
        self.plots: list[list[str]] = []
        self.plot_units: dict[str, str] = {}
        #: the units a person reads this model's results in (``[model] units``, ``["psi", "in", "Q=in^3/s"]``;
        #: :class:`~hydroservo.units.UnitChoice`'s items); if empty, the units its parameters were given in
        self.display_units: list[str] = []
        #: what a study measures of each run by default (:mod:`hydroservo.analysis.metrics`), e.g. "final(x_mm)"
        self.metrics: list[str] = []
        #: what a user should know when reading a run of this model (a known discrepancy with its source, a
        #: flagged peak that the source has too), each with where it is explained; printed with every run
        self.notes: list[str] = []
        #: the circuit's fluid (:meth:`set_fluid`), or None: each component keeps its own values
        self.fluid: CircuitFluid | None = None
        self._model: Model | None = None
        self._model_key: Any = None

    # -- structure --------------------------------------------------------------
    def add(self, component: Component) -> Component:
        """Add a component; its name must be new."""
        if component.name in self.components:
            raise ModelError(f"component {component.name!r} already exists in system {self.name!r}")
        self.components[component.name] = component
        if self.fluid is not None:
            self._apply_fluid(component, self.fluid.properties())
        return component

    def replace(self, component: Component) -> Component:
        """Put ``component`` in place of the component of the same name, keeping every connection and
        hydraulic link: it must offer the signals and ports they use (a linearised version of it does)."""
        name = component.name
        if name not in self.components:
            raise ModelError(f"replace: no component {name!r} in system {self.name!r}")
        used = {ref.split(".", 1)[1] for pair in self.connections.items() for ref in pair if ref.split(".", 1)[0] == name}
        ports = {ref.split(".", 1)[1] for pair in self.links for ref in pair if ref.split(".", 1)[0] == name}
        offered = set(component.INPUTS) | set(component.OUTPUTS)
        missing = sorted((used - offered) | (ports - set(component.HYDRAULIC) - set(component.MECHANICAL)))
        if missing:
            raise ModelError(
                f"replace {name!r}: {type(component).__name__} has no {', '.join(missing)}, which the system connects"
            )
        self.components[name] = component
        for state in [k for k in self.initial if k.split(".", 1)[0] == name and k.split(".", 1)[1] not in component.STATES]:
            del self.initial[state]  # the initial value of a state the new component does not have
            self.initial_given.pop(state, None)
        if self.fluid is not None:
            self._apply_fluid(component, self.fluid.properties())
        return component

    def set_fluid(
        self,
        name: str,
        temperature: float | str = "40 degC",
        pressure: float | str = 0.0,
        bulk_modulus: float | str | None = None,
    ) -> CircuitFluid:
        """Name the circuit's oil once: a fluid of :data:`hydroservo.fluids.FLUIDS` at ``temperature``
        (with its unit, ``"40 degC"``) and ``pressure`` (gauge; where the properties are evaluated).

        Every component parameter that is a fluid property (density ``rho``,
        viscosity ``nu``, bulk modulus ``beta_e``) takes the fluid's value, except
        those set on the component itself. ``bulk_modulus`` sets the effective
        bulk modulus of the circuit instead of the oil's.

        Examples
        --------
        >>> from hydroservo import System, components as c
        >>> s = System()
        >>> _ = s.add(c.FourWayValve("valve"))
        >>> _ = s.set_fluid("iso-vg46", "50 degC", bulk_modulus="1.2 GPa")
        >>> round(s["valve"].values["nu"] * 1e6, 1)  # cSt
        30.0
        """
        given = []
        values: dict[str, float | None] = {}
        for key, val, unit in (("temperature", temperature, "degC"), ("pressure", pressure, "Pa"), ("bulk_modulus", bulk_modulus, "Pa")):
            if val is None:
                values[key] = None
                continue
            try:
                values[key] = to_si(val, unit, what=f"fluid {key}")
            except UnitError as exc:
                raise ParameterError(str(exc)) from None
            if isinstance(val, str):
                given.append((key, val.strip()))
        if values["bulk_modulus"] is not None and not values["bulk_modulus"] > 0:
            raise ParameterError(f"fluid bulk_modulus = {bulk_modulus!r}: expected a positive pressure")
        fluid = CircuitFluid(
            str(name), float(values["temperature"] or 0.0), float(values["pressure"] or 0.0), values["bulk_modulus"], tuple(given)
        )
        props = fluid.properties()  # checks the name, the temperature and the pressure
        for comp in self.components.values():
            self._apply_fluid(comp, props)
        self.fluid = fluid
        return fluid

    def _apply_fluid(self, comp: Component, props: Mapping[str, float]) -> None:
        for key, spec in comp.PARAMETERS.items():
            if spec.fluid and key not in comp.explicit:
                what = f"{comp.name}.{key} (the circuit fluid's {spec.fluid.replace('_', ' ')})"
                comp.values[key] = spec.check(props[spec.fluid], what)
                comp.given.pop(key, None)
        comp.changed()

    def __getitem__(self, name: str) -> Component:
        try:
            return self.components[name]
        except KeyError:
            raise ModelError(
                f"no component {name!r} in system {self.name!r}{did_you_mean(name, self.components)}; components: "
                f"{', '.join(self.components)}"
            ) from None

    def connect(self, source: str, *targets: str) -> None:
        """Connect hydraulic or mechanical ports, or feed a signal output into inputs.

        * Hydraulic ports ("comp.port", e.g. ``connect("valve.A", "cyl.A")``)
          or mechanical ports (``connect("cyl.R", "load.P1")``): all the ports
          named join one node, with any ports they are already linked to; order
          does not matter. See :mod:`hydroservo.system.nodes`.
        * Signals: output ``source`` ("comp.output") feeds each input ``targets``
          ("comp.input").
        """
        if port_of(self.components, source) is not None or any(
            port_of(self.components, t) is not None for t in targets
        ):
            self._link(source, *targets)
            return
        sc, so = split_name(source, "connection source")
        comp = self[sc]
        if so not in comp.OUTPUTS:
            named = [*comp.HYDRAULIC, *comp.MECHANICAL]
            ports = f"; ports: {', '.join(named)}" if named else ""
            raise ModelError(
                f"connection {source!r}: {type(comp).__name__} {sc!r} has no output {so!r}; outputs: "
                f"{', '.join(comp.OUTPUTS)}{ports}"
            )
        for target in targets:
            tc, ti = split_name(target, "connection target")
            tcomp = self[tc]
            if ti not in tcomp.INPUTS:
                raise ModelError(
                    f"connection {source!r} -> {target!r}: {type(tcomp).__name__} {tc!r} has no input {ti!r}; inputs: {', '.join(tcomp.INPUTS)}"
                )
            if target in self.connections:
                raise ModelError(f"input {target!r} is already connected to {self.connections[target]!r}")
            linked = {ref for pair in self.links for ref in pair}
            ports_of: list[tuple[str, Hydraulic | Mechanical]] = [*tcomp.HYDRAULIC.items(), *tcomp.MECHANICAL.items()]
            for pname, port in ports_of:
                if ti in port_signals(port) and f"{tc}.{pname}" in linked:
                    raise ModelError(
                        f"input {target!r} is already fed by the node of port {tc}.{pname}; connect the "
                        "port or its signals, not both"
                    )
            u_out, u_in = comp.OUTPUTS[so].unit, tcomp.INPUTS[ti].unit
            if u_out and u_in and not same_dimension(u_out, u_in):
                raise ModelError(
                    f"connection {source!r} [{u_out}] -> {target!r} [{u_in}]: the units have different dimensions"
                )
            self.connections[target] = source

    def _link(self, *ports: str) -> None:
        if len(ports) < 2:
            raise ModelError(f"connection {ports[0]!r}: a port connects to at least one other port")
        kinds: dict[str, str] = {}
        for ref in ports:
            cname, pname = split_name(ref, "port connection")
            comp = self[cname]
            port = comp.HYDRAULIC.get(pname) or comp.MECHANICAL.get(pname)
            if port is None:
                known = ", ".join([*comp.HYDRAULIC, *comp.MECHANICAL]) or "none"
                raise ModelError(
                    f"connection {' – '.join(ports)}: {type(comp).__name__} {cname!r} has no port "
                    f"{pname!r}; its ports: {known} (a port connects only to ports of its kind)"
                )
            kinds[ref] = port_kind(port)
            for signal in port_signals(port):
                if signal not in comp.INPUTS:
                    continue
                if f"{cname}.{signal}" in self.connections:
                    raise ModelError(
                        f"connection {' – '.join(ports)}: {ref}'s {signal} is already connected as a signal to "
                        f"{self.connections[f'{cname}.{signal}']!r}; connect the port or its signals, not both"
                    )
        if len(set(ports)) < len(ports):
            raise ModelError(f"connection {' – '.join(ports)}: a port is named twice")
        joined = {ref for pair in self.links for ref in pair if any(r in pair for r in ports)}
        for ref in joined - set(kinds):  # the ports these join through earlier links
            found = port_of(self.components, ref)
            assert found is not None
            kinds[ref] = port_kind(found[1])
        if len(set(kinds.values())) > 1:
            listed = ", ".join(f"{ref} ({kind})" for ref, kind in kinds.items())
            raise ModelError(f"connection {' – '.join(ports)}: ports of different kinds cannot join: {listed}")
        self.links.extend((ports[0], other) for other in ports[1:])

    def nodes(self) -> list[Node]:
        """The hydraulic and mechanical nodes: sets of connected ports."""
        return nodes(self.links)

    def references(self) -> list[str]:
        """The bibliography entries this system draws on (keys of :mod:`hydroservo.references`), in its order.

        Its source's; every published law its equations call, as the model is assembled (so a cylinder's
        bulk-modulus law is cited only when it is the one chosen), with the keys its docstring cites; each
        component's own (:func:`hydroservo.components.reference.citations`: what the component is, the
        parameter sets its defaults come from); and its fluid's. PyBaMM's citations registry does the same for
        its models. ``hydroservo.references.cite(key)`` gives each in full.

        Examples
        --------
        >>> from hydroservo import System, components as c
        >>> s = System()
        >>> _ = s.add(c.Mass("load", m=2.0))
        >>> s.references()  # the Stribeck friction law, and the end stops (Hopsan's cylinder's)
        ['Efe2014', 'Hopsan2026']
        """
        import inspect

        from hydroservo.components.reference import citations
        from hydroservo.references import cited_in, keys

        found = [self.meta["citation"]] if self.meta.get("citation") else []
        for law in _laws_called(lambda: assemble(self)):
            found += cited_in(inspect.getdoc(law) or "")
        for comp in self.components.values():
            found += citations(comp)
        if self.fluid is not None:
            from hydroservo.fluids import get_fluid

            fluid = get_fluid(self.fluid.name)
            found += cited_in(inspect.getdoc(type(fluid)) or "") + cited_in(getattr(fluid, "description", "") or "")
        order = {k: i for i, k in enumerate(keys())}
        return sorted(set(found) & set(order), key=order.__getitem__)

    def diagram(self, file: str | Path | None = None, *, parameters: bool = True,
                title: str | None = None) -> Schematic:
        """The circuit diagram (ISO 1219-1 symbols, laid out automatically; :mod:`hydroservo.plotting.schematic`),
        written to ``file`` (``.svg``, ``.png`` or ``.pdf``) when given. ``parameters``: each component's main
        parameters beside its name, in the units they were given in."""
        from hydroservo.plotting.schematic import draw

        drawing = draw(self, parameters=parameters, title=title)
        if file is not None:
            drawing.save(file)
        return drawing

    def _repr_svg_(self) -> str:  # where HTML is not shown: the circuit
        return self.diagram().svg

    def _repr_html_(self) -> str:
        """In a notebook: name, description, source, notes, the circuit and (folded) the parameters."""
        from hydroservo.io.notebook import system_html

        return system_html(self)

    def __repr__(self) -> str:
        source = f", from {self.source}" if self.source else ""
        about = f": {self.description}" if self.description else ""
        return f"<System {self.name!r}{about} ({len(self.components)} components{source})>"

    def hydraulic_inputs(self) -> dict[str, list[tuple[float, str]]]:
        """The inputs the hydraulic and mechanical nodes feed: "comp.input" -> terms (coefficient, "comp.output")
        (see :func:`hydroservo.system.nodes.resolve`; raises for a node with no pressure port or two)."""
        return resolve(self.components, self.links) if self.links else {}

    def alias(self, name: str, expr: str, unit: str = "", description: str = "") -> None:
        """Name an expression of signals, e.g. ``alias("y", "-load.x", "m")``.

        The name is an identifier, or names joined by dots as another tool names its variables
        (``Mass.P2.Position``, Hopsan's ``Mass#P2#Position``); it must not be a signal's name."""
        if not (name.isidentifier() or re.fullmatch(r"\w+(\.\w+)+", name, flags=re.ASCII)):
            raise ModelError(f"alias {name!r}: expected an identifier, or names joined by dots (Mass.P2.Position)")
        if not isinstance(unit, str):
            raise ModelError(f"alias {name!r}: unit {unit!r}: expected a unit name such as 'mm'")
        try:
            check_unit(unit)
        except UnitError as exc:
            raise ModelError(f"alias {name!r}: {exc}") from None
        self.aliases[name] = Alias(str(expr), unit, description)

    def set_initial(self, state: str, value: str | float) -> None:
        """Initial value of ``state`` ("comp.state"): a number (SI), a quantity string,
        or an expression of parameters such as ``"load.W / cyl.A_A"``."""
        cname, sname = split_name(state, "initial condition")
        comp = self[cname]
        if sname not in comp.STATES:
            raise ModelError(
                f"initial condition {state!r}: {cname!r} has no state {sname!r}; states: {', '.join(comp.STATES)}"
            )
        self.initial_given.pop(state, None)
        if isinstance(value, str):
            try:
                si = to_si(value, comp.STATES[sname].unit, what=f"initial {state}")
            except HydroservoError:
                pass  # not a quantity: an expression of parameters, checked at build time
            else:
                self.initial_given[state] = value.strip()
                value = si
        self.initial[state] = value

    # -- parameters ---------------------------------------------------------
    def set(self, name: str, value: Any) -> None:
        """Set a parameter ("comp.param") or option; values may carry units."""
        cname, pname = split_name(name, "parameter")
        comp = self[cname]
        comp.set(**{pname: value})

    def parameter_names(self) -> list[str]:
        return [f"{c}.{p}" for c, comp in self.components.items() for p in comp.PARAMETERS]

    def declared(self, kind: str) -> dict[str, Any]:
        """What the components declare of one ``kind`` (``"PARAMETERS"``, ``"INPUTS"``, ``"STATES"``,
        ``"OUTPUTS"``), by full name: ``{"load.m": Param(...), ...}``."""
        return {f"{c}.{k}": spec for c, comp in self.components.items() for k, spec in getattr(comp, kind).items()}

    def parameter_values(self, *, as_run: bool = False) -> dict[str, float]:
        """Every numeric parameter's value [SI] by "comp.param"; with ``as_run``, as a run takes them: the stroke a
        valve and the spool that drives it share, set on one of them, on both."""
        values = {f"{c}.{p}": comp.values[p] for c, comp in self.components.items() for p in comp.PARAMETERS}
        if as_run:
            self._share_strokes(values, ())
        return values

    def parameter_key(self, key: str) -> str:
        """The current name "comp.param" of a numeric parameter given as ``key`` (a former name is accepted
        with a warning); an error for an unknown component or parameter, or an option (structural)."""
        cname, pname = split_name(key, "parameter")
        comp = self[cname]
        pname = comp.current_name(pname)
        if pname in comp.OPTIONS:
            raise ParameterError(
                f"{cname}.{pname}: is an option (structural); set it on the system with System.set, not per run"
            )
        if pname not in comp.PARAMETERS:
            comp.parse(pname, 0.0)  # raises the unknown-parameter error, with the known names
        return f"{cname}.{pname}"

    def parse_parameters(self, values: Mapping[str, Any] | None) -> dict[str, float]:
        """Check and convert a mapping "comp.param" -> value (with units) to SI."""
        out: dict[str, float] = {}
        for key, val in (values or {}).items():
            key = self.parameter_key(key)
            cname, pname = key.split(".", 1)
            out[key] = self[cname].parse(pname, val)
        return out

    def __getstate__(self) -> dict[str, Any]:
        """A system pickles without its compiled model (CasADi graphs do not pickle); it is rebuilt on first use."""
        state = dict(self.__dict__)
        state["_model"], state["_model_key"] = None, None
        return state

    def copy(self) -> System:
        """A deep copy (components included), e.g. to vary options."""
        new = copy.deepcopy(self)
        new._model = None
        new._model_key = None
        return new

    # -- building ----------------------------------------------------------
    def _structure_key(self) -> Any:
        def tables(c: Component) -> Any:  # arrays, and dicts of arrays (a valve's compensation tables)
            found: list[Any] = []
            for k, v in sorted(vars(c).items()):
                if isinstance(v, np.ndarray):
                    found.append((k, v.tobytes()))
                elif isinstance(v, dict) and v and all(isinstance(a, np.ndarray) for a in v.values()):
                    found.append((k, tuple((name, a.tobytes()) for name, a in sorted(v.items()))))
            return tuple(found)

        def declared(c: Component) -> Any:  # an instance's own declarations: a signal block's unit, a line's ends
            return (
                tuple((k, v.unit) for k, v in c.PARAMETERS.items()),
                tuple((k, v.unit, v.nominal) for k, v in c.STATES.items()),
                tuple((k, v.unit, v.nominal) for k, v in c.ALGEBRAIC.items()),
                tuple((k, v.unit, v.default) for k, v in c.INPUTS.items()),
                tuple((k, v.unit) for k, v in c.OUTPUTS.items()),
                tuple(c.LIMITS),
            )

        return (
            tuple(
                (n, type(c).__name__, tuple(sorted(c.option_values.items())), tables(c), c.structure_key(), declared(c))
                for n, c in self.components.items()
            ),
            tuple(sorted(self.connections.items())),
            tuple(self.links),
            tuple(sorted((k, (a.expr, a.unit)) for k, a in self.aliases.items())),
            tuple(sorted((k, str(v)) for k, v in self.initial.items())),
        )

    def build(self) -> Model:
        """Assemble the compiled model, or return it if nothing structural changed since.

        Compiled models are also kept across systems (the last :data:`BUILT_KEPT`), by their name and
        structure: loading the same model file again, or a copy of a system, finds its model built.
        """
        key = (self.name, self._structure_key())
        if self._model is not None and self._model_key == key:
            return self._model
        try:
            self.check_components()
            if key in _BUILT:  # another system of this structure built it
                _BUILT.move_to_end(key)
                self._model = _BUILT[key]
            else:
                self._model = Model(assemble(self))
        except (ModelError, ParameterError) as exc:
            if self.source and not str(exc).startswith(self.source):
                raise type(exc)(f"{self.source}: {exc}") from None
            raise
        self._model_key = key
        _BUILT[key] = self._model
        while len(_BUILT) > BUILT_KEPT:
            _BUILT.popitem(last=False)
        return self._model

    # -- running (thin wrappers over Model) ---------------------------------
    def simulate(
        self, t_end: float | str | None = None, params: Mapping[str, Any] | None = None, **kwargs: Any
    ) -> Result:
        """Simulate the system from its initial state and return every signal.

        Parameters
        ----------
        t_end : float or str, optional
            Duration [s], or a quantity (``"500 ms"``); default the system's :attr:`t_end`.
        params : mapping, optional
            Parameter values for this run only, ``"component.parameter"`` -> value, with units
            (``{"load.W": "3000 lbf"}``) or SI numbers; the system itself is not changed.
        **kwargs
            The integration's settings, those of :meth:`hydroservo.system.model.Model.simulate`: ``n_points``
            (output times, default 1001) or ``t_eval`` [s]; ``accuracy`` (deviation wanted, relative to each
            signal's range; default 1e-4) or ``rtol``/``atol``; ``method`` (``"auto"``: compiled ``rodas3`` for
            up to 20 states where a C compiler is found, else ``"cvodes"``; or ``"cvodes"``, ``"rodas3"``,
            ``"ros23"``, ``"dopri5"``); ``initial`` (``"parameters"``, ``"trim"`` or states [SI]);
            ``max_steps``; ``events``.

        Returns
        -------
        Result
            Signals by name, SI inside (``r["cyl.pA"]`` [Pa], ``r.get("cyl.pA", "psi")``), shown in the
            model's units by :meth:`~hydroservo.system.result.Result.summary`, ``to_pandas``, ``to_csv`` and
            ``plot`` (:meth:`unit_choice`); ``r.t`` [s]; ``r.stats`` (method, steps, wall time);
            ``r.warnings`` (physical bounds crossed, also issued as
            :class:`~hydroservo.errors.ImplausibleResultWarning`).

        Raises
        ------
        ParameterError
            A value out of its range or of the wrong unit, an unknown parameter or setting.
        SolverError
            The integration failed: the message says when, in which state and why.

        Examples
        --------
        >>> import hydroservo as hs
        >>> r = hs.load_model("flight-simulator").simulate(t_end="0.5 s", params={"load.W": "3000 lbf"})
        >>> round(float(r.get("y", "in")[-1]), 1), r.summary()["p2"]["unit"]
        (10.1, 'psi')
        """
        model = self.build()
        t = self.t_end if t_end is None else to_si(t_end, "s", what="t_end")
        result = model.simulate(t, self._vector(model, params), **kwargs)
        result.panels = self.default_panels()
        result.unit_choice = self.unit_choice()
        return result

    def unit_choice(self, units: Any = None) -> UnitChoice:
        """The units results of this model are shown in: ``units`` (``"p=bar, mm"``, ``"si"``; the user's) over
        the model's own (:meth:`model_units`).

        Examples
        --------
        >>> import hydroservo as hs
        >>> fs = hs.load_model("flight-simulator")
        >>> choice = fs.unit_choice("Q=L/min")
        >>> choice.unit("cyl.pA", "Pa"), choice.unit("valve.QA", "m^3/s"), choice.unit("load.v", "m/s")
        ('psi', 'L/min', 'in/s')
        """
        return UnitChoice.parse(units).over(self.model_units())

    def model_units(self) -> UnitChoice:
        """The model's own display units: its plot units by signal, over its declared :attr:`display_units`;
        without those, the unit its parameters, fluid and initial values were most often given in for each
        dimension (absolute pressures and temperatures aside), velocities and accelerations in the length unit
        per second (squared) if none was given."""
        per_signal = UnitChoice(dict(self.plot_units))
        if self.display_units:
            return per_signal.over(UnitChoice.parse(self.display_units, what=f"{self.source or self.name}: [model] units"))
        texts = [t for comp in self.components.values() for t in comp.given.values()]
        texts += list(self.initial_given.values())
        if self.fluid is not None:
            texts += [t for k, t in self.fluid.given if k != "temperature"]
        return per_signal.over(inferred_units(texts))

    def default_panels(self, aliases: bool = True) -> list[list[str]]:
        """The main signals to plot, panel by panel: the model file's ``plots``, else one panel per alias (unless
        ``aliases`` is False), else what an engineer looks at first (positions; spool positions; the pressures of
        the circuit's volumes, chambers and accumulators; speeds), else one panel per state (at most 8 panels)."""
        if self.plots:
            return [list(panel) for panel in self.plots]
        if self.aliases and aliases:
            return [[a] for a in list(self.aliases)[:8]]
        positions, spools, pressures, speeds = [], [], [], []
        for cname, comp in self.components.items():
            if not comp.STATES:
                continue  # sources and signal blocks without dynamics
            outputs = comp.OUTPUTS
            for name in ("x", "theta"):
                if name in outputs and name in comp.STATES:
                    positions.append(f"{cname}.{name}")
            if "xv" in outputs:
                spools.append(f"{cname}.xv")
            if "omega" in outputs and "omega" in comp.STATES:
                speeds.append(f"{cname}.omega")
            pressures += [f"{cname}.{port.p}" for port in comp.HYDRAULIC.values() if port.p in outputs]
        panels = [panel for panel in (positions, spools, pressures[:6], speeds) if panel]
        if panels:
            return panels
        return [[f"{c}.{s}"] for c, comp in self.components.items() for s in comp.STATES][:8]

    def trim(self, params: Mapping[str, Any] | None = None, **kwargs: Any) -> dict[str, float]:
        """Equilibrium state; see :meth:`hydroservo.system.model.Model.trim`."""
        model = self.build()
        return model.trim(self._vector(model, params), **kwargs)

    def batch(
        self, param_sets: Mapping[str, Iterable[Any]], t_end: float | str | None = None, **kwargs: Any
    ) -> BatchResult:
        """Many runs at once; see :meth:`hydroservo.system.model.Model.batch`.

        ``param_sets`` maps "comp.param" to equally long sequences of values
        (units allowed). A value out of range, of the wrong unit or breaking a
        component's cross-parameter check fails its own run, with the reason in
        :attr:`BatchResult.failed`; the other runs go ahead.
        """
        model = self.build()
        t = self.t_end if t_end is None else to_si(t_end, "s", what="t_end")
        given, n = batch_columns(param_sets)
        columns = {self.parameter_key(key): vals for key, vals in given.items()}
        invalid: dict[int, str] = {}
        si: dict[str, np.ndarray] = {}
        for key, vals in columns.items():
            cname, pname = key.split(".", 1)
            column = np.full(n, np.nan)
            for i, val in enumerate(vals):
                try:
                    column[i] = self[cname].parse(pname, val)
                except HydroservoError as exc:
                    invalid.setdefault(i, str(exc))
            si[key] = column
        for a, b in self.stroke_pairs():  # one stroke per valve: a varied stroke is the spool's and the valve's
            if (a in si) != (b in si):
                si[b if a in si else a] = si[a if a in si else b].copy()
            else:
                for run in np.flatnonzero(si[a] != si[b]).tolist() if a in si else []:
                    invalid.setdefault(run, f"run {run}: {a} and {b} differ; the spool and the valve have one stroke")
        for i in range(n):
            if i not in invalid:
                try:
                    self.check_components({key: float(col[i]) for key, col in si.items()}, only_changed=True)
                except HydroservoError as exc:
                    invalid[i] = str(exc)
        found = model.batch(t, self._vector(model, None), si, failed=invalid, **kwargs)
        found.unit_choice = self.unit_choice()
        found.panels = self.default_panels()
        return found

    def calibrate(self, records: Any, fit: Any, **options: Any) -> Any:
        """Fit parameters of this system to rig records, with exact gradients and Fisher-information intervals;
        see :func:`hydroservo.identification.calibration.calibrate` (the system itself is not changed: the
        result's ``system`` is the calibrated copy).

        Examples
        --------
        >>> import hydroservo as hs
        >>> from hydroservo.identification.rig import Sensor, virtual_rig
        >>> arm = hs.load_model("robot-arm")
        >>> rec = virtual_rig(arm, {"load.x": Sensor(200, "mm", noise=0.02)}, params={"load.B": 320.0}, seed=1)
        >>> cal = arm.calibrate([rec], ["load.B"], noise={"load.x": "0.02 mm"}, initial="model")
        >>> bool(abs(cal.values[0] - 320.0) < 2 * cal.stderr[0])
        True
        """
        from hydroservo.identification.calibration import calibrate

        return calibrate(self, records, fit, **options)

    def plan_experiment(self, records: Any, fit: Any, noise: Any, **options: Any) -> Any:
        """What planned experiments (records as the virtual rig makes them) would determine of the parameters
        ``fit``, before any record exists; see :func:`hydroservo.identification.calibration.plan_experiment`."""
        from hydroservo.identification.calibration import plan_experiment

        return plan_experiment(self, records, fit, noise, **options)

    def parameter_vector(self, params: Mapping[str, Any] | None = None) -> np.ndarray:
        """The parameter vector of the built model (SI, in :attr:`Model.parameter_names` order):
        the components' values, with ``params`` ("comp.param" -> value, units allowed) applied.

        Every entry point goes through here, so ranges and the components'
        cross-parameter checks (a stroke that fits the chamber volumes, a
        deadband inside the travel) hold for ``simulate(params=...)``,
        ``trim``, values changed by :meth:`set` after a first build, and the
        analysis and identification tools alike.

        Raises
        ------
        ParameterError
            Naming the parameter, its value and what was expected.
        """
        return self._vector(self.build(), params)

    def _vector(self, model: Model, params: Mapping[str, Any] | None) -> np.ndarray:
        """:meth:`parameter_vector` for ``model``, built already; a bare number for a parameter the model gives in
        a unit other than SI is taken in SI with a :class:`~hydroservo.errors.BareNumberWarning` (:func:`model_unit`)."""
        import warnings

        for key, val in (params or {}).items():
            cname, _, pname = str(key).partition(".")
            unit = model_unit(self.components[cname], pname, val) if cname in self.components else None
            if unit is not None:
                si = coherent_unit(self.components[cname].PARAMETERS[pname].unit)
                warnings.warn(BareNumberWarning(
                    f"params {key!r}: {val!r} is taken in SI, {val} {si}, but the model gives {key} in {unit} "
                    f"({self.components[cname].given[pname]!r}); give the unit to say which you mean: "
                    f"{{{key!r}: '{val} {unit}'}} or {{{key!r}: '{val} {si}'}}"), stacklevel=3)
        given = self.parse_parameters(params)
        values = self.parameter_values()
        values.update(given)
        self._share_strokes(values, set(given))
        self.check_components({k: values[k] for k in {*given, *self._stroke_keys()}})
        return np.array([values[n] for n in model.parameter_names], dtype=float)

    #: The stroke a valve shares with the spool that drives it: parameter name on both.
    STROKE = "xv_max"

    def stroke_pairs(self) -> list[tuple[str, str]]:
        """(valve, spool) stroke parameters that are one stroke: a spool's ``xv`` feeds a valve's ``xv``
        and both declare ``xv_max``."""
        pairs = []
        for target, source in self.connections.items():
            (tc, ti), (sc, so) = target.split("."), source.split(".")
            if ti == so == "xv" and all(self.STROKE in self.components[c].PARAMETERS for c in (tc, sc)):
                pairs.append((f"{tc}.{self.STROKE}", f"{sc}.{self.STROKE}"))
        return pairs

    def _stroke_keys(self) -> frozenset[str]:
        return frozenset(key for pair in self.stroke_pairs() for key in pair)

    def _share_strokes(self, values: dict[str, float], given: Collection[str]) -> None:
        """One stroke per valve: the value set (on the component, or for this run) goes to both of a pair;
        two different values set on both are refused."""
        for a, b in self.stroke_pairs():
            if (a in given) != (b in given):  # for this run: the one given is both's, as in a batch
                values[b if a in given else a] = values[a if a in given else b]
                continue
            set_a = a in given or a.split(".")[1] in self[a.split(".")[0]].explicit
            set_b = b in given or b.split(".")[1] in self[b.split(".")[0]].explicit
            if set_a and not set_b:
                values[b] = values[a]
            elif set_b and not set_a:
                values[a] = values[b]
            elif values[a] != values[b]:
                raise ParameterError(
                    f"{a} = {values[a]:g} m and {b} = {values[b]:g} m: the spool {b.split('.')[0]!r} drives the "
                    f"valve {a.split('.')[0]!r}, and they have one stroke; set it on one of them (the other takes it)"
                )

    def check_components(self, overrides: Mapping[str, float] | None = None, *, only_changed: bool = False) -> None:
        """Run every component's cross-parameter check (or, with ``only_changed``, those of the components
        ``overrides`` touches), with ``overrides`` ("comp.param" -> SI value) applied."""
        by_comp: dict[str, dict[str, Any]] = {}
        for key, val in (overrides or {}).items():
            cname, pname = key.split(".", 1)
            by_comp.setdefault(cname, {})[pname] = val
        for cname, comp in self.components.items():
            changed = by_comp.get(cname)
            if changed:
                comp.replace(**changed).check()
            elif not only_changed:
                comp.check()
