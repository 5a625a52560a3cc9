"""Systems: components connected into one ODE ``dx/dt = f(t, x, p)``.

A :class:`System` holds components, connections (an output of one component
feeds an input of another), aliases (named expressions of signals, with a
unit) and initial conditions. :meth:`System.build` assembles one CasADi
expression graph with every parameter a symbol, and returns a
:class:`~hydroservo.system.model.Model`; the model is rebuilt only when the
structure changes, never when a parameter value does.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from hydroservo.components.base import Component
from hydroservo.errors import HydroservoError, ModelError, ParameterError
from hydroservo.system.expressions import evaluate
from hydroservo.units import to_si, ureg

if TYPE_CHECKING:
    from hydroservo.system.model import Model
    from hydroservo.system.result import BatchResult, Result

__all__ = ["System", "Alias"]


@dataclass(frozen=True)
class Alias:
    """A named signal: an expression of other signals, with its unit."""

    expr: str
    unit: str
    description: str = ""


def _split(ref: str, what: str) -> tuple[str, str]:
    parts = str(ref).split(".")
    if len(parts) != 2 or not all(parts):
        raise ModelError(f"{what}: {ref!r} is not of the form 'component.signal'")
    return parts[0], parts[1]


class System:
    """Components connected into one model.

    Examples
    --------
    >>> from hydroservo import System, components as c
    >>> s = System("spring-mass")
    >>> _ = s.add(c.Mass("load", m=2.0, k=800.0, x0=0.01, incline=0.0))
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
        self.aliases: dict[str, Alias] = {}
        self.initial: dict[str, str | float] = {}
        self.source: str | None = None
        #: panels for plots of a run (lists of signal names) and the units to show them in
        self.plots: list[list[str]] = []
        self.plot_units: dict[str, str] = {}
        self._model: Model | None = None
        self._model_key: Any = None

    # -- structure --------------------------------------------------------------
    def add(self, component: Component) -> Component:
        """Add a component; its name must be new."""
        if component.name in self.components:
            raise ModelError(f"component {component.name!r} already exists in system {self.name!r}")
        self.components[component.name] = component
        return component

    def __getitem__(self, name: str) -> Component:
        try:
            return self.components[name]
        except KeyError:
            raise ModelError(
                f"no component {name!r} in system {self.name!r}; components: {', '.join(self.components)}"
            ) from None

    def connect(self, source: str, *targets: str) -> None:
        """Feed output ``source`` ("comp.output") into each input ``targets`` ("comp.input")."""
        sc, so = _split(source, "connection source")
        comp = self[sc]
        if so not in comp.OUTPUTS:
            raise ModelError(
                f"connection {source!r}: {type(comp).__name__} {sc!r} has no output {so!r}; outputs: {', '.join(comp.OUTPUTS)}"
            )
        for target in targets:
            tc, ti = _split(target, "connection target")
            tcomp = self[tc]
            if ti not in tcomp.INPUTS:
                raise ModelError(
                    f"connection {source!r} -> {target!r}: {type(tcomp).__name__} {tc!r} has no input {ti!r}; inputs: {', '.join(tcomp.INPUTS)}"
                )
            if target in self.connections:
                raise ModelError(f"input {target!r} is already connected to {self.connections[target]!r}")
            u_out, u_in = comp.OUTPUTS[so].unit, tcomp.INPUTS[ti].unit
            if u_out and u_in and ureg.Unit(u_out).dimensionality != ureg.Unit(u_in).dimensionality:
                raise ModelError(
                    f"connection {source!r} [{u_out}] -> {target!r} [{u_in}]: the units have different dimensions"
                )
            self.connections[target] = source

    def alias(self, name: str, expr: str, unit: str = "", description: str = "") -> None:
        """Name an expression of signals, e.g. ``alias("y", "-load.x", "m")``."""
        if not name.isidentifier():
            raise ModelError(f"alias {name!r}: expected an identifier")
        self.aliases[name] = Alias(str(expr), unit, description)

    def set_initial(self, state: str, value: str | float) -> None:
        """Initial value of ``state`` ("comp.state"): a number (SI), a quantity string,
        or an expression of parameters such as ``"load.W / cyl.A_A"``."""
        cname, sname = _split(state, "initial condition")
        comp = self[cname]
        if sname not in comp.STATES:
            raise ModelError(
                f"initial condition {state!r}: {cname!r} has no state {sname!r}; states: {', '.join(comp.STATES)}"
            )
        if isinstance(value, str):
            try:
                value = to_si(value, comp.STATES[sname].unit, what=f"initial {state}")
            except HydroservoError:
                pass  # not a quantity: an expression of parameters, checked at build time
        self.initial[state] = value

    # -- parameters ---------------------------------------------------------
    def set(self, name: str, value: Any) -> None:
        """Set a parameter ("comp.param") or option; values may carry units."""
        cname, pname = _split(name, "parameter")
        comp = self[cname]
        comp.set(**{pname: value})

    def parameter_names(self) -> list[str]:
        return [f"{c}.{p}" for c, comp in self.components.items() for p in comp.PARAMETERS]

    def parameter_values(self) -> dict[str, float]:
        return {f"{c}.{p}": comp.values[p] for c, comp in self.components.items() for p in comp.PARAMETERS}

    def parse_parameters(self, values: Mapping[str, Any] | None) -> dict[str, float]:
        """Check and convert a mapping "comp.param" -> value (with units) to SI."""
        out: dict[str, float] = {}
        for key, val in (values or {}).items():
            cname, pname = _split(key, "parameter")
            comp = self[cname]
            if pname in comp.OPTIONS:
                raise ParameterError(
                    f"{key}: is an option (structural); set it on the system with System.set, not per run"
                )
            out[key] = comp.parse(pname, val)
        return out

    def copy(self) -> System:
        """A deep copy (components included), e.g. to vary options."""
        new = copy.deepcopy(self)
        new._model = None
        new._model_key = None
        return new

    # -- building ----------------------------------------------------------
    def _structure_key(self) -> Any:
        def tables(c: Component) -> Any:
            return tuple((k, np.asarray(v).tobytes()) for k, v in sorted(vars(c).items()) if isinstance(v, np.ndarray))

        return (
            tuple(
                (n, type(c).__name__, tuple(sorted(c.option_values.items())), tables(c))
                for n, c in self.components.items()
            ),
            tuple(sorted(self.connections.items())),
            tuple(sorted((k, (a.expr, a.unit)) for k, a in self.aliases.items())),
            tuple(sorted((k, str(v)) for k, v in self.initial.items())),
        )

    def build(self) -> Model:
        """Assemble (or return the cached) compiled model."""
        key = self._structure_key()
        if self._model is not None and self._model_key == key:
            return self._model
        from hydroservo.system.model import Model

        for comp in self.components.values():
            comp.check()
        self._model = Model(*_assemble(self))
        self._model_key = key
        return self._model

    # -- running (thin wrappers over Model) ---------------------------------
    def simulate(
        self, t_end: float | str | None = None, params: Mapping[str, Any] | None = None, **kwargs: Any
    ) -> Result:
        """Simulate; see :meth:`hydroservo.system.model.Model.simulate`."""
        model = self.build()
        t = self.t_end if t_end is None else to_si(t_end, "s", what="t_end")
        return model.simulate(t, self._p(params), **kwargs)

    def trim(self, params: Mapping[str, Any] | None = None, **kwargs: Any) -> dict[str, float]:
        """Equilibrium state; see :meth:`hydroservo.system.model.Model.trim`."""
        return self.build().trim(self._p(params), **kwargs)

    def batch(
        self, param_sets: Mapping[str, Iterable[Any]], t_end: float | str | None = None, **kwargs: Any
    ) -> BatchResult:
        """Many runs at once; see :meth:`hydroservo.system.model.Model.batch`."""
        model = self.build()
        t = self.t_end if t_end is None else to_si(t_end, "s", what="t_end")
        sets = {k: [self.parse_parameters({k: v})[k] for v in vals] for k, vals in param_sets.items()}
        return model.batch(t, self._p(None), sets, **kwargs)

    def _p(self, params: Mapping[str, Any] | None) -> np.ndarray:
        model = self.build()
        values = self.parameter_values()
        values.update(self.parse_parameters(params))
        return np.array([values[n] for n in model.parameter_names], dtype=float)


