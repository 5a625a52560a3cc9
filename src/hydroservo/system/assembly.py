"""Assembly of a system's components into one CasADi expression graph.

Every parameter, state and algebraic unknown becomes a symbol; each component's outputs are
built once, on first demand, from its inputs, which are the outputs of other
components (so an output that depends on states alone never creates an
algebraic loop, and a true loop is reported with its chain of components).
Algebraic unknowns declared by components are then solved for in the graph
(:mod:`hydroservo.system.implicit`), and become outputs.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Protocol

import casadi as ca
import numpy as np

from hydroservo.components.base import Component
from hydroservo.errors import ModelError
from hydroservo.system.expressions import check_dimension, evaluate
from hydroservo.system.implicit import newton
from hydroservo.system.plausibility import Watched

__all__ = ["Structure", "Assembly", "assemble"]


class Structure(Protocol):
    """What the assembly reads of a system (:class:`~hydroservo.system.System` is one)."""

    @property
    def name(self) -> str: ...

    @property
    def components(self) -> Mapping[str, Component]: ...

    @property
    def connections(self) -> Mapping[str, str]: ...

    @property
    def aliases(self) -> Mapping[str, Any]: ...

    @property
    def initial(self) -> Mapping[str, str | float]: ...

    def hydraulic_inputs(self) -> Mapping[str, list[tuple[float, str]]]: ...


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
    def __init__(self, system: Structure, perturbed: tuple[str, ...] = ()) -> None:
        self.system = system
        #: A symbol added to each of these inputs (``component.input``): the inputs of a linearisation.
        self.perturb = {target: ca.SX.sym(f"d({target})") for target in perturbed}
        self.t = ca.SX.sym("t")
        self.p: dict[str, dict[str, ca.SX]] = {}
        self.x: dict[str, dict[str, ca.SX]] = {}
        self.z: dict[str, dict[str, ca.SX]] = {}
        #: What a component's equations see as ``x``: its states and its algebraic unknowns.
        self.xz: dict[str, dict[str, ca.SX]] = {}
        self.out: dict[str, dict[str, Any]] = {}
        self.stack: list[str] = []
        self.fed = system.hydraulic_inputs()
        for cname, comp in system.components.items():
            self.p[cname] = {k: ca.SX.sym(f"{cname}.{k}") for k in comp.PARAMETERS}
            self.x[cname] = {k: ca.SX.sym(f"{cname}.{k}") for k in comp.STATES}
            clash = set(comp.STATES) & set(comp.ALGEBRAIC)
            if clash:
                raise ModelError(f"{type(comp).__name__} declares {', '.join(sorted(clash))} as a state and an algebraic unknown")
            self.z[cname] = {k: ca.SX.sym(f"{cname}.{k}") for k in comp.ALGEBRAIC}
            self.xz[cname] = {**self.x[cname], **self.z[cname]}

    def input(self, cname: str, key: str) -> Any:
        value = self._input(cname, key)
        target = f"{cname}.{key}"
        return value + self.perturb[target] if target in self.perturb else value

    def _input(self, cname: str, key: str) -> Any:
        comp = self.system.components[cname]
        if key not in comp.INPUTS:
            raise ModelError(f"{type(comp).__name__} {cname!r} reads undeclared input {key!r}")
        target = f"{cname}.{key}"
        if target in self.fed:
            total: Any = ca.SX(0.0)
            for coef, ref in self.fed[target]:
                sc, so = ref.split(".")
                total = total + coef * self.outputs(sc)[so]
            return total
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
        out = comp.output_equations(self.t, self.xz[cname], _Inputs(self, cname), self.p[cname])
        if set(out) != set(comp.OUTPUTS):
            raise ModelError(
                f"{type(comp).__name__}.output_equations returned {sorted(out)}, declared {sorted(comp.OUTPUTS)}"
            )
        self.stack.pop()
        self.out[cname] = {k: ca.SX(v) if not isinstance(v, ca.SX) else v for k, v in out.items()}
        return self.out[cname]


@dataclass
class _Columns:
    """Named expressions with units and descriptions: the states or the outputs of the model."""

    names: list[str] = field(default_factory=list)
    exprs: list[Any] = field(default_factory=list)

    def add(self, name: str, expr: Any) -> None:
        self.names.append(name)
        self.exprs.append(ca.SX(expr))

    def vector(self) -> Any:
        return ca.vertcat(*self.exprs) if self.exprs else ca.SX(0, 1)


def _check_connections(system: Structure) -> None:
    for target, source in system.connections.items():
        for ref in (target, source):
            c = ref.split(".")[0]
            if c not in system.components:
                raise ModelError(f"connection {source!r} -> {target!r}: no component {c!r}")


def _states(asm: _Assembler, units: dict[str, str], descriptions: dict[str, str]) -> tuple[_Columns, _Columns, list[float]]:
    """The states (symbols), their rates and their nominal magnitudes, component by component."""
    states, rates, nominal = _Columns(), _Columns(), []
    for cname, comp in asm.system.components.items():
        y = asm.outputs(cname)
        if not comp.STATES:
            continue
        der = comp.state_equations(asm.t, asm.xz[cname], _Inputs(asm, cname), asm.p[cname], y)
        if set(der) != set(comp.STATES):
            raise ModelError(
                f"{type(comp).__name__}.state_equations returned {sorted(der)}, declared {sorted(comp.STATES)}"
            )
        for sname, spec in comp.STATES.items():
            full = f"{cname}.{sname}"
            states.add(full, asm.x[cname][sname])
            rates.add(full, der[sname])
            units[full], descriptions[full] = spec.unit, spec.description
            nominal.append(spec.nominal)
    return states, rates, nominal


def _outputs(
    asm: _Assembler, states: _Columns, params: dict[str, Any], units: dict[str, str], descriptions: dict[str, str]
) -> _Columns:
    """The outputs that are not states of the same name, then the aliases (expressions of signals)."""
    system = asm.system
    outputs = _Columns()
    signals: dict[str, Any] = dict(zip(states.names, states.exprs, strict=True))
    param_units = {f"{c}.{k}": spec.unit for c, comp in system.components.items() for k, spec in comp.PARAMETERS.items()}
    for cname, comp in system.components.items():
        for oname, spec in comp.OUTPUTS.items():
            full = f"{cname}.{oname}"
            signals[full] = asm.out[cname][oname]
            if full in units:  # an output that is the state itself
                continue
            outputs.add(full, signals[full])
            units[full], descriptions[full] = spec.unit, spec.description
    for cname, unknowns in asm.z.items():  # algebraic unknowns are recorded as outputs
        for zname, sym in unknowns.items():
            signals[f"{cname}.{zname}"] = sym
            outputs.add(f"{cname}.{zname}", sym)
    for aname, alias in system.aliases.items():
        if aname in signals:
            raise ModelError(f"alias {aname!r} clashes with a signal name")
        # a signal and a parameter of one name (a source's output p and its setting p): the signal, which may be driven
        outputs.add(aname, evaluate(alias.expr, {**params, **signals}, what=f"alias {aname!r}"))
        check_dimension(alias.expr, {**param_units, **units}, alias.unit, what=f"alias {aname!r}")
        units[aname], descriptions[aname] = alias.unit, alias.description or alias.expr
    return outputs


def _initial_state(asm: _Assembler, states: _Columns, params: dict[str, Any]) -> _Columns:
    """Initial conditions, symbolic in the parameters: the system's, else each state's declared one."""
    system = asm.system
    x0 = _Columns()
    for full in states.names:
        cname, sname = full.split(".")
        if full in system.initial:
            val = evaluate(system.initial[full], params, what=f"initial condition of {full!r}")
        else:
            init = system.components[cname].STATES[sname].initial
            val = asm.p[cname][init] if isinstance(init, str) else float(init)
        x0.add(full, val)
    return x0


def _limits(asm: _Assembler) -> list[tuple[Watched, Any, Any, Any]]:
    """Every declared :class:`~hydroservo.components.base.Limit`: what is watched, its expression and bounds.

    A limit on an input watches the signal connected to it (a cylinder's
    position is its load's ``x``); an unconnected input is not watched.
    """
    system = asm.system
    found: list[tuple[Watched, Any, Any, Any]] = []
    nan = ca.SX(float("nan"))
    for cname, comp in system.components.items():
        for sig, lim in comp.LIMITS.items():
            if sig in comp.STATES:
                name, expr = f"{cname}.{sig}", asm.x[cname][sig]
            elif sig in comp.ALGEBRAIC:
                name, expr = f"{cname}.{sig}", asm.z[cname][sig]
            elif sig in comp.OUTPUTS:
                name, expr = f"{cname}.{sig}", asm.out[cname][sig]
            elif sig in comp.INPUTS:
                source = system.connections.get(f"{cname}.{sig}")
                terms = asm.fed.get(f"{cname}.{sig}", [])
                if source is None and len(terms) == 1:
                    source = terms[0][1]
                if source is None:
                    continue
                name, expr = source, asm.input(cname, sig)
            else:
                raise ModelError(f"{type(comp).__name__} declares a limit on {sig!r}, which is not one of its signals")
            lo = asm.p[cname][lim.lower] if lim.lower else nan
            hi = asm.p[cname][lim.upper] if lim.upper else nan
            found.append((Watched(name, lim.kind, cname, lim.lower, lim.upper, lim.hint), expr, lo, hi))
    return found


def _switches(asm: _Assembler) -> tuple[list[str], list[Any], list[float]]:
    """Every component's switching functions (``Component.switch_equations``), named ``component.switch``."""
    names: list[str] = []
    exprs: list[Any] = []
    nominal: list[float] = []
    for cname, comp in asm.system.components.items():
        found = comp.switch_equations(asm.t, asm.xz[cname], _Inputs(asm, cname), asm.p[cname], asm.out[cname])
        for key, (expr, scale) in found.items():
            names.append(f"{cname}.{key}")
            exprs.append(ca.SX(expr))
            nominal.append(float(scale) if float(scale) > 0 else 1.0)
    return names, exprs, nominal


@dataclass
class _Implicit:
    """The algebraic unknowns of all components: symbols, residuals, first guesses."""

    names: list[str] = field(default_factory=list)
    z: list[Any] = field(default_factory=list)
    residual: list[Any] = field(default_factory=list)
    guess: list[Any] = field(default_factory=list)
    nominal: list[float] = field(default_factory=list)


def _algebraic(asm: _Assembler, units: dict[str, str], descriptions: dict[str, str]) -> _Implicit:
    """Every component's algebraic unknowns with their residuals and guesses, checked against the declarations."""
    found = _Implicit()
    for cname, comp in asm.system.components.items():
        if not comp.ALGEBRAIC:
            continue
        args = (asm.t, asm.xz[cname], _Inputs(asm, cname), asm.p[cname])
        res, guess = comp.residual_equations(*args), comp.guess_equations(*args)
        for what, got in (("residual_equations", res), ("guess_equations", guess)):
            if set(got) != set(comp.ALGEBRAIC):
                raise ModelError(
                    f"{type(comp).__name__}.{what} returned {sorted(got)}, declared {sorted(comp.ALGEBRAIC)}"
                )
        for zname, spec in comp.ALGEBRAIC.items():
            full = f"{cname}.{zname}"
            found.names.append(full)
            found.z.append(asm.z[cname][zname])
            found.residual.append(ca.SX(res[zname]))
            found.guess.append(ca.SX(guess[zname]))
            found.nominal.append(spec.nominal if spec.nominal > 0 else 1.0)
            units[full], descriptions[full] = spec.unit, spec.description
    return found


@dataclass(frozen=True)
class Assembly:
    """A system as one CasADi graph: what :func:`assemble` returns and :class:`~hydroservo.system.model.Model`
    compiles. Every expression is in the symbols ``t``, ``x`` (the states, SI) and ``p`` (the parameters)."""

    name: str  #: the system's name
    t: Any  #: time [s], an SX symbol
    x: Any  #: the states, an SX column
    p: Any  #: the parameters (then the perturbed inputs' symbols, if any), an SX column
    f: Any  #: the states' rates dx/dt
    y: Any  #: the outputs (components' outputs, then aliases)
    x0: Any  #: the initial state, in ``p`` only
    state_names: list[str]
    parameter_names: list[str]
    output_names: list[str]
    units: dict[str, str]  #: unit of every state, output and algebraic unknown
    descriptions: dict[str, str]
    nominal: np.ndarray  #: the states' nominal magnitudes
    parameter_units: dict[str, str]
    #: the physical bounds of :mod:`hydroservo.system.plausibility`: (what, expression, low, high)
    limits: list[tuple[Watched, Any, Any, Any]] = field(default_factory=list)
    #: the algebraic unknowns solved inside the graph, and the size of their last Newton correction
    convergence: tuple[list[str], Any] | None = None
    #: where the equations have kinks (``Component.switch_equations``): names, expressions, nominal magnitudes
    switches: tuple[list[str], Any, np.ndarray] = field(default_factory=lambda: ([], ca.SX(0, 1), np.zeros(0)))


def assemble(system: Structure, perturbed: tuple[str, ...] = ()) -> Assembly:
    """``system`` as one CasADi graph (:class:`Assembly`), what :class:`~hydroservo.system.model.Model` compiles.

    ``perturbed`` names component inputs (``"valve.xv"``) to which a symbol
    is added, whatever feeds them: the inputs of a linearisation. Their symbols
    come last in the parameter vector, named ``d(valve.xv)``, in the input's unit.
    """
    if not system.components:
        raise ModelError(f"system {system.name!r} has no components")
    _check_connections(system)
    for full in system.initial:  # a state may be gone since it was given: its component's options or size changed
        cname, sname = full.split(".")
        if cname not in system.components or sname not in system.components[cname].STATES:
            known = ", ".join(system.components[cname].STATES) if cname in system.components else "none"
            raise ModelError(
                f"initial condition {full!r}: {cname!r} has no state {sname!r} (its states depend on its options "
                f"or size); states: {known}"
            )
    for target in perturbed:
        cname, _, key = target.partition(".")
        if cname not in system.components or key not in system.components[cname].INPUTS:
            known = ", ".join(system.components[cname].INPUTS) if cname in system.components else "no such component"
            raise ModelError(f"input {target!r}: not an input of the system's components (inputs of {cname!r}: {known})")
    asm = _Assembler(system, tuple(perturbed))
    units: dict[str, str] = {}
    descriptions: dict[str, str] = {}
    states, rates, nominal = _states(asm, units, descriptions)
    implicit = _algebraic(asm, units, descriptions)
    params = {f"{c}.{k}": sym for c, d in asm.p.items() for k, sym in d.items()}
    outputs = _outputs(asm, states, params, units, descriptions)
    x0 = _initial_state(asm, states, params)
    limits = _limits(asm)
    switch_names, switch_exprs, switch_nominal = _switches(asm)
    convergence = None
    if implicit.names:
        zsym = ca.vertcat(*implicit.z)
        solution, correction = newton(
            zsym, ca.vertcat(*implicit.residual), ca.vertcat(*implicit.guess), implicit.nominal, implicit.names
        )
        rates.exprs = [ca.substitute(e, zsym, solution) for e in rates.exprs]
        outputs.exprs = [ca.substitute(e, zsym, solution) for e in outputs.exprs]
        limits = [(w, ca.substitute(ca.SX(e), zsym, solution), lo, hi) for w, e, lo, hi in limits]
        switch_exprs = [ca.substitute(e, zsym, solution) for e in switch_exprs]
        convergence = (implicit.names, correction)
    param_units = {
        f"{c}.{k}": spec.unit for c, comp in system.components.items() for k, spec in comp.PARAMETERS.items()
    }
    for target, sym in asm.perturb.items():
        cname, _, key = target.partition(".")
        params[sym.name()] = sym
        param_units[sym.name()] = system.components[cname].INPUTS[key].unit
    return Assembly(
        name=system.name,
        t=asm.t,
        x=states.vector(),
        p=ca.vertcat(*params.values()) if params else ca.SX(0, 1),
        f=rates.vector(),
        y=outputs.vector(),
        x0=x0.vector(),
        state_names=states.names,
        parameter_names=list(params),
        output_names=outputs.names,
        units=units,
        descriptions=descriptions,
        nominal=np.array(nominal, dtype=float),
        parameter_units=param_units,
        limits=limits,
        convergence=convergence,
        switches=(switch_names, ca.vertcat(*switch_exprs) if switch_exprs else ca.SX(0, 1), np.array(switch_nominal)),
    )
