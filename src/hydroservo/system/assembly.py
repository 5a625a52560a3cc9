"""Assembly of a system's components into one CasADi expression graph.

Every parameter and state becomes a symbol; each component's outputs are
built once, on first demand, from its inputs, which are the outputs of other
components (so an output that depends on states alone never creates an
algebraic loop, and a true loop is reported with its chain of components).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from hydroservo.errors import ModelError
from hydroservo.system.expressions import evaluate

if TYPE_CHECKING:
    from hydroservo.components.base import Output, State
    from hydroservo.system.system import System

__all__ = ["assemble"]


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


def assemble(system: System) -> tuple[Any, ...]:
    """The arguments of :class:`~hydroservo.system.model.Model` for ``system``."""
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
    spec: State | Output  # a state's declaration, then an output's
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