class _Inputs(Mapping[str, Any]):
    """Inputs of one component, resolved on first access (lazy; detects loops)."""

    def __init__(self, asm: _Assembler, cname: str) -> None:
        self.asm, self.cname = asm, cname

    def __getitem__(self, key: str) -> Any:
        return self.asm.input(self.cname, key)

    def __iter__(self) -> Any:
        return iter(self.asm.system.components[self.cname].INPUTS)

    def __len__(self) -> int:
        return len(self.asm.system.components[self.cname].INPUTS)


class _Assembler:
    def __init__(self, system: System) -> None:
        self.system = system
        self.t = ca.SX.sym("t")
        self.p: dict[str, dict[str, ca.SX]] = {}
        self.x: dict[str, dict[str, ca.SX]] = {}
        self.out: dict[str, dict[str, Any]] = {}
        self.stack: list[str] = []
        for cname, comp in system.components.items():
            self.p[cname] = {k: ca.SX.sym(f"{cname}.{k}") for k in comp.PARAMETERS}
            self.x[cname] = {k: ca.SX.sym(f"{cname}.{k}") for k in comp.STATES}

    def input(self, cname: str, key: str) -> Any:
        comp = self.system.components[cname]
        if key not in comp.INPUTS:
            raise ModelError(f"{type(comp).__name__} {cname!r} reads undeclared input {key!r}")
        target = f"{cname}.{key}"
        source = self.system.connections.get(target)
        if source is None:
            default = comp.INPUTS[key].default
            if default is None:
                raise ModelError(
                    f"input {target!r} ({comp.INPUTS[key].description}) is not connected and has no default"
                )
            return ca.SX(default)
        sc, so = source.split(".")
        return self.outputs(sc)[so]

    def outputs(self, cname: str) -> dict[str, Any]:
        if cname in self.out:
            return self.out[cname]
        if cname in self.stack:
            loop = " -> ".join(self.stack[self.stack.index(cname) :] + [cname])
            raise ModelError(f"algebraic loop through the outputs of {loop}: one of them must hold a state")
        self.stack.append(cname)
        comp = self.system.components[cname]
        out = comp.output_equations(self.t, self.x[cname], _Inputs(self, cname), self.p[cname])
        if set(out) != set(comp.OUTPUTS):
            raise ModelError(
                f"{type(comp).__name__}.output_equations returned {sorted(out)}, declared {sorted(comp.OUTPUTS)}"
            )
        self.stack.pop()
        self.out[cname] = {k: ca.SX(v) if not isinstance(v, ca.SX) else v for k, v in out.items()}
        return self.out[cname]


def _assemble(system: System) -> tuple[Any, ...]:
    if not system.components:
        raise ModelError(f"system {system.name!r} has no components")
    asm = _Assembler(system)
    for target, source in system.connections.items():
        for ref in (target, source):
            c, s = ref.split(".")
            if c not in system.components:
                raise ModelError(f"connection {source!r} -> {target!r}: no component {c!r}")

    state_names: list[str] = []
    xs: list[ca.SX] = []
    rhs: list[ca.SX] = []
    units: dict[str, str] = {}
    descriptions: dict[str, str] = {}
    nominal: list[float] = []
    for cname, comp in system.components.items():
        y = asm.outputs(cname)
        if comp.STATES:
            der = comp.state_equations(asm.t, asm.x[cname], _Inputs(asm, cname), asm.p[cname], y)
            if set(der) != set(comp.STATES):
                raise ModelError(
                    f"{type(comp).__name__}.state_equations returned {sorted(der)}, declared {sorted(comp.STATES)}"
                )
            for sname, spec in comp.STATES.items():
                full = f"{cname}.{sname}"
                state_names.append(full)
                xs.append(asm.x[cname][sname])
                rhs.append(ca.SX(der[sname]))
                units[full] = spec.unit
                descriptions[full] = spec.description
                nominal.append(spec.nominal)

    # outputs (that are not states of the same name) and aliases
    out_names: list[str] = []
    out_exprs: list[ca.SX] = []
    signals: dict[str, Any] = {n: x for n, x in zip(state_names, xs)}
    for cname, comp in system.components.items():
        for oname, spec in comp.OUTPUTS.items():
            full = f"{cname}.{oname}"
            expr = asm.out[cname][oname]
            signals[full] = expr
            if full in units:  # an output that is the state itself
                continue
            out_names.append(full)
            out_exprs.append(expr)
            units[full] = spec.unit
            descriptions[full] = spec.description
    params = {f"{c}.{k}": s for c, d in asm.p.items() for k, s in d.items()}
    for aname, alias in system.aliases.items():
        if aname in signals:
            raise ModelError(f"alias {aname!r} clashes with a signal name")
        expr = evaluate(alias.expr, {**signals, **params}, what=f"alias {aname!r}")
        out_names.append(aname)
        out_exprs.append(ca.SX(expr))
        units[aname] = alias.unit
        descriptions[aname] = alias.description or alias.expr

    # initial conditions, symbolic in the parameters
    x0: list[Any] = []
    for full in state_names:
        cname, sname = full.split(".")
        if full in system.initial:
            val = evaluate(system.initial[full], params, what=f"initial condition of {full!r}")
        else:
            init = system.components[cname].STATES[sname].initial
            val = asm.p[cname][init] if isinstance(init, str) else float(init)
        x0.append(ca.SX(val))

    param_names = list(params)
    param_units = {
        f"{c}.{k}": spec.unit for c, comp in system.components.items() for k, spec in comp.PARAMETERS.items()
    }
    return (
        system.name,
        asm.t,
        ca.vertcat(*xs) if xs else ca.SX(0, 1),
        ca.vertcat(*[params[n] for n in param_names]) if params else ca.SX(0, 1),
        ca.vertcat(*rhs) if rhs else ca.SX(0, 1),
        ca.vertcat(*out_exprs) if out_exprs else ca.SX(0, 1),
        ca.vertcat(*x0) if x0 else ca.SX(0, 1),
        state_names,
        param_names,
        out_names,
        units,
        descriptions,
        np.array(nominal, dtype=float),
        param_units,
    )
